"""Scenes the tool builds itself, from empty files of each serialization era (built-in layouts)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from unityscaffold.unity.scene import SceneDocument
from unityscaffold.unity.values import ObjectRef, ScriptRef

DATA = Path(__file__).resolve().parents[1] / "data" / "unity"
Check = Callable[[SceneDocument], None]
SCRIPT = ScriptRef("ff98778ae051cfd40a6e4effdf851ebd")

# Written by hand after docs/unity-yaml.md#eras (5.5-2018.2 layout): no real file of
# that era is in the corpus, so this pins the legacy layouts.
LEGACY = """%YAML 1.1
%TAG !u! tag:unity3d.com,2011:
--- !u!29 &1
OcclusionCullingSettings:
  m_ObjectHideFlags: 0
  serializedVersion: 2
--- !u!1 &100
GameObject:
  m_ObjectHideFlags: 0
  m_PrefabParentObject: {fileID: 0}
  m_PrefabInternal: {fileID: 0}
  serializedVersion: 5
  m_Component:
  - component: {fileID: 101}
  m_Layer: 0
  m_Name: Old
  m_TagString: Untagged
  m_Icon: {fileID: 0}
  m_NavMeshLayer: 0
  m_StaticEditorFlags: 0
  m_IsActive: 1
--- !u!4 &101
Transform:
  m_ObjectHideFlags: 0
  m_PrefabParentObject: {fileID: 0}
  m_PrefabInternal: {fileID: 0}
  m_GameObject: {fileID: 100}
  m_LocalRotation: {x: 0, y: 0, z: 0, w: 1}
  m_LocalPosition: {x: 0, y: 0, z: 0}
  m_LocalScale: {x: 1, y: 1, z: 1}
  m_Children: []
  m_Father: {fileID: 0}
  m_RootOrder: 0
  m_LocalEulerAnglesHint: {x: 0, y: 0, z: 0}
"""


def _empty_2022() -> str:
    text = (DATA / "ros-sharp" / "ROSVersionSwitch.unity").read_text()
    settings = text[: text.index("--- !u!1 &")].replace("{fileID: 705507994}", "{fileID: 0}")
    return settings + (
        "--- !u!1660057539 &9223372036854775807\nSceneRoots:\n"
        "  m_ObjectHideFlags: 0\n  m_Roots: []\n"
    )


BASES = {
    "empty-2020": (DATA / "ros-tcp-connector" / "SampleScene.unity").read_text(),
    "empty-2022": _empty_2022(),
    "legacy-2017": LEGACY,
}


def _build(scene: SceneDocument) -> None:
    robot = scene.ensure_gameobject("Robot/base_link/camera")
    connector = scene.ensure_component("Robot", SCRIPT, {"RosBridgeServerUrl": "ws://robot:9090"})
    scene.ensure_component(
        robot,
        ScriptRef("1" * 32),
        [
            ("Topic", "/camera/image"),
            ("Connector", ObjectRef(connector.file_id)),
            ("Target", ObjectRef(robot.transform_id or 0)),
            ("Rate", 30.0),
        ],
    )
    scene.ensure_gameobject("Robot/base_link/lidar")
    scene.ensure_gameobject("World")


@pytest.mark.parametrize("base", sorted(BASES))
def test_a_scene_built_from_scratch_is_sound_and_stable(
    tmp_path: Path, base: str, assert_sound: Check
) -> None:
    path = tmp_path / "Built.unity"
    path.write_text(BASES[base])
    scene = SceneDocument.load(path)
    _build(scene)
    assert scene.write()
    assert_sound(scene)
    reloaded = SceneDocument.load(path)
    assert reloaded.text().encode() == path.read_bytes()
    _build(reloaded)
    assert not reloaded.changed and reloaded.write() is False
    assert [go.path for go in reloaded.gameobjects()][-5:] == [
        "Robot",
        "Robot/base_link",
        "Robot/base_link/camera",
        "Robot/base_link/lidar",
        "World",
    ]


def test_built_objects_use_the_files_era() -> None:
    legacy = SceneDocument.parse(LEGACY, "legacy.unity")
    _build(legacy)
    new_docs = [d for d in legacy.documents() if d.file_id > 101]
    assert all("m_CorrespondingSourceObject" not in d.text for d in new_docs)
    assert all("m_PrefabParentObject: {fileID: 0}" in d.text for d in new_docs)
    world = legacy.find_gameobject("World")
    assert legacy.field(world.transform_id, "m_RootOrder") == "2"
    modern = SceneDocument.parse(_empty_2022(), "new.unity")
    _build(modern)
    roots = modern.field(9223372036854775807, "m_Roots")
    assert roots == [{"fileID": str(go.transform_id)} for go in modern.roots()]
    assert all("m_RootOrder" not in d.text for d in modern.documents())
