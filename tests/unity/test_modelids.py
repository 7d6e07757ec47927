"""Model objects' fileIDs: xxHash64 as specified, and the IDs a Unity 2022.3 scene holds for
the two COLLADA models ROS#'s r2d2 sample references."""

from __future__ import annotations

import re

import pytest
from helpers import require
from robot_helpers import R2D2

from unityscaffold.unity.meta import read_meta_guid
from unityscaffold.unity.modelids import (
    MODEL_PREFAB_FILE_ID,
    ROOT_PATH,
    model_file_id,
    xxhash64,
)


@pytest.mark.parametrize(
    ("data", "digest"),
    [
        (b"", 0xEF46DB3751D8E999),
        (b"a", 0xD24EC4F1A98C6E5B),
        (b"abc", 0x44BC2CF5AD770999),
        # 32 bytes and more take the four-lane path
        (b"Nobody inspects the spammish repetition", 0xFBCEA83C8A378BF1),
    ],
)
def test_xxhash64_gives_the_reference_digests(data: bytes, digest: int) -> None:
    assert xxhash64(data) == digest


def test_every_reference_of_the_scene_to_a_model_is_a_computed_id() -> None:
    scene = R2D2 / "Scenes/Completed/gazebo_simulation_scene_ROS2_1_Camera_COMPLETED.unity"
    require(scene.is_file(), f"ROS#'s r2d2 sample ({R2D2})")
    text = scene.read_text(encoding="utf-8")
    meshes = R2D2 / "Urdf/file_server2/urdf_tutorial/meshes"
    for model in ("l_finger.dae", "l_finger_tip.dae"):
        guid = read_meta_guid(meshes / f"{model}.meta")
        found = {int(i) for i in re.findall(rf"\{{fileID: (-?\d+), guid: {guid}, type: 3\}}", text)}
        # a model with one node: Unity folds it into the root, and names its mesh after it
        (node,) = re.findall(r'<node id="[^"]*" name="([^"]*)"', (meshes / model).read_text())
        computed = {
            MODEL_PREFAB_FILE_ID,
            model_file_id("GameObject", ROOT_PATH),
            model_file_id("Transform", ROOT_PATH),
            model_file_id("MeshFilter", ROOT_PATH),
            model_file_id("MeshRenderer", ROOT_PATH),
            model_file_id("Mesh", node),
        }
        assert found == computed, model
