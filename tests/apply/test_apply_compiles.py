"""Everything apply generates (messages, scripts, user halves) compiles with Mono's mcs against
stubs of ROS#'s runtime and of UnityEngine, in ROS 1 and ROS 2 projects."""

from __future__ import annotations

from pathlib import Path

from csharp import compile_applied_project
from helpers import run_cli

REPO = Path(__file__).resolve().parents[2]


def test_the_sample_projects_generated_code_compiles(mcs, tmp_path):
    compile_applied_project(mcs, REPO / "sample_project" / "robot.yaml", tmp_path, ros2=False)


def test_the_generated_scripts_avoid_apis_unity_2023_made_obsolete(mcs, tmp_path):
    # The stub UnityEngine makes FindObjectOfType an error under UNITY_2023_1_OR_NEWER.
    compile_applied_project(
        mcs,
        REPO / "sample_project" / "robot.yaml",
        tmp_path,
        ros2=False,
        defines=("UNITY_2023_1_OR_NEWER",),
    )


ROS2_MANIFEST = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
interfaces: [ws]
connector: {gameobject: Ros/Connector, url: "ws://10.0.0.2:9090", serializer: newtonsoft}
topics:
  - {name: /cmd_vel, type: geometry_msgs/Twist, direction: publish, rate: 30, gameobject: Robot}
  - {name: /joint_states, type: sensor_msgs/JointState, direction: subscribe, gameobject: Robot/Arm}
  - {name: /arm/status, type: arm_msgs/ArmStatus, direction: subscribe, throttle: 50,
     gameobject: Robot/Arm}
services:
  - {name: /arm/home, type: arm_msgs/Home, role: server, gameobject: Robot/Arm}
  - {name: /trigger, type: std_srvs/Trigger, role: client}
"""
ARM_STATUS = """\
# Status of a robot arm.
uint8 STATE_IDLE=0
uint8 STATE_MOVING=1
string NAME_PREFIX="arm_"
std_msgs/Header header
uint8 state 0
float64[<=7] joint_positions
string<=16 name "arm_1"
float32[3] tool_offset [0.0, 0.0, 0.1]
"""


def test_an_init_project_with_a_ros2_package_applies_idempotently_and_compiles(mcs, tmp_path):
    project = tmp_path / "arm_project"
    assert run_cli("init", str(project), "--ros", "2").code == 0
    (project / "robot.yaml").write_text(ROS2_MANIFEST)
    package = project / "ws" / "arm_msgs"
    (package / "msg").mkdir(parents=True)
    (package / "srv").mkdir()
    (package / "msg" / "ArmStatus.msg").write_text(ARM_STATUS)
    (package / "srv" / "Home.srv").write_text("float64 speed 0.5\n---\nbool success\n")
    first = run_cli("apply", str(project / "robot.yaml"))
    assert first.code == 0, first.err
    assert "add ArmHomeServer to Robot/Arm" in first.out
    assert "add TriggerClient to Ros/Connector" in first.out
    settings = (project / "ProjectSettings" / "ProjectSettings.asset").read_text()
    assert "    Standalone: ROS2\n" in settings
    scene = (project / "Assets" / "Scenes" / "Main.unity").read_text()
    assert "  RosBridgeServerUrl: ws://10.0.0.2:9090\n" in scene
    assert "  Serializer: 1\n" in scene and "  selectedRosVersion: 1\n" in scene
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0
    compile_applied_project(mcs, project / "robot.yaml", tmp_path, ros2=True)


def test_switching_the_manifest_to_ros1_removes_the_ros2_define(tmp_path):
    project = tmp_path / "p"
    assert run_cli("init", str(project), "--ros", "2").code == 0
    assert run_cli("apply", str(project / "robot.yaml")).code == 0
    manifest = project / "robot.yaml"
    manifest.write_text(manifest.read_text().replace("ros: 2", "ros: 1"))
    assert run_cli("apply", str(manifest)).code == 0
    settings = (project / "ProjectSettings" / "ProjectSettings.asset").read_text()
    assert "scriptingDefineSymbols: {}\n" in settings
    assert "  selectedRosVersion: 0\n" in (project / "Assets" / "Scenes" / "Main.unity").read_text()
