"""File output, the one way unityscaffold writes files: compare before writing, then replace.

A ``DesiredFile`` is a file as it should be. ``plan_files`` compares desired files with the disk
and says what writing them would do, as ``FileChange`` values of a ``ChangeKind``: create,
update, unchanged, or skip (a create-only file that exists, such as a ``.meta`` whose GUID must
never change). Planning reads and never writes, so ``plan`` and ``apply --check`` share it.

``write_files`` writes a batch all or nothing: each changed file goes to a temporary file in its
own folder, and only once every one is written are they renamed into place, so a failure leaves
no half-written file, no temporary file and no new folder behind. ``write_if_changed`` is the
same path for a single file, ``write_chunks_if_changed`` for one too large to hold twice. A file
whose bytes are unchanged is never rewritten, an existing file keeps its permission bits, and a
new one gets the mode the umask allows.

Files are written with LF line endings, but a file that differs from the desired one only in
CRLF line endings counts as unchanged (``same_text``): Git for Windows checks text out with
CRLF (``core.autocrlf=true``) unless ``.gitattributes`` says otherwise, and such a checkout is
not drift.

This module sits at the bottom of the layers (see ``tests/test_layers.py``): it imports only
``unityscaffold.errors``, so every other package may use it.
"""

from __future__ import annotations

import contextlib
import enum
import hashlib
import itertools
import os
import re
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from unityscaffold.errors import UserError

__all__ = [
    "MAX_NAME_BYTES",
    "ChangeKind",
    "DesiredFile",
    "FileChange",
    "check_name_lengths",
    "name_too_long",
    "plan_files",
    "real_path",
    "same_text",
    "temp_leftovers",
    "write_chunks_if_changed",
    "write_files",
    "write_if_changed",
]


MAX_NAME_BYTES = 255
"""The longest file or folder name, in bytes of UTF-8, that common file systems take (ext4,
APFS, NTFS count 255 of their units). A fixed figure, not the local one, so that a project that
applies here also applies on a teammate's machine."""


def name_too_long(relative: str, extra: int = 0) -> str | None:
    """The first ``/``-separated part of ``relative`` whose name, with ``extra`` more bytes
    (a ``.meta`` suffix), would not fit in ``MAX_NAME_BYTES``; None when all fit."""
    return next(
        (p for p in relative.split("/") if len(p.encode("utf-8")) + extra > MAX_NAME_BYTES), None
    )


def check_name_lengths(paths: Iterable[Path]) -> None:
    """Refuse, before anything is read or written, a path with a name the disk cannot hold
    (an ``OSError`` half-way through would leave a partial result)."""
    for path in paths:
        part = name_too_long(path.as_posix())
        if part is not None:
            raise UserError(
                f"cannot write {path}: the name '{part[:24]}…' is "
                f"{len(part.encode('utf-8'))} bytes long",
                hint=f"file systems take names of at most {MAX_NAME_BYTES} bytes; "
                "shorten the name in the manifest or the interface it comes from",
            )


def real_path(path: Path) -> Path:
    """``path`` absolute, with its symbolic links and ``..`` followed as the system follows them.

    Paths are resolved once, through this, and compared as text after: a project reached through
    a link and the same files reached by their real path must not count as two places. A link
    that leads back into itself is the user's to fix, not an internal error.
    """
    try:
        return path.resolve()
    # RuntimeError: a link loop (Python < 3.13); ValueError: a name the system cannot encode
    except (RuntimeError, OSError, ValueError) as exc:
        raise UserError(
            f"cannot follow {path}: {exc}",
            hint="write a folder that exists, with no symbolic link on the way that leads back "
            "to itself",
        ) from None


class ChangeKind(enum.Enum):
    """What writing one desired file does to the disk."""

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
    kind: ChangeKind
    content: bytes
    reason: str = ""

    @property
    def writes(self) -> bool:
        return self.kind in (ChangeKind.CREATE, ChangeKind.UPDATE)


