"""Built-in Unity components a manifest may declare, laid out as Unity 2022.3 serializes them.

Each class lists its serialized fields in Unity's order after ``m_GameObject``, with the value a
component added in the editor starts with and what the field stores (the kinds of
``unity/catalog.py``; ``block`` for a nested mapping that is copied as it is and cannot be set).
The order and the form were read off scenes Unity 2022.3 saved (ROS#'s sample scenes; the tests
compare new documents with them byte for byte); the table itself is written here, the mesh
components' in ``_builtin_meshes`` with the primitives and built-in assets, the joints only the
URDF import writes in ``_joint_layouts``. An ``asset:Class`` field names an asset
(``apply/_assets.py``).

Also the built-in tags and layers every project has, which need no ``TagManager.asset``.
"""

from __future__ import annotations

from dataclasses import dataclass

from unityscaffold.unity._builtin_meshes import (
    BUILTIN_MATERIALS,
    BUILTIN_MESHES,
    MESH_COLLIDER_SHAPE,
    MESH_LAYOUTS,
    PRIMITIVES,
    Primitive,
)
from unityscaffold.unity._joint_layouts import JOINT_LAYOUTS
from unityscaffold.unity.catalog import CatalogField

__all__ = [
    "BUILTIN_LAYERS",
    "BUILTIN_MATERIALS",
    "BUILTIN_MESHES",
    "BUILTIN_TAGS",
    "BUILTIN_TYPES",
    "PRIMITIVES",
    "BuiltinClass",
    "Primitive",
    "builtin_class",
    "layer_number",
]

#: Tags every project has (Unity's TagManager lists only the ones a project adds).
BUILTIN_TAGS = (
    "Untagged",
    "Respawn",
    "Finish",
    "EditorOnly",
    "MainCamera",
    "Player",
    "GameController",
)
#: Layers every project has, by number.
BUILTIN_LAYERS = ["Default", "TransparentFX", "Ignore Raycast", "Water", "UI"]
_LAYER_NUMBERS = {"Default": 0, "TransparentFX": 1, "Ignore Raycast": 2, "Water": 4, "UI": 5}

_LAYERMASK_NONE = "\n    serializedVersion: 2\n    m_Bits: 0"
_LAYERMASK_ALL = "\n    serializedVersion: 2\n    m_Bits: 4294967295"


@dataclass(frozen=True, slots=True)
class _Field:
    name: str
    kind: str  # int, float, bool, Vector2/3/4, Quaternion, Color, ref:Class, asset:Class, block
    default: str  # the text after "name:" (a block starts with a line break)


def _collider(*shape: _Field, version: str) -> tuple[_Field, ...]:
    return (
        _Field("m_Material", "asset", "{fileID: 0}"),
        _Field("m_IncludeLayers", "block", _LAYERMASK_NONE),
        _Field("m_ExcludeLayers", "block", _LAYERMASK_NONE),
        _Field("m_LayerOverridePriority", "int", "0"),
        _Field("m_IsTrigger", "bool", "0"),
        _Field("m_ProvidesContacts", "bool", "0"),
        _Field("m_Enabled", "bool", "1"),
        _Field("serializedVersion", "fixed", version),
        *shape,
    )


_CENTER = _Field("m_Center", "Vector3", "{x: 0, y: 0, z: 0}")

