"""Fixtures for the C# generator's tests: whole sets compiled once per session with Mono's mcs.

Big sets (all Debian ROS 1 types, all Jazzy interfaces) are generated and compiled once per
session; each compile returns mcs's output so tests can assert on errors and warnings. The
helpers behind them are in ``codegen_helpers``.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from codegen_helpers import compile_all, compile_runtime
from csharp import Compiled

from unityscaffold.codegen import GeneratedCode
from unityscaffold.interfaces.model import Dialect


@pytest.fixture(scope="session")
def compiled_all_ros1(
    mcs: str, ros1_share: Path, tmp_path_factory: pytest.TempPathFactory
) -> tuple[GeneratedCode, Compiled]:
    return compile_all(mcs, Dialect.ROS1, tmp_path_factory.mktemp("all_ros1"))


@pytest.fixture(scope="session")
def compiled_all_ros2(
    mcs: str, ros2_share: Path, tmp_path_factory: pytest.TempPathFactory
) -> tuple[GeneratedCode, Compiled]:
    return compile_all(mcs, Dialect.ROS2, tmp_path_factory.mktemp("all_ros2"))


@pytest.fixture(scope="session")
def runtime_ros1(mcs: str, ros1_share: Path, tmp_path_factory: pytest.TempPathFactory) -> Compiled:
    compiled = compile_runtime(mcs, Dialect.ROS1, tmp_path_factory.mktemp("runtime_ros1"))
    compiled.assert_clean()
    return compiled


@pytest.fixture(scope="session")
def runtime_ros2(mcs: str, ros2_share: Path, tmp_path_factory: pytest.TempPathFactory) -> Compiled:
    compiled = compile_runtime(mcs, Dialect.ROS2, tmp_path_factory.mktemp("runtime_ros2"))
    compiled.assert_clean()
    return compiled