# ----- planning: read, never write ---------------------------------------------------------------


def same_text(current: bytes, wanted: bytes) -> bool:
    """Whether two files have the same content once CRLF line endings are read as LF."""
    if current == wanted:
        return True
    if b"\r" not in current and b"\r" not in wanted:
        return False  # no copies of a 100 MB scene to learn that
    return current.replace(b"\r\n", b"\n") == wanted.replace(b"\r\n", b"\n")


def _blocking_ancestor(path: Path, seen: dict[Path, Path | None]) -> Path | None:
    """An ancestor of ``path`` that exists but is not a folder (``seen`` caches by folder)."""
    folder = path.parent
    if folder not in seen:
        seen[folder] = next(
            (p for p in reversed(path.parents) if p.exists() and not p.is_dir()), None
        )
    return seen[folder]


def _folder_missing(folder: str, missing: dict[str, bool]) -> bool:
    """Whether ``folder`` is certainly absent, so that nothing inside it exists (POSIX only).

    ENOENT on the folder means no part of its path is a file (that would be ENOTDIR): every
    file planned inside it is a create, without a system call each. ``missing`` caches by folder.
    """
    found = missing.get(folder)
    if found is None:
        try:
            os.stat(folder)
            found = False
        except FileNotFoundError:
            found = os.name == "posix"  # Windows reports a file in the way as not found too
        except OSError:
            found = False  # the file's own read explains what is wrong
        missing[folder] = found
    return found


def _read(name: str) -> bytes:
    """The whole file, unbuffered (a buffered reader costs more than a small file's read)."""
    with open(name, "rb", buffering=0) as stream:
        return stream.readall()


def _change(
    want: DesiredFile, seen: dict[Path, Path | None], missing: dict[str, bool]
) -> FileChange:
    path = want.path
    name = os.fspath(path)
    if _folder_missing(os.path.dirname(name) or ".", missing):
        return FileChange(path, ChangeKind.CREATE, want.content)
    try:
        # Read first: an existing file settles every question below with one system call.
        current = _read(name)
    except OSError as exc:
        if isinstance(exc, FileNotFoundError) and os.name == "posix":
            # ENOENT: nothing there and no ancestor is a file (that would be ENOTDIR), so the
            # checks below would stat for nothing. Windows reports both as not found.
            return FileChange(path, ChangeKind.CREATE, want.content)
        if path.is_dir():
            raise UserError(
                f"cannot write {path}: a folder of that name exists",
                hint="name a file, not a folder, or move that folder away",
            ) from None
        blocker = _blocking_ancestor(path, seen)
        if blocker is not None:
            raise UserError(
                f"cannot write {path}: {blocker} exists and is not a folder",
                hint="choose another output folder, or move that file away",
            ) from None
        if isinstance(exc, FileNotFoundError):
            return FileChange(path, ChangeKind.CREATE, want.content)
        raise UserError(f"cannot read {path}: {exc.strerror}") from None
    if same_text(current, want.content):
        return FileChange(path, ChangeKind.UNCHANGED, want.content)
    if want.create_only:
        return FileChange(path, ChangeKind.SKIP, want.content, "exists; kept as it is")
    return FileChange(path, ChangeKind.UPDATE, want.content)


def plan_files(desired: Iterable[DesiredFile]) -> list[FileChange]:
    """What writing ``desired`` would change, sorted by path; reads, never writes."""
    by_path: dict[Path, DesiredFile] = {}
    for want in desired:
        other = by_path.setdefault(want.path, want)
        if other.content != want.content:
            raise UserError(f"two different contents planned for {want.path}")
    seen: dict[Path, Path | None] = {}
    missing: dict[str, bool] = {}
    # sorted as Paths sort, by their parts, without Path's slower comparison methods
    return [
        _change(by_path[path], seen, missing) for path in sorted(by_path, key=lambda p: p.parts)
    ]


# ----- writing: temporary files first, renamed into place at the end -----------------------------


