"""The components ROS#'s importer adds to each GameObject, with the fields it sets.

Only what the importer sets is listed; every other serialized field keeps the value a new
component gets in the editor (the writer's layouts). Numbers are float32 as ROS# computes them
(C# casts to ``float`` before the arithmetic). References to objects the import makes are
symbolic (``ComponentRef``, ``MaterialRef``, ``CYLINDER_MESH``): the writer turns them into
fileIDs and GUIDs.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TypeAlias

from unityscaffold.unity.values import AssetRef, Enum, FieldValue, InlineMap
from unityscaffold.urdf import _configurable as c
from unityscaffold.urdf import transforms as t
from unityscaffold.urdf._inertia import principal_axes
from unityscaffold.urdf.model import (
    Box,
    Cylinder,
    Geometry,
    Inertial,
    Joint,
    JointType,
    Link,
    Material,
    Mesh,
    Sphere,
    Vector3,
)

__all__ = [
    "CYLINDER_MESH",
    "DEFAULT_MATERIAL",
    "ComponentRef",
    "ImportedComponent",
    "MaterialRef",
    "Value",
    "geometry_components",
    "joint_components",
    "link_components",
    "material_name",
    "part_components",
    "plugin_components",
]


@dataclass(frozen=True, slots=True)
class ComponentRef:
    """The component of class ``component`` on the imported object ``key``."""

    key: str
    component: str


@dataclass(frozen=True, slots=True)
class MaterialRef:
    """``Materials/<name>.mat`` in the robot's asset folder (ROS#'s ``UrdfMaterial``): ``name``
    is the file's, which ``urdf._material_names`` makes of the material's."""

    name: str

    @property
    def path(self) -> str:
        """The ``.mat`` file's path in the robot's asset folder."""
        return f"Materials/{self.name}.mat"


@dataclass(frozen=True, slots=True)
class _CylinderMesh:
    """The Mesh ROS# makes in code for a cylinder collider (one per collider, in the scene)."""


CYLINDER_MESH = _CylinderMesh()
Value: TypeAlias = FieldValue | ComponentRef | MaterialRef | _CylinderMesh | Sequence["Value"]


@dataclass(frozen=True, slots=True)
class ImportedComponent:
    """A component class (``HingeJoint``, ``UrdfLink``) and the fields the importer sets."""

    name: str
    fields: tuple[tuple[str, Value], ...] = ()

    def field(self, name: str) -> Value | None:
        return next((v for k, v in self.fields if k == name), None)


_PRIMITIVES = "0000000000000000e000000000000000"  # Unity's built-in meshes
_BUILTIN_EXTRA = "0000000000000000f000000000000000"  # its built-in materials and shaders
_PRIMITIVE_MESHES = {Box: 10202, Cylinder: 10206, Sphere: 10207}
DEFAULT_MATERIAL = AssetRef(10303, _BUILTIN_EXTRA, 0)  # what CreatePrimitive's renderer has
_GEOMETRY_TYPE = {Box: 0, Cylinder: 1, Sphere: 2, Mesh: 3}
_JOINT_TYPE = {
    JointType.FIXED: 0,
    JointType.CONTINUOUS: 1,
    JointType.REVOLUTE: 2,
    JointType.FLOATING: 3,
    JointType.PRISMATIC: 4,
    JointType.PLANAR: 5,
}
_JOINT_SCRIPT = {
    JointType.FIXED: "UrdfJointFixed",
    JointType.CONTINUOUS: "UrdfJointContinuous",
    JointType.REVOLUTE: "UrdfJointRevolute",
    JointType.FLOATING: "UrdfJointFloating",
    JointType.PRISMATIC: "UrdfJointPrismatic",
    JointType.PLANAR: "UrdfJointPlanar",
}
_MIN_INERTIA = t.f32(1e-6)


def _vector(v: Vector3) -> InlineMap:
    return InlineMap.of(x=v[0], y=v[1], z=v[2])


def _quaternion(q: t.Quaternion) -> InlineMap:
    return InlineMap.of(x=q[0], y=q[1], z=q[2], w=q[3])


def link_components(link: Link, key: str, *, has_joint: bool) -> list[ImportedComponent]:
    """UrdfLink, and Rigidbody and UrdfInertial for a link with an ``<inertial>``."""
    base = link.inertial is None and not has_joint
    found = [ImportedComponent("UrdfLink", (("IsBaseLink", base),))]
    if link.inertial is not None:
        found += _inertial_components(link.inertial, key)
    return found


