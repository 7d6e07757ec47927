"""Indexing: hierarchy paths, components and scripts, prefab instances, serialization eras."""

from __future__ import annotations

from pathlib import Path

import pytest

from unityscaffold.errors import UserError
from unityscaffold.unity.scene import SceneDocument

DATA = Path(__file__).resolve().parents[1] / "data" / "unity"


def _load(name: str) -> SceneDocument:
    return SceneDocument.load(next(DATA.rglob(name)))


@pytest.mark.parametrize(
    ("name", "paths"),
    [
        ("ROSVersionSwitch.unity", ["Main Camera", "Directional Light", "RosSocket"]),
        ("DemoScene.unity", ["Main Camera", "Directional Light", "Demo"]),
        (
            "gazebo_simulation_scene_ROS2_1_Camera.unity",
            ["World", "World/Main Camera", "World/Directional Light", "World/Plane"],
        ),
        ("Table.prefab", ["Table", "Table/Plane"]),
        (
            "EmptyVisualizationSuite.prefab",
            ["BlankVisualizationSuite", "BlankVisualizationSuite/BasicDrawingManager"],
        ),
        ("SampleScene.unity", []),
    ],
)
def test_gameobjects_are_listed_by_path_in_hierarchy_order(name: str, paths: list[str]) -> None:
    assert [go.path for go in _load(name).gameobjects()] == paths


def test_roots_follow_m_root_order_in_a_2020_scene() -> None:
    scene = _load("DemoScene.unity")
    orders = [scene.field(go.transform_id, "m_RootOrder") for go in scene.roots()]
    assert orders == ["0", "1", "2"]


def test_roots_follow_scene_roots_in_a_2022_scene() -> None:
    scene = _load("ROSVersionSwitch.unity")
    listed = scene.field(9223372036854775807, "m_Roots")
    assert [{"fileID": str(go.transform_id)} for go in scene.roots()] == listed


def test_components_come_in_m_component_order_with_their_scripts() -> None:
    scene = _load("ROSVersionSwitch.unity")
    comps = scene.components_of("RosSocket")
    assert [c.type_name for c in comps] == ["Transform", "MonoBehaviour", "MonoBehaviour"]
    assert comps[1].script is not None
    assert comps[1].script.guid == "ff98778ae051cfd40a6e4effdf851ebd"
    assert comps[1].script.file_id == 11500000
    assert all(c.gameobject_id == scene.find_gameobject("RosSocket").file_id for c in comps)


def test_find_component_recognises_a_script_on_a_gameobject() -> None:
    scene = _load("ROSVersionSwitch.unity")
    found = scene.find_component("RosSocket", "ff98778ae051cfd40a6e4effdf851ebd")
    assert found is not None and found.file_id == 1259760939
    assert scene.find_component("RosSocket", "ff98778ae051cfd40a6e4effdf851ebd", 123) is None
    assert scene.find_component("Main Camera", "ff98778ae051cfd40a6e4effdf851ebd") is None


def test_a_prefab_instance_is_an_opaque_node_and_its_stripped_parts_are_flagged() -> None:
    scene = _load("EmptyVisualizationSuite.prefab")
    node = scene.find_gameobject("BlankVisualizationSuite/BasicDrawingManager")
    assert node.is_prefab_instance and not node.editable
    stripped = [d for d in scene.documents() if d.stripped]
    assert [(d.class_id, d.file_id) for d in stripped] == [(4, 2742884835330475003)]


def test_a_missing_gameobject_lists_the_names_at_that_level() -> None:
    scene = _load("gazebo_simulation_scene_ROS2_1_Camera.unity")
    with pytest.raises(UserError) as info:
        scene.find_gameobject("World/Camera")
    message = info.value.render()
    assert "'Camera' under 'World'" in message
    assert "'Directional Light', 'Main Camera', 'Plane'" in message


def test_a_path_into_a_prefab_instance_explains_why_it_cannot_be_reached() -> None:
    scene = _load("EmptyVisualizationSuite.prefab")
    with pytest.raises(UserError, match="is a prefab instance"):
        scene.find_gameobject("BlankVisualizationSuite/BasicDrawingManager/Child")


def test_an_ambiguous_path_lists_the_candidates() -> None:
    text = (
        _load("ROSVersionSwitch.unity").text().replace("m_Name: Main Camera", "m_Name: RosSocket")
    )
    scene = SceneDocument.parse(text, "dupe.unity")
    with pytest.raises(UserError) as info:
        scene.find_gameobject("RosSocket")
    assert "2 GameObjects match 'RosSocket'" in info.value.message
    assert "&963194225" in info.value.message and "&1259760938" in info.value.message


@pytest.mark.parametrize("path", ["", "/", "A//B"])
def test_an_empty_path_segment_is_refused(path: str) -> None:
    with pytest.raises(UserError, match="invalid GameObject path"):
        _load("DemoScene.unity").find_gameobject(path)


@pytest.mark.parametrize(
    ("name", "root_order", "scene_roots", "is_scene"),
    [
        ("ROSVersionSwitch.unity", False, True, True),
        ("DemoScene.unity", True, False, True),
        ("EmptyScene.unity", True, False, True),
        ("Target.prefab", True, False, False),
    ],
)
def test_the_serialization_era_is_detected_per_file(
    name: str, root_order: bool, scene_roots: bool, is_scene: bool
) -> None:
    doc = _load(name)
    era = doc.era
    assert (era.root_order, era.scene_roots, doc.is_scene) == (root_order, scene_roots, is_scene)
    assert era.modern_prefab_fields and not era.classid_component_items


def test_names_in_double_quotes_are_decoded(tmp_path: Path) -> None:
    text = _load("DemoScene.unity").text().replace("m_Name: Demo", 'm_Name: "\\u0414emo"')
    assert SceneDocument.parse(text, "q.unity").find_gameobject("\u0414emo").name == "\u0414emo"


# A prefab instance renamed in Unity to a long name that needs double quotes (a non-ASCII
# letter): Unity folds it over lines in the modification's value, keeping spaces before a fold.
LONG_NAME = "Basic Drawing Manager \u00e9 for the left arm, the right arm and the head  camera"


@pytest.mark.parametrize(
    "value",
    [
        '"Basic Drawing Manager \\u00E9 for the left arm, the right arm and the head \n'
        '        camera"',
        "Basic Drawing Manager for the left arm, the right arm, the head and the\n"
        "        tail camera",
    ],
)
def test_a_prefab_instance_named_over_several_lines_is_found_by_its_name(value: str) -> None:
    text = (DATA / "ros-tcp-connector" / "EmptyVisualizationSuite.prefab").read_text()
    text = text.replace("      value: BasicDrawingManager\n", f"      value: {value}\n")
    scene = SceneDocument.parse(text)
    name = LONG_NAME if value.startswith('"') else " ".join(value.split())
    node = scene.find_gameobject(f"BlankVisualizationSuite/{name}")
    assert node.is_prefab_instance
