"""A Unity project on disk: its root, its per-project salt, and where its scripts are.

Script GUIDs are read from the ``.cs.meta`` files of the project itself (``Assets/``) and of
its embedded packages (``Packages/``): the files a team commits. ``Library/`` is Unity's cache,
present on one machine and not on another (CI), so nothing in it may change an answer: the
scripts of packages Unity installs there (ROS#, uGUI) are known from their catalogs instead.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path

from unityscaffold.errors import UserError
from unityscaffold.fileout import real_path
from unityscaffold.unity.meta import read_meta_guid
from unityscaffold.unity.values import ScriptRef

__all__ = [
    "FALLBACK_SALT",
    "ScriptInfo",
    "find_project_root",
    "project_salt",
    "script_index",
    "script_ref_for_file",
]

#: Salt for projects without ``productGUID`` (GUIDs are then only unique per asset path).
FALLBACK_SALT = "unityscaffold-default-salt"
SCRIPT_ROOTS = ("Assets", "Packages")
_PRODUCT_GUID_RE = re.compile(r"^\s*productGUID: ([0-9a-f]{32})\s*$", re.M)


@dataclass(frozen=True, slots=True)
class ScriptInfo:
    """A ``.cs`` script found in the project: class name (= file stem), path, and GUID."""

    class_name: str
    path: str  # project-relative, posix
    guid: str


def find_project_root(path: str | Path) -> Path | None:
    """The nearest ancestor of ``path`` (or itself) holding ``Assets/`` and ``ProjectSettings/``."""
    current = real_path(Path(path))
    for candidate in (current, *current.parents):
        if (candidate / "Assets").is_dir() and (candidate / "ProjectSettings").is_dir():
            return candidate
    return None


def project_salt(root: str | Path) -> str:
    """The project's ``productGUID`` (random per project, committed by teams) or the fallback."""
    settings = Path(root) / "ProjectSettings" / "ProjectSettings.asset"
    try:
        text = settings.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return FALLBACK_SALT
    match = _PRODUCT_GUID_RE.search(text)
    return match.group(1) if match else FALLBACK_SALT


def script_index(root: str | Path) -> dict[str, ScriptInfo]:
    """Every ``.cs`` script with a ``.meta`` under the script roots, keyed by GUID."""
    base = Path(root)
    found: dict[str, ScriptInfo] = {}
    for top in SCRIPT_ROOTS:
        for directory, dirs, files in os.walk(base / top):
            dirs.sort()
            for name in sorted(files):
                if not name.endswith(".cs.meta"):
                    continue
                meta = Path(directory) / name
                guid = read_meta_guid(meta)
                if guid is not None and guid not in found:
                    rel = meta.relative_to(base).as_posix()[: -len(".meta")]
                    found[guid] = ScriptInfo(name[: -len(".cs.meta")], rel, guid)
    return found


def script_ref_for_file(path: str | Path) -> ScriptRef:
    """The ``m_Script`` reference of a ``.cs`` file, read from the ``.meta`` beside it."""
    script = Path(path)
    if script.suffix != ".cs":
        raise UserError(f"{script} is not a C# script (.cs)")
    guid = read_meta_guid(script.with_name(script.name + ".meta"))
    if guid is None:
        raise UserError(
            f"{script} has no .meta file with a GUID",
            hint="let Unity import the script once, or generate it with scaffold apply",
        )
    return ScriptRef(guid, class_name=script.stem)
