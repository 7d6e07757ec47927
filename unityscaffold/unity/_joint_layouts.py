"""The physics joints only the URDF import writes, laid out as Unity 2022.3 serializes them.

Each layout lists the fields after ``m_GameObject`` in Unity's order, with what a new component
starts with; a field is ``(name, kind, default text)`` as in ``unity.builtins``.

- FixedJoint and HingeJoint: read off the scene Unity saved after ROS#'s importer built r2d2
  (siemens/ros-sharp, ``gazebo_simulation_scene_ROS2_1_Camera_COMPLETED.unity``).
- ConfigurableJoint: read off ``ConfigurableJointConversionZooSub.unity`` of
  https://github.com/Unity-Technologies/EntityComponentSystemSamples/blob/ac4a787d28b466b5e278b0ecf7a42b3d2aa2f05b/PhysicsSamples/Assets/Tests/JointTest/ConfigurableJoint/ConfigurableJointConversionZooSub.unity
  (28 ConfigurableJoints, all with this key order and these nested ``serializedVersion``\\ s;
  its Rigidbody, BoxCollider, MeshRenderer and Transform documents have the very fields of the
  2022.3 r2d2 scene's). The defaults are that file's values of the fields its joints leave
  alone; ``m_ProjectionDistance`` is 1 there while a 2018 ml-agents prefab has 0.1, so that one
  default is not pinned down (projection is off, ``m_ProjectionMode: 0``, and the import does
  not own the field).
"""

from __future__ import annotations

__all__ = ["JOINT_LAYOUTS"]

_Layout = tuple[int, tuple[tuple[str, str, str], ...]]

_TAIL = (
    ("m_BreakForce", "float", "Infinity"),
    ("m_BreakTorque", "float", "Infinity"),
    ("m_EnableCollision", "bool", "0"),
    ("m_EnablePreprocessing", "bool", "1"),
    ("m_MassScale", "float", "1"),
    ("m_ConnectedMassScale", "float", "1"),
)
_CONNECTED = (
    ("m_ConnectedBody", "ref:Rigidbody", "{fileID: 0}"),
    ("m_ConnectedArticulationBody", "asset", "{fileID: 0}"),
)
_ANCHORS = (
    ("m_Anchor", "Vector3", "{x: 0, y: 0, z: 0}"),
    ("m_Axis", "Vector3", "{x: 1, y: 0, z: 0}"),
    ("m_AutoConfigureConnectedAnchor", "bool", "1"),
    ("m_ConnectedAnchor", "Vector3", "{x: 0, y: 0, z: 0}"),
)
_ZERO = "{x: 0, y: 0, z: 0}"
_SPRING = "\n    spring: 0\n    damper: 0"
_LIMIT = "\n    limit: 0\n    bounciness: 0\n    contactDistance: 0"
# a new JointDrive: no spring, no damper, Unity's largest force (not float.MaxValue)
_DRIVE = (
    "\n    serializedVersion: 4\n    positionSpring: 0\n    positionDamper: 0"
    "\n    maximumForce: 3.4028233e+38\n    useAcceleration: 0"
)


def _motions() -> tuple[tuple[str, str, str], ...]:
    axes = ("X", "Y", "Z", "AngularX", "AngularY", "AngularZ")
    return tuple((f"m_{axis}Motion", "int", "2") for axis in axes)  # 2: Free


JOINT_LAYOUTS: dict[str, _Layout] = {
    "FixedJoint": (138, (*_CONNECTED, *_TAIL)),
    "HingeJoint": (
        59,
        (
            *_CONNECTED,
            *_ANCHORS,
            ("serializedVersion", "fixed", "2"),
            ("m_UseSpring", "bool", "0"),
            ("m_Spring", "block", "\n    spring: 0\n    damper: 0\n    targetPosition: 0"),
            ("m_UseMotor", "bool", "0"),
            ("m_Motor", "block", "\n    targetVelocity: 0\n    force: 0\n    freeSpin: 0"),
            ("m_UseLimits", "bool", "0"),
            ("m_ExtendedLimits", "bool", "0"),
            ("m_UseAcceleration", "bool", "0"),
            (
                "m_Limits",
                "block",
                "\n    min: 0\n    max: 0\n    bounciness: 0\n    bounceMinVelocity: 0.2"
                "\n    contactDistance: 0",
            ),
            *_TAIL,
        ),
    ),
    "ConfigurableJoint": (
        153,
        (
            *_CONNECTED,
            *_ANCHORS,
            ("serializedVersion", "fixed", "3"),
            ("m_SecondaryAxis", "Vector3", "{x: 0, y: 1, z: 0}"),
            *_motions(),
            ("m_LinearLimitSpring", "block", _SPRING),
            ("m_LinearLimit", "block", _LIMIT),
            ("m_AngularXLimitSpring", "block", _SPRING),
            ("m_LowAngularXLimit", "block", _LIMIT),
            ("m_HighAngularXLimit", "block", _LIMIT),
            ("m_AngularYZLimitSpring", "block", _SPRING),
            ("m_AngularYLimit", "block", _LIMIT),
            ("m_AngularZLimit", "block", _LIMIT),
            ("m_TargetPosition", "Vector3", _ZERO),
            ("m_TargetVelocity", "Vector3", _ZERO),
            ("m_XDrive", "block", _DRIVE),
            ("m_YDrive", "block", _DRIVE),
            ("m_ZDrive", "block", _DRIVE),
            ("m_TargetRotation", "Quaternion", "{x: 0, y: 0, z: 0, w: 1}"),
            ("m_TargetAngularVelocity", "Vector3", _ZERO),
            ("m_RotationDriveMode", "int", "0"),
            ("m_AngularXDrive", "block", _DRIVE),
            ("m_AngularYZDrive", "block", _DRIVE),
            ("m_SlerpDrive", "block", _DRIVE),
            ("m_ProjectionMode", "int", "0"),
            ("m_ProjectionDistance", "float", "1"),
            ("m_ProjectionAngle", "float", "180"),
            ("m_ConfiguredInWorldSpace", "bool", "0"),
            ("m_SwapBodies", "bool", "0"),
            *_TAIL,
        ),
    ),
}
