"""An instance of a model or prefab in a scene, as Unity 2022.3 saves one.

A scene holds an instance as a ``PrefabInstance`` document (the source asset and the changes
made to its objects), one *stripped* document for each object of the source the scene itself
refers to (the instance's root Transform, which its parent lists among its children, and each
GameObject a component was added to), and the added components as ordinary documents. The
layout is the one Unity wrote for the instances ROS#'s URDF importer made of the r2d2 sample's
``.dae`` models (``tests/urdf/test_models.py`` compares with it); the order of the changes and
the form of a material set on a renderer are Unity's too (``tests/unity/test_prefabinstance.py``).

``ModelInstance`` is what the urdf stage decides (which source, which changes, in Unity's
order); ``instance_documents`` lays it out once the writer knows the GUIDs of the assets and
the fileIDs of the scene's documents.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace

from unityscaffold.unity._scalars import format_float, format_string
from unityscaffold.unity.modelids import MODEL_PREFAB_FILE_ID

__all__ = [
    "AddedMeshCollider",
    "AssetObject",
    "ModelInstance",
    "Modification",
    "in_unity_order",
    "instance_documents",
    "material_modifications",
    "root_modifications",
]

GuidOf = Callable[[str], str]


@dataclass(frozen=True, slots=True)
class AssetObject:
    """An object in an asset: ``path`` relative to the robot's asset folder, the object's
    fileID there and the reference's ``type`` (3 for an imported model or a prefab, 2 for an
    asset Unity saved itself, such as a Mesh ``.asset``)."""

    path: str
    file_id: int
    type: int

    def render(self, guid_of: GuidOf) -> str:
        return f"{{fileID: {self.file_id}, guid: {guid_of(self.path)}, type: {self.type}}}"


@dataclass(frozen=True, slots=True)
class Modification:
    """One changed property of an object of the source (by its fileID there); ``value`` is
    the text Unity writes after ``value:`` (a number as Unity formats it, or a string), and
    ``reference`` the asset written as ``objectReference`` (none: ``{fileID: 0}``)."""

    target: int
    property_path: str
    value: str
    reference: AssetObject | None = None


@dataclass(frozen=True, slots=True)
class AddedMeshCollider:
    """A MeshCollider added to the source's GameObject ``target``, colliding with ``mesh``;
    ``convex`` as ROS# sets it (its importer leaves a model's colliders concave)."""

    target: int
    mesh: AssetObject
    convex: bool = False


@dataclass(frozen=True, slots=True)
class ModelInstance:
    """An instance of the asset at ``source`` (relative to the robot's asset folder), whose
    root has the Transform ``root_transform``; the changes in the order Unity saves them."""

    source: str
    source_type: int
    root_transform: int
    modifications: tuple[Modification, ...]
    removed: tuple[int, ...] = ()
    added: tuple[AddedMeshCollider, ...] = ()

    def with_convex(self, convex: bool) -> ModelInstance:
        """The same instance with its added colliders' ``convex`` set (UrdfRobot's inspector
        button "Convex", the manifest's ``convex:``)."""
        added = tuple(replace(a, convex=convex) for a in self.added)
        return replace(self, added=added)

    def with_changes(self, changes: tuple[Modification, ...]) -> ModelInstance:
        """The same instance with ``changes`` made after its own, in Unity's order."""
        return replace(self, modifications=in_unity_order((*self.modifications, *changes)))

    def scene_roles(self) -> tuple[str, ...]:
        """A name for each document the instance needs in a scene, for the writer to give
        each a fileID: the instance, its root's stripped Transform, then per added component
        the stripped GameObject it sits on (once) and the component."""
        roles = ["instance", "transform"]
        for added in self.added:
            if f"gameobject:{added.target}" not in roles:
                roles.append(f"gameobject:{added.target}")
            roles.append(f"collider:{added.target}")
        return tuple(roles)


def root_modifications(
    transform: int,
    gameobject: int,
    name: str,
    position: tuple[float, float, float],
    rotation: tuple[float, float, float, float],
) -> tuple[Modification, ...]:
    """What Unity records for every instance's root: its place, turn and name, in its order."""
    x, y, z = (format_float(v) for v in position)
    qx, qy, qz, qw = (format_float(v) for v in rotation)
    pose = (
        ("m_LocalPosition.x", x),
        ("m_LocalPosition.y", y),
        ("m_LocalPosition.z", z),
        ("m_LocalRotation.w", qw),
        ("m_LocalRotation.x", qx),
        ("m_LocalRotation.y", qy),
        ("m_LocalRotation.z", qz),
        ("m_LocalEulerAnglesHint.x", "0"),
        ("m_LocalEulerAnglesHint.y", "0"),
        ("m_LocalEulerAnglesHint.z", "0"),
    )
    named = Modification(gameobject, "m_Name", format_string(name, column=13, indent=8))
    return (*(Modification(transform, path, value) for path, value in pose), named)


