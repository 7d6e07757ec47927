"""An object's ``primitive``: the components Unity's GameObject > 3D Object menu adds after
the Transform, as built-in component entries that come before the object's own ``components``;
and the mesh a new MeshCollider takes, as in the editor.

They are recognised like any built-in component (by class, without an ``id``), so an entry of
``components`` of the same class sets fields on the primitive's own one. What the primitive
owns is what makes it that shape: the presence of the three components and their built-in
mesh (the MeshFilter's, and a MeshCollider's); the renderer's and collider's other fields keep
what the scene has, starting from the menu's values (``Primitive.start``).

The lock records the shape and the components apply added for it (``LockPrimitive``): never
one it found on the object, which stays the user's. When the shape changes, what the old one
added and the new one does not make (a cube's BoxCollider, for a sphere) is removed, unless a
``components`` entry of the object declares that class; a collider both make (a cylinder's and
a capsule's CapsuleCollider) stays and gets the new shape's fitted values. With no record (a lock
from before primitives were recorded) nothing is removed: a note names the other collider kept.
Dropping ``primitive`` keeps the components too: they become the user's.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

from unityscaffold.apply._assets import asset_value
from unityscaffold.apply._lock import LockPrimitive
from unityscaffold.manifest.model import BuiltinComponent, ComponentField, SceneObject
from unityscaffold.unity import GameObject, SceneDocument
from unityscaffold.unity.builtins import PRIMITIVES, builtin_class
from unityscaffold.unity.values import AssetRef, FieldValue, ObjectRef

__all__ = [
    "declared_components",
    "filter_mesh",
    "primitive_components",
    "remove_replaced",
    "restarted_ids",
    "start_component",
]


def primitive_components(item: SceneObject) -> tuple[BuiltinComponent, ...]:
    """The built-in components ``item``'s primitive adds, in the menu's order, with the
    fields the primitive keeps."""
    if item.primitive is None:
        return ()
    shape = PRIMITIVES[item.primitive]
    where = item.locations.of("primitive")
    owned = tuple(ComponentField(name, value, where) for name, value in shape.owned)
    return (
        BuiltinComponent("MeshFilter", (ComponentField("m_Mesh", shape.mesh, where),), None, where),
        BuiltinComponent("MeshRenderer", (), None, where),
        BuiltinComponent(shape.collider, owned, None, where),
    )


def declared_components(item: SceneObject) -> tuple[BuiltinComponent, ...]:
    """The primitive's components (first, as Unity's menu adds them), then the entry's."""
    return (*primitive_components(item), *item.components)


def start_component(item: SceneObject, comp: BuiltinComponent) -> BuiltinComponent | None:
    """The values Unity's menu fits to ``item``'s primitive collider ``comp`` (for a new one,
    or one a change of shape keeps); None for any other component."""
    if item.primitive is None or comp.key is not None:
        return None
    shape = PRIMITIVES[item.primitive]
    if comp.type != shape.collider or not shape.start:
        return None
    where = item.locations.of("primitive")
    fields = tuple(ComponentField(name, value, where) for name, value in shape.start)
    return BuiltinComponent(comp.type, fields, None, where)


def restarted_ids(item: SceneObject, recorded: LockPrimitive | None) -> frozenset[int]:
    """The components an earlier shape of ``item`` made, when its shape changed since: a
    collider among them that the new shape makes too takes the new shape's values."""
    if recorded is None or item.primitive is None or recorded.shape == item.primitive:
        return frozenset()
    return frozenset(recorded.file_ids)


def remove_replaced(
    doc: SceneDocument, go: GameObject, item: SceneObject, recorded: LockPrimitive | None
) -> list[str]:
    """Remove what ``item``'s earlier primitive added that its current one does not make and
    no ``components`` entry declares; one line for each. Without a record (a lock from before
    primitives were recorded), another shape's collider is kept, with a note."""
    if item.primitive is None or (recorded is not None and recorded.shape == item.primitive):
        return []
    making = {c.type for c in primitive_components(item)}
    declared = {c.type for c in item.components}
    if recorded is None:
        return _unrecorded_notes(doc, go, item, making | declared)
    edits = []
    for comp in doc.components_of(go):
        if comp.file_id not in recorded.file_ids or comp.type_name in making | declared:
            continue
        if doc.remove_component(comp):
            edits.append(
                f"remove {comp.type_name} from {item.path} (its {recorded.shape} "
                f"primitive made it; it is a {item.primitive} now)"
            )
    return edits


def _unrecorded_notes(
    doc: SceneDocument, go: GameObject, item: SceneObject, wanted: set[str]
) -> list[str]:
    colliders = {p.collider for p in PRIMITIVES.values()} - wanted
    return [
        f"note: {item.path} keeps its {comp.type_name} beside the {item.primitive}'s "
        f"{PRIMITIVES[str(item.primitive)].collider}: no lock records that apply made it "
        "(remove it in Unity if an earlier primitive did)"
        for comp in doc.components_of(go)
        if comp.type_name in colliders
    ]


def filter_mesh(
    doc: SceneDocument,
    go: GameObject,
    item: SceneObject,
    project_root: Path,
    planned: Mapping[str, AssetRef],
) -> FieldValue | None:
    """The mesh a new MeshCollider on ``item`` takes, as Unity's editor gives a MeshCollider
    added to an object its MeshFilter's mesh: the one the entry declares for the MeshFilter,
    else the one the scene's MeshFilter holds; None without a MeshFilter."""
    for comp in declared_components(item):
        mesh = next((f for f in comp.fields if f.name == "m_Mesh"), None)
        if comp.type == "MeshFilter" and comp.key is None and mesh is not None:
            where = mesh.location
            return asset_value("asset:Mesh", mesh.value, where, "m_Mesh", project_root, planned)
    meshfilter = builtin_class("MeshFilter")
    assert meshfilter is not None
    found = doc.find_builtin(go, meshfilter)
    if found is None:
        return None
    return _reference(doc.field(found.file_id, "m_Mesh"))


def _reference(stored: object) -> FieldValue | None:
    """A reference field as the scene holds it (``{fileID: F, guid: G, type: T}``)."""
    if not isinstance(stored, Mapping):
        return None
    try:
        file_id = int(stored["fileID"])
        if "guid" not in stored:
            return ObjectRef(file_id)
        return AssetRef(file_id, str(stored["guid"]), int(stored["type"]))
    except (KeyError, TypeError, ValueError):
        return None
