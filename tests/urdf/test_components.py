"""The fields ROS#'s importer sets on each component, checked against the r2d2 scene ROS#'s
importer built in Unity 2022.3, and rule by rule where the scene has no example."""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path

import pytest

from unityscaffold.unity import SceneDocument
from unityscaffold.unity._emit import value_equals
from unityscaffold.unity.catalog import rossharp_catalog
from unityscaffold.unity.meta import read_meta_guid
from unityscaffold.unity.setvalue import component_label
from unityscaffold.unity.values import AssetRef, FieldValue, InlineMap, ObjectRef
from unityscaffold.urdf import parse_urdf, read_urdf
from unityscaffold.urdf.objects import (
    CYLINDER_MESH,
    ComponentRef,
    ImportedObject,
    MaterialRef,
    Value,
    importer_tree,
)

from .test_objects import HAND_MADE


def _paired(scene: SceneDocument, tree: ImportedObject) -> dict[str, str]:
    """key → scene path of every imported object, walking both trees in step."""
    paths: dict[str, str] = {}

    def walk(obj: ImportedObject, path: str) -> None:
        paths[obj.key] = path
        go = scene.find_gameobject(path)
        if go.is_prefab_instance:
            return
        names = [c.name for c in scene.children(go) if f"{path}/{c.name}" not in HAND_MADE]
        assert names == [child.name for child in obj.children], path
        seen: dict[str, int] = {}
        for child in obj.children:
            index = seen[child.name] = seen.get(child.name, -1) + 1
            siblings = [c for c in scene.children(go) if c.name == child.name]
            walk(child, siblings[index].path)

    walk(tree, tree.name)
    return paths


class Resolver:
    """Turns the stage's symbolic references into what the scene holds."""

    def __init__(self, scene: SceneDocument, paths: dict[str, str], materials: Path) -> None:
        self.scene, self.paths, self.materials = scene, paths, materials
        self.names = rossharp_catalog().all_class_names()

    def component(self, path: str, name: str) -> int:
        components = self.scene.components_of(self.scene.find_gameobject(path))
        return next(c.file_id for c in components if component_label(c, self.names) == name)

    def value(self, value: Value) -> FieldValue:
        if isinstance(value, ComponentRef):
            return ObjectRef(self.component(self.paths[value.key], value.component))
        if isinstance(value, MaterialRef):
            guid = read_meta_guid(self.materials / f"{value.name}.mat.meta")
            assert guid is not None, value
            return AssetRef(2100000, guid, 2)
        if isinstance(value, list):
            return [self.value(item) for item in value]
        assert not isinstance(value, (ComponentRef, MaterialRef)) and value is not CYLINDER_MESH
        return value  # type: ignore[return-value]


def _same(stored: object, value: FieldValue) -> bool:
    """A partial struct (``m_Spring``'s spring and damper) compares key by key."""
    if isinstance(value, Mapping) and not isinstance(value, InlineMap):
        return isinstance(stored, dict) and all(_same(stored[k], v) for k, v in value.items())
    return value_equals(stored, value)


def test_every_field_the_importer_sets_is_the_value_in_the_scene(
    r2d2_urdf: Path, r2d2_scene: Path
) -> None:
    scene = SceneDocument.load(r2d2_scene)
    tree = importer_tree(read_urdf(r2d2_urdf))
    paths = _paired(scene, tree)
    resolver = Resolver(scene, paths, r2d2_urdf.parent / "Urdf" / "file_server2" / "Materials")
    checked = 0
    for _, obj in tree.walk():
        go = scene.find_gameobject(paths[obj.key])
        if go.is_prefab_instance:
            assert obj.components == ()
            continue
        stored = scene.components_of(go)[1:]  # after the Transform
        assert [component_label(c, resolver.names) for c in stored] == obj.component_names
        for component, ours in zip(stored, obj.components, strict=True):
            for name, value in ours.fields:
                found = scene.field(component, name)
                if value is CYLINDER_MESH:
                    assert isinstance(found, dict), name
                    mesh = scene.document(int(found["fileID"]))
                    assert mesh is not None and mesh.class_id == 43
                else:
                    assert _same(found, resolver.value(value)), (go.path, ours.name, name, found)
                checked += 1
    assert checked == 472  # with the 12 primitive renderers' m_PreserveUVs