def _inertial_components(inertial: Inertial, key: str) -> list[ImportedComponent]:
    mass = t.f32(inertial.mass)
    centre = _vector(t.origin_position(inertial.origin) if inertial.origin else (0.0, 0.0, 0.0))
    tensor, rotation = _principal_inertia(inertial)
    body = (
        ("m_Mass", mass),
        ("m_CenterOfMass", centre),
        ("m_InertiaTensor", tensor),
        ("m_InertiaRotation", rotation),
        ("m_ImplicitCom", False),
        ("m_ImplicitTensor", False),
    )
    values: tuple[tuple[str, Value], ...] = (
        ("Mass", mass),
        ("CenterOfMass", centre),
        ("InertiaTensor", tensor),
        ("InertiaTensorRotation", rotation),
    )
    script: tuple[tuple[str, Value], ...] = (
        ("_rigidbody", ComponentRef(key, "Rigidbody")),
        ("DisplayInertiaGizmo", False),
        ("rigidbodyDataSource", Enum(0)),  # RigidbodyDataSource.Urdf
        *values,
        *((f"Urdf{name}", value) for name, value in values),
    )
    return [ImportedComponent("Rigidbody", body), ImportedComponent("UrdfInertial", script)]


def _principal_inertia(inertial: Inertial) -> tuple[InlineMap, InlineMap]:
    """The inertia tensor's principal moments (Unity's axes, each at least ROS#'s 1e-6) and
    the rotation of the principal axes (``_inertia``, then ROS→Unity: ``(y, -z, -x, w)``)."""
    i = inertial.inertia
    xx, xy, xz, yy, yz, zz = (t.f32(v) for v in (i.ixx, i.ixy, i.ixz, i.iyy, i.iyz, i.izz))
    values, (qx, qy, qz, qw) = principal_axes(((xx, xy, xz), (xy, yy, yz), (xz, yz, zz)))
    x, y, z = (max(v, _MIN_INERTIA) for v in values)
    return _vector((y, z, x)), _quaternion((qy, -qz, -qx, qw))


def joint_components(joint: Joint, key: str, parent_key: str) -> list[ImportedComponent]:
    """The joint script and Unity joint ROS# adds for ``joint`` (both links have a Rigidbody)."""
    script = ImportedComponent(
        _JOINT_SCRIPT[joint.type],
        (
            ("JointName", joint.name),
            ("_jointType", Enum(_JOINT_TYPE[joint.type])),
            ("EffortLimit", 1000.0),  # ROS#'s defaults: the URDF's <limit> is not used here
            ("VelocityLimit", 1000.0),
        ),
    )
    connected: tuple[tuple[str, Value], ...] = (
        ("m_ConnectedBody", ComponentRef(parent_key, "Rigidbody")),
        ("m_AutoConfigureConnectedAnchor", True),
    )
    if joint.type is JointType.FIXED:  # a FixedJoint serializes no anchors
        return [script, ImportedComponent("FixedJoint", connected[:1])]
    if joint.type not in (JointType.REVOLUTE, JointType.CONTINUOUS):  # see _configurable
        found = [script, ImportedComponent("ConfigurableJoint", (*connected, *c.fields(joint)))]
        if joint.type is JointType.PRISMATIC:
            found.append(ImportedComponent("PrismaticJointLimitsManager", c.limits(joint)))
        return found
    # in Unity's order of HingeJoint's fields
    hinge: list[tuple[str, Value]] = [
        ("m_ConnectedBody", ComponentRef(parent_key, "Rigidbody")),
        ("m_Axis", _vector(t.unity_axis(joint.axis))),
        ("m_AutoConfigureConnectedAnchor", True),
    ]
    if joint.dynamics is not None:
        spring = {
            "spring": t.f32(joint.dynamics.friction),
            "damper": t.f32(joint.dynamics.damping),
            "targetPosition": 0.0,
        }
        hinge.append(("m_Spring", spring))
    if joint.type is JointType.CONTINUOUS:
        hinge_joint = ImportedComponent("HingeJoint", tuple(hinge))
        return [script, hinge_joint, ImportedComponent("HingeJointAngleCalculator")]
    limits, manager = _hinge_limits(joint)
    hinge_joint = ImportedComponent("HingeJoint", (*hinge, *limits))
    return [script, hinge_joint, manager, ImportedComponent("HingeJointAngleCalculator")]


def _hinge_limits(joint: Joint) -> tuple[list[tuple[str, Value]], ImportedComponent]:
    """HingeJointLimitsManager's large limits and the HingeJoint limits it applies at once."""
    fields: list[tuple[str, Value]] = []
    if joint.limit is None:
        return fields, ImportedComponent("HingeJointLimitsManager", (("Tolerance", 5.0),))
    # (float)upper * -1.0f * Mathf.Rad2Deg: a rotation about the axis turns the other way
    large_min = t.f32(t.f32(-t.f32(joint.limit.upper)) * t.RAD2DEG)
    large_max = t.f32(t.f32(-t.f32(joint.limit.lower)) * t.RAD2DEG)
    if large_max < large_min:  # ROS# keeps the limits ordered
        large_min = large_max
    applied = _applied_limits(large_min, large_max)
    if applied is None:
        fields.append(("m_UseLimits", False))
    else:
        fields += [("m_UseLimits", True), ("m_Limits", {"min": applied[0], "max": applied[1]})]
    manager = ImportedComponent(
        "HingeJointLimitsManager",
        (("LargeAngleLimitMin", large_min), ("LargeAngleLimitMax", large_max), ("Tolerance", 5.0)),
    )
    return fields, manager


