"""Deterministic fileIDs for new objects.

A fileID is a 63-bit positive hash of stable names (GameObject path, script GUID, role), never of
the file's location on disk, so the same inputs give the same scene anywhere. A collision with an
existing ID (or a reserved value) is resolved by rehashing with a counter, which is itself
deterministic for a given file.
"""

from __future__ import annotations

import hashlib
from collections.abc import Container, Iterator, Sequence

__all__ = ["RESERVED_FILE_IDS", "candidate_file_ids", "stable_file_id"]

INT64_MAX = (1 << 63) - 1
#: 0 is null, 1–4 are a scene's settings objects, INT64_MAX is SceneRoots.
RESERVED_FILE_IDS = frozenset({0, 1, 2, 3, 4, INT64_MAX})


def stable_file_id(parts: Sequence[str], taken: Container[int] = ()) -> int:
    """A fileID derived from ``parts`` that is not reserved and not in ``taken``."""
    return next(value for value in candidate_file_ids(parts) if value not in taken)


def candidate_file_ids(parts: Sequence[str]) -> Iterator[int]:
    """The fileIDs ``parts`` may get, in the order ``stable_file_id`` tries them.

    An object made with ``stable_file_id`` is found again by walking these until one is free
    (it was never made) or is that object.
    """
    seed = "\x1f".join(parts)
    attempt = 0
    while True:
        data = seed if attempt == 0 else f"{seed}\x1f#{attempt}"
        digest = hashlib.sha256(data.encode("utf-8")).digest()
        value = int.from_bytes(digest[:8], "big") & INT64_MAX
        if value not in RESERVED_FILE_IDS:
            yield value
        attempt += 1
