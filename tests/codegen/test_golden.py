"""Whole generated trees, held fixed and compared byte for byte (and compiled).

Regenerate after an intended change, then review the diff:

    UPDATE_GOLDEN=1 python3 -m pytest tests/codegen/test_golden.py
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from conftest import DATA, GOLDEN, Compiled, compile_cs

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


def _tree(root: Path) -> dict[str, bytes]:
    return {
        p.relative_to(root).as_posix(): p.read_bytes()
        for p in sorted(root.rglob("*"))
        if p.is_file()
    }


def _generate(case: str, tmp_path: Path) -> Path:
    out = tmp_path / "out"
    assert main(["msgs", "gen", *CASES[case], "--out", str(out)]) == 0
    return out


@pytest.mark.parametrize("case", sorted(CASES))
def test_generated_tree_matches_golden(case: str, tmp_path: Path) -> None:
    out = _generate(case, tmp_path)
    golden = GOLDEN / case
    if os.environ.get("UPDATE_GOLDEN"):
        for old in sorted(golden.rglob("*"), reverse=True) if golden.exists() else []:
            old.unlink() if old.is_file() else old.rmdir()
        for name, data in _tree(out).items():
            (golden / name).parent.mkdir(parents=True, exist_ok=True)
            (golden / name).write_bytes(data)
    expected, actual = _tree(golden), _tree(out)
    assert sorted(actual) == sorted(expected)
    for name in expected:
        assert actual[name] == expected[name], f"{name} differs from {golden / name}"


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
