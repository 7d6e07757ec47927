"""The scene half of the ``robots:`` section: each robot's imported GameObjects written into its
scene, known by fileIDs derived from the robot's GameObject path and each object's URDF key.

``place_robots`` runs before ``objects:`` and ``components:``, so that those can target links
(``r2d2/base_link/head``) and refer to them (``@r2d2/base_link``). What the URDF sets is
enforced on every run; what the user added (components, children, fields the import leaves
alone) is kept (``unity.owned``).

A visual's or collision's ``<mesh>`` is an object of role ``Role.MODEL`` (key
``link[i]/visual[j]/shape``), which is no GameObject of the scene's own but an instance of a
model or prefab: ``_Writer._model`` adds its documents (``_models``: the
``ModelInstance`` in ``RobotImport.models[key]``, laid out by ``unity.prefabinstance``) and
lists its root's stripped Transform among its parent's children; ``sync_owned`` writes such
documents whole and ``remove_owned`` removes them when the URDF drops the mesh. Its asset files
(``RobotImport.model_assets``) go with the others in ``_plan``.
"""

from __future__ import annotations

import functools
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field

from unityscaffold.apply._context import SceneContext
from unityscaffold.apply._editor import SceneEditor
from unityscaffold.apply._lock import LockFile, LockRobot
from unityscaffold.apply.robots._adopt import adopt_existing, keep_unity_rounding
from unityscaffold.apply.robots._fields import refuse_owned_builtin_fields
from unityscaffold.apply.robots._models import model_documents
from unityscaffold.apply.robots._owned import owned_fields
from unityscaffold.apply.robots._plan import PlannedRobot
from unityscaffold.apply.robots._slots import Slots
from unityscaffold.errors import LocatedError, UserError, located_at
from unityscaffold.manifest.model import SceneObject
from unityscaffold.unity import AssetRef, InlineMap, ObjectRef, SceneDocument
from unityscaffold.unity.builtins import builtin_class
from unityscaffold.unity.mesh import mesh_document
from unityscaffold.unity.owned import (
    OwnedComponent,
    OwnedDocument,
    OwnedObject,
)
from unityscaffold.unity.rotation import euler_to_quaternion
from unityscaffold.unity.values import FieldValue
from unityscaffold.urdf.cylinder import cylinder_collider_mesh
from unityscaffold.urdf.objects import (
    CYLINDER_MESH,
    ComponentRef,
    ImportedComponent,
    ImportedObject,
    MaterialRef,
    Role,
    Value,
)

__all__ = ["place_robots", "refuse_reshaped_robot_objects", "remove_kept"]

_MATERIAL_FILE_ID = 2100000
# the rest of HingeJoint's m_Limits, which the import leaves at a new joint's values
_LIMITS_REST = {"bounciness": 0.0, "bounceMinVelocity": 0.2, "contactDistance": 0.0}


def place_robots(
    ctx: SceneContext, editor: SceneEditor, robots: Sequence[PlannedRobot], lock: LockFile
) -> None:
    """Every robot of this scene written into it (see the module's docstring), and what an
    earlier apply made for robots the manifest no longer has removed."""
    scene = editor.plan.relative
    here = [robot for robot in robots if robot.entry.scene == scene]
    for robot in here:
        with located_at(robot.entry.locations.item):
            _place(ctx, editor, robot, lock)
    placed = {robot.gameobject for robot in here}
    for old in lock.robots:
        if old.scene == scene and old.gameobject not in placed:
            _remove(editor, old.gameobject, set(old.file_ids))


def _remove(editor: SceneEditor, robot: str, ids: set[int]) -> None:
    """Remove what ``robot`` no longer makes; what cannot go yet waits for ``remove_kept``."""
    removed, kept = editor.doc.remove_owned(ids)
    editor.plan.edits += [f"remove {path} (robot {robot})" for path in removed]
    editor.plan.robot_leftovers.setdefault(robot, {}).update(kept)


def remove_kept(editor: SceneEditor) -> None:
    """Once every other entry of the scene is done: what a robot kept because something else
    was on it is tried again (what apply itself pruned since no longer counts, so a second
    apply finds nothing more to remove), and what stays is said and stays recorded."""
    scene = editor.plan.relative
    for robot, kept in sorted(editor.plan.robot_leftovers.items()):
        removed, still = editor.doc.remove_owned(set(kept))
        editor.plan.edits += [f"remove {path} (robot {robot})" for path in removed]
        for file_id, path in sorted(still.items(), key=lambda item: item[1]):
            if editor.doc.document(file_id) is not None and _is_gameobject(editor, file_id):
                editor.plan.edits.append(
                    f"note: kept {path} (robot {robot}), which the URDF no longer has: "
                    "something else is on it (a component, a child or a reference); delete "
                    "it in Unity if it is not needed"
                )
        editor.plan.robots.append(LockRobot(scene, robot, tuple(sorted(still))))


