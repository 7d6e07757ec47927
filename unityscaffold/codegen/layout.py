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
from unityscaffold.fileout import DesiredFile, real_path
from unityscaffold.unity.meta import folder_meta, guid_for, monoscript_meta
from unityscaffold.unity.project import FALLBACK_SALT, find_project_root, project_salt

__all__ = ["output_files"]

_ROOT_FOLDERS = {"Assets", "Packages"}


def _base_and_salt(out_dir: Path) -> tuple[Path, str, bool]:
    root = find_project_root(out_dir)
    if root is not None:
        return root, project_salt(root), True
    return out_dir.parent, FALLBACK_SALT, False


def output_files(
    code: GeneratedCode, out_dir: Path, *, project: Path | None = None
) -> list[DesiredFile]:
    """Every file ``code`` puts under ``out_dir``: sources (UTF-8, LF) and metas.

    ``project`` is the Unity project's real path when the caller knows it (apply): ``out_dir``
    is then a path inside it, taken as written, so that its files have the same paths as the
    rest of the plan's. Else ``out_dir`` is resolved and its project looked for above it.
    """
    if project is not None:
        base, salt, in_project = project, project_salt(project), True
    else:
        out_dir = real_path(out_dir)
        base, salt, in_project = _base_and_salt(out_dir)
    # Asset paths are strings joined onto the output folder's: a pathlib call per file and
    # folder was a tenth of generating Debian's 183 types.
    out_asset = out_dir.relative_to(base).as_posix()
    prefix = "" if out_asset == "." else out_asset + "/"
    desired: list[DesiredFile] = []
    folders: set[str] = {"."} if in_project and code.files else set()
    for file in code.files:
        path = out_dir / file.path
        desired.append(DesiredFile(path, file.text.encode("utf-8")))
        desired.append(
            DesiredFile(
                path.with_name(path.name + ".meta"),
                monoscript_meta(guid_for(salt, prefix + file.path)).encode(),
                True,
            )
        )
        parts = file.path.split("/")[:-1]
        folders.update("/".join(parts[:end]) for end in range(1, len(parts) + 1))
    for folder in folders:
        relative = out_asset if folder == "." else prefix + folder
        if relative in _ROOT_FOLDERS or relative == ".":
            continue
        path = out_dir if folder == "." else out_dir / folder
        desired.append(
            DesiredFile(
                path.with_name(path.name + ".meta"),
                folder_meta(guid_for(salt, relative)).encode(),
                True,
            )
        )
    return sorted(desired, key=lambda d: d.path.parts)  # the order of Path's own comparison
