"""The pre-commit hook this repository ships (``.pre-commit-hooks.yaml``), run by the real
``pre-commit`` in a temporary git repository holding a copy of the sample project: a project in
sync passes, a drifted one fails and says what differs and which command fixes it.

pre-commit would install unityscaffold into a virtual environment of its own for
``language: python``; here the hook's definition is used as shipped except that it runs this
checkout's ``scaffold`` (``language: system``), so the test needs no network.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from helpers import require

REPO = Path(__file__).resolve().parents[2]
PRE_COMMIT = shutil.which("pre-commit")
GIT = shutil.which("git")


def _git(repo: Path, *args: str, env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        ["git", "-c", "user.name=t", "-c", "user.email=t@example.invalid", *args],
        cwd=repo,
        env=env,
        capture_output=True,
        text=True,
    )


@pytest.fixture
def hooked(tmp_path: Path) -> tuple[Path, dict[str, str]]:
    require(PRE_COMMIT, "pre-commit (pip install pre-commit)")
    require(GIT, "git")
    [hook] = yaml.safe_load((REPO / ".pre-commit-hooks.yaml").read_text())
    assert hook["language"] == "python"
    hook["language"] = "system"
    repo = tmp_path / "robot"
    shutil.copytree(REPO / "sample_project", repo)
    config = {"repos": [{"repo": "local", "hooks": [hook]}]}
    (repo / ".pre-commit-config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    scaffold = bin_dir / "scaffold"
    scaffold.write_text(f'#!/bin/sh\nexec "{sys.executable}" -m unityscaffold "$@"\n')
    scaffold.chmod(0o755)
    env = {
        **os.environ,
        "PATH": f"{bin_dir}{os.pathsep}{os.environ['PATH']}",
        "PYTHONPATH": str(REPO),
        "PRE_COMMIT_HOME": str(tmp_path / "pre-commit-cache"),
    }
    _git(repo, "init", "-q", ".", env=env)
    _git(repo, "add", "-A", env=env)
    return repo, env


def _run_hook(repo: Path, env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [str(PRE_COMMIT), "run", "--all-files", "--color", "never"],
        cwd=repo,
        env=env,
        capture_output=True,
        text=True,
    )


def test_a_project_in_sync_passes(hooked):
    repo, env = hooked
    run = _run_hook(repo, env)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "Passed" in run.stdout


def test_drift_fails_with_the_summary_and_the_command_that_fixes_it(hooked):
    repo, env = hooked
    manifest = repo / "robot.yaml"
    manifest.write_text(manifest.read_text().replace("rate: 10", "rate: 20"))
    run = _run_hook(repo, env)
    assert run.returncode == 1, run.stdout + run.stderr
    assert "Failed" in run.stdout
    assert "update  Assets/RosGenerated/Scripts/CmdVelPublisher.cs" in run.stdout
    assert "the Unity project differs from the manifest" in run.stdout
    assert "run `scaffold apply robot.yaml`" in run.stdout


def test_a_changed_interface_file_alone_triggers_the_hook_in_a_commit(hooked):
    repo, env = hooked
    assert _git(repo, "commit", "-q", "-m", "in sync", env=env).returncode == 0
    installed = subprocess.run(
        [str(PRE_COMMIT), "install"], cwd=repo, env=env, capture_output=True, text=True
    )
    assert installed.returncode == 0, installed.stderr
    definition = repo / "ros_ws/src/diffbot_msgs/msg/WheelState.msg"
    definition.write_text(definition.read_text() + "float64 torque\n")
    _git(repo, "add", str(definition), env=env)
    commit = _git(repo, "commit", "-m", "add torque", env=env)
    assert commit.returncode != 0, commit.stdout + commit.stderr
    assert "run `scaffold apply robot.yaml`" in commit.stdout + commit.stderr
