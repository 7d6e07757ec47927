"""Fixtures for the C# generator's tests: generation helpers and Mono's compiler.

Big sets (all Debian ROS 1 types, all Jazzy interfaces) are generated and compiled once per
session; each compile returns mcs's output so tests can assert on errors and warnings.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from csharp import MCS_FLAGS, Compiled, compile_cs  # noqa: F401 (re-exported to tests)

from unityscaffold.codegen import Generation, Options, generate
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry

HERE = Path(__file__).resolve().parent
DATA = HERE / "data"
STUB = HERE / "stubs" / "RosSharpStub.cs"
GOLDEN = HERE / "golden"


def write_tree(generation: Generation, out: Path) -> list[Path]:
    paths = []
    for file in generation.files:
        path = out / file.path
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(file.text, encoding="utf-8", newline="\n")
        paths.append(path)
    return paths


def generate_all(dialect: Dialect, **options: object) -> Generation:
    registry = Registry.load(dialect)
    interfaces, problems = registry.parse_all()
    assert not problems
    return generate(registry, interfaces, Options(dialect, **options))  # type: ignore[arg-type]


def generate_data(dialect: Dialect, names: list[str], **options: object) -> Generation:
    folder = DATA / ("ros1" if dialect is Dialect.ROS1 else "ros2")
    registry = Registry.load(dialect, [folder])
    roots = [registry.get(n) for n in names]
    return generate(registry, roots, Options(dialect, **options))  # type: ignore[arg-type]


@pytest.fixture(scope="session")
def compiled_all_ros1(
    mcs: str, ros1_share: Path, tmp_path_factory: pytest.TempPathFactory
) -> tuple[Generation, Compiled]:
    out = tmp_path_factory.mktemp("all_ros1")
    generation = generate_all(Dialect.ROS1, include_shipped=True)
    sources = [STUB, *write_tree(generation, out / "src")]
    return generation, compile_cs(mcs, sources, out / "AllRos1.dll", ros2=False)


@pytest.fixture(scope="session")
def compiled_all_ros2(
    mcs: str, ros2_share: Path, tmp_path_factory: pytest.TempPathFactory
) -> tuple[Generation, Compiled]:
    out = tmp_path_factory.mktemp("all_ros2")
    generation = generate_all(Dialect.ROS2, include_shipped=True)
    sources = [STUB, *write_tree(generation, out / "src")]
    return generation, compile_cs(mcs, sources, out / "AllRos2.dll", ros2=True)


def _runtime(mcs: str, dialect: Dialect, out: Path) -> Compiled:
    """A stand-in for ROS#'s runtime assembly: the stub plus every type ROS# ships that the
    test packages use (generated with --include-shipped)."""
    names = ["scaffold_test_msgs/Kitchen", "scaffold_test_msgs/Cook", "scaffold_test_msgs/Lookup"]
    generation = generate_data(dialect, names, include_shipped=True)
    shipped = [f for f in generation.files if not f.path.startswith("ScaffoldTest/")]
    sources = [STUB]
    for file in shipped:
        path = out / "src" / file.path
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(file.text, encoding="utf-8")
        sources.append(path)
    return compile_cs(mcs, sources, out / "RosSharpRuntime.dll", ros2=dialect is Dialect.ROS2)


@pytest.fixture(scope="session")
def runtime_ros1(mcs: str, ros1_share: Path, tmp_path_factory: pytest.TempPathFactory) -> Compiled:
    compiled = _runtime(mcs, Dialect.ROS1, tmp_path_factory.mktemp("runtime_ros1"))
    compiled.assert_clean()
    return compiled


@pytest.fixture(scope="session")
def runtime_ros2(mcs: str, ros2_share: Path, tmp_path_factory: pytest.TempPathFactory) -> Compiled:
    compiled = _runtime(mcs, Dialect.ROS2, tmp_path_factory.mktemp("runtime_ros2"))
    compiled.assert_clean()
    return compiled
