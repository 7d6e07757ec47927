"""The no-op record: a repeated ``apply``/``plan`` on an unchanged project replays the output
of the last run that verified it, instead of loading the manifest and planning again.

A run of ``scaffold apply`` (also ``--check``, ``--dry-run``) or ``scaffold plan`` that found
the project in sync and wrote nothing is recorded in the user's cache folder
(``unityscaffold.usercache``, under ``noop/``): what it printed, and what it learnt from the
file system, by content. The next identical command looks again at every one of those things;
only if each is as recorded does it print the recorded bytes and exit 0, else it runs as usual
(and records again if it verifies a no-op). The record is never needed: with it, without it,
or with a damaged or foreign one, output is the same.

What the answer depended on is observed, not listed, so inputs added later are covered too
(``_recorder``): every file opened for reading and the source of every module run (compared
by a blake2b hash of their bytes), every folder listed (compared by its names and each entry's
kind), and every ``os.stat``/``os.lstat``/``os.access`` probe (compared by what a program can
learn from it without times: existence, type and permissions, a file's size, a symlink's
target). No ``stat`` time, inode or size is ever taken as proof that a file's bytes are the
same: a file changed through a memory mapping, or on a mount that serves a cached ``stat``,
keeps them.

The key of a record is everything else the output may depend on: the command line as given,
the current folder, the whole environment, which streams are terminals, the interpreter,
unityscaffold's version and where it was imported from. A record file starts with a blake2b
checksum of the rest; a record that is cut short, damaged, of another format or for another
key is no record.

Turn it off with ``UNITYSCAFFOLD_NO_CACHE=1`` (every cache) or ``UNITYSCAFFOLD_NO_REPLAY=1``
(only this one). Kept to the standard library: a replay loads nothing else.
"""

from __future__ import annotations

import marshal
import os
import sys
import zlib
from stat import S_IFMT, S_IFREG, S_ISLNK, S_ISREG

from unityscaffold import __version__
from unityscaffold.usercache import cache_root, record_cache_folder

try:  # what hashlib.blake2b is, without importing hashlib and OpenSSL (a tenth of a replay)
    from _blake2 import blake2b
except ImportError:  # pragma: no cover - another interpreter than CPython
    from hashlib import blake2b

TYPE_CHECKING = False  # typing itself is not loaded for a replay
if TYPE_CHECKING:
    from typing import Any

# The recording half (``_recorder``) is imported only when a command is run: it shares the
# key, the record's layout and the look at a path, which must be the same on both sides.
__all__ = ["replay"]

_FORMAT = 2
#: The start of a record's checksummed part: a record of another format is no record.
_MAGIC = b"unityscaffold no-op record %d\n" % _FORMAT
_CHECKSUM = 32  # bytes of blake2b over the rest of the file
#: Commands whose verified no-op may be recorded (the first word that is not an option).
_COMMANDS = ("apply", "plan")
# Taken before the recorder puts its observers in their place.
_real_stat = os.stat
_real_lstat = os.lstat

#: How a path was looked at, in the order a replay compares them (cheapest first):
#: ``os.stat``, ``os.lstat``, a folder listed, a file read.
_STAT, _LSTAT, _LIST, _READ = 0, 1, 2, 3
#: A file is hashed in pieces of this size (a 100 MB scene is not held whole).
_PIECE = 1 << 20
# A FIFO opened for reading is not waited on (only regular files are hashed).
_OPEN_FLAGS = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)


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
    name = f"{zlib.crc32(data):08x}{zlib.adler32(data):08x}.rec"
    return os.path.join(record_cache_folder(root), name)


def _content(path: str) -> tuple[Any, ...]:
    """A file's type, and for a regular file the hash of its bytes."""
    handle = os.open(path, _OPEN_FLAGS)
    try:
        mode = os.fstat(handle).st_mode
        if not S_ISREG(mode):
            return (S_IFMT(mode),)  # a folder (open refuses it to the program) or a device
        digest = blake2b(digest_size=32)
        while piece := os.read(handle, _PIECE):
            digest.update(piece)
        return (S_IFREG, digest.digest())
    finally:
        os.close(handle)


def _listing(path: str) -> tuple[Any, ...]:
    """A folder's names, each with what its entry tells without a ``stat`` of the program's:
    whether it is a symlink, a folder or a file (the last two through the symlink)."""
    with os.scandir(path) as entries:
        return tuple(
            sorted(
                (entry.name, entry.is_symlink() | entry.is_dir() << 1 | entry.is_file() << 2)
                for entry in entries
            )
        )


def _look(path: str, how: int) -> tuple[Any, ...]:
    """What a program can have learnt of ``path`` by looking at it ``how``; or ``(-errno,)``."""
    try:
        if how == _READ:
            return _content(path)
        if how == _LIST:
            return _listing(path)
        st = _real_stat(path) if how == _STAT else _real_lstat(path)
        if S_ISREG(st.st_mode):
            return (st.st_mode, st.st_size)
        if S_ISLNK(st.st_mode):
            return (st.st_mode, os.readlink(path))
        return (st.st_mode,)
    except OSError as exc:
        return (-(exc.errno or 1),)
    except ValueError:  # a NUL in the path: the program was refused it as well
        return (-1,)


def _checksum(body: bytes) -> bytes:
    return blake2b(body, digest_size=_CHECKSUM).digest()


def _decode(data: bytes) -> tuple[Any, ...] | None:
    """A record's ``(key, output, looks)``, or None for anything damaged or foreign."""
    body = data[_CHECKSUM:]
    if len(data) <= _CHECKSUM or data[:_CHECKSUM] != _checksum(body):
        return None
    if not body.startswith(_MAGIC):
        return None
    try:
        # marshal: read with no module to import, and fast; its format is the interpreter's,
        # which the key names (another's may not load, which is no record either)
        key, output, looks = marshal.loads(body[len(_MAGIC) :])
    except (ValueError, TypeError, EOFError, MemoryError):
        return None
    shaped = (
        isinstance(key, str)
        and isinstance(output, list)
        and isinstance(looks, list)
        and all(_is_output(item) for item in output)
        and all(_is_look(item) for item in looks)
    )
    return (key, output, looks) if shaped else None


def _is_output(item: Any) -> bool:
    return (
        isinstance(item, tuple) and len(item) == 2 and item[0] in (1, 2) and type(item[1]) is bytes
    )


def _is_look(item: Any) -> bool:
    return (
        isinstance(item, tuple)
        and len(item) == 3
        and isinstance(item[0], str)
        and item[1] in (_STAT, _LSTAT, _LIST, _READ)
        and isinstance(item[2], tuple)
    )


def replay(argv: list[str]) -> int | None:
    """Print the recorded output and return 0, or None to run as usual."""
    root = cache_root()
    if root is None or _disabled() or _command(argv) not in _COMMANDS:
        return None
    if not all(hasattr(s, "buffer") for s in (sys.stdout, sys.stderr)):
        return None
    try:
        key = _key(argv)  # os.getcwd() fails in a deleted folder
        with open(_record_path(root, key), "rb") as handle:
            record = _decode(handle.read())
    except OSError:
        return None  # no record
    if record is None or record[0] != key:
        return None
    _, output, looks = record
    for path, how, facts in looks:
        if _look(path, how) != facts:
            return None
    for fd, data in output:
        stream = sys.stdout if fd == 1 else sys.stderr
        stream.flush()
        stream.buffer.write(data)
        stream.buffer.flush()
    return 0  # only a run that exited 0 is recorded
