"""Where generated classes go in a Unity project, with their ``.meta`` files.

``<out>/<Pkg>/<msg|srv|action>/<Class>.cs``, each with a ``.cs.meta`` and every folder with a
folder ``.meta``. GUIDs are ``guid_for(salt, asset path)``: the asset path is relative to the
Unity project root when ``out`` is inside one (salt: the project's; ``out`` itself gets a
folder ``.meta`` too), else relative to ``out``'s parent (fallback salt; nothing is written
outside ``out``). Metas are create-only: an existing one is never changed.
"""

from __future__ import annotations

from pathlib import Path

from unityscaffold.codegen.generate import GeneratedCode
from unityscaffold.fileout import DesiredFile
from unityscaffold.unity.meta import folder_meta, guid_for, monoscript_meta
from unityscaffold.unity.project import FALLBACK_SALT, find_project_root, project_salt

__all__ = ["output_files"]

_ROOT_FOLDERS = {"Assets", "Packages"}


def _base_and_salt(out_dir: Path) -> tuple[Path, str, bool]:
    root = find_project_root(out_dir)
    if root is not None:
        return root, project_salt(root), True
    return out_dir.parent, FALLBACK_SALT, False


def output_files(code: GeneratedCode, out_dir: Path) -> list[DesiredFile]:
    """Every file ``code`` puts under ``out_dir``: sources (UTF-8, LF) and metas."""
    out_dir = out_dir.resolve()
    base, salt, in_project = _base_and_salt(out_dir)
    desired: list[DesiredFile] = []
    folders: set[Path] = set()
    for file in code.files:
        path = out_dir / file.path
        asset = path.relative_to(base).as_posix()
        desired.append(DesiredFile(path, file.text.encode("utf-8")))
        desired.append(
            DesiredFile(
                path.with_name(path.name + ".meta"),
                monoscript_meta(guid_for(salt, asset)).encode(),
                True,
            )
        )
        folders.update(
            p for p in path.parents if out_dir in p.parents or (in_project and p == out_dir)
        )
    for folder in sorted(folders):
        relative = folder.relative_to(base)
        if len(relative.parts) <= 1 and relative.as_posix() in _ROOT_FOLDERS | {"."}:
            continue
        desired.append(
            DesiredFile(
                folder.with_name(folder.name + ".meta"),
                folder_meta(guid_for(salt, relative.as_posix())).encode(),
                True,
            )
        )
    return sorted(desired, key=lambda d: d.path)
