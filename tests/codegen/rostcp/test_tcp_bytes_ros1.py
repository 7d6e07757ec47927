"""ROS 1 bytes: every Debian ROS 1 type the suite enumerates plus the sample's diffbot_msgs,
as our classes with the vendored connector's real MessageSerializer, equal genpy's serialize().

For each type (messages, action messages, both halves of every service): the default instance
and four seeded random ones (extremes, NaN/±inf/-0.0, UTF-8, array lengths 0-3) from genpy.
The C# instance built from the same values serializes to genpy's bytes; the class's Deserialize
reads genpy's bytes to the last one and gives the same values; a default-constructed instance
equals genpy's default. All cases run in one Mono process. The only failures allowed are those a
shipped class's warning announces (Debian's: the connector's QuaternionMsg starts with w = 1).
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest
from helpers import SYSTEM_PYTHON, require

from tests.codegen.rostcp.tcp_helpers import HERE, connector_package
from tests.codegen.rostcp.wire import Case, Verdict, build_checker, excused, run_checker
from tests.runtime.runtime_helpers import (
    SAMPLE_INTERFACES,
    message_types,
    python_package_of,
    ros1_registry,
    service_types,
)
from unityscaffold.codegen import ClassRole, GeneratedCode, Options
from unityscaffold.codegen.rostcp import generate
from unityscaffold.interfaces.model import Dialect, MessageSpec
from unityscaffold.interfaces.registry import Registry

CASES_SCRIPT = HERE / "python" / "ros1_cases.py"


Types = dict[str, tuple[MessageSpec, str]]
Run = tuple[list[Verdict], Types, GeneratedCode]


def _types(code: GeneratedCode, registry: Registry) -> Types:
    """genpy's name of each type -> (its spec, its C# class)."""
    found: Types = {}
    for spec in message_types(registry):
        found[spec.full_name] = (spec, code.message_class(spec.full_name).full_name)
    for service in service_types(registry):
        roles = code.classes[f"{service.package}/srv/{service.name}"]
        for role, half in (
            (ClassRole.REQUEST, service.request),
            (ClassRole.RESPONSE, service.response),
        ):
            name = f"{service.package}/srv/{half.name}"
            found[name] = (half, roles[role].full_name)
    return found


@pytest.fixture(scope="module")
def ros1_verdicts(
    mcs: str, mono: str, ros1_share: Path, tmp_path_factory: pytest.TempPathFactory
) -> Run:
    require(Path("/usr/lib/genpy/genmsg_py.py").exists(), "Debian's python3-genpy")
    work = tmp_path_factory.mktemp("tcp_bytes_ros1")
    registry = ros1_registry()
    roots = [*message_types(registry), *service_types(registry)]
    code = generate(registry, roots, Options(Dialect.ROS1))
    types = _types(code, registry)
    python_package_of(SAMPLE_INTERFACES, "diffbot_msgs", work / "python")
    env = {**os.environ, "PYTHONPATH": str(work / "python")}
    made = subprocess.run(
        [str(SYSTEM_PYTHON), str(CASES_SCRIPT), "--random", "4"],
        input="\n".join(types),
        capture_output=True,
        text=True,
        check=True,
        env=env,
        timeout=600,
    )
    cases = []
    for line in made.stdout.splitlines():
        name, label, reference, values = line.split("\t")
        cases.append(Case(name, label, types[name][1], reference, values))
    exe = build_checker(mcs, connector_package(), code, work / "bin", ros2=False)
    return run_checker(mono, exe, cases, work), types, code


def test_every_ros1_case_equals_genpy_but_what_a_warning_announces(ros1_verdicts: Run) -> None:
    verdicts, types, code = ros1_verdicts
    registry = ros1_registry()
    unexpected = [
        f"{v.ros_type} {v.label}: {v.problem}"
        for v in verdicts
        if v.problem and not excused(v, types[v.ros_type][0], registry, code)
    ]
    assert not unexpected, "\n".join(unexpected)
    assert len({v.ros_type for v in verdicts}) == len(types) > 200
    assert len(verdicts) == 5 * len(types)


def test_random_ros1_cases_all_pass(ros1_verdicts: Run) -> None:
    verdicts, _, _ = ros1_verdicts
    failed = [
        f"{v.ros_type} {v.label}: {v.problem}"
        for v in verdicts
        if v.problem and v.label != "default"
    ]
    assert not failed, "\n".join(failed)


def test_only_defaults_holding_a_quaternion_fail_and_the_quaternion_is_warned_about(
    ros1_verdicts: Run,
) -> None:
    """The connector's QuaternionMsg starts with w = 1 (genpy: 0): the default instance of a
    type that holds one outside a variable-length array differs, and nothing else."""
    verdicts, types, code = ros1_verdicts
    registry = ros1_registry()
    failed = {v.ros_type for v in verdicts if v.problem}
    assert "geometry_msgs/Quaternion" in failed
    for name in failed:
        spec = types[name][0]
        held = {m.full_name for m in registry.closure([spec])} | {spec.full_name}
        assert "geometry_msgs/Quaternion" in held, name
    assert all(v.problem.startswith("DEFAULT") for v in verdicts if v.problem)
    warned = [s for s in code.skipped if s.warning and "never registers" not in s.warning]
    assert [s.ros_type for s in warned] == ["geometry_msgs/Quaternion"]
