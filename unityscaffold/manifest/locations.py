"""Where a manifest item and its keys were written (``Locations``), shared by the model's
modules."""

from __future__ import annotations

from dataclasses import dataclass

from unityscaffold.errors import SourceLocation

__all__ = ["Locations"]


@dataclass(frozen=True, slots=True)
class Locations:
    """Where an item and each of its keys' values were written.

    ``of(key)`` falls back to the item itself for keys that were left to their default, so a
    later error about a defaulted value still points somewhere useful.
    """

    item: SourceLocation
    keys: tuple[tuple[str, SourceLocation], ...] = ()

    def of(self, key: str) -> SourceLocation:
        for name, location in self.keys:
            if name == key:
                return location
        return self.item

    def has(self, key: str) -> bool:
        return any(name == key for name, _ in self.keys)
