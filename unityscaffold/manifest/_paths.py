"""Checks that paths written in the manifest stay where they must.

Paths inside the project (``output``, scenes, scripts) are kept as normalised POSIX text,
relative to the project root; they may not be absolute, climb out with ``..``, or, when the
project exists on disk, leave it through a symbolic link. Writing through such a path would
put files outside the project, which ``apply`` must never do.
"""

from __future__ import annotations

import posixpath
import re
from pathlib import Path, PurePosixPath

from unityscaffold.errors import UserError
from unityscaffold.fileout import MAX_NAME_BYTES, name_too_long, real_path
from unityscaffold.manifest._read import Reader
from unityscaffold.manifest._yaml import YEntry

__all__ = ["folder_path", "project_path"]

_DRIVE = re.compile(r"^[A-Za-z]:")


def _portable(reader: Reader, entry: YEntry, value: str) -> bool:
    if "\\" in value:
        reader.invalid(
            entry,
            "a path with '/' separators",
            hint="write '/' between folders: the manifest is shared across systems",
        )
        return False
    return True


def _is_absolute(value: str) -> bool:
    return value.startswith("/") or bool(_DRIVE.match(value))


def project_path(
    reader: Reader,
    entry: YEntry,
    value: str,
    project_root: Path,
    *,
    expected: str,
    under: str | None = None,
) -> str | None:
    """``value`` normalised relative to the project, or None after reporting why it is wrong.

    ``under`` (e.g. ``Assets``) is a folder the path must lie strictly inside.
    """
    if not _portable(reader, entry, value):
        return None
    if _is_absolute(value):
        reader.invalid(
            entry,
            expected,
            hint="write the path relative to the project root, the folder that holds Assets/",
        )
        return None
    norm = posixpath.normpath(value)
    if norm == ".." or norm.startswith("../"):
        reader.invalid(
            entry,
            expected,
            hint=f"'{value}' leaves the project through '..'; "
            "every path must stay inside the project",
        )
        return None
    if under is not None and not norm.startswith(under + "/"):
        reader.invalid(
            entry,
            expected,
            hint=f"it must be a folder inside {under}/, where "
            f"Unity compiles scripts, e.g. {under}/RosGenerated",
        )
        return None
    long_part = name_too_long(norm, len(".meta"))
    if long_part is not None:
        reader.invalid(
            entry,
            expected,
            hint=f"'{long_part[:24]}…' is {len(long_part.encode('utf-8'))} bytes long; a file "
            f"or folder name holds at most {MAX_NAME_BYTES} bytes, and Unity adds '.meta' "
            "beside it",
        )
        return None
    base = project_root / under if under else project_root
    if project_root.is_dir():
        try:
            real, real_base = real_path(project_root / norm), real_path(base)
        except UserError as error:
            reader.invalid(entry, expected, hint=error.message)
            return None
        if real != real_base and not real.is_relative_to(real_base):
            reader.invalid(
                entry,
                expected,
                hint=f"'{norm}' resolves to {real.as_posix()} "
                "through a symbolic link, outside "
                f"{'the project' if under is None else under + '/'}",
            )
            return None
    return PurePosixPath(norm).as_posix()


def folder_path(
    reader: Reader, entry: YEntry, value: str, base: Path, *, allow_absolute: bool
) -> Path | None:
    """A folder written relative to the manifest (``project``, ``interfaces``), as its real path
    (symbolic links followed once, here, so that every path derived from it agrees)."""
    if not _portable(reader, entry, value):
        return None
    if _is_absolute(value) and not allow_absolute:
        reader.invalid(
            entry,
            "a path relative to the manifest's folder",
            hint="the manifest lives in git beside the project; an absolute path "
            "would not work on another machine",
        )
        return None
    try:
        # resolved, not normalised as text: 'link/..' is where the link's target's parent is
        return real_path(base / value)
    except UserError as error:
        reader.invalid(entry, "a folder relative to the manifest's folder", hint=error.message)
        return None
