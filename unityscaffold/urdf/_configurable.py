"""Joints ROS# makes a ConfigurableJoint for, which the import refuses for now.

ROS# gives a prismatic, planar or floating joint a ConfigurableJoint (and a prismatic one a
PrismaticJointLimitsManager) when both its links have an ``<inertial>``. No scene Unity 2022.3
saved with a ConfigurableJoint is at hand to check its serialized layout against, so rather
than write one Unity might read differently, each such joint is a located error. A joint whose
child (or parent) link has no ``<inertial>`` gets no Unity joint from ROS# and is imported.
"""

from __future__ import annotations

from unityscaffold.errors import DiagnosticSink
from unityscaffold.urdf.model import JointType, Robot

__all__ = ["refuse_configurable_joints"]

_CONFIGURABLE = (JointType.PRISMATIC, JointType.PLANAR, JointType.FLOATING)


def refuse_configurable_joints(robot: Robot) -> None:
    """Raise one located error naming every joint that would need a ConfigurableJoint."""
    inertial: dict[str, bool] = {}
    for link in robot.links:
        inertial.setdefault(link.name, link.inertial is not None)  # ROS# finds the first
    sink = DiagnosticSink()
    for joint in robot.joints:
        if joint.type not in _CONFIGURABLE:
            continue
        if inertial.get(joint.child) and inertial.get(joint.parent):
            sink.error(
                joint.location,
                f"{joint.type.value} joint {joint.name!r} needs a ConfigurableJoint, which is "
                "not supported yet: no Unity-written scene with one is at hand to check its "
                "fields against",
                hint="make it a revolute, continuous or fixed joint, or leave the child "
                "link without <inertial> (ROS# then adds no Unity joint)",
            )
    sink.raise_if_errors()