def material_modifications(
    renderers: tuple[int, ...], material: AssetObject
) -> tuple[Modification, ...]:
    """What Unity records when a script sets ``sharedMaterial`` on each of ``renderers`` (ROS#'s
    ``UrdfMaterial.SetMaterial``), each renderer holding one material: its first entry."""
    return tuple(Modification(r, "m_Materials.Array.data[0]", "", material) for r in renderers)


def in_unity_order(changes: tuple[Modification, ...]) -> tuple[Modification, ...]:
    """``changes`` as Unity keeps them: by their target's fileID (a signed number), each
    target's in the order they were made (``docs/unity-yaml.md`` shows where this is seen)."""
    return tuple(sorted(changes, key=lambda change: change.target))


def instance_documents(
    instance: ModelInstance,
    *,
    parent: int,
    ids: Mapping[str, int],
    guid_of: GuidOf,
) -> list[tuple[int, str]]:
    """``(fileID, text)`` of each document the instance adds to a scene, in the order of
    ``instance.scene_roles()``: ``parent`` is the fileID of the Transform it sits under,
    ``ids`` gives a fileID to each role, ``guid_of`` the GUID of an asset path."""

    def of_source(file_id: int) -> str:
        return AssetObject(instance.source, file_id, instance.source_type).render(guid_of)

    def stripped(class_id: int, class_name: str, file_id: int, source_id: int) -> str:
        return (
            f"--- !u!{class_id} &{file_id} stripped\n{class_name}:\n"
            f"  m_CorrespondingSourceObject: {of_source(source_id)}\n"
            f"  m_PrefabInstance: {{fileID: {ids['instance']}}}\n"
            "  m_PrefabAsset: {fileID: 0}\n"
        )

    documents = [(ids["instance"], _prefab_instance(instance, parent, ids, of_source, guid_of))]
    transform = ids["transform"]
    documents.append((transform, stripped(4, "Transform", transform, instance.root_transform)))
    for added in instance.added:
        go_id = ids[f"gameobject:{added.target}"]
        if all(file_id != go_id for file_id, _ in documents):
            documents.append((go_id, stripped(1, "GameObject", go_id, added.target)))
        collider = ids[f"collider:{added.target}"]
        documents.append((collider, _mesh_collider(collider, go_id, added, guid_of)))
    return documents


def _prefab_instance(
    instance: ModelInstance,
    parent: int,
    ids: Mapping[str, int],
    of_source: Callable[[int], str],
    guid_of: GuidOf,
) -> str:
    lines = [
        f"--- !u!1001 &{ids['instance']}",
        "PrefabInstance:",
        "  m_ObjectHideFlags: 0",
        "  serializedVersion: 2",
        "  m_Modification:",
        "    serializedVersion: 3",
        f"    m_TransformParent: {{fileID: {parent}}}",
        "    m_Modifications:",
    ]
    for change in instance.modifications:
        reference = change.reference.render(guid_of) if change.reference else "{fileID: 0}"
        lines += [
            f"    - target: {of_source(change.target)}",
            f"      propertyPath: {change.property_path}",
            f"      value: {change.value}",
            f"      objectReference: {reference}",
        ]
    lines += _items("    m_RemovedComponents:", [f"- {of_source(i)}" for i in instance.removed])
    lines += ["    m_RemovedGameObjects: []", "    m_AddedGameObjects: []"]
    added: list[str] = []
    for component in instance.added:
        added += [
            f"- targetCorrespondingSourceObject: {of_source(component.target)}",
            "  insertIndex: -1",
            f"  addedObject: {{fileID: {ids[f'collider:{component.target}']}}}",
        ]
    lines += _items("    m_AddedComponents:", added)
    source = AssetObject(instance.source, MODEL_PREFAB_FILE_ID, instance.source_type)
    lines.append(f"  m_SourcePrefab: {source.render(guid_of)}")
    return "\n".join(lines) + "\n"


def _items(key: str, items: list[str]) -> list[str]:
    """A block sequence (dashes at the key's indentation), or ``[]`` when empty."""
    if not items:
        return [f"{key} []"]
    pad = key[: len(key) - len(key.lstrip())]
    return [key, *(pad + item for item in items)]


def _mesh_collider(file_id: int, gameobject: int, added: AddedMeshCollider, guid_of: GuidOf) -> str:
    """A MeshCollider as ``AddComponent`` makes it in 2022.3, with ROS#'s mesh and convexity."""
    return (
        f"--- !u!64 &{file_id}\nMeshCollider:\n"
        "  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n"
        "  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n"
        f"  m_GameObject: {{fileID: {gameobject}}}\n  m_Material: {{fileID: 0}}\n"
        "  m_IncludeLayers:\n    serializedVersion: 2\n    m_Bits: 0\n"
        "  m_ExcludeLayers:\n    serializedVersion: 2\n    m_Bits: 0\n"
        "  m_LayerOverridePriority: 0\n  m_IsTrigger: 0\n  m_ProvidesContacts: 0\n"
        "  m_Enabled: 1\n  serializedVersion: 5\n"
        f"  m_Convex: {int(added.convex)}\n  m_CookingOptions: 30\n"
        f"  m_Mesh: {added.mesh.render(guid_of)}\n"
    )
