"""References set after every component of every kind is in the scene: an entry may name a
component that a later entry (uGUI's, a project script's, ROS#'s) or a later object adds, in any
order; and each component changed in a run is said once, however many of its fields change."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import init_with_unreadable_script, run_cli

from unityscaffold.unity.scene import SceneDocument

HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
"""
# Each entry names a component another entry or object adds: uGUI to uGUI, a script apply cannot
# read (an untyped field) to uGUI, ROS# to a built-in component of a declared object.
ENTRIES = [
    '  - {script: Button, gameobject: Canvas/B, fields: {m_TargetGraphic: "@Canvas/B:Image"}}',
    "  - {script: Image, gameobject: Canvas/B}",
    "  - {script: Assets/Scripts/Blind.cs, gameobject: Canvas/B,"
    ' fields: {Shown: "@Canvas/B:Text"}}',
    "  - {script: Text, gameobject: Canvas/B}",
    "  - {script: ImagePublisher, gameobject: Robot, create: true,"
    ' fields: {ImageCamera: "@Robot/Eye"}}',
]
OBJECTS = """\
objects:
  - {path: Robot/Eye, components: [Camera]}
  - {path: Canvas, ui: true, components: [Canvas]}
  - {path: Canvas/B, ui: true, components: [CanvasRenderer]}
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    return init_with_unreadable_script(tmp_path / "p")


def _apply(project: Path, body: str, *extra: str):
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", str(project / "robot.yaml"), *extra)


def _targets(project: Path) -> dict[str, str]:
    """Each reference field the entries set -> the class of what it holds."""
    scene = SceneDocument.load(project / "Assets" / "Scenes" / "Main.unity")
    found = {}
    for path, name in (
        ("Canvas/B", "m_TargetGraphic"),
        ("Canvas/B", "Shown"),
        ("Robot", "ImageCamera"),
    ):
        go = scene.find_gameobject(path)
        for comp in scene.components_of(go):
            value = scene.field(comp, name)
            if isinstance(value, dict):
                target = scene.document(int(value["fileID"]))
                assert target is not None, (name, value)
                held = scene.field(target.file_id, "m_Script") if target.class_id == 114 else None
                found[name] = held["guid"] if isinstance(held, dict) else target.type_name
    return found


@pytest.mark.parametrize("order", ["as written", "reversed"])
def test_a_reference_to_a_component_a_later_entry_adds_resolves_in_any_order(
    project: Path, order: str
) -> None:
    entries = ENTRIES if order == "as written" else ENTRIES[::-1]
    run = _apply(project, "components:\n" + "\n".join(entries) + "\n" + OBJECTS)
    assert run.code == 0, run.err
    assert _targets(project) == {
        "m_TargetGraphic": "fe87c0e1cc204ed48ad3b37840f39efc",  # uGUI's Image
        "Shown": "5f7201a12d95ffc409449d95f23cf332",  # uGUI's Text
        "ImageCamera": "Camera",
    }
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_a_component_changed_in_a_plain_and_a_reference_field_is_updated_once(
    project: Path,
) -> None:
    body = """\
components:
  - {script: TwistPublisher, gameobject: Robot, create: true,
     fields: {Topic: /a, PublishedTransform: "@Main Camera"}}
  - {script: Image, gameobject: Canvas/B}
  - {script: Text, gameobject: Canvas/T}
  - {script: Button, gameobject: Canvas/B,
     fields: {m_Interactable: true, m_TargetGraphic: "@Canvas/B:Image"}}
objects:
  - path: Canvas
    ui: true
    components: [{type: Canvas, fields: {m_RenderMode: 0, m_Camera: "@Main Camera"}}]
  - {path: Canvas/B, ui: true, components: [CanvasRenderer]}
  - {path: Canvas/T, ui: true, components: [CanvasRenderer]}
  - {path: Eye, components: [Camera]}
"""
    assert _apply(project, body).code == 0
    changed = (
        body.replace(
            '/a, PublishedTransform: "@Main Camera', '/b, PublishedTransform: "@Directional Light'
        )
        .replace(
            'm_Interactable: true, m_TargetGraphic: "@Canvas/B:Image',
            'm_Interactable: false, m_TargetGraphic: "@Canvas/T:Text',
        )
        .replace('m_RenderMode: 0, m_Camera: "@Main Camera', 'm_RenderMode: 1, m_Camera: "@Eye')
    )
    run = _apply(project, changed)
    assert run.code == 0, run.err
    lines = run.out.splitlines()
    for said in (
        "update TwistPublisher on Robot",
        "update Button on Canvas/B",
        "update Canvas on Canvas",
    ):
        assert lines.count(f"  {said}") == 1, run.out
