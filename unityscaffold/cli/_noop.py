"""The no-op record: a repeated ``apply``/``plan`` on an unchanged project replays the output
of the last run that verified it, instead of loading the manifest and planning again.

A run of ``scaffold apply`` (also ``--check``, ``--dry-run``) or ``scaffold plan`` that found
the project in sync and wrote nothing is recorded in the user's cache folder
(``unityscaffold.usercache``, under ``noop/``): what it printed, its exit status, and the
``stat`` of everything its answer depended on. The next identical command compares those
``stat`` results with the file system's; if every one is equal it prints the recorded bytes
and exits, else it runs as usual (and records again if it verifies a no-op). The record is
never needed: with it, without it, or with a corrupt or foreign one, output is the same.

What the answer depended on is observed, not listed, so inputs added later are covered too:
while the command runs, every file opened (Python's ``open`` audit event), every folder listed
(``os.scandir``/``os.listdir`` events) and every ``os.stat``/``os.lstat``/``os.access``
probe (``exists``, ``is_file``, ``is_dir``, ``resolve`` …, absent paths included) is
recorded, and so are the source file of every loaded module outside the standard library (an
edited or upgraded unityscaffold, jinja2, ruamel.yaml …) and the folders on ``sys.path``.
A folder's ``stat`` changes whenever an entry is added, removed or renamed in it, so a new
stray file, a leftover temporary file or a new package under ``Library/PackageCache`` is seen.
Compared per path: file type and mode, size, mtime and ctime in nanoseconds, inode and
device. ctime cannot be set back by ``touch`` or ``os.utime``, so an edit hidden behind a
restored mtime is still seen.

The key of a record is everything else the output may depend on: the command line as given,
the current folder, the whole environment, which streams are terminals, the interpreter,
unityscaffold's version and where it was imported from. A run is recorded only if:

- the command said it verified a no-op (``verified``) and exited 0;
- nothing outside the cache folder was written, removed or renamed, and no other process
  or network connection was asked anything;
- no path was modified "racily": its mtime and ctime are older than the run's start by more
  than the file system's timestamp granularity (a file changed within the same clock tick
  as it was read could change again with the same timestamps, as git's index guards against).

Turn it off with ``UNITYSCAFFOLD_NO_CACHE=1`` (every cache) or ``UNITYSCAFFOLD_NO_REPLAY=1``
(only this one). Kept to the standard library: a replay loads nothing else.
"""

from __future__ import annotations

import io
import marshal
import os
import sys
import time
import zlib
from stat import S_IFMT, S_ISLNK

from unityscaffold import __version__
from unityscaffold.usercache import cache_root

TYPE_CHECKING = False  # typing itself is not loaded for a replay
if TYPE_CHECKING:
    from typing import Any

__all__ = ["Recorder", "replay", "verified"]

_FORMAT = 1
#: Records kept; the oldest are removed beyond this (each project and command has its own).
_KEEP = 200
#: Commands whose verified no-op may be recorded (the first word that is not an option).
_COMMANDS = ("apply", "plan")
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
#: asks whether a writer still runs (its temporary file is a leftover only once it has gone).
_ELSEWHERE = (
    "socket.",
    "subprocess.",
    "os.exec",
    "os.posix_spawn",
    "os.spawn",
    "os.system",
    "os.kill",
)

_WATCHED = frozenset({"open", "os.scandir", "os.listdir", *_WRITE_EVENTS})

_real_stat = os.stat
_real_lstat = os.lstat
_real_access = os.access
_real_realpath = os.path.realpath
_active: Recorder | None = None
_hooked = False


def _disabled() -> bool:
    return bool(os.environ.get("UNITYSCAFFOLD_NO_REPLAY"))


def _command(argv: list[str]) -> str | None:
    return next((arg for arg in argv if not arg.startswith("-")), None)


def _isatty(stream: Any) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError, OSError):
        return False


def _key(argv: list[str]) -> str:
    """What the output may depend on besides files, as one text (kept whole in the record)."""
    identity = [
        _FORMAT,
        __version__,
        __file__,  # the same version imported from another checkout is other code
        sys.executable,
        sys.version,
        sys.argv[0] if sys.argv else "",
        repr(sys.flags),
        sys.warnoptions,
        os.getcwd(),
        argv,
        sorted(os.environ.items()),
        [_isatty(s) for s in (sys.stdin, sys.stdout, sys.stderr)],
        [getattr(s, "encoding", None) for s in (sys.stdout, sys.stderr)],
    ]
    return ascii(identity)


def _record_path(root: str, key: str) -> str:
    """The record's file, named by two checksums of its key (a clash only costs a record)."""
    data = key.encode("ascii")
    return os.path.join(root, "noop", f"{zlib.crc32(data):08x}{zlib.adler32(data):08x}.rec")


#: How a path was asked about: ``os.lstat``, ``os.stat``, or ``os.lstat`` by ``realpath``.
_LSTAT, _STAT, _SHAPE = 0, 1, 2


def _probe(path: str, how: int) -> tuple[int, ...]:
    """The facts compared for one path: mode, size, mtime, ctime, inode, device; or [-errno].

    ``realpath`` only asks whether each folder on the way is a symlink: for those that are
    not, only their type and identity are kept, so a file added to /tmp or the home folder
    does not count as a change.
    """
    try:
        st = _real_stat(path) if how == _STAT else _real_lstat(path)
    except OSError as exc:
        return (-(exc.errno or 1),)
    if how == _SHAPE and not S_ISLNK(st.st_mode):
        return (S_IFMT(st.st_mode), st.st_ino, st.st_dev)
    return (st.st_mode, st.st_size, st.st_mtime_ns, st.st_ctime_ns, st.st_ino, st.st_dev)


def replay(argv: list[str]) -> int | None:
    """Print the recorded output and return its exit status, or None to run as usual."""
    root = cache_root()
    if root is None or _disabled() or _command(argv) not in _COMMANDS:
        return None
    try:
        key = _key(argv)  # os.getcwd() fails in a deleted folder
        with open(_record_path(root, key), "rb") as handle:
            # marshal: read with no module to import, and fast; its format is the
            # interpreter's, which the key names
            found, status, output, paths = marshal.loads(handle.read())
        if found != key:
            return None
        for path, how, facts in paths:
            if _probe(path, how) != facts:
                return None
        if not isinstance(status, int) or not all(
            fd in (1, 2) and isinstance(data, bytes) for fd, data in output
        ):
            return None
    except (OSError, EOFError, ValueError, TypeError, IndexError):
        return None  # no record, or one this version cannot use: the usual way
    if not all(hasattr(s, "buffer") for s in (sys.stdout, sys.stderr)):
        return None
    for fd, data in output:
        stream = sys.stdout if fd == 1 else sys.stderr
        stream.flush()
        stream.buffer.write(data)
        stream.buffer.flush()
    return status


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
