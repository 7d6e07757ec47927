"""The ConfigurableJoint ROS#'s importer gives a prismatic, planar or floating joint.

ROS# adds these (``UrdfJointPrismatic/Planar/Floating.Create`` and ``ImportJointData``) when
both links have an ``<inertial>``; what they set, on top of a new ConfigurableJoint (layout:
``unity/_joint_layouts.py``):

- every joint: the parent link's Rigidbody as connected body, the connected anchor configured
  automatically (``UrdfJoint.AddCorrectJointType``);
- prismatic: the axis (ROS→Unity, ``(-1, 0, 0)`` without ``<axis>``), x motion Limited and the
  five others Locked, with ``<dynamics>`` an x drive of spring = friction, damper = damping and
  ``float.MaxValue`` as its force; a PrismaticJointLimitsManager holding ``<limit>``'s lower and
  upper as floats (it limits the joint at run time: the ConfigurableJoint's own linear limit
  stays a new joint's);
- floating: nothing more (all six motions stay Free);
- planar: the axis and secondary axis ``Vector3.OrthoNormalize`` makes of the joint's normal,
  ``forward`` and ``left``, x and y motion Free, the rest Locked, x and y drives from
  ``<dynamics>`` and a linear limit of ``<limit upper>``. Only a normal along the URDF's z axis
  (Unity's y) is imported: OrthoNormalize then leaves forward and left as they are, whatever
  Unity's float arithmetic; any other normal (ROS#'s default ``(-1, 0, 0)`` among them) is
  refused at its joint (no Unity-written planar joint checks what Unity picks then).
"""

from __future__ import annotations

import math

from unityscaffold.errors import DiagnosticSink
from unityscaffold.unity.values import FieldValue, InlineMap
from unityscaffold.urdf import transforms as t
from unityscaffold.urdf.model import Dynamics, Joint, JointType, Robot, Vector3

__all__ = ["fields", "limits", "refuse_unchecked_joints"]

_FREE, _LIMITED, _LOCKED = 2, 1, 0
_MOTIONS = ("X", "Y", "Z", "AngularX", "AngularY", "AngularZ")
_FLOAT_MAX = 3.4028234663852886e38  # C#'s float.MaxValue, which ROS# gives a drive's force
# what OrthoNormalize leaves of Vector3.forward and Vector3.left for a normal along Unity's y
_PLANE_AXES = ((0.0, 0.0, 1.0), (-1.0, 0.0, 0.0))
Fields = tuple[tuple[str, FieldValue], ...]


def fields(joint: Joint) -> Fields:
    """What ROS#'s ``ImportJointData`` sets on ``joint``'s ConfigurableJoint (besides the
    connected body and anchor every joint gets), in Unity's order."""
    if joint.type is JointType.FLOATING:
        return ()
    if joint.type is JointType.PRISMATIC:
        axes: Fields = (("m_Axis", _vector(t.unity_axis(joint.axis))),)
        motions = (_LIMITED, _LOCKED, _LOCKED, _LOCKED, _LOCKED, _LOCKED)
        drives: tuple[str, ...] = ("m_XDrive",)
    else:  # planar, with a normal refuse_unchecked_joints let through
        axis, secondary = _PLANE_AXES
        axes = (("m_Axis", _vector(axis)), ("m_SecondaryAxis", _vector(secondary)))
        motions = (_FREE, _FREE, _LOCKED, _LOCKED, _LOCKED, _LOCKED)
        drives = ("m_XDrive", "m_YDrive")
    found: list[tuple[str, FieldValue]] = list(axes)
    found += [(f"m_{name}Motion", m) for name, m in zip(_MOTIONS, motions, strict=True)]
    if joint.type is JointType.PLANAR and joint.limit is not None:
        limit = {"limit": t.f32(joint.limit.upper), "bounciness": 0.0, "contactDistance": 0.0}
        found.append(("m_LinearLimit", limit))
    if joint.dynamics is not None:
        found += [(name, _drive(joint.dynamics)) for name in drives]
    return tuple(found)


def limits(joint: Joint) -> Fields:
    """PrismaticJointLimitsManager's fields: ``InitializeLimits`` copies lower and upper (no
    ordering: ``OnValidate`` runs only when the inspector changes a value)."""
    tolerance = ("Tolerance", t.f32(0.01))
    if joint.limit is None:
        return (tolerance,)
    return (
        ("PositionLimitMin", t.f32(joint.limit.lower)),
        ("PositionLimitMax", t.f32(joint.limit.upper)),
        tolerance,
    )


def refuse_unchecked_joints(robot: Robot) -> None:
    """Raise one located error naming every planar joint that gets a ConfigurableJoint and
    whose normal is not along the URDF's z axis."""
    inertial: dict[str, bool] = {}
    for link in robot.links:
        inertial.setdefault(link.name, link.inertial is not None)  # ROS# finds the first
    sink = DiagnosticSink()
    for joint in robot.joints:
        if joint.type is not JointType.PLANAR:
            continue
        if not (inertial.get(joint.child) and inertial.get(joint.parent)):
            continue  # ROS# adds no Unity joint
        if not _along_unity_y(t.unity_axis(joint.axis)):
            sink.error(
                joint.location,
                f"planar joint {joint.name!r} has a normal ({_text(joint.axis)}) that is not "
                "along the URDF's z axis: the ConfigurableJoint axes ROS# derives from it with "
                "Unity's Vector3.OrthoNormalize are not checked against Unity for such a normal",
                hint='give it <axis xyz="0 0 1"/> (motion in the xy plane), or leave the child '
                "link without <inertial> (ROS# then adds no Unity joint)",
            )
    sink.raise_if_errors()


def _along_unity_y(normal: Vector3) -> bool:
    """Whether ``Vector3.OrthoNormalize(ref normal, ref forward, ref left)`` is exact: for a
    normal along Unity's y axis (the URDF's z) forward and left are already unit vectors
    orthogonal to it and to each other, and come out unchanged. Along x or z, left or forward
    is cancelled and Unity picks some other vector: not checked."""
    x, y, z = normal
    return x == 0 and z == 0 and y != 0 and not math.isnan(y)


def _drive(dynamics: Dynamics) -> dict[str, FieldValue]:
    return {
        "serializedVersion": 4,
        "positionSpring": t.f32(dynamics.friction),
        "positionDamper": t.f32(dynamics.damping),
        "maximumForce": t.f32(_FLOAT_MAX),
        "useAcceleration": False,
    }


def _vector(v: Vector3) -> InlineMap:
    return InlineMap.of(x=v[0], y=v[1], z=v[2])


def _text(axis: Vector3 | None) -> str:
    return "none: ROS#'s default" if axis is None else " ".join(f"{v:g}" for v in axis)
