"""Scripts an earlier apply generated in another output folder, to be moved, not recreated.

When ``output:`` changes, each script keeps its ``.meta`` GUID (scenes refer to the script by
it, so components stay attached) and its user half keeps its content (your code moves with
it); the old files are then pruned with their folders.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from unityscaffold.apply._lock import LockFile
from unityscaffold.manifest.model import Manifest
from unityscaffold.unity.meta import read_meta_guid

__all__ = ["Moves", "find_moves"]

_USER_SUFFIX = ".User.cs"


@dataclass(slots=True)
class Moves:
    """By file name (``CmdVelPublisher.cs``): what the earlier copy elsewhere had."""

    guids: dict[str, str] = field(default_factory=dict)
    sources: dict[str, str] = field(default_factory=dict)  # user half -> its old asset path
    owned: set[str] = field(default_factory=set)  # every such script's old asset path

    def guid(self, name: str) -> str | None:
        return self.guids.get(name)


def find_moves(manifest: Manifest, lock: LockFile) -> Moves:
    """The scripts ``lock`` records outside the current output folder, by file name."""
    moves = Moves()
    inside = manifest.output + "/"
    recorded = sorted({*lock.files, *lock.user_files})
    for relative in recorded:
        if relative.startswith(inside) or "/Scripts/" not in relative:
            continue
        name = relative.rsplit("/", 1)[-1]
        if not name.endswith(".cs"):
            continue
        moves.owned.add(relative)
        guid = read_meta_guid(manifest.project_root / (relative + ".meta"))
        if guid is not None:
            moves.guids.setdefault(name, guid)
        if name.endswith(_USER_SUFFIX) and relative in lock.user_files:
            moves.sources.setdefault(name, relative)
    return moves