def _revolute(lower: str, upper: str) -> ImportedObject:
    limit = f'<limit effort="1" velocity="1" lower="{lower}" upper="{upper}"/>' if upper else ""
    inertial = (
        '<inertial><mass value="1"/>'
        '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'
    )
    robot = parse_urdf(
        f'<robot name="r"><link name="p">{inertial}</link><link name="c">{inertial}</link>'
        f'<joint name="j" type="revolute"><parent link="p"/><child link="c"/>{limit}</joint>'
        "</robot>".encode()
    )
    return importer_tree(robot).children[1].children[2]


@pytest.mark.parametrize(
    ("lower", "upper", "use", "limits"),
    [
        ("0", "0.548", True, (-31.398087, 0.0)),
        ("-1.5", "1.5", True, (-85.943665, 85.943665)),
        # past half a turn on both sides: the manager leaves the limits off at angle 0
        ("-4", "4", False, None),
        ("-3.1", "0.05", True, (-2.8647919, 177.61691)),
        # past half a turn on one side: limited on the near side only
        ("-3.2", "0.05", True, (-2.8647919, 180.0)),
    ],
)
def test_revolute_limits_are_what_rossharps_limits_manager_applies_at_import(
    lower: str, upper: str, use: bool, limits: tuple[float, float] | None
) -> None:
    hinge = next(c for c in _revolute(lower, upper).components if c.name == "HingeJoint")
    assert hinge.field("m_UseLimits") is use
    if limits is None:
        assert hinge.field("m_Limits") is None
    else:
        applied = hinge.field("m_Limits")
        assert isinstance(applied, dict)
        assert (applied["min"], applied["max"]) == pytest.approx(limits)


def test_a_revolute_joint_without_limit_gets_only_the_managers_tolerance() -> None:
    link = _revolute("", "")
    manager = next(c for c in link.components if c.name == "HingeJointLimitsManager")
    assert manager.fields == (("Tolerance", 5.0),)


def test_a_missing_axis_is_rossharps_default_and_missing_dynamics_leave_the_spring() -> None:
    hinge = next(c for c in _revolute("0", "1").components if c.name == "HingeJoint")
    axis = hinge.field("m_Axis")
    assert isinstance(axis, InlineMap) and axis.items == (("x", -1.0), ("y", 0.0), ("z", 0.0))
    assert hinge.field("m_Spring") is None


def test_a_non_diagonal_inertia_gets_its_principal_moments_in_unitys_axes() -> None:
    robot = parse_urdf(
        b'<robot name="r"><link name="p"><inertial><mass value="1"/>'
        b'<inertia ixx="2" ixy="1" ixz="0" iyy="2" iyz="0" izz="5"/></inertial></link></robot>'
    )
    body = importer_tree(robot).children[1].components[1]
    tensor, rotation = body.field("m_InertiaTensor"), body.field("m_InertiaRotation")
    assert isinstance(tensor, InlineMap) and isinstance(rotation, InlineMap)
    # ROS#'s order of Smith's eigenvalues (5, 1, 3), then (y, z, x)
    assert [v for _, v in tensor.items] == pytest.approx([1, 3, 5], abs=1e-6)
    assert [v for _, v in rotation.items] == pytest.approx(
        [0.27059802, -0.65328151, -0.65328139, -0.27059805], abs=1e-6
    )


def test_tiny_moments_are_raised_to_rossharps_minimum() -> None:
    robot = parse_urdf(
        b'<robot name="r"><link name="p"><inertial><mass value="1"/>'
        b'<inertia ixx="0" ixy="0" ixz="0" iyy="2e-7" iyz="0" izz="3"/></inertial></link></robot>'
    )
    body = importer_tree(robot).children[1].components[1]
    tensor = body.field("m_InertiaTensor")
    assert isinstance(tensor, InlineMap)
    assert [v for _, v in tensor.items] == pytest.approx([1e-6, 3.0, 1e-6])
    assert math.copysign(1, dict(tensor.items)["x"]) == 1
