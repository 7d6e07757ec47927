"""A robot entry whose GameObject is already in the scene, and not as apply made it.

The common case is a team moving to this tool with a robot imported by hand through ROS#'s
editor window. Such a robot is adopted when it is the import of the entry's URDF: its objects
are matched to the planned import by the importer's structure (each object's name among its
siblings in order, its Urdf* and built-in components by class in order, a mesh geometry's
prefab instance and the documents Unity made for it), and apply takes over their fileIDs, so
that whatever points into the robot stays valid. From then on the robot is apply's like one it
imported: the slots it took over are recorded in the lock (``LockRobot.adopted``).

What is there but not the URDF's import (a link missing, another structure, an object that is
no robot at all) is refused before anything is written, saying the first difference: a second
root of the same name would make every later ``@r2d2/...`` path ambiguous, and guessing would
rewrite a robot the user built.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping
from dataclasses import replace
from typing import NoReturn

from unityscaffold.apply.robots._plan import PlannedRobot
from unityscaffold.errors import LocatedError
from unityscaffold.unity import InlineMap, SceneDocument
from unityscaffold.unity.index import GameObject
from unityscaffold.unity.owned import OwnedObject
from unityscaffold.unity.setvalue import component_label
from unityscaffold.unity.values import FieldValue
from unityscaffold.urdf.objects import ImportedObject, Role

__all__ = ["Slot", "adopt_existing", "keep_unity_rounding"]

Slot = tuple[str, str]  # (the object's URDF key, its role: "GameObject", "UrdfLink#0", ...)
#: An object's components, each as (class, role in the writer's slots: ``_place._roles``).
Roles = Callable[[ImportedObject], list[tuple[str, str]]]


def adopt_existing(
    doc: SceneDocument,
    robot: PlannedRobot,
    parent: int | None,
    ours: int,
    names: Mapping[str, str],
    roles: Roles,
) -> dict[Slot, int]:
    """The slots of a robot imported by hand at ``robot``'s path (none when there is nothing
    there but ``ours``, the root apply made), or a located error saying why it cannot be
    taken over. ``parent`` is the GameObject the robot goes under (None: a root), ``names``
    ROS#'s script GUIDs to class, ``roles`` an object's components' (class, slot role)."""
    name = robot.gameobject.rpartition("/")[2]
    found = [i for i in doc.hierarchy.children_named(parent, name) if i != ours]
    if not found:
        return {}
    go = doc.gameobject(found[0])
    if go.is_prefab_instance or "UrdfRobot" not in _labels(doc, go, names):
        _refuse_other(doc, robot, go, names)
    count = len(found) + (ours in doc.hierarchy.nodes)
    if count > 1:
        raise LocatedError.at(
            robot.entry.locations.of("gameobject"),
            f"{robot.entry.scene} has {count} GameObjects at '{go.path}', robots imported by "
            "hand or by apply: apply cannot tell which one this entry is",
            hint="delete or rename all but one of them in Unity",
        )
    matcher = _Matcher(doc, robot, names, roles)
    matcher.match(robot.imported.objects, go)
    return matcher.slots


def _refuse(robot: PlannedRobot, difference: str) -> NoReturn:
    raise LocatedError.at(
        robot.entry.locations.of("gameobject"),
        f"the robot imported by hand at '{robot.gameobject}' in {robot.entry.scene} is not "
        f"the import of {robot.entry.urdf.name}: {difference}",
        hint="apply takes over a robot imported in Unity's editor only when it is the URDF's "
        "import (the same names, order and components); delete it in Unity to let apply "
        "import it anew, or give this entry another `gameobject`",
    )


def _refuse_other(
    doc: SceneDocument, robot: PlannedRobot, go: GameObject, names: Mapping[str, str]
) -> NoReturn:
    where = robot.entry.locations.of("gameobject")
    scene = robot.entry.scene
    if go.is_prefab_instance:
        raise LocatedError.at(
            where,
            f"{scene} already has '{go.path}', an instance of a prefab, where this robot goes",
            hint="apply imports a robot as GameObjects of the scene itself: delete or rename "
            "the instance in Unity, or give this entry another `gameobject`",
        )
    kinds = ", ".join(_labels(doc, go, names))
    raise LocatedError.at(
        where,
        f"{scene} already has a GameObject '{go.path}' ({kinds}), which is not a robot, "
        "where this robot goes",
        hint="rename or move that GameObject in Unity, or give this entry another `gameobject`",
    )


