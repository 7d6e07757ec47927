"""Generated connector classes compile with mcs, warnings as errors, against the vendored
connector's real message runtime and shipped classes, with and without ``ROS2``; and the golden
trees of the test packages hold the generated text fixed.

Regenerate the golden trees after an intended change, then review the diff:

    UNITYSCAFFOLD_UPDATE=1 python3 -m pytest tests/codegen/rostcp/test_tcp_compile.py
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from codegen_helpers import DATA
from helpers import assert_same_tree, updating

from tests.codegen.rostcp.tcp_helpers import (
    HERE,
    compile_generated,
    compile_runtime,
    connector_package,
    write_files,
)
from unityscaffold.codegen import GeneratedCode, Options
from unityscaffold.codegen.rostcp import generate
from unityscaffold.interfaces.model import ActionSpec, Dialect, MessageSpec
from unityscaffold.interfaces.registry import Registry

GOLDEN = HERE / "golden"
GOLDEN_CASES = {
    "ros1": (
        Dialect.ROS1,
        DATA / "ros1",
        ["scaffold_test_msgs/Kitchen", "scaffold_test_msgs/Cook", "scaffold_test_msgs/Lookup"],
    ),
    "ros2": (Dialect.ROS2, HERE / "data" / "ros2", ["tcp_test_msgs/msg/Pantry"]),
}


def _every_type(dialect: Dialect) -> list[GeneratedCode]:
    """Every interface found, in as few runs as the connector's one-class-per-name rule allows:
    messages, then each service alone (test_msgs has a message and a service of one name);
    ROS 2 actions and types with a wstring are refused, so left out."""
    registry = Registry.load(dialect)
    interfaces, problems = registry.parse_all()
    assert not problems
    usable = [i for i in interfaces if "WString" not in i.name]
    messages = [i for i in usable if isinstance(i, MessageSpec)]
    others = [i for i in usable if not isinstance(i, MessageSpec)]
    if dialect is Dialect.ROS2:
        others = [i for i in others if not isinstance(i, ActionSpec)]
    if dialect is Dialect.ROS1:
        return [generate(registry, interfaces, Options(dialect))]
    return [
        generate(registry, roots, Options(dialect)) for roots in [messages, *([o] for o in others)]
    ]


def _sources(codes: list[GeneratedCode], out: Path) -> list[Path]:
    texts: dict[str, str] = {}
    for code in codes:
        for file in code.files:
            assert texts.setdefault(file.path, file.text) == file.text, file.path
    written = write_files(
        GeneratedCode(tuple(f for c in codes for f in c.files if texts.pop(f.path, None)), ()), out
    )
    return written


@pytest.mark.parametrize("dialect", [Dialect.ROS1, Dialect.ROS2], ids=["ros1", "ros2"])
def test_every_type_compiles_against_the_connectors_runtime(
    dialect: Dialect, mcs: str, tmp_path: Path, request: pytest.FixtureRequest
) -> None:
    request.getfixturevalue("ros1_share" if dialect is Dialect.ROS1 else "ros2_share")
    ros2 = dialect is Dialect.ROS2
    references = compile_runtime(mcs, connector_package(), tmp_path / "runtime", ros2=ros2)
    sources = _sources(_every_type(dialect), tmp_path / "src")
    assert len(sources) > 30
    compile_generated(
        mcs, sources, references, tmp_path / "Generated.dll", ros2=ros2
    ).assert_clean()


@pytest.mark.parametrize("case", sorted(GOLDEN_CASES))
def test_generated_tree_matches_golden_and_compiles(
    case: str, mcs: str, tmp_path: Path, request: pytest.FixtureRequest
) -> None:
    dialect, folder, names = GOLDEN_CASES[case]
    request.getfixturevalue("ros1_share" if dialect is Dialect.ROS1 else "ros2_share")
    registry = Registry.load(dialect, [folder])
    code = generate(registry, [registry.get(n) for n in names], Options(dialect))
    out = tmp_path / "out"
    sources = write_files(code, out)
    if updating():
        shutil.rmtree(GOLDEN / case, ignore_errors=True)
        shutil.copytree(out, GOLDEN / case)
    assert_same_tree(out, GOLDEN / case)
    ros2 = dialect is Dialect.ROS2
    references = compile_runtime(mcs, connector_package(), tmp_path / "runtime", ros2=ros2)
    compile_generated(mcs, sources, references, tmp_path / "Golden.dll", ros2=ros2).assert_clean()


@pytest.mark.parametrize("dialect", [Dialect.ROS1, Dialect.ROS2], ids=["ros1", "ros2"])
def test_a_flipped_ros2_define_fails_to_compile_instead_of_garbling_the_wire(
    dialect: Dialect, mcs: str, tmp_path: Path, request: pytest.FixtureRequest
) -> None:
    case = "ros1" if dialect is Dialect.ROS1 else "ros2"
    request.getfixturevalue(f"{case}_share")
    flipped = dialect is Dialect.ROS1
    references = compile_runtime(mcs, connector_package(), tmp_path / "runtime", ros2=flipped)
    program = tmp_path / "Uses.cs"
    used = "ScaffoldTest.KitchenMsg" if case == "ros1" else "TcpTest.PantryMsg"
    program.write_text(f"class Uses {{ object m = new RosMessageTypes.{used}(); }}\n")
    sources = [*sorted((GOLDEN / case).rglob("*.cs")), program]
    compiled = compile_generated(mcs, sources, references, tmp_path / "Flipped.dll", ros2=flipped)
    assert compiled.returncode != 0
    assert "CS0234" in compiled.output or "CS0246" in compiled.output, compiled.output
