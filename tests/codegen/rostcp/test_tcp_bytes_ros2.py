"""ROS 2 bytes: every message and service type of the Jazzy wheels the suite installs (the ROS 2
stack's venv: common_interfaces, test_msgs, rcl_interfaces, …), as our classes with the vendored
connector's real MessageSerializer under ROS2, equal rclpy's serialize_message.

For each type (messages, both halves of every service): the default instance and four seeded
random ones from rclpy. The C# instance built from the same values serializes to rclpy's bytes
except in the alignment padding, which must be zero (rmw_fastrtps leaves it uninitialised: a
walk of the type finds it) and ends where the payload does; the class's Deserialize reads
rclpy's bytes to the payload's end and gives the same values; a default-constructed instance
equals rclpy's default; and rclpy's deserialize_message turns our bytes back into the original.
Types that hold a wstring are refused by the generator (test_tcp_generate) and left out; ROS 2
actions too. The only failures allowed are those a shipped class's warning announces.
"""

from __future__ import annotations

import subprocess

import pytest

from tests.codegen.rostcp.tcp_helpers import HERE, connector_package, ros2_python
from tests.codegen.rostcp.wire import Case, Verdict, build_checker, excused, run_checker
from unityscaffold.codegen import ClassRole, GeneratedCode, GeneratedFile, Options
from unityscaffold.codegen.rostcp import generate
from unityscaffold.interfaces.model import Dialect, MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry

CASES_SCRIPT = HERE / "python" / "ros2_cases.py"
Types = dict[str, tuple[MessageSpec, str]]
Run = tuple[list[Verdict], Types, GeneratedCode, Registry]


def _holds_wstring(spec: MessageSpec, registry: Registry) -> bool:
    return any(
        f.type.base == "wstring" for m in [spec, *registry.closure([spec])] for f in m.fields
    )


def _generate_all(registry: Registry) -> tuple[GeneratedCode, Types]:
    """Messages in one run, each service in a run of its own (test_msgs has messages and
    services of one name: the connector registers one class per name); one code of it all."""
    interfaces, problems = registry.parse_all()
    assert not problems, problems
    messages = [
        m
        for m in registry.closure(i for i in interfaces if isinstance(i, MessageSpec))
        if m.owner is None and not _holds_wstring(m, registry)
    ]
    services = [
        s
        for s in interfaces
        if isinstance(s, ServiceSpec)
        and not any(_holds_wstring(h, registry) for h in (s.request, s.response))
    ]
    options = Options(Dialect.ROS2)
    runs = [generate(registry, messages, options)]
    types: Types = {
        m.full_name: (m, runs[0].message_class(m.full_name).full_name) for m in messages
    }
    for service in services:
        code = generate(registry, [service], options)
        runs.append(code)
        roles = code.classes[f"{service.package}/srv/{service.name}"]
        for role, half in (
            (ClassRole.REQUEST, service.request),
            (ClassRole.RESPONSE, service.response),
        ):
            types[half.full_name] = (half, roles[role].full_name)
    files: dict[str, GeneratedFile] = {}
    for code in runs:
        for file in code.files:
            assert files.setdefault(file.path, file).text == file.text, file.path
    skipped = tuple({s.path: s for code in runs for s in code.skipped}.values())
    classes = {name: roles for code in runs for name, roles in code.classes.items()}
    return GeneratedCode(tuple(files.values()), skipped, classes), types


@pytest.fixture(scope="module")
def ros2_verdicts(mcs: str, mono: str, tmp_path_factory: pytest.TempPathFactory) -> Run:
    python = ros2_python()
    work = tmp_path_factory.mktemp("tcp_bytes_ros2")
    registry = Registry.load(Dialect.ROS2, [python.parents[1] / "share"], use_builtin=False)
    code, types = _generate_all(registry)
    made = subprocess.run(
        [str(python), str(CASES_SCRIPT), "make", "--random", "4"],
        input="\n".join(types),
        capture_output=True,
        text=True,
        check=True,
        timeout=900,
    )
    cases = []
    for line in made.stdout.splitlines():
        name, label, reference, mask, end, values = line.split("\t")
        cases.append(Case(name, label, types[name][1], reference, values, mask, int(end)))
    exe = build_checker(mcs, connector_package(), code, work / "bin", ros2=True)
    verdicts = run_checker(mono, exe, cases, work)
    ours = "".join(f"{v.ros_type}\t{v.label}\t{v.ours}\n" for v in verdicts if v.ours)
    back = subprocess.run(
        [str(python), str(CASES_SCRIPT), "check", "--random", "4"],
        input=ours,
        capture_output=True,
        text=True,
        check=True,
        timeout=900,
    )
    lost = {}
    for line in back.stdout.splitlines():
        name, label, got = line.split("\t")
        lost[f"{name} {label}"] = f"rclpy's deserialize_message gives {got}"
    verdicts = [
        Verdict(
            v.ros_type, v.label, _joined(v.problem, lost.get(f"{v.ros_type} {v.label}")), v.ours
        )
        for v in verdicts
    ]
    return verdicts, types, code, registry


def _joined(*problems: str | None) -> str | None:
    found = [p for p in problems if p]
    return "; ".join(found) if found else None


def test_every_ros2_case_equals_rclpy_but_what_a_warning_announces(ros2_verdicts: Run) -> None:
    verdicts, types, code, registry = ros2_verdicts
    unexpected = [
        f"{v.ros_type} {v.label}: {v.problem}"
        for v in verdicts
        if v.problem and not excused(v, types[v.ros_type][0], registry, code)
    ]
    assert not unexpected, "\n".join(unexpected)
    assert len({v.ros_type for v in verdicts}) == len(types) > 200
    assert len(verdicts) == 5 * len(types)


def test_the_test_msgs_cases_all_pass(ros2_verdicts: Run) -> None:
    """Arrays, Bounded/UnboundedSequences, MultiNested (empty Constants inside), Strings
    (bounded, defaults), Defaults, Constants, Empty: what the connector's own classes and
    generator get wrong."""
    verdicts, _, _, _ = ros2_verdicts
    names = (
        "Arrays",
        "BoundedSequences",
        "UnboundedSequences",
        "MultiNested",
        "Strings",
        "Defaults",
        "Constants",
        "Empty",
    )
    checked = {v.ros_type for v in verdicts if v.ros_type.startswith("test_msgs/msg/")}
    assert {f"test_msgs/msg/{n}" for n in names} <= checked
    failed = [
        f"{v.ros_type} {v.label}: {v.problem}"
        for v in verdicts
        if v.problem and v.ros_type.startswith("test_msgs/")
    ]
    assert not failed, "\n".join(failed)


def test_the_stale_shipped_classes_fail_and_are_warned_about(ros2_verdicts: Run) -> None:
    verdicts, _, code, _ = ros2_verdicts
    warnings = {s.ros_type: s.warning for s in code.skipped if s.warning}
    failed = {v.ros_type for v in verdicts if v.problem}
    for stale in (
        "sensor_msgs/msg/Range",
        "shape_msgs/msg/SolidPrimitive",
        "visualization_msgs/msg/Marker",
        "std_msgs/msg/Empty",
        "std_srvs/srv/Trigger_Request",
    ):
        assert stale in failed, stale
    for warned in (
        "sensor_msgs/msg/Range",
        "shape_msgs/msg/SolidPrimitive",
        "visualization_msgs/msg/Marker",
        "visualization_msgs/msg/MarkerArray",
        "std_msgs/msg/Empty",
    ):
        assert warned in warnings, warned