# What an ``objects:`` entry would change on a robot's object that the import puts back
_IMPORT_OWNS = ("position", "rotation", "scale", "sibling_index", "primitive")


def refuse_reshaped_robot_objects(editor: SceneEditor, objects: Sequence[SceneObject]) -> None:
    """An ``objects:`` entry may add to a robot's GameObject (components, children), not move
    it, reorder it or give it another shape: the import puts its pose, its place among its
    siblings and its meshes back first on every run,
    so each apply would report the same two updates while ``--check`` passed."""
    scene = editor.plan.relative
    owned = {i for r in editor.plan.robots if r.scene == scene for i in r.file_ids}
    for item in objects:
        keys = [key for key in _IMPORT_OWNS if item.locations.has(key)]
        if not keys:
            continue
        try:
            go = editor.doc.find_gameobject(editor.path(item.path))
        except UserError:
            continue  # not in the scene yet: the entry makes it, no robot did
        robot = next((r.gameobject for r in editor.plan.robots if go.file_id in r.file_ids), "")
        if go.file_id in owned:
            raise LocatedError.at(
                item.locations.of(keys[0]),
                f"'{item.path}' belongs to robot {robot}, whose `robots` entry and URDF set "
                f"its {keys[0]}",
                hint="move the robot with its `robots` entry's position and rotation, change "
                "the URDF, or put what you add on a child object of your own",
            )
    refuse_owned_builtin_fields(editor, objects)


def _is_gameobject(editor: SceneEditor, file_id: int) -> bool:
    found = editor.doc.document(file_id)
    return found is not None and found.class_id == 1


def _place(ctx: SceneContext, editor: SceneEditor, robot: PlannedRobot, lock: LockFile) -> None:
    doc, scene = editor.doc, editor.plan.relative
    parent_path, _, _ = robot.gameobject.rpartition("/")
    parent, holder = 0, None
    if parent_path:
        holder = editor.gameobject(parent_path, True, robot.entry.locations.of("gameobject"))
        parent = holder.transform_id or 0
    writer = _writer(ctx, editor, robot, lock, holder.file_id if holder else None)
    objects = writer.objects(robot.imported.objects, parent)
    before = lock.robot_ids(scene, robot.gameobject)
    editor.robot_fields.update(owned_fields(robot.gameobject, objects))
    used = writer.slots.used
    _remove(editor, robot.gameobject, set(before - used))
    kept = writer.slots.recorded()
    editor.plan.robots.append(LockRobot(scene, robot.gameobject, tuple(sorted(used)), kept))
    adopted = set(writer.slots.taken.values())
    said = doc.sync_owned(keep_unity_rounding(doc, objects, adopted), writer.documents)
    if any(line.startswith("create ") for line in said) and len(said) > 3:
        made = sum(line.startswith("create ") for line in said)
        editor.plan.edits.append(f"import robot {robot.gameobject} ({made} new objects)")
        said = [line for line in said if not line.startswith("create ")]
    editor.plan.edits += [f"{line} (robot {robot.gameobject})" for line in said]
    if writer.adopting and said:
        editor.plan.edits.append(
            f"note: adopting robot {robot.gameobject} changes what differs from its URDF and "
            "entry (above); the entry keeps hand edits of the root's pose and UrdfRobot's "
            "switches with `position`, `rotation`, `kinematic`, `gravity` and `convex`"
        )


def _writer(
    ctx: SceneContext, editor: SceneEditor, robot: PlannedRobot, lock: LockFile, holder: int | None
) -> _Writer:
    """The robot's writer, with the fileIDs an earlier apply gave it (``_slots``: derived, or
    kept in the lock where the scene still has them), or those of a robot imported by hand at
    the robot's path now (``_adopt``, which refuses whatever else is there)."""
    doc, scene, root = editor.doc, editor.plan.relative, robot.imported.objects

    def class_of(file_id: int) -> int | None:
        return _class_of(doc, file_id)

    before = lock.robot_ids(scene, robot.gameobject)
    kept = lock.robot_adopted(scene, robot.gameobject)
    writer = _Writer(ctx, robot, Slots.of(robot.gameobject, root, class_of, before, kept))
    root_id = writer.slots.file_id(root.key, "GameObject", 1)
    found = adopt_existing(doc, robot, holder, root_id, ctx.rossharp_names, _slot_roles)
    if not found:
        return writer
    count = sum(role == "GameObject" for _, role in found)
    editor.plan.edits.append(f"adopt robot {robot.gameobject}, imported by hand ({count} objects)")
    writer = _Writer(ctx, robot, Slots.of(robot.gameobject, root, class_of), adopting=True)
    writer.slots.take(found)
    return writer


