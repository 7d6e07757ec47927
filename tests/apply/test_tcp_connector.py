"""``runtime: ros-tcp-connector``: the scripts (golden files), the ROSConnection in the scene,
that everything compiles against the vendored connector, and switching runtimes."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from connector_csharp import compile_with_connector, connector
from helpers import assert_same_tree, run_cli, updating

from unityscaffold.apply._tcpconnector import CONNECTION_GUID, PACKAGE_URL
from unityscaffold.unity.meta import read_meta_guid

REPO = Path(__file__).resolve().parents[2]
GOLDEN = Path(__file__).parent / "golden" / "tcpconnector"

MANIFEST = """\
version: 1
ros: {ros}
runtime: ros-tcp-connector
scene: Assets/Scenes/Main.unity
connector: {{host: 192.168.1.10, port: 10001, show_hud: false, keepalive: 0.5,
            tf_topics: [/tf, /tf_static]}}
interfaces: [ws]
topics:
  - {{name: /chatter, type: std_msgs/String, direction: publish, rate: 2, queue: 1, latch: true}}
  - {{name: /echo, type: std_msgs/String, direction: subscribe, gameobject: Robot}}
  - {{name: /base_status, type: diffbot_msgs/BaseStatus, direction: subscribe}}
  - {{name: /ping, type: std_msgs/Empty, direction: publish}}
services:
  - {{name: /trigger, type: std_srvs/Trigger, role: client}}
  - {{name: /set, type: std_srvs/SetBool, role: server, gameobject: Robot}}
  - {{name: /speed_limit, type: diffbot_msgs/SetSpeedLimit, role: client}}
  - {{name: /reset, type: std_srvs/Empty, role: server}}
{actions}"""
# a shipped action (nav_msgs) and a generated one (the sample's diffbot_msgs)
ROS1_ACTIONS = """\
actions:
  - {name: /map, type: nav_msgs/action/GetMap, role: client}
  - {name: /sim/map, type: nav_msgs/action/GetMap, role: server, gameobject: Robot}
  - {name: /dock, type: diffbot_msgs/action/Dock, role: client, gameobject: Robot}
  - {name: /sim/dock, type: diffbot_msgs/action/Dock, role: server, gameobject: Robot}
"""


SHARP_MANIFEST = """\
version: 1
ros: 1
scene: Assets/Scenes/Main.unity
topics:
  - {name: /chatter, type: std_msgs/String, direction: publish, rate: 2}
  - {name: /echo, type: std_msgs/String, direction: subscribe, gameobject: Robot}
services:
  - {name: /trigger, type: std_srvs/Trigger, role: client}
  - {name: /set, type: std_srvs/SetBool, role: server, gameobject: Robot}
"""


ROS1_TOPIC = "{name: /base_status, type: diffbot_msgs/BaseStatus, direction: subscribe}"
ROS2_TOPIC = "{name: /pantry, type: tcp_test_msgs/msg/Pantry, direction: publish}"


def _init(tmp_path: Path, ros: int, runtime: str = "ros-tcp-connector") -> Path:
    project = tmp_path / f"ros{ros}"
    done = run_cli("init", str(project), "--ros", str(ros), "--runtime", runtime)
    assert done.code == 0, done.err
    return project


def _applied(tmp_path: Path, ros: int) -> Path:
    project = _init(tmp_path, ros)
    if ros == 1:  # the sample's package is written for ROS 1
        shutil.copytree(REPO / "sample_project" / "ros_ws" / "src", project / "ws")
        text = MANIFEST.format(ros=ros, actions=ROS1_ACTIONS)
    else:  # the connector generator's own ROS 2 test package
        shutil.copytree(REPO / "tests" / "codegen" / "rostcp" / "data" / "ros2", project / "ws")
        text = MANIFEST.format(ros=ros, actions="").replace(ROS1_TOPIC, ROS2_TOPIC)
        text = _without_sample(text, folder=True)
    (project / "robot.yaml").write_text(text)
    done = run_cli("apply", str(project / "robot.yaml"))
    assert done.code == 0, done.err
    assert "add ROSConnection to ROSConnection" in done.out
    assert "add EchoSubscriber to Robot" in done.out
    assert "Packages/manifest.json" not in done.out + done.err  # pinned as the scripts need
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0
    return project


def _without_sample(text: str, *, folder: bool = False) -> str:
    """``text`` without the sample package's entries (and its folder, unless ``folder``)."""
    return "".join(
        line
        for line in text.splitlines(keepends=True)
        if "diffbot" not in line and (folder or "[ws]" not in line)
    )


def _scripts(project: Path) -> list[Path]:
    return sorted((project / "Assets" / "RosGenerated" / "Scripts").glob("*.cs"))


def _generated(project: Path) -> list[Path]:
    """Every generated C# file: the message classes and the scripts with their user halves."""
    return sorted((project / "Assets" / "RosGenerated").rglob("*.cs"))


