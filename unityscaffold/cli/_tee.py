"""What the no-op recorder puts in place of ``sys.stdout`` and ``sys.stderr`` while a command
runs: a text stream whose bytes reach the real stream at once and are kept, in order, with the
stream they went to, so that a replay prints them the same (see ``_recorder``).

Standard library only, as the rest of the record.
"""

from __future__ import annotations

import io

from unityscaffold.cli._noop import _isatty

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["wrap_stream"]


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


def wrap_stream(stream: Any, fd: int, log: list[tuple[int, bytes]]) -> io.TextIOWrapper:
    return io.TextIOWrapper(
        io.BufferedWriter(_Tee(fd, stream.buffer, log)),
        encoding=stream.encoding,
        errors=stream.errors,
        line_buffering=True,
        write_through=True,
    )