def _slot_roles(obj: ImportedObject) -> list[tuple[str, str]]:
    return [(component.name, role) for component, role in _roles(obj.components)]


def _class_of(doc: SceneDocument, file_id: int) -> int | None:
    found = doc.document(file_id)
    return None if found is None else found.class_id


@dataclass(slots=True)
class _Writer:
    """Turns the import's tree into owned objects with their fileIDs and references."""

    ctx: SceneContext
    robot: PlannedRobot
    slots: Slots
    documents: list[OwnedDocument] = field(default_factory=list)
    adopting: bool = False  # this run takes over a robot imported by hand

    @property
    def ids(self) -> dict[tuple[str, str], int]:
        return self.slots.ids

    def file_id(self, key: str, role: str, class_id: int) -> int:
        return self.slots.file_id(key, role, class_id)

    def objects(self, root: ImportedObject, parent: int) -> list[OwnedObject]:
        """Every object, parents first; every fileID is picked before any field refers to one."""
        walked = [o for _, o in root.walk()]
        for obj in walked:
            if obj.role is Role.MODEL:
                continue  # named by _model, once its parent's Transform is known
            self.file_id(obj.key, "GameObject", 1)
            self.file_id(obj.key, "Transform", 4)
            for component, role in _roles(obj.components):
                self.file_id(obj.key, role, _class_id(component))
        parents = {c.key: self.ids[(o.key, "Transform")] for o in walked for c in o.children}
        for obj in walked:
            if obj.role is Role.MODEL:
                self.ids[(obj.key, "Transform")] = self._model(obj, parents[obj.key])
        paths = dict(_paths(root, self.robot.gameobject))
        return [
            self._object(obj, parents.get(obj.key, parent), paths[obj.key])
            for obj in walked
            if obj.role is not Role.MODEL
        ]

    def _model(self, obj: ImportedObject, parent: int) -> int:
        """A mesh geometry (see the module's docstring): the instance's documents added to
        ``documents``, and the fileID of its root's stripped Transform returned."""
        transform, documents = model_documents(
            self.robot.imported.models[obj.key],
            key=obj.key,
            file_id=self.file_id,
            parent=parent,
            guids=self.robot.guids,
            convex=self.robot.entry.convex,
        )
        self.documents += documents
        return transform

    def _object(self, obj: ImportedObject, parent: int, path: str) -> OwnedObject:
        components = tuple(
            self._component(obj, component, role) for component, role in _roles(obj.components)
        )
        # the root takes the name its entry's path gives it (the URDF's by default)
        name = path.rpartition("/")[2] if obj.role is Role.ROBOT else obj.name
        return OwnedObject(
            self.ids[(obj.key, "GameObject")],
            self.ids[(obj.key, "Transform")],
            name,
            path,
            parent,
            self._transform(obj),
            components,
            tuple(self.ids[(c.key, "Transform")] for c in obj.children),
            hide_flags=8 if obj.not_editable else 0,
        )

    def _transform(self, obj: ImportedObject) -> tuple[tuple[str, FieldValue], ...]:
        pose = obj.transform
        rotation, position = pose.rotation, pose.position
        fields: list[tuple[str, FieldValue]] = []
        entry = self.robot.entry
        if obj.role is Role.ROBOT:
            if entry.rotation is not None:
                rotation = euler_to_quaternion(*entry.rotation)
            if entry.position is not None:
                position = entry.position
        fields += [
            ("m_LocalRotation", _map("xyzw", rotation)),
            ("m_LocalPosition", _map("xyz", position)),
            ("m_LocalScale", _map("xyz", pose.scale)),
        ]
        if obj.role is Role.ROBOT and entry.rotation is not None:
            fields.append(("m_LocalEulerAnglesHint", _map("xyz", entry.rotation)))
        return tuple(fields)

    def _component(
        self, obj: ImportedObject, component: ImportedComponent, role: str
    ) -> OwnedComponent:
        file_id = self.ids[(obj.key, role)]
        fields = [(name, self._value(obj, value)) for name, value in component.fields]
        fields = _with_switches(component.name, fields, self.robot, obj)
        builtin = builtin_class(component.name, imported=True)
        if builtin is not None:
            if component.name == "HingeJoint":
                fields = [(n, _full_limits(v) if n == "m_Limits" else v) for n, v in fields]
            return OwnedComponent(file_id, component.name, builtin=builtin, fields=tuple(fields))
        script = self.ctx.rossharp.script(component.name)
        defaults = self.ctx.defaults(script).values
        return OwnedComponent(
            file_id, component.name, script=script, fields=tuple(fields), defaults=defaults
        )

    def _value(self, obj: ImportedObject, value: Value) -> FieldValue:
        if isinstance(value, ComponentRef):
            return ObjectRef(self._component_id(value))
        if isinstance(value, MaterialRef):
            guid = self.robot.guids[value.path]
            return AssetRef(_MATERIAL_FILE_ID, guid, 2)
        if value is CYLINDER_MESH:
            return ObjectRef(self._cylinder(obj))
        if isinstance(value, list | tuple):
            return [self._value(obj, item) for item in value]
        return value  # type: ignore[return-value]

    def _component_id(self, ref: ComponentRef) -> int:
        role = f"{ref.component}#0"
        if (ref.key, role) not in self.ids:
            raise UserError(f"the import refers to {ref.component} of {ref.key}, which it lacks")
        return self.ids[(ref.key, role)]

    def _cylinder(self, obj: ImportedObject) -> int:
        file_id = self.file_id(obj.key, "Mesh", 43)
        if not any(d.file_id == file_id for d in self.documents):
            text = f"--- !u!43 &{file_id}\n{_cylinder_body()}"
            self.documents.append(OwnedDocument(43, file_id, text))
        return file_id