def _make_folders(folder: str, created: list[str], ready: set[str]) -> None:
    """Create ``folder`` and its missing parents, recording each in ``created`` for rollback.

    Paths are strings here and below: this runs for every file written, and pathlib's parsing
    and hashing cost more than the system calls.
    """
    if folder in ready:
        return
    missing = []
    path = folder
    while path not in ready and not os.path.isdir(path):
        missing.append(path)
        parent = os.path.dirname(path) or "."
        if parent == path:
            break
        path = parent
    for path in reversed(missing):
        os.mkdir(path)
        created.append(path)
    ready.add(folder)
    ready.update(missing)


# A temporary file is ``.<target name>.<pid>-<n>.tmp`` beside its target: hidden (Unity does
# not import dot files) and named after the process that made it.
_TEMP_RE = re.compile(r"^\..+\.(\d+)-\d+\.tmp$")


def _temp_name(target: str, attempt: int) -> str:
    folder, name = os.path.split(target)
    suffix = f".{os.getpid()}-{attempt}.tmp"
    room = MAX_NAME_BYTES - 1 - len(suffix)
    if len(name) * 4 > room and len(encoded := name.encode("utf-8")) > room:
        # A target name near the limit would make a temporary name the disk refuses: its start
        # and a digest of all of it instead (still one temporary name per target).
        digest = hashlib.sha256(encoded).hexdigest()[:16]
        name = encoded[: room - len(digest) - 1].decode("utf-8", "ignore") + "~" + digest
    return os.path.join(folder, f".{name}{suffix}")


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True  # exists, owned by someone else
    return True


def temp_leftovers(folders: Iterable[Path]) -> list[Path]:
    """Temporary files in ``folders`` that a killed writer left behind, sorted.

    A write that fails removes its temporary files; one killed (SIGKILL, power loss) cannot.
    Files of a process still running are left alone: they may be another apply's, about to be
    renamed into place.
    """
    found = []
    for folder in set(folders):
        try:
            entries = list(os.scandir(folder))
        except OSError:
            continue
        for entry in entries:
            match = _TEMP_RE.match(entry.name)
            if match and entry.is_file(follow_symlinks=False) and not _alive(int(match[1])):
                found.append(Path(entry.path))
    return sorted(found)


def _write_temp(change: FileChange, durable: bool, chunks: Chunks | None = None) -> str:
    """``change``'s content (or ``chunks()``) in a new temporary file beside its target, with
    the target's permission bits (what the umask allows for a new file); removed again if this
    fails."""
    target = os.fspath(change.path)
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0)
    for attempt in itertools.count():
        temp = _temp_name(target, attempt)
        try:
            # 0o666 less the umask, as open() gives a new file
            handle = os.open(temp, flags, 0o666)
            break
        except FileExistsError:
            continue
    try:
        # Straight to write(2) on the descriptor: setting up a file object took longer than
        # writing a small generated file.
        try:
            for piece in chunks() if chunks is not None else (change.content,):
                rest = memoryview(piece)
                while rest:  # a write may take only part of it
                    rest = rest[os.write(handle, rest) :]
            if durable:
                # On disk before the rename, so that after a power loss the target holds the
                # old bytes or the new ones. About 2 ms a file on ext4: worth it for a scene,
                # not for hundreds of generated files that the next apply rewrites anyway.
                os.fsync(handle)
        finally:
            os.close(handle)
        if change.kind is not ChangeKind.CREATE:
            try:
                mode = os.stat(target).st_mode
            except FileNotFoundError:
                mode = None  # gone meanwhile: the new file gets what the umask allows
            if mode is not None:
                os.chmod(temp, mode & 0o7777)
    except BaseException:
        _remove(temp)
        raise
    return temp


def _remove(temp: str) -> None:
    with contextlib.suppress(FileNotFoundError):
        os.unlink(temp)


