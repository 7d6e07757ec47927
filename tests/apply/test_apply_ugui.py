"""uGUI's components: a new one is written with every field Unity serializes, as Unity 2022.3
writes it (compared with documents Unity saved), a manifest's values typed and in place; one
already in the scene keeps the bytes the manifest does not set; and the table is what its
script derives from the real documents."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import run_cli, text_diff

from unityscaffold.unity.scene import SceneDocument

REPO = Path(__file__).resolve().parents[2]
DATA = REPO / "tests" / "data" / "unity" / "ros-sharp"
SAMPLE = DATA / "ROS2_3_With_UI.documents.txt"
SCRIPT = REPO / "scripts" / "update_ugui_fields.py"
TABLE = REPO / "unityscaffold" / "unity" / "ugui_fields.json"
HEADER = "version: 1\nros: 2\nproject: .\nscene: Assets/Scenes/Main.unity\n"


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return tmp_path / "p"


def _apply(project: Path, body: str):
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", str(project / "robot.yaml"))


def _scene(project: Path) -> SceneDocument:
    return SceneDocument.load(project / "Assets" / "Scenes" / "Main.unity")


def _real(guid: str) -> str:
    for part in re.split(r"^(?=--- )", SAMPLE.read_text(encoding="utf-8"), flags=re.M):
        if f"guid: {guid}, type: 3}}" in part:
            return part
    raise AssertionError(f"no document of {guid} in {SAMPLE.name}")


def _fields(text: str) -> str:
    """A MonoBehaviour's script fields (after m_EditorClassIdentifier), references to objects
    of the file reduced to whether they are null."""
    body = text.split("  m_EditorClassIdentifier: \n", 1)[1]
    return re.sub(r"\{fileID: [1-9]\d*\}", "{fileID: N}", body)


def _component(project: Path, path: str, class_name: str) -> str:
    scene = _scene(project)
    from unityscaffold.unity.ugui import UGUI_SCRIPTS

    guid = UGUI_SCRIPTS[class_name][1]
    found = [c for c in scene.components_of(path) if c.script and c.script.guid == guid]
    assert len(found) == 1
    doc = scene.document(found[0].file_id)
    assert doc is not None
    return doc.text


# class, the GameObject, the fields that give it the saved document's values
CASES = [
    ("Image", "Canvas/JoystickBackground", "{}"),
    ("CanvasScaler", "Canvas", "{}"),
    ("GraphicRaycaster", "Canvas", "{}"),
    ("EventSystem", "EventSystem", "{}"),
    ("StandaloneInputModule", "EventSystem", "{}"),
    (
        "Slider",
        "Canvas/Slider",
        '{m_MinValue: -0.3, m_MaxValue: 0.3, m_TargetGraphic: "@Canvas/Slider/Handle", '
        'm_FillRect: "@Canvas/Slider/Fill", m_HandleRect: "@Canvas/Slider/Handle"}',
    ),
]
OBJECTS = """\
objects:
  - {path: Canvas, ui: true}
  - {path: Canvas/JoystickBackground, ui: true, components: [CanvasRenderer]}
  - {path: Canvas/Slider, ui: true}
  - {path: Canvas/Slider/Fill, ui: true, components: [CanvasRenderer]}
  - {path: Canvas/Slider/Handle, ui: true, components: [CanvasRenderer]}
"""


@pytest.mark.parametrize(("name", "path", "fields"), CASES, ids=[c[0] for c in CASES])
def test_a_new_ugui_component_is_written_as_unity_2022_3_saved_it(project, name, path, fields):
    from unityscaffold.unity.ugui import UGUI_SCRIPTS

    extra = "  - {script: Image, gameobject: Canvas/Slider/Handle}\n" if name == "Slider" else ""
    body = f"{OBJECTS}components:\n  - {{script: {name}, gameobject: {path}, fields: {fields}}}\n"
    run = _apply(project, body + extra)
    assert run.code == 0, run.err
    ours = _fields(_component(project, path, name))
    assert ours == _fields(_real(UGUI_SCRIPTS[name][1]))
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_a_new_text_button_and_toggle_hold_every_field_with_the_manifest_values_in_place(project):
    body = f"""{OBJECTS}components:
  - {{script: Text, gameobject: Canvas/Label, create: true, fields: {{m_Text: Speed, m_RaycastTarget: false}}}}
  - {{script: Button, gameobject: Canvas/Go, create: true, fields: {{m_Interactable: false}}}}
  - {{script: Toggle, gameobject: Canvas/On, create: true, fields: {{m_IsOn: true, toggleTransition: None}}}}
