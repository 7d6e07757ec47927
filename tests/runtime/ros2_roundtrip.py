"""Round trips through the real rosbridge 2.x: rclpy on one side (data/ros2/roundtrip_node.py,
data/ros2/service_node.py, in the ROS 2 stack's venv), and on the other either ROS#'s real
client under Mono with our generated ROS 2 classes (csharp/Echo.cs, csharp/ServiceEcho.cs) or a
plain JSON websocket client doing the same (data/ros2/json_echo.py), which tells what rosbridge
itself cannot carry from what ROS# or our classes get wrong."""

from __future__ import annotations

import json
import sys
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from processes import wait_for

from tests.runtime.client import CSHARP, mcs_compile
from tests.runtime.lines import Lines, start
from tests.runtime.ros2 import Rosbridge2
from tests.runtime.runtime_helpers import write_code
from unityscaffold.codegen import ClassRole, Options, generate
from unityscaffold.interfaces.model import Dialect, MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry

DATA = Path(__file__).parent / "data" / "ros2"


def ros2_registry(share: Path) -> Registry:
    """The interfaces the stack's venv carries (``share``), and nothing else."""
    return Registry.load(Dialect.ROS2, [share], use_environment=False, use_builtin=False)


def ros2_message_types(registry: Registry) -> list[MessageSpec]:
    """Every message type of a ``msg/`` folder (an action's parts travel only inside its action
    operations, a service's only inside its calls)."""
    interfaces, problems = registry.parse_all()
    assert not problems, problems
    found = {s.full_name: s for s in registry.closure(interfaces) if s.subfolder == "msg"}
    return [found[name] for name in sorted(found)]


def ros2_service_types(registry: Registry) -> list[ServiceSpec]:
    interfaces, problems = registry.parse_all()
    assert not problems, problems
    return sorted((i for i in interfaces if isinstance(i, ServiceSpec)), key=lambda s: s.full_name)


@dataclass(frozen=True)
class Ros2Echo:
    exe: Path
    classes: dict[str, str]  # ROS type -> C# class(es), as the plan files name them


def build_ros2_echo(
    mcs: str,
    client: Path,
    registry: Registry,
    messages: Sequence[MessageSpec],
    out: Path,
    services: Sequence[ServiceSpec] = (),
) -> Ros2Echo:
    """Echo.exe (or ServiceEcho.exe) beside ROS#'s ROS 2 client, with our classes for every
    type ROS# does not ship (what ``apply`` sets up)."""
    code = generate(registry, [*messages, *services], Options(Dialect.ROS2))
    sources = [CSHARP / "Echo.cs", *write_code(code, out / "src")]
    if services:
        sources.append(CSHARP / "ServiceEcho.cs")
    folder = client.parent
    exe = folder / f"{out.name}.exe"
    references = [client, folder / "Newtonsoft.Json.dll", folder / "websocket-sharp.dll"]
    main = "ServiceEcho" if services else "Echo"
    mcs_compile(mcs, sources, exe, references=references, target="exe", main=main, defines=["ROS2"])
    classes = {spec.full_name: code.message_class(spec.full_name).full_name for spec in messages}
    for service in services:
        halves = code.classes[service.full_name]
        classes[service.full_name] = " ".join(
            halves[role].full_name for role in (ClassRole.REQUEST, ClassRole.RESPONSE)
        )
    return Ros2Echo(exe, classes)


@dataclass(frozen=True)
class Outcome:
    results: dict[str, Any]
    node_output: str
    client_output: str


def message_round_trip(
    bridge: Rosbridge2,
    client: list[str],
    classes: dict[str, str],
    types: Sequence[str],
    work: Path,
    *,
    seed: int,
    timeout: float = 90,
) -> Outcome:
    """rclpy publishes a random instance of each type, ``client`` (argv before ``URL PLAN``)
    echoes it through rosbridge, rclpy compares (data/ros2/roundtrip_node.py)."""
    plan = [
        {"type": name, "in": f"/{work.name}{seed}/in{i}", "out": f"/{work.name}{seed}/out{i}"}
        for i, name in enumerate(types)
    ]
    lines = "".join(f"{p['in']} {p['out']} {classes[p['type']]}\n" for p in plan)
    return _run_pair(bridge, client, "roundtrip_node.py", plan, lines, work, seed, timeout)


def service_round_trip(
    bridge: Rosbridge2,
    client: list[str],
    classes: dict[str, str],
    types: Sequence[str],
    work: Path,
    *,
    seed: int,
    timeout: float = 90,
) -> Outcome:
    """Both halves of each service type through ``client``, as a caller of an rclpy server and
    as a server rclpy calls (data/ros2/service_node.py, csharp/ServiceEcho.cs)."""
    plan = [
        {"type": name, "py": f"/{work.name}{seed}/py{i}", "cs": f"/{work.name}{seed}/cs{i}"}
        for i, name in enumerate(types)
    ]
    lines = "".join(f"{p['py']} {p['cs']} {classes[p['type']]}\n" for p in plan)
    served = frozenset(p["py"] for p in plan)
    return _run_pair(
        bridge, client, "service_node.py", plan, lines, work, seed, timeout, served=served
    )


def json_client(kind: str) -> list[str]:
    """The plain JSON websocket client's argv (``topics`` or ``services``), before URL PLAN."""
    return [sys.executable, str(DATA / "json_echo.py"), kind]


def identity_classes(types: Sequence[str]) -> dict[str, str]:
    """What the JSON client's plan lines name: the ROS types themselves."""
    return {name: name for name in types}


def _run_pair(
    bridge: Rosbridge2,
    client: list[str],
    node: str,
    plan: list[dict[str, str]],
    plan_lines: str,
    work: Path,
    seed: int,
    timeout: float,
    served: frozenset[str] = frozenset(),
) -> Outcome:
    """Run the rclpy side and, once it says "ready" and rosbridge's own node has discovered
    every one of its ``served`` services (it refuses a call to one it has not seen, and rosapi's
    listing does not tell: it is another node), the client, on ``work``'s plan files."""
    work.mkdir(parents=True, exist_ok=True)
    (work / "plan.json").write_text(json.dumps(plan))
    (work / "plan.txt").write_text(plan_lines)
    result = work / "result.json"
    args = [str(work / "plan.json"), str(result), str(seed), str(timeout)]
    rclpy_side = bridge.ros2.run_node(DATA / node, *args)
    echo: Lines | None = None

    def discovered() -> bool:
        return bridge.knows_services(sorted(served))

    try:
        # Not ready (it ended first): its output says why, and every type is then "no answer".
        if rclpy_side.wait_for(lambda line: line == "ready", timeout) and served:
            wait_for("rosbridge to discover the rclpy services", discovered, timeout, bridge.logs)
        echo = start([*client, bridge.url, str(work / "plan.txt")])
    finally:
        node_output = rclpy_side.finish(timeout=timeout + 120)
        client_output = echo.finish() if echo else ""
    results = json.loads(result.read_text()) if result.exists() else {}
    return Outcome(results, node_output, client_output)
