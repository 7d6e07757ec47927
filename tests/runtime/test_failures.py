"""The first failures a Unity user meets, met by generated scripts in the UnityEngine stand-in
(csharp/FailureScenario.cs) with ROS#'s real RosConnector: rosbridge not running, a wrong port
(rosmaster's XML-RPC server answers there), and, with the real rosbridge, a topic type and a
service type it cannot load, and a service nobody serves. Each script logs one message that
says what to check, and nothing is thrown on the frame loop's thread."""

from __future__ import annotations

import shutil
from pathlib import Path

import processes
from helpers import run_cli

from tests.runtime.bridge import Bridge, free_port
from tests.runtime.client import CSHARP, mcs_compile

MANIFEST = """\
version: 1
ros: 1
project: .
output: Assets/RosGenerated
scene: Assets/Scenes/Main.unity
interfaces: [ghost_ws]
connector: {gameobject: RosConnector, url: "ws://localhost:9090", serializer: newtonsoft}
topics:
  - {name: /ghost, type: ghost_msgs/Ghost, direction: subscribe, gameobject: Robot}
  - {name: /ghost_out, type: ghost_msgs/Ghost, direction: publish, rate: 5, gameobject: Robot}
services:
  - {name: /haunt, type: ghost_msgs/Haunt, role: client, gameobject: Robot}
  - {name: /nobody, type: std_srvs/Trigger, role: client, gameobject: Robot}
"""


def _project(tmp_path: Path) -> Path:
    """A project whose ghost_msgs rosbridge has never heard of."""
    project = tmp_path / "ghost_unity"
    assert run_cli("init", str(project), "--ros", "1").code == 0
    package = project / "ghost_ws" / "ghost_msgs"
    (package / "msg").mkdir(parents=True)
    (package / "srv").mkdir()
    (package / "msg" / "Ghost.msg").write_text("string text\n")
    (package / "srv" / "Haunt.srv").write_text("string whom\n---\nbool done\n")
    (project / "robot.yaml").write_text(MANIFEST)
    applied = run_cli("apply", str(project / "robot.yaml"))
    assert applied.code == 0, applied.err
    return project / "Assets" / "RosGenerated"


def _build(mcs: str, client: Path, package: Path, generated: Path, out: Path) -> Path:
    out.mkdir()
    for dll in client.parent.glob("*.dll"):  # ROS#'s client and plugins; mono loads them here
        if dll.name != "UnityEngine.dll":
            shutil.copy2(dll, out / dll.name)
    engine = out / "UnityEngine.dll"
    mcs_compile(mcs, [CSHARP / "UnityEngineRuntime.cs"], engine)
    connector = package / "Runtime" / "RosBridgeClient" / "RosCommunication" / "RosConnector.cs"
    exe = out / "FailureScenario.exe"
    mcs_compile(
        mcs,
        [connector, *sorted(generated.rglob("*.cs")), CSHARP / "FailureScenario.cs"],
        exe,
        references=[engine, *(out / n for n in ("RosBridgeClient.dll", "Newtonsoft.Json.dll"))],
        target="exe",
    )
    return exe


def test_failures_are_one_clear_message_each_and_never_thrown(
    bridge: Bridge,
    mcs: str,
    mono: str,
    rossharp_client: Path,
    rossharp_package: Path,
    tmp_path: Path,
) -> None:
    generated = _project(tmp_path)
    exe = _build(mcs, rossharp_client, rossharp_package, generated, tmp_path / "bin")
    wrong_port = "ws://127.0.0.1:" + bridge.master_url.rsplit(":", 1)[1]
    not_running = f"ws://127.0.0.1:{free_port()}"
    run = processes.run([mono, str(exe), bridge.url, wrong_port, not_running], timeout=120)
    output = run.stdout + run.stderr
    assert run.returncode == 0 and "done" in run.stdout.splitlines(), output
    assert "Unhandled Exception" not in output
    lines = run.stdout.splitlines()

    def once(line: str) -> None:
        assert lines.count(line) == 1, f"{line!r} not once in:\n{output}"

    hint = "Is rosbridge running at that address and port?"
    for url, timeout in ((wrong_port, 1), (not_running, 1)):
        once(
            f"[warning] GhostSubscriber: no connection to {url} within {timeout} s; "
            f"subscription to /ghost is not set up. {hint}"
        )
    once(f"[warning] NobodyClient: not connected to {wrong_port}; /nobody not called.")
    # With a working rosbridge: the topic type it cannot load, the service type it cannot load,
    # a service nobody serves. rosbridge 0.11 tells the client nothing (ROS# could not read it).
    once(
        "[log] GhostSubscriber: nothing on /ghost (ghost_msgs/Ghost) 2 s after subscribing. "
        "If it is published, rosbridge's log says why it is not passed on "
        "(a type rosbridge cannot load, for one)."
    )
    for name, service, kind in (
        ("HauntClient", "/haunt", "ghost_msgs/Haunt"),
        ("NobodyClient", "/nobody", "std_srvs/Trigger"),
    ):
        once(
            f"[warning] {name}: no response from {service} ({kind}) within 2 s. Is it "
            "advertised? If so, rosbridge's log says why the call failed "
            "(a type rosbridge cannot load, for one)."
        )
    ours = [line for line in lines if line.startswith(("[warning] Ghost", "[warning] Nobody"))]
    ours += [line for line in lines if line.startswith(("[warning] Haunt", "[log] Ghost"))]
    assert len(ours) == 6, output
    # The reason is where the messages point: rosbridge's log names the type it cannot load.
    log = (bridge.home / "rosbridge.log").read_text(errors="replace")
    assert "ghost_msgs" in log
