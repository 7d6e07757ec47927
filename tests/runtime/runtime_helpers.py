"""Helpers of the runtime tests: which types to exercise, their C# classes, the echo program,
and running the rospy side of a round trip."""

from __future__ import annotations

import json
import os
import subprocess
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from helpers import SYSTEM_PYTHON

from tests.runtime.bridge import GENMSG_PY, GENSRV_PY, ROS1_SHARE, Bridge
from tests.runtime.client import CSHARP, build_client, mcs_compile
from tests.runtime.lines import Lines, start
from unityscaffold.codegen import ClassRole, GeneratedCode, Options, generate
from unityscaffold.interfaces.model import Dialect, MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry

REPO = Path(__file__).resolve().parents[2]
DATA = Path(__file__).parent / "data"
SAMPLE_INTERFACES = REPO / "sample_project" / "ros_ws" / "src"
# Its ROS 2 counterpart (scripts/ros2_stack.py builds it into the ROS 2 stack).
SAMPLE_ROS2_INTERFACES = REPO / "sample_project" / "ros2_ws" / "src"
# ROS# maps these two to its hand-written time primitives: a known defect (test_wire_defects.py).
TIME_PRIMITIVES = ("std_msgs/Time", "std_msgs/Duration")


def ros1_registry() -> Registry:
    """Debian's ROS 1 packages plus the sample's diffbot_msgs (no built-in copies)."""
    return Registry.load(Dialect.ROS1, [SAMPLE_INTERFACES], use_builtin=False)


def message_types(registry: Registry) -> list[MessageSpec]:
    """Every message type: .msg files, action messages; service halves separately."""
    interfaces, problems = registry.parse_all()
    assert not problems, problems
    messages: dict[str, MessageSpec] = {}
    for spec in registry.closure(interfaces):
        if spec.subfolder != "srv":
            messages[spec.full_name] = spec
    return [messages[name] for name in sorted(messages)]


def python_package_of(interfaces: Path, package: str, out: Path) -> None:
    """genpy modules for ``package`` (its messages, the messages of its actions as genaction
    writes them, and its services) under ``out/package``, importable by rospy and rosbridge."""
    registry = Registry.load(Dialect.ROS1, [interfaces], use_builtin=False)
    interfaces_of, problems = registry.parse_all()
    assert not problems, problems
    msg_folder = out / "definitions" / package / "msg"
    msg_folder.mkdir(parents=True)
    for spec in registry.closure(interfaces_of):
        if spec.package == package and spec.subfolder != "srv":
            (msg_folder / f"{spec.name}.msg").write_text(spec.text)
    includes = [f"-I{package}:{msg_folder}"] + [
        f"-I{p.parent.name}:{p}" for p in sorted(ROS1_SHARE.glob("*/msg")) if p.is_dir()
    ]
    target = out / package
    target.mkdir()
    (target / "__init__.py").write_text("")
    for kind, script, folder in (
        ("msg", GENMSG_PY, msg_folder),
        ("srv", GENSRV_PY, interfaces / package / "srv"),
    ):
        sources = sorted(folder.glob(f"*.{kind}"))
        base = [str(SYSTEM_PYTHON), str(script), "-p", package, "-o", str(target / kind)]
        base += includes
        for source in sources:
            subprocess.run([*base, str(source)], check=True, capture_output=True, timeout=60)
        if sources:
            subprocess.run([*base, "--initpy"], check=True, capture_output=True, timeout=60)


def write_code(code: GeneratedCode, out: Path) -> list[Path]:
    paths = []
    for file in code.files:
        if file.path.endswith(".cs"):
            path = out / file.path
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(file.text, encoding="utf-8")
            paths.append(path)
    return paths


@dataclass(frozen=True)
class EchoProgram:
    folder: Path
    classes: dict[str, str]  # ROS type -> C# full class name


def build_ours_only_client(
    mcs: str,
    package: Path,
    registry: Registry,
    roots: Sequence[MessageSpec | ServiceSpec],
    out: Path,
) -> Path:
    """ROS#'s client compiled without its message classes, with ours for ``roots`` and every
    type they use instead (``--include-shipped``)."""
    code = generate(registry, list(roots), Options(Dialect.ROS1, include_shipped=True))
    return build_client(mcs, package, out, message_sources=write_code(code, out / "src"))