def _labels(doc: SceneDocument, go: GameObject, names: Mapping[str, str]) -> list[str]:
    return [component_label(c, names) for c in doc.components_of(go)]


class _Matcher:
    """Walks the planned import and the scene's robot together, filling ``slots``."""

    def __init__(
        self, doc: SceneDocument, robot: PlannedRobot, names: Mapping[str, str], roles: Roles
    ) -> None:
        self.doc, self.robot, self.names, self.roles = doc, robot, names, roles
        self.slots: dict[Slot, int] = {}

    def match(self, root: ImportedObject, go: GameObject) -> None:
        pending = [(root, go)]
        while pending:
            obj, found = pending.pop(0)
            if obj.role is Role.MODEL:
                self._model(obj, found)
                continue
            self._object(obj, found)
            pending += self._children(obj, found)

    def _object(self, obj: ImportedObject, go: GameObject) -> None:
        if go.is_prefab_instance or not go.editable:
            _refuse(
                self.robot,
                f"'{go.path}' is a prefab instance where the import has a "
                f"GameObject with {', '.join(obj.component_names)}",
            )
        self.slots[(obj.key, "GameObject")] = go.file_id
        self.slots[(obj.key, "Transform")] = go.transform_id or 0
        have = [(c, component_label(c, self.names)) for c in self.doc.components_of(go)][1:]
        at = 0
        for name, role in self.roles(obj):
            nxt = next((n for n in range(at, len(have)) if have[n][1] == name), None)
            if nxt is None:
                labels = ", ".join(label for _, label in have) or "no component"
                _refuse(
                    self.robot,
                    f"'{go.path}' has no {name} after the Transform and "
                    f"{', '.join(r for r, _ in self.roles(obj)[:at])} (it has {labels})",
                )
            at = nxt + 1
            component = have[nxt][0]
            self.slots[(obj.key, role)] = component.file_id
            if name == "MeshCollider":
                self._inline_mesh(obj, component.file_id)

    def _inline_mesh(self, obj: ImportedObject, collider: int) -> None:
        """The cylinder collider's Mesh, saved in the scene (slot ``Mesh``)."""
        mesh = self.doc.field(collider, "m_Mesh")
        if isinstance(mesh, dict) and "guid" not in mesh and mesh.get("fileID", "0") != "0":
            found = self.doc.document(int(mesh["fileID"]))
            if found is not None and found.class_id == 43:
                self.slots[(obj.key, "Mesh")] = found.file_id

    def _children(
        self, obj: ImportedObject, go: GameObject
    ) -> list[tuple[ImportedObject, GameObject]]:
        """Each planned child with the scene's child of its name, in order (children the user
        added in between are passed over)."""
        have = self.doc.children(go)
        at, pairs = 0, []
        for child in obj.children:
            nxt = next((n for n in range(at, len(have)) if have[n].name == child.name), None)
            if nxt is None:
                what = "model instance" if child.role is Role.MODEL else "child"
                _refuse(
                    self.robot,
                    f"'{go.path}' has no {what} '{child.name}' (the URDF's {child.key}) "
                    "in its place",
                )
            at = nxt + 1
            pairs.append((child, have[nxt]))
        return pairs

    def _model(self, obj: ImportedObject, go: GameObject) -> None:
        """A mesh geometry: the instance of the model, with the documents Unity made for it."""
        if not go.is_prefab_instance:
            _refuse(self.robot, f"'{go.path}' is not an instance of the mesh's model")
        instance = self.robot.imported.models[obj.key]
        source = self.doc.field(go.file_id, "m_SourcePrefab")
        guid = self.robot.guids.get(instance.source)
        if not isinstance(source, dict) or source.get("guid") != guid:
            shown = source.get("guid") if isinstance(source, dict) else source
            _refuse(
                self.robot,
                f"'{go.path}' is an instance of the asset {shown}, not of "
                f"{self.robot.assets}/{instance.source} (GUID {guid}); `assets` must be "
                "the folder the robot was imported into",
            )
        parts = self._instance_parts(go.file_id)
        self.slots[(obj.key, "model instance")] = go.file_id
        for role in instance.scene_roles()[1:]:
            kind, _, target = role.partition(":")
            source_id = instance.root_transform if kind == "transform" else int(target)
            class_id = {"transform": 4, "gameobject": 1, "collider": 64}[kind]
            found = parts.get((class_id, source_id))
            if found is None and instance.source.endswith(".prefab"):
                # ROS#'s STL post-processor gives its prefab's objects random fileIDs; apply
                # writes its own prefab there, so the instance would point at nothing
                _refuse(
                    self.robot,
                    f"'{go.path}' is an instance of ROS#'s STL prefab "
                    f"{self.robot.assets}/{instance.source}, whose objects are not the ones "
                    "of the prefab apply writes (robots with STL meshes are not adopted yet)",
                )
            if found is None:
                what = {4: "the stripped Transform of", 1: "the stripped GameObject of"}
                _refuse(
                    self.robot,
                    f"'{go.path}' lacks "
                    f"{what.get(class_id, 'the MeshCollider the import adds to')} its model's "
                    f"object {source_id}",
                )
            self.slots[(obj.key, f"model {role}")] = found

    def _instance_parts(self, instance: int) -> dict[tuple[int, int], int]:
        """The instance's stripped documents by (class, source fileID), and each added
        MeshCollider by (64, the source fileID of the stripped GameObject it is on)."""
        held = f"m_PrefabInstance: {{fileID: {instance}}}"
        stripped: dict[tuple[int, int], int] = {}
        for doc in self.doc.documents():
            if doc.stripped and held in doc.text:
                source = self.doc.field(doc.file_id, "m_CorrespondingSourceObject")
                if isinstance(source, dict):
                    stripped.setdefault((doc.class_id, int(source["fileID"])), doc.file_id)
        on = {go: source for (class_id, source), go in stripped.items() if class_id == 1}
        for doc in self.doc.documents():
            if doc.class_id == 64 and not doc.stripped:
                owner = self.doc.component(doc.file_id).gameobject_id
                if owner in on:
                    stripped.setdefault((64, on[owner]), doc.file_id)
        return stripped


