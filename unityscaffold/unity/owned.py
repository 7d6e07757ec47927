"""Objects a generator owns in a scene, known by the fileIDs it gave them (not by path).

The URDF import writes a whole hierarchy whose objects may share names ("unnamed" siblings),
so they are found by fileID: each ``OwnedObject`` and ``OwnedComponent`` names the fileID it
has, derived by the caller from stable keys. ``SceneDocument.sync_owned`` creates what is
missing, enforces the ``fields`` given on what exists, and keeps what is not listed: other
fields, other components and children (added by a user), whose places are kept after the
owned ones. ``OwnedDocument`` is a document owned whole (a Mesh made in code).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from unityscaffold.unity._fileids import candidate_file_ids
from unityscaffold.unity.builtins import BuiltinClass
from unityscaffold.unity.values import FieldValue, ScriptRef, Verbatim

__all__ = ["Fields", "OwnedComponent", "OwnedDocument", "OwnedObject", "owned_file_id"]

Fields = tuple[tuple[str, FieldValue], ...]


@dataclass(frozen=True, slots=True)
class OwnedComponent:
    """A built-in component (``builtin``) or a MonoBehaviour (``script``, written new with
    every field of ``defaults``); ``fields`` are enforced on every run."""

    file_id: int
    label: str  # the class, for messages
    builtin: BuiltinClass | None = None
    script: ScriptRef | None = None
    fields: Fields = ()
    defaults: tuple[tuple[str, FieldValue | Verbatim], ...] = ()

    @property
    def class_id(self) -> int:
        return self.builtin.class_id if self.builtin is not None else 114


@dataclass(frozen=True, slots=True)
class OwnedObject:
    """A GameObject with its Transform (``transform`` fields enforced), under the Transform
    ``parent`` (0: a root of the scene), with its owned ``components`` after the Transform
    and its owned ``children`` (their Transforms' fileIDs) first among its children."""

    file_id: int
    transform_id: int
    name: str
    path: str  # for messages
    parent: int
    transform: Fields
    components: tuple[OwnedComponent, ...]
    children: tuple[int, ...]
    hide_flags: int = 0


@dataclass(frozen=True, slots=True)
class OwnedDocument:
    """A document owned whole: its text is enforced byte for byte (a Mesh made in code, or a
    model instance's PrefabInstance, stripped objects and added components)."""

    class_id: int
    file_id: int
    text: str


def owned_file_id(
    parts: Sequence[str], class_id: int, class_of: Callable[[int], int | None], used: set[int]
) -> int:
    """The fileID of the owned object ``parts`` names: the first candidate derived from them
    that is free or already holds an object of ``class_id`` (the one made before), and that
    this run has not given to another object (recorded in ``used``)."""
    for candidate in candidate_file_ids(parts):
        if candidate in used:
            continue
        found = class_of(candidate)
        if found is None or found == class_id:
            used.add(candidate)
            return candidate
    raise AssertionError("unreachable: candidate_file_ids never ends")  # pragma: no cover