def build_echo(
    mcs: str,
    client: Path,
    registry: Registry,
    roots: list[MessageSpec],
    out: Path,
    *,
    include_shipped: bool = False,
    namespace: str | None = None,
    services: Sequence[ServiceSpec] = (),
) -> EchoProgram:
    """Echo.exe beside ``client``. By default the client is ROS#'s with its shipped classes and
    ours cover the rest; with ``include_shipped`` the client already holds ours for every type
    (``build_ours_only_client``)."""
    options = Options(Dialect.ROS1, include_shipped=include_shipped, namespace=namespace)
    code = generate(registry, [*roots, *services], options)
    sources = [CSHARP / "Echo.cs"]
    if services:
        sources.append(CSHARP / "ServiceEcho.cs")
    if not include_shipped:
        sources += write_code(code, out / "src")
    folder = client.parent
    exe = folder / f"{out.name}.exe"
    references = [client, folder / "Newtonsoft.Json.dll", folder / "websocket-sharp.dll"]
    main = "ServiceEcho" if services else "Echo"
    mcs_compile(mcs, sources, exe, references=references, target="exe", main=main)
    classes = {spec.full_name: code.message_class(spec.full_name).full_name for spec in roots}
    for service in services:
        halves = code.classes[f"{service.package}/srv/{service.name}"]
        classes[service.full_name] = " ".join(
            halves[role].full_name for role in (ClassRole.REQUEST, ClassRole.RESPONSE)
        )
    return EchoProgram(exe, classes)


def service_types(registry: Registry) -> list[ServiceSpec]:
    """Every ROS 1 service type."""
    interfaces, problems = registry.parse_all()
    assert not problems, problems
    return sorted((i for i in interfaces if isinstance(i, ServiceSpec)), key=lambda s: s.full_name)


@dataclass(frozen=True)
class RoundTrip:
    results: dict[str, Any]
    echo_output: str
    node_output: str


def round_trip(
    bridge: Bridge,
    mono: str,
    echo: EchoProgram,
    entries: list[str] | list[dict[str, Any]],
    work: Path,
    *,
    seed: int = 13,
    timeout: float = 60,
) -> RoundTrip:
    """rospy publishes each type, ROS#'s client echoes it through rosbridge, rospy compares.
    An entry is a type name or a plan entry (see data/roundtrip_node.py: key, set, delay)."""
    work.mkdir(parents=True, exist_ok=True)
    plan = [
        {
            **({"type": entry} if isinstance(entry, str) else entry),
            "in": f"/rt{seed}/in{i}",
            "out": f"/rt{seed}/out{i}",
        }
        for i, entry in enumerate(entries)
    ]
    (work / "plan.json").write_text(json.dumps(plan))
    (work / "plan.txt").write_text(
        "".join(f"{p['in']} {p['out']} {echo.classes[p['type']]}\n" for p in plan)
    )
    return _run_pair(bridge, mono, echo, work, "roundtrip_node.py", seed, timeout)


def _run_pair(
    bridge: Bridge, mono: str, echo: EchoProgram, work: Path, node: str, seed: int, timeout: float
) -> RoundTrip:
    """Run the rospy side (``data/node``) and, once it says "ready" (its topics or services are
    known to the master), the C# side, on ``work``'s plan files. Either side still running when
    it should have ended is killed, and says so in its output."""
    result = work / "result.json"
    args = [str(work / "plan.json"), str(result), str(seed), str(timeout)]
    rospy_side = start([str(SYSTEM_PYTHON), str(DATA / node), *args], bridge.env)
    client: Lines | None = None
    try:
        # Not ready (it ended first): its output says why, and every type is then "no answer".
        rospy_side.wait_for(lambda line: line == "ready", timeout)
        client = start(
            [mono, str(echo.folder), bridge.url, str(work / "plan.txt")],
            {**os.environ, "MONO_ENV_OPTIONS": ""},
        )
    finally:
        # The node ends on its own within ``timeout``; a hang is killed and reported by the
        # caller's assertion, with both outputs. ROS#'s Close can hang on a socket rosbridge
        # broke: the client is killed after finish's grace period then.
        node_output = rospy_side.finish(timeout=timeout + 60)
        echo_output = client.finish() if client else ""
    results = json.loads(result.read_text()) if result.exists() else {}
    return RoundTrip(results, echo_output, node_output)


def service_round_trip(
    bridge: Bridge,
    mono: str,
    echo: EchoProgram,
    types: list[str],
    work: Path,
    *,
    seed: int = 31,
    timeout: float = 60,
) -> RoundTrip:
    """Both halves of each service type through ROS#'s client, as client and as server (see
    data/service_node.py and csharp/ServiceEcho.cs)."""
    work.mkdir(parents=True, exist_ok=True)
    plan = [
        {"type": name, "py": f"/srv{seed}/py{i}", "cs": f"/srv{seed}/cs{i}"}
        for i, name in enumerate(types)
    ]
    (work / "plan.json").write_text(json.dumps(plan))
    (work / "plan.txt").write_text(
        "".join(f"{p['py']} {p['cs']} {echo.classes[p['type']]}\n" for p in plan)
    )
    return _run_pair(bridge, mono, echo, work, "service_node.py", seed, timeout)
