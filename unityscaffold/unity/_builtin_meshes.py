"""The mesh components a manifest may declare (MeshFilter, MeshRenderer, MeshCollider), laid out
as Unity 2022.3 serializes them, the built-in resources their asset fields may name, and what
Unity's GameObject > 3D Object menu puts on each primitive it makes.

The layouts and defaults are those of the objects Unity 2022.3's GameObject > 3D Object menu
made in scenes and prefabs it saved; the tests compare new documents with them byte for byte. A
MeshRenderer therefore starts with Unity's Default-Material, as a primitive does; a MeshCollider
with no mesh (apply gives a new one the MeshFilter's, as the editor does: ``apply._primitives``).
(``CreatePrimitive`` called from an editor script, as ROS#'s URDF importer calls it, leaves
``m_PreserveUVs: 1`` on the renderer instead: 12 of 12 such renderers in ROS#'s r2d2 scene; the
menu's have 0.)

Where each primitive was checked (Unity 2022.3 writes every one with the Transform, then the
MeshFilter, the MeshRenderer and the collider, in that order):

- Plane and Cube: ROS#'s Gazebo and Unity simulation sample scenes,
  https://github.com/siemens/ros-sharp/blob/65dfc8f286eb64e7a733c7928fbea4a42040c45c/com.siemens.ros-sharp/Samples~/Unity%20Simulation%20Scene%20ROS2/UnitySimulationScene.unity
  (the Cube; the Plane is in the tests' copy of the Gazebo step-1 scene).
- Sphere, Capsule, Cylinder and Quad: menu-made objects saved as prefabs, untouched but for
  their position, in a Unity 2022.3 project (URP 14.0.12),
  https://github.com/Alex144xD/Tesis/blob/ec6bf96cdac34ab2d8201c77216547bbcb92bbd8/Assets/Prefabs/
  (``Sphere.prefab``, ``Capsule (1).prefab``, ``Cylinder.prefab``, ``Quad.prefab``); the
  Capsule and Cylinder agree with those of another 2022.3 project,
  https://github.com/AFabulousWhale/EditorTools/blob/fc308952021becd38beb4d695232c45565a3da09/Assets/Prefabs/

Unity fits a new collider to the mesh's bounds, so the values are the bounds' float arithmetic,
not round numbers: the Cylinder's CapsuleCollider gets ``m_Radius: 0.5000001`` and a centre a few
1e-8 off zero (the built-in Cylinder mesh is not exactly centred). The Sphere's SphereCollider
(radius 0.5) and the Capsule's CapsuleCollider (radius 0.5, height 2, along Y) come out as a new
collider's defaults; the Quad's MeshCollider holds the Quad mesh, as the Plane's holds the Plane.
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
    "Primitive",
]

# Unity's built-in resources: meshes in the "extra" resources, materials in the default ones.
_EXTRA = "0000000000000000e000000000000000"
_DEFAULT = "0000000000000000f000000000000000"

#: Built-in meshes by name, each seen on a primitive's MeshFilter in files Unity 2022.3 saved
#: (the six primitives' sources above; ROS#'s r2d2 import also has Cube, Cylinder and Sphere).
BUILTIN_MESHES = {
    "Cube": AssetRef(10202, _EXTRA, 0),
    "Cylinder": AssetRef(10206, _EXTRA, 0),
    "Sphere": AssetRef(10207, _EXTRA, 0),
    "Capsule": AssetRef(10208, _EXTRA, 0),
    "Plane": AssetRef(10209, _EXTRA, 0),
    "Quad": AssetRef(10210, _EXTRA, 0),
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
    """What the 3D Object menu puts on a new object after its Transform: a MeshFilter with
    ``mesh``, a MeshRenderer, and ``collider``.

    ``owned`` are the collider's fields that make it this shape (a MeshCollider's mesh): apply
    keeps them. ``start`` are the values Unity fitted to the mesh, every shape field of the
    collider: a new collider gets them, and then keeps what the scene has.
    """

    mesh: str
    collider: str
    owned: tuple[tuple[str, str], ...] = ()
    start: tuple[tuple[str, float | int | tuple[float, ...]], ...] = ()


_ORIGIN = (0.0, 0.0, 0.0)

#: The primitives by the manifest's name, each checked against one Unity 2022.3's menu made.
PRIMITIVES = {
    "plane": Primitive("Plane", "MeshCollider", owned=(("m_Mesh", "Plane"),)),
    "cube": Primitive(
        "Cube", "BoxCollider", start=(("m_Size", (1.0, 1.0, 1.0)), ("m_Center", _ORIGIN))
    ),
    "sphere": Primitive(
        "Sphere", "SphereCollider", start=(("m_Radius", 0.5), ("m_Center", _ORIGIN))
    ),
    "capsule": Primitive(
        "Capsule",
        "CapsuleCollider",
        start=(("m_Radius", 0.5), ("m_Height", 2.0), ("m_Direction", 1), ("m_Center", _ORIGIN)),
    ),
    "cylinder": Primitive(
        "Cylinder",
        "CapsuleCollider",  # Unity has no cylinder collider: a capsule as tall as the mesh
        start=(
            ("m_Radius", 0.5000001),
            ("m_Height", 2.0),
            ("m_Direction", 1),
            ("m_Center", (5.9604645e-08, 0.0, -8.940697e-08)),
        ),
    ),
    "quad": Primitive("Quad", "MeshCollider", owned=(("m_Mesh", "Quad"),)),
}
