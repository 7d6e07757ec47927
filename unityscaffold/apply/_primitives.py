"""An object's ``primitive``: the components Unity's GameObject > 3D Object menu adds after
the Transform, as built-in component entries that come before the object's own ``components``.

They are recognised like any built-in component (by class, without an ``id``), so an entry of
``components`` of the same class sets fields on the primitive's own one. What the primitive
owns is what makes it that shape: the presence of the three components and their built-in
mesh (the MeshFilter's, and a MeshCollider's); the renderer's and collider's other fields keep
what the scene has, starting from the menu's values.
"""

from __future__ import annotations

from unityscaffold.manifest.model import BuiltinComponent, ComponentField, SceneObject
from unityscaffold.unity.builtins import PRIMITIVES

__all__ = ["primitive_components"]


def primitive_components(item: SceneObject) -> tuple[BuiltinComponent, ...]:
    """The built-in components ``item``'s primitive adds, in the menu's order."""
    if item.primitive is None:
        return ()
    shape = PRIMITIVES[item.primitive]
    where = item.locations.of("primitive")
    collider = tuple(ComponentField(name, value, where) for name, value in shape.collider_fields)
    return (
        BuiltinComponent("MeshFilter", (ComponentField("m_Mesh", shape.mesh, where),), None, where),
        BuiltinComponent("MeshRenderer", (), None, where),
        BuiltinComponent(shape.collider, collider, None, where),
    )
