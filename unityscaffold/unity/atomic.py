"""Atomic, compare-before-write file output."""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path

__all__ = ["write_if_changed"]


def write_if_changed(path: str | os.PathLike[str], data: str | bytes) -> bool:
    """Write ``data`` to ``path`` only if its bytes differ; return whether the file was written.

    ``str`` is encoded as UTF-8 with no newline translation. The new content goes to a temporary
    file in the same directory which then replaces the target with ``os.replace``, so readers
    never see a half-written file; an existing file's permission bits are kept.
    """
    target = Path(path)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    try:
        if target.read_bytes() == payload:
            return False
        mode: int | None = target.stat().st_mode & 0o7777
    except FileNotFoundError:
        mode = None
    fd, temp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(payload)
            handle.flush()
            os.fsync(handle.fileno())
        if mode is not None:
            os.chmod(temp, mode)
        os.replace(temp, target)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(temp)
        raise
    return True
