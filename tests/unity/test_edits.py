"""Edits: attach and update components, create GameObjects, remove components, refuse safely."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError, UserError
from unityscaffold.unity import _documents
from unityscaffold.unity.scene import GameObjectNotFound, SceneDocument
from unityscaffold.unity.values import AssetRef, Enum, InlineMap, ObjectRef, ScriptRef

DATA = Path(__file__).resolve().parents[1] / "data" / "unity"
CONNECTOR = ScriptRef("ff98778ae051cfd40a6e4effdf851ebd")
PUBLISHER = ScriptRef("92dedf3f173285b4d9a806dec2334596")
Check = Callable[[SceneDocument], None]


def _target(scene: SceneDocument) -> str:
    return "RosConnector" if scene.is_scene else f"{scene.roots()[0].path}/RosConnector"


def _attach_all_kinds(scene: SceneDocument) -> None:
    go = scene.ensure_gameobject(_target(scene))
    connector = scene.ensure_component(
        go,
        CONNECTOR,
        [
            ("selectedRosVersion", Enum(1)),
            ("SecondsTimeout", 10),
            ("Serializer", 0),
            ("protocol", Enum(0)),
            ("RosBridgeServerUrl", "ws://localhost:9090"),
        ],
    )
    scene.ensure_component(
        go,
        PUBLISHER,
        [
            ("Topic", "/joy"),
            ("FrameId", "Unity"),
            ("CycleTime", 0.1),
            ("Enabled", True),
            ("Connector", ObjectRef(connector.file_id)),
            ("Self", ObjectRef(go.file_id)),
            ("Material", AssetRef(2100000, "e84c5fd102288448a8e2305335f05d28", 2)),
            ("Names", ["a", "b: c", "\u00e9"]),
            ("Empty", []),
            ("Offset", InlineMap.of(x=0, y=1.5, z=0)),
            ("Label", ""),
            ("Limits", {"min": -1, "max": 1.25}),
        ],
    )


def test_attaching_to_every_corpus_file_is_sound_and_idempotent(
    corpus_file: Path, assert_sound: Check
) -> None:
    scene = SceneDocument.load(corpus_file)
    _attach_all_kinds(scene)
    assert scene.changed
    assert_sound(scene)
    again = SceneDocument.parse(scene.text(), scene.path)
    _attach_all_kinds(again)
    assert again.text() == scene.text() and not again.changed and again.diff() == ""


def test_unchanged_documents_keep_their_bytes(corpus_file: Path) -> None:
    scene = SceneDocument.load(corpus_file)
    before = {d.file_id: d.text for d in scene.documents()}
    _attach_all_kinds(scene)
    touched = [d for d in scene.documents() if before.get(d.file_id, d.text) != d.text]
    kinds = {d.type_name for d in touched}
    assert kinds <= {"GameObject", "Transform", "SceneRoots"}, kinds


def test_a_new_component_lands_in_the_gameobject_and_after_the_header(
    scene_2022: SceneDocument,
) -> None:
    comp = scene_2022.ensure_component("Main Camera", CONNECTOR, {"SecondsTimeout": 5})
    go = scene_2022.find_gameobject("Main Camera")
    assert go.component_ids[-1] == comp.file_id
    doc = scene_2022.document(comp.file_id)
    assert doc is not None
    assert doc.text.endswith("  m_EditorClassIdentifier: \n  SecondsTimeout: 5\n")
    ids = [d.file_id for d in scene_2022.documents()]
    assert ids == sorted(ids)  # scenes stay sorted by fileID, SceneRoots last


def test_changing_one_field_is_a_one_line_diff(corpus_file: Path) -> None:
    scene = SceneDocument.load(corpus_file)
    _attach_all_kinds(scene)
    base = SceneDocument.parse(scene.text(), scene.path)
    go = base.find_gameobject(_target(base))
    assert base.ensure_component(go, PUBLISHER, [("CycleTime", 0.25)])
    changed = [
        line
        for line in base.diff().splitlines()
        if line[:1] in "+-" and not line.startswith(("+++", "---"))
    ]
    assert changed == ["-  CycleTime: 0.1", "+  CycleTime: 0.25"]


def test_an_equal_value_written_differently_keeps_its_bytes(scene_2022: SceneDocument) -> None:
    text = scene_2022.text().replace("SecondsTimeout: 10", "SecondsTimeout: 010")
    scene = SceneDocument.parse(text, "s.unity")
    assert not scene.set_fields(
        1259760939, {"SecondsTimeout": 10, "RosBridgeServerUrl": "ws://0.0.0.0:9090"}
    )
    assert scene.text() == text


def test_missing_fields_are_inserted_in_declaration_order(scene_2022: SceneDocument) -> None:
    scene_2022.set_fields(
        1259760939,
        [
            ("A", 1),
            ("SecondsTimeout", 10),
            ("B", 2),
            ("RosBridgeServerUrl", "ws://0.0.0.0:9090"),
            ("C", 3),
        ],
    )
    doc = scene_2022.document(1259760939)
    assert doc is not None
    keys = [line.split(":")[0].strip() for line in doc.text.splitlines()[-8:]]
    assert keys == [
        "selectedROSVersion",
        "A",
        "SecondsTimeout",
        "B",
        "Serializer",
        "protocol",
        "RosBridgeServerUrl",
        "C",
    ]


def _root_names(scene: SceneDocument) -> list[str]:
    return [go.name for go in scene.roots()]


def test_a_new_root_in_a_2022_scene_is_appended_to_scene_roots(
    scene_2022: SceneDocument, assert_sound: Check
) -> None:
    go = scene_2022.ensure_gameobject("Robot")
    assert scene_2022.field(9223372036854775807, "m_Roots")[-1] == {"fileID": str(go.transform_id)}
    transform = scene_2022.document(go.transform_id or 0)
    assert transform is not None and "m_RootOrder" not in transform.text
    assert "m_ConstrainProportionsScale: 0" in transform.text
    assert _root_names(scene_2022)[-1] == "Robot"
    assert_sound(scene_2022)


def test_a_new_root_in_a_2020_scene_gets_the_next_root_order(
    scene_2020: SceneDocument, assert_sound: Check
) -> None:
    go = scene_2020.ensure_gameobject("Robot")
    assert scene_2020.field(go.transform_id, "m_RootOrder") == "3"
    assert scene_2020.field(go.transform_id, "m_ConstrainProportionsScale") is None
    assert _root_names(scene_2020) == ["Main Camera", "Directional Light", "Demo", "Robot"]
    assert_sound(scene_2020)


def test_new_children_get_their_sibling_index_as_root_order(scene_2020: SceneDocument) -> None:
    first = scene_2020.ensure_gameobject("Demo/a")
    second = scene_2020.ensure_gameobject("Demo/b")
    assert [scene_2020.field(g.transform_id, "m_RootOrder") for g in (first, second)] == ["0", "1"]
    parent = scene_2020.find_gameobject("Demo")
    assert scene_2020.field(parent.transform_id, "m_Children") == [
        {"fileID": str(first.transform_id)},
        {"fileID": str(second.transform_id)},
    ]


def test_a_new_path_is_made_with_one_look_at_the_hierarchy(
    scene_2022: SceneDocument, assert_sound: Check, monkeypatch: pytest.MonkeyPatch
) -> None:
    builds: list[int] = []
    build = _documents.build_hierarchy
    monkeypatch.setattr(
        _documents, "build_hierarchy", lambda docs, by_id: builds.append(1) or build(docs, by_id)
    )
    made = scene_2022.ensure_gameobject("Robot/base_link/camera/optical_frame")
    assert len(builds) == 2  # to find where the path stops, then for the answer
    assert [go.name for go in scene_2022.gameobjects()][-4:] == [
        "Robot",
        "base_link",
        "camera",
        "optical_frame",
    ]
    assert made.path == "Robot/base_link/camera/optical_frame"
    parent = scene_2022.find_gameobject("Robot/base_link/camera")
    assert scene_2022.children(parent) == [made]
    assert_sound(scene_2022)


def test_gameobject_creation_is_refused_unless_asked(scene_2020: SceneDocument) -> None:
    with pytest.raises(
        GameObjectNotFound, match="names there: 'Demo', 'Directional Light', 'Main Camera'"
    ) as info:
        scene_2020.ensure_gameobject("Robot", create=False)
    assert info.value.hint is None  # how to create it depends on the command: its caller says


def test_file_ids_depend_on_names_not_on_where_the_file_is(tmp_path: Path) -> None:
    source = (DATA / "ros-sharp" / "ROSVersionSwitch.unity").read_bytes()
    outputs = []
    for folder in ("one", "two/deeper"):
        path = tmp_path / folder / "Scene.unity"
        path.parent.mkdir(parents=True)
        path.write_bytes(source)
        scene = SceneDocument.load(path)
        _attach_all_kinds(scene)
        outputs.append(scene.text())
    assert outputs[0] == outputs[1]


def test_a_file_id_collision_is_resolved_by_rehashing(scene_2022: SceneDocument) -> None:
    planned = SceneDocument.parse(scene_2022.text(), "p.unity").ensure_gameobject("Robot")
    text = (
        scene_2022.text()
        .replace("&963194225", f"&{planned.file_id}")
        .replace("{fileID: 963194225}", f"{{fileID: {planned.file_id}}}")
    )
    scene = SceneDocument.parse(text, "c.unity")
    go = scene.ensure_gameobject("Robot")
    assert go.file_id != planned.file_id
    assert scene.validate() == []


def test_a_component_in_a_prefab_follows_its_gameobject(assert_sound: Check) -> None:
    scene = SceneDocument.load(DATA / "unity-robotics-hub" / "Target.prefab")
    comp = scene.ensure_component("Target", CONNECTOR, {"SecondsTimeout": 1})
    docs = scene.documents()
    assert docs[-1].file_id == comp.file_id  # after the GameObject's last component
    assert_sound(scene)


def test_a_second_root_in_a_prefab_is_refused() -> None:
    scene = SceneDocument.load(DATA / "unity-robotics-hub" / "Target.prefab")
    with pytest.raises(UserError, match="single root"):
        scene.ensure_gameobject("Other")


def test_editing_inside_a_prefab_instance_is_refused() -> None:
    scene = SceneDocument.load(DATA / "ros-tcp-connector" / "EmptyVisualizationSuite.prefab")
    with pytest.raises(LocatedError, match="prefab instance") as info:
        scene.ensure_component("BlankVisualizationSuite/BasicDrawingManager", CONNECTOR)
    assert "--- !u!1001 &1914626938635344595" in info.value.render()
    with pytest.raises(LocatedError, match="stripped"):
        scene.set_fields(2742884835330475003, {"m_LocalPosition": InlineMap.of(x=1, y=0, z=0)})
    with pytest.raises(UserError, match="prefab instance"):
        scene.ensure_gameobject("BlankVisualizationSuite/BasicDrawingManager/Child")


def test_removing_a_component_unlinks_it_and_nulls_references(
    scene_2022: SceneDocument, assert_sound: Check
) -> None:
    go = scene_2022.ensure_gameobject("RosSocket")
    publisher = scene_2022.ensure_component(go, PUBLISHER, {"Connector": ObjectRef(1259760939)})
    assert scene_2022.remove_component(1259760939)
    assert 1259760939 not in scene_2022.find_gameobject("RosSocket").component_ids
    assert scene_2022.field(publisher, "Connector") == {"fileID": "0"}
    assert not scene_2022.remove_component(1259760939)
    assert_sound(scene_2022)


def test_removing_a_transform_is_refused(scene_2022: SceneDocument) -> None:
    with pytest.raises(UserError, match="is a Transform"):
        scene_2022.remove_component(1259760940)


@pytest.mark.parametrize(
    ("name", "value", "message"),
    [
        ("m_Script", 1, "cannot be set"),
        ("bad:name", 1, "not a serialized field name"),
        ("Big", 1e39, "float32"),
        ("Nested", [[1]], "cannot serialize"),
    ],
)
def test_bad_field_requests_are_user_errors(
    scene_2022: SceneDocument, name: str, value: object, message: str
) -> None:
    with pytest.raises(UserError, match=message):
        scene_2022.ensure_component("RosSocket", PUBLISHER, [(name, value)])  # type: ignore[list-item]
    assert not scene_2022.changed


def test_a_field_given_twice_is_refused(scene_2022: SceneDocument) -> None:
    with pytest.raises(UserError, match="more than once"):
        scene_2022.ensure_component("RosSocket", PUBLISHER, [("Topic", "a"), ("Topic", "b")])
