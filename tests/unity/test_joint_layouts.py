"""A new ConfigurableJoint as Unity 2022.3 serializes it, checked against the facts of a
Unity-written scene (no such file is vendored here, so its facts are restated below).

Reference: the ConfigurableJoint of the GameObject ``free_hinge_z`` in
https://github.com/Unity-Technologies/EntityComponentSystemSamples/blob/ac4a787d28b466b5e278b0ecf7a42b3d2aa2f05b/PhysicsSamples/Assets/Tests/JointTest/ConfigurableJoint/ConfigurableJointConversionZooSub.unity
(28 ConfigurableJoints share its keys and nesting; its other documents have the layouts of
Unity 2022.3's r2d2 scene). Its authors changed the anchor and the six motions (a hinge about
z); every other value is the one below.
"""

from __future__ import annotations

import yaml

from unityscaffold.unity.builtins import builtin_class

# (key, value) in the order of the reference document, after m_GameObject; a nested
# mapping is a tuple of its own (key, value) pairs
_SPRING = (("spring", 0), ("damper", 0))
_LIMIT = (("limit", 0), ("bounciness", 0), ("contactDistance", 0))
_DRIVE = (
    ("serializedVersion", 4),
    ("positionSpring", 0),
    ("positionDamper", 0),
    ("maximumForce", 3.4028233e38),
    ("useAcceleration", 0),
)
_ORIGIN = {"x": 0, "y": 0, "z": 0}
REFERENCE = (
    ("m_ConnectedBody", {"fileID": 0}),
    ("m_ConnectedArticulationBody", {"fileID": 0}),
    ("m_Anchor", {"x": -1.47, "y": 0, "z": 0}),
    ("m_Axis", {"x": 1, "y": 0, "z": 0}),
    ("m_AutoConfigureConnectedAnchor", 1),
    ("m_ConnectedAnchor", _ORIGIN),
    ("serializedVersion", 3),
    ("m_SecondaryAxis", {"x": 0, "y": 1, "z": 0}),
    ("m_XMotion", 0),
    ("m_YMotion", 0),
    ("m_ZMotion", 0),
    ("m_AngularXMotion", 0),
    ("m_AngularYMotion", 0),
    ("m_AngularZMotion", 2),
    ("m_LinearLimitSpring", _SPRING),
    ("m_LinearLimit", _LIMIT),
    ("m_AngularXLimitSpring", _SPRING),
    ("m_LowAngularXLimit", _LIMIT),
    ("m_HighAngularXLimit", _LIMIT),
    ("m_AngularYZLimitSpring", _SPRING),
    ("m_AngularYLimit", _LIMIT),
    ("m_AngularZLimit", _LIMIT),
    ("m_TargetPosition", _ORIGIN),
    ("m_TargetVelocity", _ORIGIN),
    ("m_XDrive", _DRIVE),
    ("m_YDrive", _DRIVE),
    ("m_ZDrive", _DRIVE),
    ("m_TargetRotation", {"x": 0, "y": 0, "z": 0, "w": 1}),
    ("m_TargetAngularVelocity", _ORIGIN),
    ("m_RotationDriveMode", 0),
    ("m_AngularXDrive", _DRIVE),
    ("m_AngularYZDrive", _DRIVE),
    ("m_SlerpDrive", _DRIVE),
    ("m_ProjectionMode", 0),
    ("m_ProjectionDistance", 1),
    ("m_ProjectionAngle", 180),
    ("m_ConfiguredInWorldSpace", 0),
    ("m_SwapBodies", 0),
    ("m_BreakForce", float("inf")),
    ("m_BreakTorque", float("inf")),
    ("m_EnableCollision", 0),
    ("m_EnablePreprocessing", 1),
    ("m_MassScale", 1),
    ("m_ConnectedMassScale", 1),
)
# what the reference's authors changed, as a new joint has them (Unity's defaults: no anchor,
# every motion Free, as on the reference's other joints)
NEW = {
    "m_Anchor": _ORIGIN,
    **{f"m_{axis}Motion": 2 for axis in ("X", "Y", "Z", "AngularX", "AngularY", "AngularZ")},
}


def _pairs(node: yaml.Node) -> object:
    """A YAML node as (key, value) pairs in document order, scalars as numbers."""
    if isinstance(node, yaml.MappingNode):
        if node.flow_style:
            return {k.value: _number(v.value) for k, v in node.value}
        return tuple((k.value, _pairs(v)) for k, v in node.value)
    assert isinstance(node, yaml.ScalarNode)
    return _number(node.value)


def _number(text: str) -> object:
    if text == "Infinity":
        return float("inf")
    number = float(text)
    return int(number) if number.is_integer() and "e" not in text else number


def test_a_new_configurable_joint_has_the_keys_nesting_and_defaults_unity_writes() -> None:
    joint = builtin_class("ConfigurableJoint", imported=True)
    assert joint is not None and joint.class_id == 153
    written = _pairs(yaml.compose(joint.body))
    expected = tuple((key, NEW.get(key, value)) for key, value in REFERENCE)
    assert [key for key, _ in written] == [key for key, _ in REFERENCE]  # type: ignore[union-attr]
    assert written == expected
