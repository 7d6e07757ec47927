"""The one place files get written: compare before writing, then write all or nothing.

``plan_files`` compares each desired file with the disk and says what would happen
(``create``, ``update``, ``unchanged``, or ``skip`` for a create-only file that exists, such as a
``.meta`` whose GUID must never change). ``write_files`` writes every changed file to a
temporary file in its folder first and renames them into place only once all are written, so
a failure leaves no half-written output; a file whose bytes are unchanged is never rewritten.
"""

from __future__ import annotations

import contextlib
import enum
import os
import tempfile
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from unityscaffold.errors import UserError

__all__ = ["Action", "DesiredFile", "FileChange", "plan_files", "write_files"]


class Action(enum.Enum):
    CREATE = "create"
    UPDATE = "update"
    UNCHANGED = "unchanged"
    SKIP = "skip"


@dataclass(frozen=True, slots=True)
class DesiredFile:
    """A file as it should be; ``create_only`` files are written only when missing."""

    path: Path
    content: bytes
    create_only: bool = False


@dataclass(frozen=True, slots=True)
class FileChange:
    """What writing one desired file would do."""

    path: Path
    action: Action
    content: bytes
    reason: str = ""

    @property
    def writes(self) -> bool:
        return self.action in (Action.CREATE, Action.UPDATE)


def _blocking_ancestor(path: Path) -> Path | None:
    """An ancestor of ``path`` that exists but is not a folder."""
    for parent in reversed(path.parents):
        if parent.exists() and not parent.is_dir():
            return parent
    return None


def _change(want: DesiredFile) -> FileChange:
    path = want.path
    if path.is_dir():
        raise UserError(f"cannot write {path}: a folder of that name exists")
    blocker = _blocking_ancestor(path)
    if blocker is not None:
        raise UserError(
            f"cannot write {path}: {blocker} exists and is not a folder",
            hint="choose another output folder, or move that file away",
        )
    try:
        current = path.read_bytes()
    except FileNotFoundError:
        return FileChange(path, Action.CREATE, want.content)
    except OSError as exc:
        raise UserError(f"cannot read {path}: {exc.strerror}") from None
    if current == want.content:
        return FileChange(path, Action.UNCHANGED, want.content)
    if want.create_only:
        return FileChange(path, Action.SKIP, want.content, "exists; kept as it is")
    return FileChange(path, Action.UPDATE, want.content)


def plan_files(desired: Iterable[DesiredFile]) -> list[FileChange]:
    """What writing ``desired`` would change, sorted by path; reads, never writes."""
    by_path: dict[Path, DesiredFile] = {}
    for want in desired:
        other = by_path.setdefault(want.path, want)
        if other.content != want.content:
            raise UserError(f"two different contents planned for {want.path}")
    return [_change(by_path[path]) for path in sorted(by_path)]


def _make_folders(folder: Path, created: list[Path], ready: set[Path]) -> None:
    if folder in ready:
        return
    ready.add(folder)
    missing = [p for p in (folder, *folder.parents) if not p.exists()]
    for path in reversed(missing):
        path.mkdir()
        created.append(path)


def _new_file_mode() -> int:
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def _write_temp(change: FileChange, mode: int) -> Path:
    handle, name = tempfile.mkstemp(
        dir=change.path.parent, prefix=f".{change.path.name}.", suffix=".tmp"
    )
    temp = Path(name)
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(change.content)
        keep = change.path.stat().st_mode & 0o7777 if change.path.exists() else mode
        os.chmod(temp, keep)
    except BaseException:
        temp.unlink(missing_ok=True)
        raise
    return temp


def write_files(changes: Sequence[FileChange]) -> list[Path]:
    """Write the ``create``/``update`` changes all at once; returns the paths written."""
    todo = [c for c in changes if c.writes]
    created: list[Path] = []
    temps: list[tuple[Path, Path]] = []
    mode = _new_file_mode()
    ready: set[Path] = set()
    try:
        for change in todo:
            _make_folders(change.path.parent, created, ready)
            temps.append((_write_temp(change, mode), change.path))
    except BaseException as exc:
        for temp, _ in temps:
            temp.unlink(missing_ok=True)
        for folder in reversed(created):
            with contextlib.suppress(OSError):
                folder.rmdir()
        if isinstance(exc, OSError):
            raise UserError(f"cannot write {exc.filename or 'output'}: {exc.strerror}") from None
        raise
    for done, (temp, path) in enumerate(temps):
        try:
            os.replace(temp, path)
        except OSError as exc:
            for leftover, _ in temps[done:]:
                leftover.unlink(missing_ok=True)
            raise UserError(
                f"cannot replace {path}: {exc.strerror}; {done} of {len(temps)} "
                "files were already written",
                hint="fix the cause (a file locked by another program?) and run "
                "again: unchanged files are skipped",
            ) from None
    return [path for _, path in temps]
