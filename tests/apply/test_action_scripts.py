"""The scripts generated for ``actions:`` entries: their text (golden files), and that they compile.

They compile against ROS#'s real client library (ROS# 2.2.1's RosBridgeClient and RosConnector,
built for ROS 1 or, with ``ROS2`` defined, for ROS 2, as the runtime tests build them) and the
Unity stand-in, and against the compile stubs other tests use, whose action operations are
checked here to be declared exactly as RosSocket.cs declares them.

Regenerate the golden files with ``UNITYSCAFFOLD_UPDATE=1`` and review the diff.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from csharp import MCS_FLAGS, UNITY_STUBS, compile_applied_project
from helpers import assert_same_tree, require, run_cli, updating

from tests.runtime.bridge import vendor_folder
from tests.runtime.client import CSHARP, build_client, build_ros2_client, mcs_compile

REPO = Path(__file__).resolve().parents[2]
GOLDEN = Path(__file__).parent / "golden" / "actions"
SAMPLE_INTERFACES = REPO / "sample_project" / "ros_ws" / "src"

MANIFEST = """\
version: 1
ros: {ros}
scene: Assets/Scenes/Main.unity
interfaces: [ws]
{namespace}actions:
  - {{name: /dock, type: diffbot_msgs/action/Dock, role: client, gameobject: Robot}}
  - {{name: /charger/dock, type: diffbot_msgs/Dock, role: server, gameobject: Charger}}
"""


def _applied(tmp_path: Path, ros: int, namespace: str | None = None) -> Path:
    project = tmp_path / f"ros{ros}"
    assert run_cli("init", str(project), "--ros", str(ros)).code == 0
    shutil.copytree(SAMPLE_INTERFACES, project / "ws")
    text = MANIFEST.format(ros=ros, namespace=f"namespace: {namespace}\n" if namespace else "")
    (project / "robot.yaml").write_text(text, encoding="utf-8")
    done = run_cli("apply", str(project / "robot.yaml"))
    assert done.code == 0, done.err
    assert "add DockActionClient to Robot" in done.out
    assert "add ChargerDockActionServer to Charger" in done.out
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0
    return project


def _scripts(project: Path, out: Path) -> Path:
    """The generated scripts (both halves), without their .meta files."""
    out.mkdir(parents=True)
    for path in sorted((project / "Assets" / "RosGenerated" / "Scripts").glob("*.cs")):
        shutil.copy2(path, out / path.name)
    return out


@pytest.mark.parametrize("ros", [1, 2])
def test_action_scripts_are_the_golden_ones(tmp_path: Path, ros: int) -> None:
    scripts = _scripts(_applied(tmp_path, ros), tmp_path / "scripts")
    expected = GOLDEN / f"ros{ros}"
    if updating():
        shutil.rmtree(expected, ignore_errors=True)
        shutil.copytree(scripts, expected)
    assert_same_tree(scripts, expected)


def _rossharp() -> Path:
    package = vendor_folder("UNITYSCAFFOLD_ROSSHARP", "ros-sharp/2.2.1/com.siemens.ros-sharp")
    require(package, "ROS# 2.2.1's com.siemens.ros-sharp folder (UNITYSCAFFOLD_ROSSHARP)")
    assert package is not None
    return package


# With a namespace of its own every message class is generated there, while ROS#'s action
# bases still take ROS#'s GoalID, GoalStatus and Header.
@pytest.mark.parametrize("namespace", [None, "MyRobot.Ros"])
@pytest.mark.parametrize("ros", [1, 2])
def test_action_scripts_compile_against_rossharps_client(
    mcs: str, tmp_path: Path, ros: int, namespace: str | None
) -> None:
    package = _rossharp()
    project = _applied(tmp_path, ros, namespace)
    build = tmp_path / "build"
    client = (build_ros2_client if ros == 2 else build_client)(mcs, package, build)
    engine = build / "UnityEngine.dll"
    mcs_compile(mcs, [CSHARP / "UnityEngineRuntime.cs"], engine)
    connector = package / "Runtime" / "RosBridgeClient" / "RosCommunication" / "RosConnector.cs"
    generated = sorted((project / "Assets" / "RosGenerated").rglob("*.cs"))
    references = [engine, client, build / "Newtonsoft.Json.dll", build / "websocket-sharp.dll"]
    # Our flags (warnings as errors), not the third-party ones: the generated code is ours.
    args = [mcs, *MCS_FLAGS, f"-out:{build / 'Assembly-CSharp.dll'}"]
    args += ["-define:ROS2"] if ros == 2 else []
    args += [f"-r:{r}" for r in references] + [str(connector), *map(str, generated)]
    done = subprocess.run(args, capture_output=True, text=True, timeout=600, check=False)
    assert done.returncode == 0 and "warning" not in done.stdout, done.stdout + done.stderr


@pytest.mark.parametrize("ros", [1, 2])
def test_action_scripts_compile_against_the_stubs(mcs: str, tmp_path: Path, ros: int) -> None:
    project = _applied(tmp_path, ros)
    compile_applied_project(mcs, project / "robot.yaml", tmp_path / "build", ros2=ros == 2)


def _declarations(text: str, names: tuple[str, ...]) -> dict[str, str]:
    """Each named method's declaration up to its body, whitespace collapsed."""
    found = {}
    for name in names:
        match = re.search(rf"public (?:string|void) {name}<[^{{;]*?(?=\{{)", text, re.S)
        assert match is not None, name
        spaced = " ".join(match.group(0).split())
        found[name] = re.sub(r"(?<=\() | (?=[,)])", "", spaced)  # no space inside ( , )
    return found


ROS2_OPERATIONS = (
    "AdvertiseAction",
    "RespondFeedback",
    "RespondResult",
    "SendActionGoalRequest",
    "CancelActionGoalRequest",
)


def test_the_stubs_action_operations_are_declared_as_rossharps() -> None:
    real = (_rossharp() / "Runtime/Libraries/RosBridgeClient/RosSocket.cs").read_text("utf-8-sig")
    stub = UNITY_STUBS[1].read_text(encoding="utf-8")

    assert _declarations(stub, ROS2_OPERATIONS) == _declarations(real, ROS2_OPERATIONS)


def test_the_ros2_starters_builtin_action_applies_and_compiles(mcs: str, tmp_path: Path) -> None:
    """A fresh ROS 2 project can use an action with nothing but unityscaffold: the starter's
    example names the built-in test_msgs/action/Fibonacci (Jazzy's, no ROS installed)."""
    project = tmp_path / "p"
    assert run_cli("init", str(project), "--ros", "2").code == 0
    manifest = project / "robot.yaml"
    starter = manifest.read_text(encoding="utf-8")
    example = "#  - {name: /fibonacci, type: test_msgs/action/Fibonacci, role: client}\n"
    assert example in starter
    manifest.write_text(starter.replace(example, example[1:]), encoding="utf-8")
    applied = run_cli("apply", str(manifest), "--json")
    assert applied.code == 0, applied.err
    files = {entry["path"] for entry in json.loads(applied.out)["files"]}
    assert "Assets/RosGenerated/Scripts/FibonacciActionClient.cs" in files
    assert run_cli("apply", "--check", str(manifest)).code == 0
    compile_applied_project(mcs, manifest, tmp_path / "build", ros2=True)
