"""``.meta`` files for the project's own scripts that Unity has not imported yet.

A manifest may name a script (by class or by ``.cs`` path) that has no ``.meta`` beside it, in a
project Unity has never opened since the script was written. Apply gives it one with the GUID
derived from the project's salt and the script's path (``unity/meta.py``), so the scene can refer
to the script now; Unity keeps an existing ``.meta`` and its GUID when it imports the script.
Only scripts under ``Assets/`` that the manifest names get one; the file is created once.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.fileout import DesiredFile
from unityscaffold.manifest.model import Manifest
from unityscaffold.unity.meta import guid_for, monoscript_meta
from unityscaffold.unity.project import ScriptInfo

__all__ = ["ScriptMetas", "plan_script_metas"]


@dataclass(slots=True)
class ScriptMetas:
    desired: list[DesiredFile] = field(default_factory=list)
    scripts: dict[str, ScriptInfo] = field(default_factory=dict)  # the index, with the new ones


def _unimported(project: Path) -> dict[str, list[str]]:
    """Class name (file stem) -> project-relative paths of ``.cs`` files without a ``.meta``."""
    found: dict[str, list[str]] = {}
    for directory, dirs, files in os.walk(project / "Assets"):
        dirs.sort()
        present = set(files)
        for name in sorted(files):
            if name.endswith(".cs") and f"{name}.meta" not in present:
                relative = (Path(directory) / name).relative_to(project).as_posix()
                found.setdefault(name[:-3], []).append(relative)
    return found


def plan_script_metas(manifest: Manifest, scripts: dict[str, ScriptInfo], salt: str) -> ScriptMetas:
    result = ScriptMetas(scripts=dict(scripts))
    named = {c.script for c in manifest.components}
    if not named:
        return result
    known = {info.class_name for info in scripts.values()}
    unimported = _unimported(manifest.project_root)
    wanted: set[str] = set()
    for script in named:
        if script.endswith(".cs"):
            if script.startswith("Assets/") and script in unimported.get(Path(script).stem, []):
                wanted.add(script)
        elif script not in known and len(unimported.get(script, [])) == 1:
            wanted.add(unimported[script][0])
    for relative in sorted(wanted):
        guid = guid_for(salt, relative)
        path = manifest.project_root / (relative + ".meta")
        result.desired.append(
            DesiredFile(path, monoscript_meta(guid).encode("utf-8"), create_only=True)
        )
        result.scripts[guid] = ScriptInfo(Path(relative).stem, relative, guid)
    return result