@functools.cache
def _cylinder_body() -> str:
    """The cylinder collider Mesh's document after its header line: the same for every
    collider (computing it costs some 100,000 float32 roundings)."""
    return mesh_document(0, "", cylinder_collider_mesh(), keep=True).split("\n", 1)[1]


def _roles(components: Sequence[ImportedComponent]) -> Iterator[tuple[ImportedComponent, str]]:
    """Each component with its role on its object: ``UrdfPlugin#2`` is the third UrdfPlugin.
    A joint's components (its UrdfJoint script and what follows it) are the joint type's:
    ``HingeJoint#0 of UrdfJointRevolute``. Another type makes new ones, as ROS#'s
    ``UrdfJoint.ChangeJointType`` destroys the old and adds the new, so that nothing the old
    type set (a revolute joint's limits) stays on a continuous joint's HingeJoint."""
    seen: dict[str, int] = {}
    joint = ""
    for component in components:
        if component.name.startswith("UrdfJoint"):
            joint = f" of {component.name}"
        n = seen.get(component.name, 0)
        seen[component.name] = n + 1
        yield component, f"{component.name}#{n}{joint}"


def _class_id(component: ImportedComponent) -> int:
    builtin = builtin_class(component.name, imported=True)
    return builtin.class_id if builtin is not None else 114


def _paths(root: ImportedObject, at: str) -> Iterator[tuple[str, str]]:
    pending = [(root, at)]
    while pending:
        obj, path = pending.pop()
        yield obj.key, path
        pending += [(child, f"{path}/{child.name}") for child in obj.children]


def _map(keys: str, values: Sequence[float]) -> InlineMap:
    return InlineMap(tuple(zip(keys, values, strict=True)))


def _full_limits(value: FieldValue) -> FieldValue:
    return {**value, **_LIMITS_REST} if isinstance(value, Mapping) else value


def _with_switches(
    name: str, fields: list[tuple[str, FieldValue]], robot: PlannedRobot, obj: ImportedObject
) -> list[tuple[str, FieldValue]]:
    """UrdfRobot's inspector switches, as its buttons set them after an import; a switch the
    entry leaves out is the import's value (a new Rigidbody's), enforced like the others, so
    that removing it from the manifest puts the scene back."""
    entry = robot.entry
    extra: list[tuple[str, FieldValue]] = []
    if name == "Rigidbody":
        extra.append(("m_UseGravity", True if entry.gravity is None else entry.gravity))
        extra.append(("m_IsKinematic", False if entry.kinematic is None else entry.kinematic))
    if name == "MeshCollider" and entry.convex is not None and obj.role is Role.SHAPE:
        fields = [(n, v) for n, v in fields if n != "m_Convex"]
        extra.append(("m_Convex", entry.convex))
    return fields + extra
