"""The changes of an instance as Unity keeps them: ordered by their target's fileID, whatever
the order the objects were changed in (two Unity-written files, whose roots' names fall on
either side of their Transforms' changes), and a material set on a renderer, written as Unity
wrote one on a model's root renderer in a 2022.3 project:
https://github.com/Alex144xD/Tesis/blob/192ed1288408b9cd726f4ec82027b9c6a61b4448/Assets/Cristal/crystal%20Rojo.prefab
(root Transform changes, then ``m_Materials.Array.data[0]`` on ``-7511558181221131132`` with an
empty ``value:`` and the ``.mat`` as ``objectReference``, then the root's ``m_Name``)."""

from __future__ import annotations

import re

from helpers import require
from robot_helpers import R2D2

from unityscaffold.unity.modelids import ROOT_PATH, model_file_id
from unityscaffold.unity.prefabinstance import (
    AssetObject,
    ModelInstance,
    Modification,
    in_unity_order,
    instance_documents,
    material_modifications,
    root_modifications,
)

from .conftest import DATA

COMPLETED = R2D2 / "Scenes/Completed/gazebo_simulation_scene_ROS2_1_Camera_COMPLETED.unity"
SUITE = DATA / "ros-tcp-connector" / "EmptyVisualizationSuite.prefab"
CHANGE = re.compile(
    r"    - target: \{fileID: (-?\d+), guid: \w+, type: 3\}\n"
    r"      propertyPath: (.*)\n      value: (.*)\n      objectReference: .*\n"
)
TRANSFORM = model_file_id("Transform", ROOT_PATH)
GAMEOBJECT = model_file_id("GameObject", ROOT_PATH)
RENDERER = model_file_id("MeshRenderer", ROOT_PATH)


def changes(text: str) -> list[tuple[Modification, ...]]:
    """Each PrefabInstance's changes, in the order the file holds them."""
    found = []
    for block in re.findall(r"    m_Modifications:\n((?:    - .*\n(?:      .*\n)*)*)", text):
        found.append(tuple(Modification(int(t), p, v) for t, p, v in CHANGE.findall(block)))
    return [f for f in found if f]


def test_unity_keeps_an_instance_s_changes_by_their_target_s_file_id() -> None:
    require(COMPLETED.is_file(), f"ROS#'s r2d2 sample scene ({COMPLETED})")
    models = changes(COMPLETED.read_text(encoding="utf-8"))
    (suite,) = changes(SUITE.read_text(encoding="utf-8"))
    assert len(models) == 8
    for kept in (*models, suite):
        assert in_unity_order(kept) == kept
    # made in the same way (a root placed, then named), yet the name is last in one, first in
    # the other: the order is the targets', not the order the changes were made in
    assert [c.property_path for c in models[0]][-1] == "m_Name"
    assert suite[0].property_path == "m_Name" and suite[0].target < suite[1].target
    assert models[0][0].target < models[0][-1].target


def test_a_material_on_a_model_s_renderer_is_written_between_its_transform_and_its_name() -> None:
    material = AssetObject("Materials/red.mat", 2100000, 2)
    root = root_modifications(TRANSFORM, GAMEOBJECT, "arm", (0.0, 0.0, 0.0), (0, 0, 0, 1))
    instance = ModelInstance("arm.dae", 3, TRANSFORM, root).with_changes(
        material_modifications((RENDERER,), material)
    )
    guids = {"arm.dae": "a" * 32, "Materials/red.mat": "b" * 32}
    ((_, text), _) = instance_documents(
        instance, parent=7, ids={"instance": 5, "transform": 6}, guid_of=guids.__getitem__
    )
    model = "guid: " + "a" * 32 + ", type: 3}"
    assert (
        f"      propertyPath: m_LocalEulerAnglesHint.z\n      value: 0\n"
        "      objectReference: {fileID: 0}\n"
        f"    - target: {{fileID: -7511558181221131132, {model}\n"
        "      propertyPath: m_Materials.Array.data[0]\n      value: \n"
        f"      objectReference: {{fileID: 2100000, guid: {'b' * 32}, type: 2}}\n"
        f"    - target: {{fileID: 919132149155446097, {model}\n"
        "      propertyPath: m_Name\n      value: arm\n"
    ) in text


def test_a_renderer_s_changes_come_after_the_instance_s_own_on_the_same_target() -> None:
    """Sorted by target only: each target's changes stay in the order they were made."""
    made = (
        Modification(2, "m_Name", "b"),
        Modification(1, "m_LocalPosition.x", "0"),
        Modification(2, "m_IsActive", "0"),
        Modification(1, "m_LocalEulerAnglesHint.x", "0"),
    )
    assert [(c.target, c.property_path) for c in in_unity_order(made)] == [
        (1, "m_LocalPosition.x"),
        (1, "m_LocalEulerAnglesHint.x"),
        (2, "m_Name"),
        (2, "m_IsActive"),
    ]
