"""The fields a robot's import enforces on each of its components, by the component's fileID:
what ``place_robots`` records for ``_fields`` to refuse entries that would fight it."""

from __future__ import annotations

from collections.abc import Iterable

from unityscaffold.apply._editor import RobotFields
from unityscaffold.unity.owned import OwnedObject

__all__ = ["owned_fields"]


def owned_fields(robot: str, objects: Iterable[OwnedObject]) -> dict[int, RobotFields]:
    """Each owned component's fileID with the fields the import enforces on it."""
    return {
        c.file_id: RobotFields(robot, c.label, frozenset(name for name, _ in c.fields))
        for obj in objects
        for c in obj.components
    }