"""  # noqa: E501
    run = _apply(project, body)
    assert run.code == 0, run.err
    text = _fields(_component(project, "Canvas/Label", "Text"))
    assert text.startswith("  m_Material: {fileID: 0}\n  m_Color: {r: 1, g: 1, b: 1, a: 1}\n")
    assert "  m_RaycastTarget: 0\n" in text and text.endswith(
        "    m_LineSpacing: 1\n  m_Text: Speed\n"
    )
    button = _fields(_component(project, "Canvas/Go", "Button"))
    assert "  m_Interactable: 0\n  m_TargetGraphic: {fileID: 0}\n  m_OnClick:\n" in button
    toggle = _fields(_component(project, "Canvas/On", "Toggle"))
    assert "  toggleTransition: 0\n  graphic: {fileID: 0}\n" in toggle
    assert toggle.endswith("      m_Calls: []\n  m_IsOn: 1\n")
    again = run_cli("apply", str(project / "robot.yaml"))
    assert again.out.endswith("wrote 0 files, removed 0\n"), again.out


def test_a_ugui_value_of_the_wrong_kind_is_refused_at_its_line(project):
    scene = project / "Assets" / "Scenes" / "Main.unity"
    before = scene.read_bytes()
    run = _apply(
        project, "components:\n  - {script: Image, gameobject: I, fields: {m_Type: Round}}\n"
    )
    assert run.code == 2, run.out
    assert "robot.yaml:6:" in run.err and "m_Type expects a member of the enum Type" in run.err
    assert "Simple, Sliced, Tiled, Filled" in run.err
    assert scene.read_bytes() == before


def test_a_ugui_component_already_in_the_scene_changes_only_the_fields_the_manifest_sets(project):
    first = _apply(project, "components:\n  - {script: EventSystem, gameobject: Events}\n")
    assert first.code == 0, first.err
    scene = project / "Assets" / "Scenes" / "Main.unity"
    full = scene.read_text()
    # as an older Unity wrote it: without m_sendNavigationEvents
    trimmed = full.replace("  m_sendNavigationEvents: 1\n", "")
    scene.write_text(trimmed)
    run = _apply(
        project, "components:\n  - {script: EventSystem, gameobject: Events, "
        "fields: {m_DragThreshold: 5}}\n"
    )  # fmt: skip
    assert run.code == 0, run.err
    assert scene.read_text() == trimmed.replace("m_DragThreshold: 10\n", "m_DragThreshold: 5\n")


def test_the_ugui_table_is_what_its_script_derives_from_unitys_documents(tmp_path: Path):
    out = tmp_path / "ugui_fields.json"
    result = subprocess.run(
        [sys.executable, str(SCRIPT), "--output", str(out)], capture_output=True, text=True
    )
    assert result.returncode == 0, result.stderr
    expected, actual = TABLE.read_bytes(), out.read_bytes()
    assert actual == expected, text_diff(expected, actual, "unityscaffold/unity/ugui_fields.json")


def test_the_ugui_script_stops_when_a_saved_document_has_a_field_its_table_lacks(tmp_path: Path):
    changed = tmp_path / "documents.txt"
    text = SAMPLE.read_text(encoding="utf-8")
    changed.write_text(
        text.replace("  m_DragThreshold: 10\n", "  m_DragThreshold: 10\n  m_New: 1\n")
    )
    result = subprocess.run(
        [sys.executable, str(SCRIPT), str(changed), "--output", str(tmp_path / "out.json")],
        capture_output=True,
        text=True,
    )
    assert result.returncode == 2
    assert "EventSystem" in result.stderr and "m_New" in result.stderr
    assert not (tmp_path / "out.json").exists()


def test_a_scene_of_an_older_unity_gets_only_the_fields_the_entry_sets(project):
    # uGUI's 2022.3 fields (m_RaycastPadding...) are not all in older versions: that Unity
    # completes the component itself
    demo = REPO / "tests" / "data" / "unity" / "unity-robotics-hub" / "DemoScene.unity"
    scene = project / "Assets" / "Scenes" / "Main.unity"
    scene.write_bytes(demo.read_bytes())
    run = _apply(project, "components:\n  - {script: Image, gameobject: I, create: true, "
                 "fields: {m_FillAmount: 0.5}}\n")  # fmt: skip
    assert run.code == 0, run.err
    assert _fields(_component(project, "I", "Image")) == "  m_FillAmount: 0.5\n"
