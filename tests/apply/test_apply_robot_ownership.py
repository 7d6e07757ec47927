"""What a robot's import owns in the scene against what other entries may set there: a
`components:` or `objects:` entry that sets a field the import enforces is refused at that
field (both would put their value back on every apply), the fields it leaves alone stay the
user's, and what the `robots` entry decides follows the entry, its defaults included."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import build_tree, run_cli, snapshot

from unityscaffold.unity.scene import SceneDocument

HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
robots:
  - urdf: ros/bot.urdf
"""
INERTIAL = (
    '<inertial><mass value="2"/>'
    '<inertia ixx="1" ixy="0" ixz="0" iyy="2" iyz="0" izz="3"/></inertial>'
)
URDF = f"""<robot name="bot">
  <material name="blue"><color rgba="0 0 0.8 1"/></material>
  <link name="base">{INERTIAL}
    <visual><geometry><box size="1 2 3"/></geometry><material name="blue"/></visual>
  </link>
  <link name="arm">{INERTIAL}
    <collision><geometry><sphere radius="0.1"/></geometry></collision>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="0 1 0"/><limit effort="1" velocity="1" lower="-1" upper="1"/></joint>
</robot>
"""
SCENE = "Assets/Scenes/Main.unity"


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return build_tree(tmp_path / "p", {"ros/bot.urdf": URDF})


def _apply(project: Path, body: str = "", *extra: str):  # type: ignore[no-untyped-def]
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", str(project / "robot.yaml"), *extra)


def _field(project: Path, path: str, class_name: str, name: str) -> object:
    scene = SceneDocument.load(project / SCENE)
    go = scene.find_gameobject(path)
    found = [c for c in scene.components_of(go) if c.type_name == class_name]
    return scene.field(found[0], name)


@pytest.mark.parametrize(
    ("body", "value", "message"),
    [
        (
            "components:\n  - {script: UrdfInertial, gameobject: bot/base, fields: {Mass: 5}}\n",
            "5}}",
            "UrdfInertial's Mass on 'bot/base' is set by robot bot's import",
        ),
        (
            "objects:\n  - {path: bot/base, components: [{type: Rigidbody, fields: "
            "{m_Drag: 1, m_Mass: 5}}]}\n",
            "5}}]}",
            "Rigidbody's m_Mass on 'bot/base' is set by robot bot's import",
        ),
        (
            "components:\n  - {script: HingeJointLimitsManager, gameobject: bot/base/arm, "
            "id: x, fields: {Tolerance: 1}}\n",
            "1}}",
            "HingeJointLimitsManager's Tolerance on 'bot/base/arm' is set by robot bot's",
        ),
    ],
)
def test_an_entry_that_sets_a_field_the_import_owns_is_refused_at_the_field(
    project: Path, body: str, value: str, message: str
) -> None:
    """Else the import and the entry each put their value back: the same update every run."""
    where = f"robot.yaml:8:{body.splitlines()[1].index(value) + 1}:"
    (project / "robot.yaml").write_text(HEADER + body)
    before = snapshot(project)
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 2, run.out + run.err
    assert f"{where} error: {message}" in run.err
    assert "hint: change the value in the URDF, or set a field the import does not own" in run.err
    assert snapshot(project) == before


def test_the_switches_of_the_robots_entry_are_named_in_the_hint(project: Path) -> None:
    body = (
        "objects:\n  - {path: bot/base/arm, components: [{type: Rigidbody, fields: "
        "{m_IsKinematic: true}}]}\n"
    )
    run = _apply(project, body)
    assert run.code == 2, run.out + run.err
    assert "hint: set `kinematic` on the robot's `robots` entry" in run.err


def test_fields_the_import_leaves_alone_stay_the_users_to_set(project: Path) -> None:
    body = (
        "objects:\n  - {path: bot/base, components: [{type: Rigidbody, fields: {m_Drag: 0.5}}]}\n"
        "components:\n  - {script: UrdfRobot, gameobject: bot, fields: {FilePath: ros/bot.urdf}}\n"
    )
    assert _apply(project, body).code == 0
    assert _field(project, "bot/base", "Rigidbody", "m_Drag") == "0.5"
    assert _field(project, "bot", "MonoBehaviour", "FilePath") == "ros/bot.urdf"
    before = snapshot(project)
    again = _apply(project, body)
    assert again.code == 0 and "the project matches the manifest" in again.out, again.out
    assert snapshot(project) == before


def test_a_switch_removed_from_the_robots_entry_puts_the_imports_value_back(
    project: Path,
) -> None:
    """The manifest is the truth: the switches left out are the importer's values, enforced."""
    assert _apply(project, "    kinematic: true\n    gravity: false\n").code == 0
    assert _field(project, "bot/base/arm", "Rigidbody", "m_IsKinematic") == "1"
    assert _field(project, "bot/base/arm", "Rigidbody", "m_UseGravity") == "0"
    run = _apply(project)
    assert run.code == 0, run.err
    assert "update bot/base/arm (robot bot)" in run.out
    for link in ("bot/base", "bot/base/arm"):
        assert _field(project, link, "Rigidbody", "m_IsKinematic") == "0"
        assert _field(project, link, "Rigidbody", "m_UseGravity") == "1"
    assert _apply(project, "", "--check").code == 0


def test_a_switch_flipped_in_unity_is_drift_put_back(project: Path) -> None:
    assert _apply(project).code == 0
    scene = project / SCENE
    text = scene.read_text()
    assert text.count("m_IsKinematic: 0") == 2
    scene.write_text(text.replace("m_IsKinematic: 0", "m_IsKinematic: 1"))
    assert _apply(project, "", "--check").code != 0
    assert _apply(project).code == 0
    assert scene.read_text() == text
