"""The records the lock keeps of what apply put into scenes: components, GameObjects, robots
and primitives, each told by its scene and path."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["LockComponent", "LockGameObject", "LockPrimitive", "LockRobot"]


@dataclass(frozen=True, slots=True, order=True)
class LockComponent:
    """A component apply attached: scene, GameObject path and script GUID identify it."""

    scene: str
    gameobject: str
    script: str
    entry: str = ""  # the manifest entry that asked for it, e.g. "topic /odom"
    file_id: int = 0  # the component's fileID in the scene; 0 in a lock from before they were


@dataclass(frozen=True, slots=True, order=True)
class LockGameObject:
    """A GameObject apply made or adopted (an entry's GameObject or one on its path)."""

    scene: str
    path: str
    file_id: int


@dataclass(frozen=True, slots=True, order=True)
class LockRobot:
    """A robot apply imported: the fileIDs of every object it made for it in ``scene`` (so
    what a changed URDF no longer has can be removed), and those it took over from a robot
    imported by hand, by the import's slot (``"link[1]/visual[0] UrdfVisual#0"``), as they
    cannot be derived from the slot as the others are."""

    scene: str
    gameobject: str
    file_ids: tuple[int, ...]
    adopted: tuple[tuple[str, int], ...] = ()


@dataclass(frozen=True, slots=True, order=True)
class LockPrimitive:
    """An object's ``primitive`` as apply last made it: the shape, and the fileIDs of the
    components apply added for it (not those it found there, which stay the user's)."""

    scene: str
    gameobject: str  # the object's manifest path
    shape: str
    file_ids: tuple[int, ...]