_LAYOUTS: dict[str, tuple[int, tuple[_Field, ...]]] = {
    "AudioListener": (81, (_Field("m_Enabled", "bool", "1"),)),
    "BoxCollider": (
        65,
        _collider(_Field("m_Size", "Vector3", "{x: 1, y: 1, z: 1}"), _CENTER, version="3"),
    ),
    "Camera": (
        20,
        (
            _Field("m_Enabled", "bool", "1"),
            _Field("serializedVersion", "fixed", "2"),
            _Field("m_ClearFlags", "int", "1"),
            _Field(
                "m_BackGroundColor", "Color", "{r: 0.19215687, g: 0.3019608, b: 0.4745098, a: 0}"
            ),
            _Field("m_projectionMatrixMode", "int", "1"),
            _Field("m_GateFitMode", "int", "2"),
            _Field("m_FOVAxisMode", "int", "0"),
            _Field("m_Iso", "int", "200"),
            _Field("m_ShutterSpeed", "float", "0.005"),
            _Field("m_Aperture", "float", "16"),
            _Field("m_FocusDistance", "float", "10"),
            _Field("m_FocalLength", "float", "50"),
            _Field("m_BladeCount", "int", "5"),
            _Field("m_Curvature", "Vector2", "{x: 2, y: 11}"),
            _Field("m_BarrelClipping", "float", "0.25"),
            _Field("m_Anamorphism", "float", "0"),
            _Field("m_SensorSize", "Vector2", "{x: 36, y: 24}"),
            _Field("m_LensShift", "Vector2", "{x: 0, y: 0}"),
            _Field(
                "m_NormalizedViewPortRect",
                "block",
                "\n    serializedVersion: 2\n    x: 0\n    y: 0\n    width: 1\n    height: 1",
            ),
            _Field("near clip plane", "float", "0.3"),
            _Field("far clip plane", "float", "1000"),
            _Field("field of view", "float", "60"),
            _Field("orthographic", "bool", "0"),
            _Field("orthographic size", "float", "5"),
            _Field("m_Depth", "float", "0"),
            _Field("m_CullingMask", "block", _LAYERMASK_ALL),
            _Field("m_RenderingPath", "int", "-1"),
            _Field("m_TargetTexture", "asset", "{fileID: 0}"),
            _Field("m_TargetDisplay", "int", "0"),
            _Field("m_TargetEye", "int", "3"),
            _Field("m_HDR", "bool", "1"),
            _Field("m_AllowMSAA", "bool", "1"),
            _Field("m_AllowDynamicResolution", "bool", "0"),
            _Field("m_ForceIntoRT", "bool", "0"),
            _Field("m_OcclusionCulling", "bool", "1"),
            _Field("m_StereoConvergence", "float", "10"),
            _Field("m_StereoSeparation", "float", "0.022"),
        ),
    ),
    "Canvas": (
        223,
        (
            _Field("m_Enabled", "bool", "1"),
            _Field("serializedVersion", "fixed", "3"),
            _Field("m_RenderMode", "int", "0"),
            _Field("m_Camera", "ref:Camera", "{fileID: 0}"),
            _Field("m_PlaneDistance", "float", "100"),
            _Field("m_PixelPerfect", "bool", "0"),
            _Field("m_ReceivesEvents", "bool", "1"),
            _Field("m_OverrideSorting", "bool", "0"),
            _Field("m_OverridePixelPerfect", "bool", "0"),
            _Field("m_SortingBucketNormalizedSize", "float", "0"),
            _Field("m_VertexColorAlwaysGammaSpace", "bool", "0"),
            _Field("m_AdditionalShaderChannelsFlag", "int", "0"),
            _Field("m_UpdateRectTransformForStandalone", "int", "0"),
            _Field("m_SortingLayerID", "int", "0"),
            _Field("m_SortingOrder", "int", "0"),
            _Field("m_TargetDisplay", "int", "0"),
        ),
    ),
    "CanvasRenderer": (222, (_Field("m_CullTransparentMesh", "bool", "1"),)),
    "CapsuleCollider": (
        136,
        _collider(
            _Field("m_Radius", "float", "0.5"),
            _Field("m_Height", "float", "2"),
            _Field("m_Direction", "int", "1"),
            _CENTER,
            version="2",
        ),
    ),
    "Light": (
        108,
        (
            _Field("m_Enabled", "bool", "1"),
            _Field("serializedVersion", "fixed", "10"),
            _Field("m_Type", "int", "2"),
            _Field("m_Shape", "int", "0"),
            _Field("m_Color", "Color", "{r: 1, g: 1, b: 1, a: 1}"),
            _Field("m_Intensity", "float", "1"),
            _Field("m_Range", "float", "10"),
            _Field("m_SpotAngle", "float", "30"),
            _Field("m_InnerSpotAngle", "float", "21.80208"),
            _Field("m_CookieSize", "float", "10"),
            _Field(
                "m_Shadows",
                "block",
                "\n    m_Type: 0\n    m_Resolution: -1\n    m_CustomResolution: -1"
                "\n    m_Strength: 1\n    m_Bias: 0.05\n    m_NormalBias: 0.4\n    m_NearPlane: 0.2"
                "\n    m_CullingMatrixOverride:"
                + "".join(
                    f"\n      e{row}{col}: {1 if row == col else 0}"
                    for row in range(4)
                    for col in range(4)
                )
                + "\n    m_UseCullingMatrixOverride: 0",
            ),
            _Field("m_Cookie", "asset", "{fileID: 0}"),
            _Field("m_DrawHalo", "bool", "0"),
            _Field("m_Flare", "asset", "{fileID: 0}"),
            _Field("m_RenderMode", "int", "0"),
            _Field("m_CullingMask", "block", _LAYERMASK_ALL),
            _Field("m_RenderingLayerMask", "int", "1"),
            _Field("m_Lightmapping", "int", "4"),
            _Field("m_LightShadowCasterMode", "int", "0"),
            _Field("m_AreaSize", "Vector2", "{x: 1, y: 1}"),
            _Field("m_BounceIntensity", "float", "1"),
            _Field("m_ColorTemperature", "float", "6570"),
            _Field("m_UseColorTemperature", "bool", "0"),
            _Field("m_BoundingSphereOverride", "Vector4", "{x: 0, y: 0, z: 0, w: 0}"),
            _Field("m_UseBoundingSphereOverride", "bool", "0"),
            _Field("m_UseViewFrustumForShadowCasterCull", "bool", "1"),
            _Field("m_ShadowRadius", "float", "0"),
            _Field("m_ShadowAngle", "float", "0"),
        ),
    ),
    "Rigidbody": (
        54,
        (
            _Field("serializedVersion", "fixed", "4"),
            _Field("m_Mass", "float", "1"),
            _Field("m_Drag", "float", "0"),
            _Field("m_AngularDrag", "float", "0.05"),
            _Field("m_CenterOfMass", "Vector3", "{x: 0, y: 0, z: 0}"),
            _Field("m_InertiaTensor", "Vector3", "{x: 1, y: 1, z: 1}"),
            _Field("m_InertiaRotation", "Quaternion", "{x: 0, y: 0, z: 0, w: 1}"),
            _Field("m_IncludeLayers", "block", _LAYERMASK_NONE),
            _Field("m_ExcludeLayers", "block", _LAYERMASK_NONE),
            _Field("m_ImplicitCom", "bool", "1"),
            _Field("m_ImplicitTensor", "bool", "1"),
            _Field("m_UseGravity", "bool", "1"),
            _Field("m_IsKinematic", "bool", "0"),
            _Field("m_Interpolate", "int", "0"),
            _Field("m_Constraints", "int", "0"),
            _Field("m_CollisionDetection", "int", "0"),
        ),
    ),
    "SphereCollider": (
        135,
        _collider(_Field("m_Radius", "float", "0.5"), _CENTER, version="3"),
    ),
}