def _stage(
    todo: Sequence[FileChange], durable: bool, chunks: Chunks | None = None
) -> list[tuple[str, Path]]:
    """Every change written to a temporary file, as ``(temporary, target)`` pairs; on failure,
    the temporary files and the folders made for them are removed again."""
    created: list[str] = []
    temps: list[tuple[str, Path]] = []
    ready: set[str] = set()
    current = None
    try:
        for change in todo:
            current = change.path
            _make_folders(os.path.dirname(os.fspath(current)) or ".", created, ready)
            temps.append((_write_temp(change, durable, chunks), current))
    except BaseException as exc:
        for temp, _ in temps:
            _remove(temp)
        for folder in reversed(created):
            with contextlib.suppress(OSError):
                os.rmdir(folder)
        if isinstance(exc, OSError):
            raise UserError(
                f"cannot write {current}: {exc.strerror}",
                hint="check that its folder can be created and written to, and that the disk "
                "has room; nothing was written",
            ) from None
        raise
    return temps


def _replace_all(temps: Sequence[tuple[str, Path]]) -> None:
    for done, (temp, path) in enumerate(temps):
        try:
            os.replace(temp, path)
        except OSError as exc:
            for leftover, _ in temps[done:]:
                _remove(leftover)
            written = f"{done} of {len(temps)} files were already written"
            raise UserError(
                f"cannot replace {path}: {exc.strerror}; "
                + (written if len(temps) > 1 else "it was left as it was"),
                hint="fix the cause (a file locked by another program?) and run "
                "again: unchanged files are skipped",
            ) from None


def write_files(
    changes: Sequence[FileChange],
    *,
    durable: bool = False,
    before_replace: Callable[[], object] | None = None,
) -> list[Path]:
    """Write the ``create``/``update`` changes all at once; returns the paths written.

    ``durable`` flushes each file to disk before it replaces its target. ``before_replace``
    runs once every temporary file is written, just before the first one replaces its target
    (``apply`` records there what it is about to do, for a run that is killed half-way).
    """
    temps = _stage([c for c in changes if c.writes], durable)
    if before_replace is not None:
        try:
            before_replace()
        except BaseException:
            for temp, _ in temps:
                _remove(temp)
            raise
    _replace_all(temps)
    return [path for _, path in temps]


def write_if_changed(path: str | os.PathLike[str], data: str | bytes) -> bool:
    """Write ``data`` to ``path`` only if its text differs (``same_text``); return whether the
    file was written.

    ``str`` is encoded as UTF-8 with no newline translation. Missing folders are created. The
    file is flushed to disk before it replaces the old one (single files are scenes and the
    manifest, which nothing regenerates).
    """
    content = data.encode("utf-8") if isinstance(data, str) else data
    return bool(write_files(plan_files([DesiredFile(Path(path), content)]), durable=True))


Chunks = Callable[[], Iterable[bytes]]


def _same_chunks(path: Path, pieces: Iterable[bytes]) -> bool:
    """Whether ``path`` holds exactly the bytes of ``pieces``, read a piece at a time."""
    try:
        stream = path.open("rb")
    except FileNotFoundError:
        return False
    except OSError:
        plan_files([DesiredFile(path, b"")])  # raises the error planning gives for this path
        raise
    with stream:
        for piece in pieces:
            if stream.read(len(piece)) != piece:
                return False
        return not stream.read(1)


def write_chunks_if_changed(path: str | os.PathLike[str], chunks: Chunks) -> bool:
    """``write_if_changed`` for content too large to hold twice (a 100 MB scene): ``chunks()``
    yields it in pieces, once to compare with the file and once more to write it, so neither
    the whole content nor the old file is ever in memory. Bytes are compared exactly (a scene
    keeps the line endings it was read with). Returns whether the file was written."""
    target = Path(path)
    if _same_chunks(target, chunks()):
        return False
    kind = ChangeKind.UPDATE if target.exists() else ChangeKind.CREATE
    _replace_all(_stage([FileChange(target, kind, b"")], True, chunks))
    return True
