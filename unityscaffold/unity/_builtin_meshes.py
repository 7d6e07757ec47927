"""The mesh components a manifest may declare (MeshFilter, MeshRenderer, MeshCollider), laid out
as Unity 2022.3 serializes them, and the built-in resources their asset fields may name.

The layouts and defaults are those of the objects Unity 2022.3's GameObject > 3D Object menu
made in scenes it saved (a Plane's MeshFilter, MeshRenderer and MeshCollider; a Cube's); the
tests compare new documents with them byte for byte. A MeshRenderer therefore starts with
Unity's Default-Material, as a primitive does; a MeshCollider with no mesh. (``CreatePrimitive``
called from an editor script, as ROS#'s URDF importer calls it, leaves ``m_PreserveUVs: 1`` on
the renderer instead: 12 of 12 such renderers in ROS#'s r2d2 scene; the menu's have 0.)
"""

from __future__ import annotations

from dataclasses import dataclass

from unityscaffold.unity.values import AssetRef

__all__ = [
    "BUILTIN_MATERIALS",
    "BUILTIN_MESHES",
    "MESH_COLLIDER_SHAPE",
    "MESH_LAYOUTS",
    "PRIMITIVES",
    "UNCHECKED_PRIMITIVES",
    "Primitive",
]

# Unity's built-in resources: meshes in the "extra" resources, materials in the default ones.
_EXTRA = "0000000000000000e000000000000000"
_DEFAULT = "0000000000000000f000000000000000"

#: Built-in meshes by name, each seen on a primitive's MeshFilter in scenes Unity 2022.3 saved
#: (ROS#'s r2d2 import makes Cube, Cylinder and Sphere with CreatePrimitive; its tutorial scene
#: has a Plane). Capsule and Quad are left out: no Unity-written file here shows their fileIDs.
BUILTIN_MESHES = {
    "Cube": AssetRef(10202, _EXTRA, 0),
    "Cylinder": AssetRef(10206, _EXTRA, 0),
    "Sphere": AssetRef(10207, _EXTRA, 0),
    "Plane": AssetRef(10209, _EXTRA, 0),
}
#: Built-in materials by name: a primitive's renderer starts with Default-Material.
BUILTIN_MATERIALS = {"Default-Material": AssetRef(10303, _DEFAULT, 0)}


def _ref(ref: AssetRef) -> str:
    return f"{{fileID: {ref.file_id}, guid: {ref.guid}, type: {ref.type}}}"


# name, kind (as in unity/builtins.py; "asset:Mesh" and "asset:Material[]" name assets), default
MESH_LAYOUTS: dict[str, tuple[int, tuple[tuple[str, str, str], ...]]] = {
    "MeshFilter": (33, (("m_Mesh", "asset:Mesh", "{fileID: 0}"),)),
    "MeshRenderer": (
        23,
        (
            ("m_Enabled", "bool", "1"),
            ("m_CastShadows", "int", "1"),
            ("m_ReceiveShadows", "bool", "1"),
            ("m_DynamicOccludee", "bool", "1"),
            ("m_StaticShadowCaster", "bool", "0"),
            ("m_MotionVectors", "int", "1"),
            ("m_LightProbeUsage", "int", "1"),
            ("m_ReflectionProbeUsage", "int", "1"),
            ("m_RayTracingMode", "int", "2"),
            ("m_RayTraceProcedural", "bool", "0"),
            ("m_RenderingLayerMask", "int", "1"),
            ("m_RendererPriority", "int", "0"),
            (
                "m_Materials",
                "asset:Material[]",
                "\n  - " + _ref(BUILTIN_MATERIALS["Default-Material"]),
            ),
            ("m_StaticBatchInfo", "block", "\n    firstSubMesh: 0\n    subMeshCount: 0"),
            ("m_StaticBatchRoot", "asset", "{fileID: 0}"),
            ("m_ProbeAnchor", "asset", "{fileID: 0}"),
            ("m_LightProbeVolumeOverride", "asset", "{fileID: 0}"),
            ("m_ScaleInLightmap", "float", "1"),
            ("m_ReceiveGI", "int", "1"),
            ("m_PreserveUVs", "bool", "0"),
            ("m_IgnoreNormalsForChartDetection", "bool", "0"),
            ("m_ImportantGI", "bool", "0"),
            ("m_StitchLightmapSeams", "bool", "1"),
            ("m_SelectedEditorRenderState", "int", "3"),
            ("m_MinimumChartSize", "int", "4"),
            ("m_AutoUVMaxDistance", "float", "0.5"),
            ("m_AutoUVMaxAngle", "float", "89"),
            ("m_LightmapParameters", "asset", "{fileID: 0}"),
            ("m_SortingLayerID", "int", "0"),
            ("m_SortingLayer", "int", "0"),
            ("m_SortingOrder", "int", "0"),
            ("m_AdditionalVertexStreams", "asset", "{fileID: 0}"),
        ),
    ),
}
#: MeshCollider's own fields after the ones every collider has (serializedVersion 5).
MESH_COLLIDER_SHAPE = (
    ("m_Convex", "bool", "0"),
    ("m_CookingOptions", "int", "30"),
    ("m_Mesh", "asset:Mesh", "{fileID: 0}"),
)


@dataclass(frozen=True, slots=True)
class Primitive:
    """What the 3D Object menu puts on a new object after its Transform: a MeshFilter
    with ``mesh``, a MeshRenderer, and ``collider`` with the values it is given (the others
    keep a new collider's)."""

    mesh: str
    collider: str
    collider_fields: tuple[tuple[str, str], ...] = ()


#: The primitives whose every component was checked against objects Unity 2022.3's menu made:
#: a Plane (ROS#'s Gazebo tutorial scene) and Cubes (ROS#'s Unity simulation
#: scene). Sphere, Cylinder, Capsule and Quad have no such example here (ROS#'s importer
#: destroys their colliders; Unity fits a collider to the mesh's bounds, which is not guessed).
PRIMITIVES = {
    "plane": Primitive("Plane", "MeshCollider", (("m_Mesh", "Plane"),)),
    "cube": Primitive("Cube", "BoxCollider"),
}
#: Primitives Unity has that apply refuses, with the collider Unity gives each.
UNCHECKED_PRIMITIVES = {
    "sphere": ("Sphere", "SphereCollider"),
    "cylinder": ("Cylinder", "CapsuleCollider"),
    "capsule": ("Capsule", "CapsuleCollider"),
    "quad": ("Quad", "MeshCollider"),
}
