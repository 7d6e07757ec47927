"""An apply killed at any moment leaves a project the next apply fully recovers.

The kill is real: ``apply`` runs in a child process that sends itself SIGKILL at the k-th call
of a file operation (``os.open`` while temporary files are written, ``os.replace`` while they
are renamed into place, ``os.unlink`` while pruning), so nothing gets a chance to clean up.
Afterwards a plain ``apply`` must leave no temporary file, no journal and no empty folder,
``--check`` must be clean, and going back to the previous manifest must neither report false
hand edits nor keep what the interrupted run added.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from helpers import run_cli, snapshot

REPO = Path(__file__).resolve().parents[2]
SCRIPTS = "unity/Assets/RosGenerated/Scripts"
# A child process that runs the CLI and kills itself at the k-th call of one os function.
KILLER = """
import os, signal, sys
name, k = sys.argv[1], int(sys.argv[2])
calls = [0]
real = getattr(os, name)
def counting(*args, **kwargs):
    calls[0] += 1
    if calls[0] == k:
        os.kill(os.getpid(), signal.SIGKILL)
    return real(*args, **kwargs)
setattr(os, name, counting)
from unityscaffold.cli import main
sys.exit(main(sys.argv[3:]))
"""
ADDED = (
    "  - {name: /imu, type: sensor_msgs/Imu, direction: subscribe, gameobject: Robot/Imu}\n"
    "  - {name: /joint_states, type: sensor_msgs/JointState, direction: subscribe,"
    " gameobject: Robot}\n"
)


@pytest.fixture
def sample(tmp_path: Path) -> Path:
    copy = tmp_path / "sample_project"
    shutil.copytree(REPO / "sample_project", copy)
    return copy


def _bigger(manifest: Path) -> str:
    """The sample's manifest with a changed rate, two more topics and one more service."""
    text = manifest.read_text()
    text = text.replace("rate: 10", "rate: 20").replace("\nservices:", ADDED + "\nservices:")
    return text.replace(
        "services:\n", "services:\n  - {name: /stop, type: std_srvs/Empty, role: client}\n"
    )


def _killed_apply(tmp_path: Path, manifest: Path, operation: str, k: int) -> None:
    killer = tmp_path / "killer.py"
    killer.write_text(KILLER)
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    run = subprocess.run(
        [sys.executable, str(killer), operation, str(k), "apply", str(manifest)],
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == -9, f"not killed at {operation} #{k}:\n{run.stdout}{run.stderr}"


def _assert_clean(project: Path) -> None:
    litter = [p for p in project.rglob("*") if re.fullmatch(r"\..+\.\d+-\d+\.tmp", p.name)]
    assert litter == []
    assert not list(project.glob("*.pending.json"))
    empty = [p for p in project.rglob("*") if p.is_dir() and not any(p.iterdir())]
    assert empty == []
    check = run_cli("apply", "--check", str(project / "robot.yaml"))
    assert check.code == 0, check.out + check.err


@pytest.mark.parametrize(
    ("operation", "k"),
    [("open", 4), ("replace", 1), ("replace", 2), ("replace", 9), ("replace", 16)],
)
def test_an_apply_killed_midway_is_recovered_by_the_next(
    sample: Path, tmp_path: Path, operation: str, k: int
) -> None:
    manifest = sample / "robot.yaml"
    manifest.write_text(_bigger(manifest))
    _killed_apply(tmp_path, manifest, operation, k)
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.out + run.err
    _assert_clean(sample)
    assert (sample / SCRIPTS / "ImuSubscriber.cs").is_file()


@pytest.mark.parametrize(
    ("operation", "k"), [("replace", 3), ("replace", 9), ("replace", 15), ("unlink", 1)]
)
def test_going_back_after_a_killed_apply_neither_blames_hand_edits_nor_keeps_its_files(
    sample: Path, tmp_path: Path, operation: str, k: int
) -> None:
    manifest = sample / "robot.yaml"
    original = manifest.read_text()
    before = snapshot(sample / "unity" / "Assets" / "RosGenerated")
    scene_path = sample / "unity" / "Assets" / "Scenes" / "Main.unity"
    original_scene = scene_path.read_bytes()
    manifest.write_text(_bigger(manifest))
    _killed_apply(tmp_path, manifest, operation, k)
    manifest.write_text(original)
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.out + run.err  # was: "generated files were edited by hand"
    _assert_clean(sample)
    assert snapshot(sample / "unity" / "Assets" / "RosGenerated") == before
    scene = (sample / "unity" / "Assets" / "Scenes" / "Main.unity").read_text()
    assert "Topic: /imu" not in scene and "Topic: /joint_states" not in scene
    assert "ServiceName: /stop" not in scene
    assert scene_path.read_bytes() == original_scene  # the GameObjects it made go too


def test_check_notices_a_temporary_file_left_by_a_dead_writer_and_apply_removes_it(
    sample: Path,
) -> None:
    dead = subprocess.run(
        [sys.executable, "-c", "import os; print(os.getpid())"],
        check=True,
        capture_output=True,
        text=True,
    )
    pid = int(dead.stdout)
    litter = sample / SCRIPTS / f".OdomSubscriber.cs.{pid}-0.tmp"
    litter.write_text("half a file")
    manifest = str(sample / "robot.yaml")
    check = run_cli("apply", "--check", manifest)
    assert check.code == 1 and f"remove  Assets/RosGenerated/Scripts/{litter.name}" in check.out
    assert run_cli("apply", manifest).code == 0
    assert not litter.exists()
    _assert_clean(sample)


def test_pruning_removes_the_folders_it_empties_with_their_metas(sample: Path) -> None:
    manifest = sample / "robot.yaml"
    text = manifest.read_text()
    for entry in ("/base_status", "/dock/feedback", "/set_speed_limit", "/dock"):
        text = re.sub(rf"  - \{{name: {entry},.*\n(     .*\n)?", "", text)
    manifest.write_text(text)
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.out + run.err
    assert "  remove  Assets/RosGenerated/Messages/Diffbot/msg\n" in run.out
    generated = sample / "unity" / "Assets" / "RosGenerated"
    assert sorted(p.name for p in generated.iterdir()) == ["Scripts", "Scripts.meta"]
    _assert_clean(sample)