def _applied_limits(large_min: float, large_max: float) -> tuple[float, float] | None:
    """What ``HingeJointLimitsManager.RecalculateJointLimits`` gives a new joint (angle 0,
    rotation 0): the limits within one turn, or None when it switches limits off."""
    angle_min, turns_min = _angle_limit(large_min), _rotations(large_min)
    angle_max, turns_max = _angle_limit(large_max), _rotations(large_max)
    tolerance = 5.0
    if large_min < 0 and 180 - angle_min < tolerance:
        angle_min, turns_min = -180.0, turns_min + 1
    elif large_min > 0 and 180 + angle_min < tolerance:
        angle_min, turns_min = 180.0, turns_min - 1
    if large_max > 0 and 180 + angle_max < tolerance:
        angle_max, turns_max = 180.0, turns_max - 1
    elif large_max < 0 and 180 - angle_max < tolerance:
        angle_max, turns_max = -180.0, turns_max + 1
    if turns_min == 0 and turns_max == 0:
        return angle_min, angle_max
    if turns_min == 0 and 0 - angle_min <= tolerance:
        return angle_min, 180.0
    if turns_max == 0 and angle_max - 0 <= tolerance:
        return -180.0, angle_max
    return None


def _angle_limit(large: float) -> float:
    """C#'s ``((x ± 180) % 360) ∓ 180`` in float32 (C#'s % keeps the dividend's sign)."""
    if large > 0:
        return t.f32(t.f32(math.fmod(t.f32(large + 180), 360)) - 180)
    return t.f32(t.f32(math.fmod(t.f32(large - 180), 360)) + 180)


def _rotations(large: float) -> int:
    if math.isnan(large):  # an absent <limit> bound: C#'s (int)NaN on x86
        return -(2**31)
    return int(t.f32(large + 180) / 360) if large > 0 else int(t.f32(large - 180) / 360)


def part_components(geometry: Geometry, *, visual: bool) -> list[ImportedComponent]:
    """UrdfVisual or UrdfCollision with its ``GeometryType``."""
    kind = Enum(_GEOMETRY_TYPE[type(geometry)])
    return [
        ImportedComponent("UrdfVisual" if visual else "UrdfCollision", (("GeometryType", kind),))
    ]


def geometry_components(
    geometry: Geometry, material: MaterialRef | None, *, visual: bool
) -> list[ImportedComponent]:
    """A primitive's renderer (with the visual's ``material``) or a collider (a mesh's model
    instance has none of its own)."""
    if isinstance(geometry, Mesh):
        return []
    if visual:
        mesh = AssetRef(_PRIMITIVE_MESHES[type(geometry)], _PRIMITIVES, 0)
        chosen: Value = DEFAULT_MATERIAL if material is None else material
        return [
            ImportedComponent("MeshFilter", (("m_Mesh", mesh),)),
            # CreatePrimitive called from an editor script leaves the renderer's UVs preserved
            # (the GameObject menu's primitives have 0)
            ImportedComponent("MeshRenderer", (("m_Materials", [chosen]), ("m_PreserveUVs", True))),
        ]
    if isinstance(geometry, Cylinder):
        return [ImportedComponent("MeshCollider", (("m_Convex", True), ("m_Mesh", CYLINDER_MESH)))]
    return [ImportedComponent("BoxCollider" if isinstance(geometry, Box) else "SphereCollider")]


def material_name(material: Material) -> str:
    """The ``.mat`` name ROS# uses: the material's name, or one made from its colour or texture."""
    if material.name:
        return material.name
    if material.color is not None:
        return "rgba-" + "-".join(_number(v) for v in material.color)
    if material.texture is not None:
        return "texture-" + material.texture.replace("\\", "/").rsplit("/", 1)[-1]
    return ""


def _number(value: float) -> str:
    """C#'s ``double.ToString()`` for the usual colour components (``1``, ``0.8``)."""
    return str(int(value)) if value == int(value) else repr(value)


def plugin_components(texts: Sequence[str]) -> list[ImportedComponent]:
    """UrdfPlugins, and one UrdfPlugin per plugin element with its text."""
    plugins = [ImportedComponent("UrdfPlugin", (("PluginText", text),)) for text in texts]
    return [ImportedComponent("UrdfPlugins"), *plugins]