_LAYOUTS["MeshCollider"] = (
    64,
    _collider(*(_Field(*f) for f in MESH_COLLIDER_SHAPE), version="5"),
)
for _name, (_class_id, _fields) in MESH_LAYOUTS.items():
    _LAYOUTS[_name] = (_class_id, tuple(_Field(*f) for f in _fields))

#: The classes a manifest may declare, sorted.
BUILTIN_TYPES = tuple(sorted(_LAYOUTS))

#: Classes the URDF import writes that a manifest cannot declare (yet): the joints.
_IMPORTED_LAYOUTS = {
    name: (class_id, tuple(_Field(*f) for f in fields))
    for name, (class_id, fields) in JOINT_LAYOUTS.items()
}


@dataclass(frozen=True, slots=True)
class BuiltinClass:
    """One built-in component class: its class ID, new body and the fields a manifest may set."""

    name: str
    class_id: int
    fields: tuple[CatalogField, ...]  # settable ones, ``unity`` is their kind
    body: str  # the lines after m_GameObject of a new component, each ending in a line break

    def kind(self, field: str) -> str | None:
        return next((f.unity for f in self.fields if f.name == field), None)


def builtin_class(name: str, *, imported: bool = False) -> BuiltinClass | None:
    """The built-in class ``name`` (``Camera``), or None if the manifest cannot declare it;
    with ``imported``, also the classes only the URDF import writes (``HingeJoint``)."""
    layout = _LAYOUTS.get(name) or (_IMPORTED_LAYOUTS.get(name) if imported else None)
    if layout is None:
        return None
    class_id, fields = layout
    body = "".join(f"  {f.name}: {f.default}\n".replace(": \n", ":\n") for f in fields)
    settable = tuple(
        CatalogField(f.name, f.kind, f.kind)
        for f in fields
        if f.kind not in ("block", "fixed", "asset")
    )
    return BuiltinClass(name, class_id, settable, body)


def layer_number(name: str) -> int | None:
    """The number of a built-in layer (``UI`` → 5), or None."""
    return _LAYER_NUMBERS.get(name)
