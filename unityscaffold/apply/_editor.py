"""One scene's edits as they are made: the components attached, updated, re-added and pruned,
and the words and lock entries that record them.

Components are recognised by GameObject + script, so a second run finds everything in place;
GameObjects apply made or adopted are known by fileID (see ``_identity``).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.apply._facts import NewFields
from unityscaffold.apply._identity import Moved
from unityscaffold.apply._lock import LockComponent, LockPrimitive, LockRobot
from unityscaffold.errors import SourceLocation, UserError, located_at
from unityscaffold.unity import (
    GameObject,
    GameObjectNotFound,
    SceneComponent,
    SceneDocument,
    ScriptRef,
)
from unityscaffold.unity.values import FieldValue

__all__ = ["RobotFields", "SceneEditor", "ScenePlan"]


@dataclass(frozen=True, slots=True)
class RobotFields:
    """The fields ``robot``'s import enforces on one of its components (class ``label``): what
    ``apply.robots`` records while placing a robot, for the entries that would fight it."""

    robot: str
    label: str
    names: frozenset[str]


@dataclass(slots=True)
class ScenePlan:
    """One scene: its text before and after, and what changed in words."""

    path: Path
    relative: str
    before: str
    after: str
    edits: list[str] = field(default_factory=list)  # one line per change, for the summary
    components: list[LockComponent] = field(default_factory=list)
    gameobjects: dict[str, int] = field(default_factory=dict)  # path -> fileID, for the lock
    followed: list[Moved] = field(default_factory=list)  # manifest paths to rewrite
    robots: list[LockRobot] = field(default_factory=list)  # what apply made for each robot
    primitives: list[LockPrimitive] = field(default_factory=list)  # what each primitive made
    # robot -> objects an earlier apply made that stay while something else is on them
    robot_leftovers: dict[str, dict[int, str]] = field(default_factory=dict)

    @property
    def changed(self) -> bool:
        return self.before != self.after


_CREATE_HINT = (
    "add it in Unity, or set `create: true` on this entry (`create_gameobjects: true` for "
    "every entry) and apply creates it"
)


_REFERENCE_HINT = (
    "add it in Unity, or declare it under `objects:` (`- {path: ...}`) and apply creates it "
    "before it sets references"
)


class SceneEditor:
    """Applies the desired components to one loaded scene, recording what it did."""

    def __init__(
        self,
        plan: ScenePlan,
        doc: SceneDocument,
        owned: set[tuple[str, str]],
        now: dict[str, str],
    ) -> None:
        self.plan = plan
        self.doc = doc
        self.owned = owned  # (GameObject path, script GUID) of components an earlier apply added
        self.now = now  # manifest path -> where that GameObject is now (--follow-renames)
        self.wanted: set[tuple[str, str]] = set()
        self.attached: set[int] = set()  # fileIDs of the components the manifest asks for
        self.keys: dict[tuple[str, str, int], list[str]] = {}  # (path, GUID, fileID) -> ids
        self.adopted: dict[tuple[str, str, int, str], int] = {}  # ... + id -> instance taken
        # (path, lock entry) of components an earlier apply made that are gone from the scene
        self.deleted: set[tuple[str, str]] = set()
        # fileID -> the fields a robot's import enforces on that component of it
        self.robot_fields: dict[int, RobotFields] = {}

    def path(self, named: str) -> str:
        """Where the GameObject the manifest calls ``named`` is (renames followed)."""
        return self.now.get(named, named)

    def _adoptable(self, go: GameObject, script: ScriptRef) -> SceneComponent | None:
        """An instance of ``script`` on ``go`` that no entry claims (made in Unity, or before
        the manifest gave ids), taken in m_Component order; None if there is none."""
        ids = self.keys.get((go.path, script.guid, script.file_id), [])
        keyed = {c.file_id for k in ids if (c := self.doc.keyed_component(go, script, k))}
        for comp in self.doc.instances(go, script):
            if comp.file_id not in self.attached and comp.file_id not in keyed:
                return comp
        return None

    def gameobject(self, path: str, create: bool, where: SourceLocation) -> GameObject:
        path = self.path(path)
        with located_at(where):
            try:
                go = self.doc.ensure_gameobject(path, create=create)
            except GameObjectNotFound as error:
                raise UserError(error.message, hint=_CREATE_HINT) from None
        self.record(go)
        return go

    def find(self, path: str, where: SourceLocation) -> GameObject:
        """A GameObject a field refers to; recorded too, so that a rename of it is caught."""
        with located_at(where):
            try:
                go = self.doc.find_gameobject(self.path(path))
            except GameObjectNotFound as error:
                raise UserError(error.message, hint=_REFERENCE_HINT) from None
        self.record(go)
        return go

    def record(self, go: GameObject) -> None:
        """Remember the fileIDs of ``go`` and of every GameObject on its path (walked up by
        parent, since a path on the way may be one of same-named siblings)."""
        hierarchy = self.doc.hierarchy
        node: int | None = go.file_id
        while node is not None and hierarchy.paths[node] not in self.plan.gameobjects:
            self.plan.gameobjects[hierarchy.paths[node]] = node
            node = hierarchy.nodes[node].parent

    def attach(
        self,
        path: str,
        create: bool,
        script: ScriptRef,
        fields: list[tuple[str, FieldValue]],
        where: SourceLocation,
        entry: str,
        key: str | None = None,
        new: NewFields | None = None,
    ) -> SceneComponent:
        """Attach ``script`` to the GameObject at ``path`` or update the one there.

        A new component is written with every field ``new`` lists (``fields`` in place of
        theirs), and a note names the fields Unity will add on its next save; an existing one
        gets only ``fields``."""
        go = self.gameobject(path, create, where)
        path = go.path
        self.wanted.add((path, script.guid))
        adopt = None
        if key is None:
            existed = self.doc.find_component(go, script.guid, script.file_id) is not None
        else:
            existed = self.doc.keyed_component(go, script, key) is not None
            slot = (path, script.guid, script.file_id, key)
            if not existed and slot in self.adopted:
                adopt = self.doc.component(self.adopted[slot])
            elif not existed:
                adopt = self._adoptable(go, script)
            existed = existed or adopt is not None
        revision = self.doc.revision
        with located_at(where):
            defaults = new.values if new is not None and self._fits(new) else ()
            component = self.doc.ensure_component(go, script, fields, key, adopt, defaults)
        self.attached.add(component.file_id)
        if adopt is not None and key is not None:
            self.adopted[(path, script.guid, script.file_id, key)] = adopt.file_id
        name = (script.class_name or script.guid) + (f"#{key}" if key else "")
        added = f"add {name} to {path}"
        # A lock entry (an instance with an id: that very entry) whose component is gone.
        if not existed and (path, entry) in self.deleted:
            readded = f"re-add {name} to {path} (removed in Unity since the last apply)"
            if readded not in self.plan.edits:
                self.plan.edits.append(readded)
        elif not existed:
            self.plan.edits.append(added)
        elif self.doc.revision != revision and not _said(self.plan.edits, name, path):
            self.plan.edits.append(f"update {name} on {path}")
        if not existed and new is not None and new.unfilled:
            self._note_unfilled(script, new.unfilled)
        # Only what apply added is apply's to prune later; a component the user attached before
        # the manifest named it stays theirs.
        if not existed:
            self.owned.add((path, script.guid))
        if (path, script.guid) in self.owned:
            self.plan.components.append(
                LockComponent(self.plan.relative, path, script.guid, entry, component.file_id)
            )
        return component

    def _fits(self, new: NewFields) -> bool:
        """Whether the scene's Unity writes the fields as ``new`` lays them out."""
        era = self.doc.era
        return not new.since_2022 or (era.modern_prefab_fields and not era.root_order)

    def _note_unfilled(self, script: ScriptRef, unfilled: tuple[str, ...]) -> None:
        """Once per script class: the fields of a new component Unity fills when it saves."""
        note = (
            f"note: Unity adds {script.class_name or script.guid}'s "
            f"{', '.join(unfilled)} when it next saves the scene (their initial values are "
            "not plain values in the C# source, so apply leaves them to Unity)"
        )
        if note not in self.plan.edits:
            self.plan.edits.append(note)

    def prune(self, previous: Iterable[LockComponent], keep: set[tuple[str, str]]) -> None:
        for old in previous:
            if old.scene != self.plan.relative:
                continue
            component = self._recorded(old)
            if component is None or component.file_id in self.attached:
                continue
            keyed = "#" in old.entry  # one of several instances: its fileID alone tells
            if (
                not keyed
                and (self.doc.hierarchy.paths.get(component.gameobject_id), old.script) in keep
            ):
                continue
            if self.doc.remove_component(component):
                self.plan.edits.append(f"remove {old.entry or old.script} from {old.gameobject}")

    def _recorded(self, old: LockComponent) -> SceneComponent | None:
        """The component a lock entry names: by fileID, or by path for a lock without them."""
        if old.file_id:
            if self.doc.document(old.file_id) is None:
                return None  # removed in Unity already: nothing to remove
            found = self.doc.component(old.file_id)
            return found if found.script and found.script.guid == old.script else None
        try:
            go = self.doc.find_gameobject(self.path(old.gameobject))
        except UserError:
            return None  # the GameObject is gone already: nothing to remove
        return self.doc.find_component(go, old.script)


def _said(edits: list[str], name: str, path: str) -> bool:
    """Whether this run already has a line for the component: one line each, however many
    passes (plain values, then references) change it."""
    return (
        f"add {name} to {path}" in edits
        or f"update {name} on {path}" in edits
        or any(e.startswith(f"re-add {name} to {path} ") for e in edits)
    )
