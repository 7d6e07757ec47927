"""The recording half of the no-op record (see ``_noop``): observes a command as it runs and,
if it verified a no-op, writes what it printed and the ``stat`` of every path it depended on.

Imported only when a command runs (not for a replay); standard library only.
"""

from __future__ import annotations

import io
import marshal
import os
import sys
import time

from unityscaffold.cli._noop import (
    _COMMANDS,
    _LSTAT,
    _SHAPE,
    _STAT,
    _command,
    _disabled,
    _isatty,
    _key,
    _probe,
    _real_lstat,
    _real_stat,
    _record_path,
)
from unityscaffold.usercache import cache_root

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["Recorder", "verified"]

#: Records kept; the oldest are removed beyond this (each project and command has its own).
_KEEP = 200
_WRITE_FLAGS = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_TRUNC | os.O_APPEND
_WRITE_EVENTS = frozenset(
    {
        "os.remove",
        "os.rename",
        "os.rmdir",
        "os.mkdir",
        "os.truncate",
        "os.utime",
        "os.chmod",
        "os.chown",
        "os.link",
        "os.symlink",
        "shutil.copyfile",
        "shutil.move",
        "shutil.rmtree",
    }
)

#: Events after which the answer may depend on more than files: not recorded. ``os.kill``
#: asks whether a writer still runs (its temporary file is a leftover only once it has gone);
#: after ``os.chdir`` relative paths name other files than in the key's folder.
_ELSEWHERE = (
    "os.chdir",
    "os.fchdir",
    "socket.",
    "subprocess.",
    "os.exec",
    "os.posix_spawn",
    "os.spawn",
    "os.system",
    "os.kill",
)

_WATCHED = frozenset({"open", "os.scandir", "os.listdir", *_WRITE_EVENTS})

_real_access = os.access
_real_realpath = os.path.realpath
_active: Recorder | None = None
_hooked = False


def verified() -> None:
    """Called by a command that found the project in sync and wrote nothing."""
    if _active is not None:
        _active.verified = True


class _Tee(io.RawIOBase):
    """A stream's bytes passed on to the real stream and kept, in order, for the record."""

    def __init__(self, fd: int, target: Any, log: list[tuple[int, bytes]]) -> None:
        super().__init__()
        self.fd, self.target, self.log = fd, target, log

    def writable(self) -> bool:
        return True

    def write(self, data: Any) -> int:
        chunk = bytes(data)
        self.log.append((self.fd, chunk))
        self.target.write(chunk)
        self.target.flush()
        return len(chunk)

    def isatty(self) -> bool:
        return _isatty(self.target)

    def fileno(self) -> int:
        return int(self.target.fileno())

    def close(self) -> None:  # the real stream stays open
        pass


def _wrap(stream: Any, fd: int, log: list[tuple[int, bytes]]) -> io.TextIOWrapper:
    return io.TextIOWrapper(
        io.BufferedWriter(_Tee(fd, stream.buffer, log)),
        encoding=stream.encoding,
        errors=stream.errors,
        line_buffering=True,
        write_through=True,
    )


def _hook(event: str, args: tuple[Any, ...]) -> None:
    # Called for every audit event of the process (imports, exec, compile ...): the few that
    # matter are picked out first, in one set lookup.
    if event in _WATCHED:
        recorder = _active
        if recorder is not None:
            recorder.event(event, args)
    elif event.startswith(_ELSEWHERE) and _active is not None:
        _active.tainted = True  # another process or the network may answer differently


def _pure_python_probes() -> bool:
    """Whether ``os.path``'s probes go through ``os.stat``/``os.lstat`` (so they are seen).

    Not on Windows (``ntpath``; its Python 3.12+ answers ``isdir``/``isfile``/``exists`` in
    C) nor Python 3.10 (its pathlib kept its own reference to ``os.stat``): there nothing is
    recorded rather than miss a probe.
    """
    import genericpath
    import posixpath

    path = os.path
    return (
        sys.version_info >= (3, 11)
        and path is posixpath
        and all(
            getattr(path, name) is getattr(genericpath, name)
            for name in ("exists", "isdir", "isfile", "getsize", "getmtime")
        )
    )


