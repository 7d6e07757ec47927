"""Helpers for the C# generator's tests: the test packages, code, and ROS#'s runtime.

A named module rather than ``conftest.py``, so tests import it explicitly (``conftest`` keeps
only fixtures, and several folders have one).
"""

from __future__ import annotations

from pathlib import Path

from csharp import ROSSHARP_STUB, Compiled, compile_cs

from unityscaffold.codegen import GeneratedCode, Options, generate
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry

HERE = Path(__file__).resolve().parent
DATA = HERE / "data"
GOLDEN = HERE / "golden"


# The action bases of the ROS# stub use these; compile them with any set that has no action.
STUB_NEEDS = {
    Dialect.ROS1: ("std_msgs/Header", "actionlib_msgs/GoalID", "actionlib_msgs/GoalStatus"),
    Dialect.ROS2: ("std_msgs/msg/Header", "action_msgs/msg/GoalInfo", "action_msgs/msg/GoalStatus"),
}


def write_tree(code: GeneratedCode, out: Path) -> list[Path]:
    """Write every generated file under ``out``; return their paths."""
    paths = []
    for file in code.files:
        path = out / file.path
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(file.text, encoding="utf-8", newline="\n")
        paths.append(path)
    return paths


def generate_all(dialect: Dialect, **options: object) -> GeneratedCode:
    """C# for every type found (the Debian ROS 1 set or the Jazzy wheels)."""
    registry = Registry.load(dialect)
    interfaces, problems = registry.parse_all()
    assert not problems
    return generate(registry, interfaces, Options(dialect, **options))  # type: ignore[arg-type]


def generate_data(dialect: Dialect, names: list[str], **options: object) -> GeneratedCode:
    """C# for ``names`` from the test packages in ``data/``."""
    folder = DATA / ("ros1" if dialect is Dialect.ROS1 else "ros2")
    registry = Registry.load(dialect, [folder])
    roots = [registry.get(n) for n in names]
    return generate(registry, roots, Options(dialect, **options))  # type: ignore[arg-type]


def compile_all(mcs: str, dialect: Dialect, out: Path) -> tuple[GeneratedCode, Compiled]:
    """Every type of ``dialect``, ROS#-shipped ones included, compiled against the stub."""
    code = generate_all(dialect, include_shipped=True)
    sources = [ROSSHARP_STUB, *write_tree(code, out / "src")]
    name = "AllRos1.dll" if dialect is Dialect.ROS1 else "AllRos2.dll"
    return code, compile_cs(mcs, sources, out / name, ros2=dialect is Dialect.ROS2)


def compile_runtime(mcs: str, dialect: Dialect, out: Path) -> Compiled:
    """A stand-in for ROS#'s runtime assembly: the stub plus every type ROS# ships that the
    test packages use (generated with --include-shipped)."""
    names = ["scaffold_test_msgs/Kitchen", "scaffold_test_msgs/Cook", "scaffold_test_msgs/Lookup"]
    code = generate_data(dialect, names, include_shipped=True)
    shipped = [f for f in code.files if not f.path.startswith("ScaffoldTest/")]
    sources = [ROSSHARP_STUB]
    for file in shipped:
        path = out / "src" / file.path
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(file.text, encoding="utf-8")
        sources.append(path)
    return compile_cs(mcs, sources, out / "RosSharpRuntime.dll", ros2=dialect is Dialect.ROS2)