def test_init_pins_the_connector_package_and_writes_a_starter_for_it(tmp_path: Path) -> None:
    project = _init(tmp_path, 1)
    deps = json.loads((project / "Packages" / "manifest.json").read_text())["dependencies"]
    assert deps["com.unity.robotics.ros-tcp-connector"] == PACKAGE_URL
    assert "com.siemens.ros-sharp" not in deps
    assert PACKAGE_URL.endswith("#v0.7.0")
    starter = (project / "robot.yaml").read_text()
    assert "runtime: ros-tcp-connector" in starter and "host: 127.0.0.1" in starter
    done = run_cli("apply", str(project / "robot.yaml"))
    assert done.code == 0, done.err
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_init_refuses_an_unknown_runtime(tmp_path: Path) -> None:
    done = run_cli("init", str(tmp_path / "p"), "--runtime", "ros2-for-unity")
    assert done.code == 2 and "--runtime must be ros-sharp or ros-tcp-connector" in done.err
    assert not (tmp_path / "p").exists()


@pytest.mark.parametrize("ros", [1, 2])
def test_connector_scripts_are_the_golden_ones(tmp_path: Path, ros: int) -> None:
    project = _applied(tmp_path, ros)
    scripts = tmp_path / "scripts"
    scripts.mkdir()
    for path in _scripts(project):
        shutil.copy2(path, scripts / path.name)
    expected = GOLDEN / f"ros{ros}"
    if updating():
        shutil.rmtree(expected, ignore_errors=True)
        shutil.copytree(scripts, expected)
    assert_same_tree(scripts, expected)


def test_the_scene_gets_one_rosconnection_with_the_manifests_settings(tmp_path: Path) -> None:
    project = _applied(tmp_path, 1)
    scene = (project / "Assets" / "Scenes" / "Main.unity").read_text()
    assert scene.count(f"guid: {CONNECTION_GUID}") == 1
    block = scene[scene.index(f"guid: {CONNECTION_GUID}") :].split("--- !u!")[0]
    assert block.splitlines()[3:] == [
        "  m_RosIPAddress: 192.168.1.10",
        "  m_RosPort: 10001",
        "  m_ConnectOnStart: 1",
        "  m_KeepaliveTime: 0.5",
        "  m_NetworkTimeoutSeconds: 2",
        "  m_SleepTimeSeconds: 0.01",
        "  m_ShowHUD: 0",
        "  m_TFTopics:",
        "  - /tf",
        "  - /tf_static",
        "  listenForTFMessages: 1",
    ]
    # each generated script points at it through its Connection field
    assert scene.count("  Connection: {fileID: ") == 12 and "  Connector: " not in scene


def test_the_rosconnection_guid_is_the_vendored_packages() -> None:
    meta = connector() / "Runtime" / "TcpConnector" / "ROSConnection.cs.meta"
    assert read_meta_guid(meta) == CONNECTION_GUID


@pytest.mark.parametrize("ros", [1, 2])
def test_connector_scripts_compile_against_the_vendored_connector(
    mcs: str, tmp_path: Path, ros: int
) -> None:
    project = _applied(tmp_path, ros)
    assert any("Messages" in p.parts for p in _generated(project))
    compiled = compile_with_connector(mcs, _generated(project), tmp_path / "build", ros2=ros == 2)
    compiled.assert_clean()


def test_a_package_pin_the_scripts_are_not_made_for_gets_a_note(tmp_path: Path) -> None:
    project = _applied(tmp_path, 1)
    packages = project / "Packages" / "manifest.json"
    packages.write_text(packages.read_text().replace("#v0.7.0", "#v0.6.0"))
    done = run_cli("plan", str(project / "robot.yaml"))
    assert done.code == 0, done.err
    assert "pins com.unity.robotics.ros-tcp-connector 0.6.0" in done.out + done.err


def _apply(project: Path) -> str:
    done = run_cli("apply", str(project / "robot.yaml"))
    assert done.code == 0, done.err
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0
    return (project / "Assets" / "Scenes" / "Main.unity").read_text()


def test_switching_runtime_back_and_forth_converges_with_check_clean(tmp_path: Path) -> None:
    project = _init(tmp_path, 1, "ros-sharp")
    tcp = _without_sample(MANIFEST.format(ros=1, actions=""))
    sharp = SHARP_MANIFEST
    manifest = project / "robot.yaml"
    manifest.write_text(sharp)
    first_sharp = _apply(project)
    assert "RosConnector" in first_sharp and CONNECTION_GUID not in first_sharp
    manifest.write_text(tcp)
    first_tcp = _apply(project)
    assert CONNECTION_GUID in first_tcp and "RosBridgeServerUrl" not in first_tcp
    manifest.write_text(sharp)
    second_sharp = _apply(project)
    assert CONNECTION_GUID not in second_sharp
    manifest.write_text(tcp)
    assert _apply(project) == first_tcp
    manifest.write_text(sharp)
    assert _apply(project) == second_sharp
    scripts = project / "Assets" / "RosGenerated" / "Scripts"
    assert "RosSharp.RosBridgeClient" in (scripts / "ChatterPublisher.cs").read_text()
