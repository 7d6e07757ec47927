"""Pausing Python's cycle collector while a scene's many small objects are built.

Loading, indexing and validating a scene make hundreds of thousands of objects (documents, their
caches, hierarchy nodes) that form no garbage cycles. Each time enough of them pile up, the
collector walks every object alive, so a 100 MB scene paid for many walks of everything it had
built so far. Reference counting still frees everything as usual while the collector is off.
"""

from __future__ import annotations

import gc
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["gc_paused"]


@contextmanager
def gc_paused() -> Iterator[None]:
    """Switch the collector off for the block; back on after it only if it was on (nesting)."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()