#: How far a robot's Transform may be from the URDF's pose and keep the scene's digits: Unity's
#: importer places objects with world-space float32 arithmetic, so a hand import holds
#: ``-0.08500004`` where the URDF says ``-0.085`` (one float32 step), which is no change.
_NEAR = 1e-6
_POSE = ("m_LocalPosition", "m_LocalRotation")


def keep_unity_rounding(
    doc: SceneDocument, objects: list[OwnedObject], adopted: Collection[int]
) -> list[OwnedObject]:
    """``objects`` without the pose fields whose scene values are within ``_NEAR`` of the
    planned ones, on the Transforms ``adopted`` (Unity wrote them), so that those keep the
    bytes Unity wrote; apply's own are written as planned, as a fresh import would be."""
    kept = []
    for obj in objects:
        found = doc.document(obj.transform_id) if obj.transform_id in adopted else None
        if found is None:
            kept.append(obj)
            continue
        fields = tuple(
            (name, value)
            for name, value in obj.transform
            if not (name in _POSE and _near(_vector(found.text, name), value))
        )
        kept.append(obj if fields == obj.transform else replace(obj, transform=fields))
    return kept


def _vector(text: str, name: str) -> dict[str, str] | None:
    """A one-line flow mapping field of a document (``{x: 0, y: 1, z: 0}``), read without a
    YAML parse: every robot object's pose is read on every run, a no-op included."""
    at = text.find(f"\n  {name}: {{")
    if at < 0:
        return None
    line = text[at + len(name) + 6 : text.find("\n", at + 1)]
    if not line.endswith("}"):
        return None
    pairs = [item.partition(": ") for item in line[:-1].split(", ")]
    return {key: value for key, _, value in pairs}


def _near(scene: dict[str, str] | None, planned: FieldValue) -> bool:
    if scene is None or not isinstance(planned, InlineMap):
        return False
    wanted = dict(planned.items)
    if set(scene) != set(wanted):
        return False
    try:
        return all(abs(float(scene[k]) - float(wanted[k])) <= _NEAR for k in wanted)  # type: ignore[arg-type]
    except ValueError:
        return False
