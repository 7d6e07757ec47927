"""The recording half of the no-op record (see ``_noop``): observes a command as it runs and,
if it verified a no-op, writes what it printed and what it learnt from every path it looked at.

Each path is looked at (hashed, listed, probed) when the program first looks at it, and again
when the run ends: a path that changed in between leaves no record, as the run may have seen
either state. A run is recorded only if:

- the command said it verified a no-op (``verified``) and exited 0;
- nothing was written, removed or renamed but the scaffold's own cache files and Python's
  bytecode, and no other process or network connection was asked anything;
- it read no device or pipe (whose bytes cannot be compared later);
- nothing it looked at changed while it ran.

Imported only when a command runs (not for a replay); standard library only.
"""

from __future__ import annotations

import marshal
import os
import sys
from stat import S_IFDIR, S_IFREG

from unityscaffold import __version__
from unityscaffold.cli._noop import (
    _COMMANDS,
    _LIST,
    _LSTAT,
    _MAGIC,
    _READ,
    _STAT,
    _checksum,
    _command,
    _disabled,
    _key,
    _look,
    _real_lstat,
    _real_stat,
    _record_path,
)
from unityscaffold.cli._tee import wrap_stream
from unityscaffold.usercache import cache_root, record_cache_folder, template_cache_folder

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

_WATCHED = frozenset({"open", "exec", "os.scandir", "os.listdir", *_WRITE_EVENTS})

_real_access = os.access
_active: Recorder | None = None
_hooked = False


