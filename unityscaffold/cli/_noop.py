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

import marshal
import os
import sys
import zlib
from stat import S_IFMT, S_ISLNK

from unityscaffold import __version__
from unityscaffold.usercache import cache_root

TYPE_CHECKING = False  # typing itself is not loaded for a replay
if TYPE_CHECKING:
    from typing import Any

# The recording half (``_recorder``) is imported only when a command is run: it shares the
# key and the probe of a path, which must be the same on both sides.
__all__ = ["replay"]

_FORMAT = 1
#: Commands whose verified no-op may be recorded (the first word that is not an option).
_COMMANDS = ("apply", "plan")
# Taken before the recorder puts its observers in their place.
_real_stat = os.stat
_real_lstat = os.lstat


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
