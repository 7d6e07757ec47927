"""What a robot's import owns in the scene against what other entries may set there: a
`components:` or `objects:` entry that sets a field the import enforces is refused at that
field (both would put their value back on every apply), the fields it leaves alone stay the
user's, and what the `robots` entry decides follows the entry, its defaults included."""

from __future__ import annotations

from pathlib import Path

import pytest
from robot_helpers import (
    HEADER,
    SCENE,
    apply_refused,
    apply_robot,
    apply_writes_nothing,
    drift_is_put_back,
    field,
    inertial,
    init_project,
)

URDF = f"""<robot name="bot">
  <material name="blue"><color rgba="0 0 0.8 1"/></material>
  <link name="base">{inertial(2, (1, 2, 3))}
    <visual><geometry><box size="1 2 3"/></geometry><material name="blue"/></visual>
  </link>
  <link name="arm">{inertial(2, (1, 2, 3))}
    <collision><geometry><sphere radius="0.1"/></geometry></collision>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="0 1 0"/><limit effort="1" velocity="1" lower="-1" upper="1"/></joint>
</robot>
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    return init_project(tmp_path, {"ros/bot.urdf": URDF})


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
    run = apply_refused(project, HEADER + body)
    assert f"{where} error: {message}" in run.err
    assert "hint: change the value in the URDF, or set a field the import does not own" in run.err


def test_the_switches_of_the_robots_entry_are_named_in_the_hint(project: Path) -> None:
    body = (
        "objects:\n  - {path: bot/base/arm, components: [{type: Rigidbody, fields: "
        "{m_IsKinematic: true}}]}\n"
    )
    run = apply_robot(project, body)
    assert run.code == 2, run.out + run.err
    assert "hint: set `kinematic` on the robot's `robots` entry" in run.err


def test_fields_the_import_leaves_alone_stay_the_users_to_set(project: Path) -> None:
    body = (
        "objects:\n  - {path: bot/base, components: [{type: Rigidbody, fields: {m_Drag: 0.5}}]}\n"
        "components:\n  - {script: UrdfRobot, gameobject: bot, fields: {FilePath: ros/bot.urdf}}\n"
    )
    assert apply_robot(project, body).code == 0
    assert field(project, "bot/base", "Rigidbody", "m_Drag") == "0.5"
    assert field(project, "bot", "MonoBehaviour", "FilePath") == "ros/bot.urdf"
    again = apply_writes_nothing(project)
    assert "the project matches the manifest" in again.out, again.out


def test_a_switch_removed_from_the_robots_entry_puts_the_imports_value_back(
    project: Path,
) -> None:
    """The manifest is the truth: the switches left out are the importer's values, enforced."""
    assert apply_robot(project, "    kinematic: true\n    gravity: false\n").code == 0
    assert field(project, "bot/base/arm", "Rigidbody", "m_IsKinematic") == "1"
    assert field(project, "bot/base/arm", "Rigidbody", "m_UseGravity") == "0"
    run = apply_robot(project)
    assert run.code == 0, run.err
    assert "update bot/base/arm (robot bot)" in run.out
    for link in ("bot/base", "bot/base/arm"):
        assert field(project, link, "Rigidbody", "m_IsKinematic") == "0"
        assert field(project, link, "Rigidbody", "m_UseGravity") == "1"
    assert apply_robot(project, "", "--check").code == 0


def test_a_switch_flipped_in_unity_is_drift_put_back(project: Path) -> None:
    assert apply_robot(project).code == 0
    assert (project / SCENE).read_text().count("m_IsKinematic: 0") == 2
    drift_is_put_back(project, "m_IsKinematic: 0", "m_IsKinematic: 1", count=-1)