class Recorder:
    """Observes one command as it runs; ``finish`` writes the record if the run qualifies."""

    def __init__(self, root: str, argv: list[str]) -> None:
        self.root = root
        self.key = _key(argv)
        self.start_ns = time.time_ns()
        self.paths: dict[tuple[str, int], tuple[int, ...]] = {}
        self.folders: set[str] = set()
        self.output: list[tuple[int, bytes]] = []
        self.tainted = False
        self.verified = False
        self.resolving = 0
        self.streams = (sys.stdout, sys.stderr)
        self.pycache = sys.pycache_prefix

    @classmethod
    def start(cls, argv: list[str]) -> Recorder | None:
        """Start observing, or None when this command is not one to record."""
        global _active, _hooked
        root = cache_root()
        if root is None or _disabled() or _command(argv) not in _COMMANDS or _active is not None:
            return None
        streams = (sys.stdout, sys.stderr)
        if not all(hasattr(s, "buffer") for s in streams) or not _pure_python_probes():
            return None
        try:
            recorder = cls(root, argv)
        except (OSError, ValueError, TypeError):  # a deleted current folder, odd streams
            return None
        if not _hooked:
            sys.addaudithook(_hook)
            _hooked = True
        for stream in recorder.streams:
            stream.flush()
        sys.stdout = _wrap(recorder.streams[0], 1, recorder.output)
        sys.stderr = _wrap(recorder.streams[1], 2, recorder.output)
        os.stat = recorder.stat
        os.lstat = recorder.lstat
        os.path.realpath = recorder.realpath  # type: ignore[assignment]
        os.access = recorder.access
        _active = recorder
        return recorder

    def _ours(self, path: str) -> bool:
        """Paths that are not inputs: the cache folder and Python's bytecode."""
        if _encloses(self.root, path):
            return True
        if self.pycache and path.startswith(self.pycache + os.sep):
            return True
        folder, name = os.path.split(path)
        if name == "__pycache__":
            return True  # made by the import system to write bytecode into
        # a module's bytecode, or the temporary file the import system writes it to
        return os.path.basename(folder) == "__pycache__" and (
            name.endswith(".pyc") or ".pyc." in name
        )

    def _seen(self, target: Any, how: int) -> None:
        if isinstance(target, int):
            return  # a file descriptor: its path was seen when it was opened
        path = os.fsdecode(os.fspath(target))
        if (path, how) not in self.paths and not self._ours(path):
            self.paths[(path, how)] = _probe(path, how)

    def stat(self, path: Any, *, dir_fd: Any = None, follow_symlinks: bool = True) -> Any:
        if dir_fd is not None:
            self.tainted = True  # relative to a folder descriptor: not a path to compare
        else:
            how = _STAT if follow_symlinks else _SHAPE if self.resolving else _LSTAT
            self._seen(path, how)
        return _real_stat(path, dir_fd=dir_fd, follow_symlinks=follow_symlinks)

    def realpath(self, path: Any, *args: Any, **kwargs: Any) -> Any:
        self.resolving += 1
        try:
            return _real_realpath(path, *args, **kwargs)
        finally:
            self.resolving -= 1

    def lstat(self, path: Any, *, dir_fd: Any = None) -> Any:
        return self.stat(path, dir_fd=dir_fd, follow_symlinks=False)

    def access(self, path: Any, mode: int, **kwargs: Any) -> bool:
        # a probe like stat (it raises no audit event): a child found missing by it counts
        if kwargs.get("dir_fd") is not None:
            self.tainted = True
        else:
            self._seen(path, _STAT if kwargs.get("follow_symlinks", True) else _LSTAT)
        return _real_access(path, mode, **kwargs)

    def event(self, event: str, args: tuple[Any, ...]) -> None:
        if event == "open":
            target, mode, flags = args
            if isinstance(target, int):
                return
            path = os.fsdecode(os.fspath(target))
            writes = any(c in mode for c in "wax+") if isinstance(mode, str) else False
            if writes or (mode is None and flags & _WRITE_FLAGS):
                if not self._ours(path):
                    self.tainted = True
                return
            self._seen(path, _STAT)
        elif event in ("os.scandir", "os.listdir"):
            target = args[0]
            if target is None:
                target = "."
            if isinstance(target, int):
                self.tainted = True
                return
            path = os.fsdecode(os.fspath(target))
            if not self._ours(path):
                self._seen(path, _STAT)
                self.folders.add(path)
        elif event in _WRITE_EVENTS:
            first = args[0] if args else None
            named = os.fsdecode(first) if isinstance(first, (str, bytes, os.PathLike)) else None
            # the cache folder's own parents are made with it
            making = event == "os.mkdir" and named is not None and _encloses(named, self.root)
            if named is None or not (self._ours(named) or making):
                self.tainted = True

    def _stop(self) -> None:
        global _active
        _active = None
        os.stat = _real_stat
        os.lstat = _real_lstat
        os.path.realpath = _real_realpath
        os.access = _real_access
        for wrapper in (sys.stdout, sys.stderr):
            try:
                wrapper.flush()
            except (OSError, ValueError):
                self.tainted = True
        sys.stdout, sys.stderr = self.streams

    def finish(self, status: int | None) -> None:
        """Stop observing; write the record if this run verified a no-op."""
        self._stop()
        if self.tainted or not self.verified or status != 0:
            return
        try:
            paths = self._settled()
        except OSError:
            return
        if paths is not None:
            self._write(paths, status)

    def _settled(self) -> list[tuple[str, int, tuple[int, ...]]] | None:
        """Every path with its facts as first seen, unless one of them is racy.

        A path changed after it was first seen is recorded as it was then, so the record
        will not match it: it is not compared again here.
        """
        paths = dict(self.paths)
        # The code itself: unityscaffold and its dependencies (the standard library is the
        # interpreter's, whose version is in the key).
        stdlib = sys.stdlib_module_names
        for name, module in list(sys.modules.items()):
            source = getattr(module, "__file__", None)
            if not isinstance(source, str) or name.partition(".")[0] in stdlib:
                continue
            if (source, _STAT) not in paths:
                paths[(source, _STAT)] = _probe(source, _STAT)
        # The folders imports search: a module added to one may be found before the one this
        # run imported. The import system lists them through its own stat, which is not seen.
        for folder in sys.path:
            if isinstance(folder, str) and (folder or ".", _STAT) not in paths:
                paths[(folder or ".", _STAT)] = _probe(folder or ".", _STAT)
        # A symlink in a listed folder: os.walk asked whether its target is a folder.
        for folder in sorted(self.folders):
            if len(paths[(folder, _STAT)]) == 1:
                continue  # absent, and recorded so
            with os.scandir(folder) as entries:
                for entry in entries:
                    if entry.is_symlink() and (entry.path, _STAT) not in paths:
                        paths[(entry.path, _STAT)] = _probe(entry.path, _STAT)
        # Timestamps of a file changed after the run started are at most one clock tick
        # (~10 ms; 2 s where the file system keeps whole seconds) older than the change. Judged
        # per path: a project on such a file system may sit beside code on a finer one.
        for facts in paths.values():
            if len(facts) == 6:
                coarse = facts[2] % 1_000_000_000 == 0 and facts[3] % 1_000_000_000 == 0
                margin = 2_050_000_000 if coarse else 50_000_000
                if max(facts[2], facts[3]) >= self.start_ns - margin:
                    return None
        return [(path, how, facts) for (path, how), facts in sorted(paths.items())]

    def _write(self, paths: list[tuple[str, int, tuple[int, ...]]], status: int) -> None:
        record = (self.key, status, self.output, paths)
        target = _record_path(self.root, self.key)
        folder = os.path.dirname(target)
        temp = f"{target}.{os.getpid()}.tmp"
        try:
            # the key holds the whole environment (tokens, passwords): for this user's eyes only
            os.makedirs(folder, mode=0o700, exist_ok=True)
            _unlink(temp)  # a dead process's, whose mode is not ours to trust
            handle = os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
            try:
                data = memoryview(marshal.dumps(record))
                while data:
                    data = data[os.write(handle, data) :]
            finally:
                os.close(handle)
            os.replace(temp, target)
            _prune(folder)
        except OSError:
            _unlink(temp)


def _encloses(folder: str, path: str) -> bool:
    """Whether ``path`` is ``folder`` or inside it (as folders, not as text prefixes)."""
    folder = folder.rstrip(os.sep) or os.sep
    return path == folder or path.startswith(folder if folder == os.sep else folder + os.sep)


def _prune(folder: str) -> None:
    """Keep the newest ``_KEEP`` records."""
    with os.scandir(folder) as entries:
        found = [(e.stat().st_mtime_ns, e.path) for e in entries if e.name.endswith(".rec")]
    if len(found) > _KEEP:
        for _, path in sorted(found)[: len(found) - _KEEP]:
            _unlink(path)


def _unlink(path: str) -> None:
    import contextlib  # only when writing a record

    with contextlib.suppress(OSError):  # a record left is only a file too many
        os.unlink(path)