def verified() -> None:
    """Called by a command that found the project in sync and wrote nothing."""
    if _active is not None:
        _active.verified = True


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
        self.records = record_cache_folder(root)
        self.templates = template_cache_folder(root, __version__)
        self.looks: dict[tuple[str, int], tuple[Any, ...]] = {}
        self.output: list[tuple[int, bytes]] = []
        self.tainted = False
        self.verified = False
        self.looking = False  # the recorder's own opens and listings are not the program's
        self.streams = (sys.stdout, sys.stderr)
        self.pycache = sys.pycache_prefix
        self.stdlib = os.path.dirname(os.__file__)

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
        recorder._code()  # what is already running: this package's first modules
        if not _hooked:
            sys.addaudithook(_hook)
            _hooked = True
        for stream in recorder.streams:
            stream.flush()
        sys.stdout = wrap_stream(recorder.streams[0], 1, recorder.output)
        sys.stderr = wrap_stream(recorder.streams[1], 2, recorder.output)
        os.stat = recorder.stat
        os.lstat = recorder.lstat
        os.access = recorder.access
        _active = recorder
        return recorder

    def _own(self, path: str) -> bool:
        """Files that are not inputs but caches of the scaffold's or Python's own making: the
        records, compiled templates and bytecode. Each is checked against what it was made from
        (the key; the template's source and Python's version; the module's source, all of
        which are looked at), so a file, never a folder, is left out: a project kept under a
        cache folder is observed like any other."""
        folder, name = os.path.split(os.path.abspath(path))
        if folder == self.records:
            return name.endswith((".rec", ".tmp"))
        if folder == self.templates:
            return ".jinja-cache" in name  # an entry, or jinja's temporary file for one
        # a module's bytecode, or the temporary file the import system writes it to
        bytecode = name.endswith(".pyc") or ".pyc." in name
        return bytecode and (
            os.path.basename(folder) == "__pycache__"
            or bool(self.pycache and _encloses(self.pycache, folder))
        )

    def _made(self, path: str) -> bool:
        """Folders the import system or a cache makes for the files above (or their parents)."""
        path = os.path.abspath(path)
        return (
            os.path.basename(path) == "__pycache__"
            or bool(self.pycache and _encloses(self.pycache, path))
            or any(_encloses(path, folder) for folder in (self.records, self.templates))
        )

    def _seen(self, target: Any, how: int) -> None:
        if isinstance(target, int):
            return  # a file descriptor: its path was seen when it was opened
        path = os.fsdecode(os.fspath(target))
        if (path, how) not in self.looks and not self._own(path):
            self.looks[(path, how)] = self._look(path, how)

    def _look(self, path: str, how: int) -> tuple[Any, ...]:
        self.looking = True
        try:
            facts = _look(path, how)
        finally:
            self.looking = False
        if how == _READ and facts[0] not in (S_IFREG, S_IFDIR) and facts[0] >= 0:
            self.tainted = True  # a device or a pipe: what it gave cannot be compared later
        return facts

    def stat(self, path: Any, *, dir_fd: Any = None, follow_symlinks: bool = True) -> Any:
        if dir_fd is not None:
            self.tainted = True  # relative to a folder descriptor: not a path to compare
        else:
            self._seen(path, _STAT if follow_symlinks else _LSTAT)
        return _real_stat(path, dir_fd=dir_fd, follow_symlinks=follow_symlinks)

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
        if self.looking:
            return
        if event == "open":
            self._opened(*args)
        elif event == "exec":
            # a module's code (or a compiled template's) about to run: its source as it is now
            # (bytecode is read with no event of its own, and without its source being opened)
            source = getattr(args[0], "co_filename", "")
            if isinstance(source, str) and source[:1] not in ("", "<") and not self._stdlib(source):
                self._seen(source, _READ)
        elif event in ("os.scandir", "os.listdir"):
            target = "." if args[0] is None else args[0]
            if isinstance(target, int):
                self.tainted = True
            else:
                self._seen(target, _LIST)
        elif event in _WRITE_EVENTS:
            first = args[0] if args else None
            named = os.fsdecode(first) if isinstance(first, (str, bytes, os.PathLike)) else None
            making = event == "os.mkdir" and named is not None and self._made(named)
            if named is None or not (making or self._own(named)):
                self.tainted = True

    def _opened(self, target: Any, mode: Any, flags: int) -> None:
        if isinstance(target, int):
            return
        writes = any(c in mode for c in "wax+") if isinstance(mode, str) else False
        if writes or (mode is None and flags & _WRITE_FLAGS):
            path = os.fsdecode(os.fspath(target))
            # jinja writes an entry through tempfile, which names the folder to open and makes
            # the file in it with an opener
            if not (self._own(path) or os.path.abspath(path) == self.templates):
                self.tainted = True
        else:
            self._seen(target, _READ)

    def _stdlib(self, source: str) -> bool:
        """Whether ``source`` is the interpreter's own (its version is in the key)."""
        folder = self.stdlib + os.sep
        if not source.startswith(folder):
            return False
        return source[len(folder) :].partition(os.sep)[0] not in ("site-packages", "dist-packages")

    def _code(self) -> None:
        """The code itself: unityscaffold and its dependencies (the standard library is the
        interpreter's, whose version is in the key), and the folders imports search (a module
        added to one may be found before the one this run imported)."""
        stdlib = sys.stdlib_module_names
        for name, module in list(sys.modules.items()):
            source = getattr(module, "__file__", None)
            if isinstance(source, str) and name.partition(".")[0] not in stdlib:
                self._seen(source, _READ)
        for entry in sys.path:
            if isinstance(entry, str):  # a folder, or a zip file imports read as one
                folder = entry or "."
                self._seen(folder, _LIST if os.path.isdir(folder) else _READ)

    def _stop(self) -> None:
        global _active
        _active = None
        os.stat = _real_stat
        os.lstat = _real_lstat
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
        # Looked at again: one that changed while the run went on may have been seen by it in
        # either state (git's index guards against the same with its racy timestamps).
        if any(self._look(path, how) != facts for (path, how), facts in list(self.looks.items())):
            return
        self._code()  # modules imported without running code of theirs (extensions)
        if not self.tainted:
            self._write(sorted((path, how, facts) for (path, how), facts in self.looks.items()))

    def _write(self, looks: list[tuple[str, int, tuple[Any, ...]]]) -> None:
        # cheapest first, so a replay that will plan finds out early
        looks.sort(key=lambda look: look[1])
        data = _encode((self.key, self.output, looks))
        target = _record_path(self.root, self.key)
        folder = os.path.dirname(target)
        temp = f"{target}.{os.getpid()}.tmp"
        try:
            # the key holds the whole environment (tokens, passwords): for this user's eyes only
            os.makedirs(folder, mode=0o700, exist_ok=True)
            _unlink(temp)  # a dead process's, whose mode is not ours to trust
            handle = os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
            try:
                view = memoryview(data)
                while view:
                    view = view[os.write(handle, view) :]
            finally:
                os.close(handle)
            os.replace(temp, target)
            _prune(folder)
        except OSError:
            _unlink(temp)


def _encode(record: tuple[Any, ...]) -> bytes:
    """A record's file: a checksum of the rest, then the format's mark and the record."""
    body = _MAGIC + marshal.dumps(record)
    return _checksum(body) + body


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
