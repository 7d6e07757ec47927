"""The manifest's `components`: ROS#'s stock scripts with their RosConnector, references to
generated scripts and to new GameObjects, and generated names that would clash."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import run_cli

HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
connector: {gameobject: RosConnector}
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return tmp_path / "p"


def _apply(project: Path, body: str):
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", str(project / "robot.yaml"))


def test_a_stock_subscriber_gets_its_required_ros_connector_and_a_rerun_is_a_no_op(project):
    run = _apply(
        project,
        """\
components:
  - script: TwistSubscriber
    gameobject: Robot
    create: true
    fields: {Topic: /cmd_vel_unity, SubscribedTransform: "@Robot"}
""",
    )
    assert run.code == 0, run.err
    assert "add RosConnector to Robot" in run.out and "add TwistSubscriber to Robot" in run.out
    scene = (project / "Assets" / "Scenes" / "Main.unity").read_text()
    assert "guid: 81c5dfb51482c2e47b602e8096d45712" in scene  # ROS# 2.2.1's TwistSubscriber
    again = run_cli("apply", str(project / "robot.yaml"))
    assert again.out.endswith("wrote 0 files, removed 0\n")


def test_a_component_may_refer_to_one_a_later_entry_attaches_on_the_first_run(project):
    run = _apply(
        project,
        """\
topics:
  - {name: /odom, type: nav_msgs/Odometry, direction: subscribe, gameobject: Robot}
components:
  - script: JointStatePublisher
    gameobject: Robot
    fields: {Topic: /joint_states, JointStateReaders: ["@Robot"]}
  - script: JointStateReader
    gameobject: Robot
""",
    )
    assert run.code == 0, run.err
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_a_generated_script_is_no_transform(project):
    before = (project / "Assets" / "Scenes" / "Main.unity").read_bytes()
    run = _apply(
        project,
        """\
topics:
  - {name: /odom, type: nav_msgs/Odometry, direction: subscribe, gameobject: Robot}
components:
  - script: TwistSubscriber
    gameobject: Robot
    fields: {Topic: /twist, SubscribedTransform: "@Robot:OdomSubscriber"}
""",
    )
    assert run.code == 2
    assert "robot.yaml:11:50: error: Robot has no Transform named OdomSubscriber" in run.err
    assert "components there: Transform, OdomSubscriber, RosConnector, TwistSubscriber" in run.err
    assert (project / "Assets" / "Scenes" / "Main.unity").read_bytes() == before


def test_a_generated_name_that_clashes_with_ros_sharps_scripts_is_refused(project):
    run = _apply(
        project,
        """\
topics:
  - {name: /odometry, type: nav_msgs/Odometry, direction: subscribe}
""",
    )
    assert run.code == 2
    assert "robot.yaml:7:" in run.err and "OdometrySubscriber" in run.err
    assert "class:" in run.err
    renamed = _apply(
        project,
        """\
topics:
  - {name: /odometry, type: nav_msgs/Odometry, direction: subscribe, class: OdomListener}
""",
    )
    assert renamed.code == 0, renamed.err


def test_a_missing_gameobject_without_creation_says_how_to_create_it(project):
    run = _apply(
        project,
        """\
components:
  - {script: TwistSubscriber, gameobject: Nowhere, create: false}
""",
    )
    assert run.code == 2
    assert "no GameObject named 'Nowhere'" in run.err
    hint = run.err.split("hint: ", 1)[1]
    assert "`create: true`" in hint and "--create" not in hint
