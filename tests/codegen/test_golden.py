"""Whole generated trees, held fixed and compared byte for byte (and compiled).

A mismatch is reported as a unified diff per file. Regenerate after an intended change, then
review the diff:

    UNITYSCAFFOLD_UPDATE=1 python3 -m pytest tests/codegen/test_golden.py
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from codegen_helpers import DATA, GOLDEN
from csharp import Compiled, compile_cs
from helpers import assert_same_tree, updating

from unityscaffold.cli import main

CASES = {
    "ros1": ["--ros", "1", "--path", str(DATA / "ros1"), "scaffold_test_msgs"],
    "ros2": ["--ros", "2", "--path", str(DATA / "ros2"), "scaffold_test_msgs"],
    "ros1_namespace": [
        "--ros",
        "1",
        "--path",
        str(DATA / "ros1"),
        "--namespace",
        "MyRobot.Msgs",
        "scaffold_test_msgs/Cook",
    ],
}


def _generate(case: str, tmp_path: Path) -> Path:
    out = tmp_path / "out"
    assert main(["msgs", "gen", *CASES[case], "--out", str(out)]) == 0
    return out


@pytest.mark.parametrize("case", sorted(CASES))
def test_generated_tree_matches_golden(case: str, tmp_path: Path) -> None:
    out = _generate(case, tmp_path)
    golden = GOLDEN / case
    if updating():
        shutil.rmtree(golden, ignore_errors=True)
        shutil.copytree(out, golden)
    assert_same_tree(out, golden)


@pytest.mark.parametrize("case", ["ros1", "ros2"])
def test_golden_csharp_compiles(
    case: str, mcs: str, tmp_path: Path, request: pytest.FixtureRequest
) -> None:
    runtime: Compiled = request.getfixturevalue(f"runtime_{case}")
    sources = sorted((GOLDEN / case).rglob("*.cs"))
    assert sources
    compile_cs(
        mcs, sources, tmp_path / "Golden.dll", ros2=case == "ros2", references=(runtime.assembly,)
    ).assert_clean()


def test_golden_namespace_case_compiles(mcs: str, tmp_path: Path, runtime_ros1: Compiled) -> None:
    sources = sorted((GOLDEN / "ros1_namespace").rglob("*.cs"))
    compile_cs(
        mcs, sources, tmp_path / "GoldenNs.dll", ros2=False, references=(runtime_ros1.assembly,)
    ).assert_clean()
