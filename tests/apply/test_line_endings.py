"""A checkout with CRLF line endings (Git for Windows' default ``core.autocrlf=true`` in a
repository without ``.gitattributes``) is not drift: generated code, scenes, ``.meta`` files,
settings and the lock compare equal modulo line endings, and apply keeps writing LF."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from helpers import require, run_cli, snapshot

REPO = Path(__file__).resolve().parents[2]
SAMPLE = REPO / "sample_project"
GIT = shutil.which("git")


def _git(repo: Path, *args: str) -> None:
    subprocess.run(
        ["git", "-c", "user.name=t", "-c", "user.email=t@example.invalid", *args],
        cwd=repo,
        check=True,
        capture_output=True,
    )


def _windows_checkout(repo: Path, project: Path) -> Path:
    """Commit ``project`` (its .gitattributes removed) into a fresh repository at ``repo`` and
    check it out again with ``core.autocrlf=true``, as Git for Windows does by default."""
    require(GIT, "git")
    copy = repo / project.name
    shutil.copytree(project, copy)
    for attributes in copy.rglob(".gitattributes"):
        attributes.unlink()
    _git(repo, "init", "-q", ".")
    _git(repo, "add", "-A")
    _git(repo, "commit", "-q", "-m", "project")
    _git(repo, "config", "core.autocrlf", "true")
    shutil.rmtree(copy)
    _git(repo, "checkout", "-q", "--", ".")
    return copy


def _crlf(path: Path) -> bool:
    data = path.read_bytes()
    return b"\r\n" in data and b"\n" not in data.replace(b"\r\n", b"")


@pytest.fixture
def windows_sample(tmp_path: Path) -> Path:
    sample = _windows_checkout(tmp_path, SAMPLE)
    unity = sample / "unity" / "Assets"
    for path in (
        unity / "RosGenerated" / "Scripts" / "OdomSubscriber.cs",
        unity / "RosGenerated" / "Scripts" / "OdomSubscriber.User.cs",
        unity / "RosGenerated" / "Scripts" / "OdomSubscriber.cs.meta",
        unity / "Scenes" / "Main.unity",
        sample / "robot.lock.json",
    ):
        assert _crlf(path), f"git did not check {path} out with CRLF"
    return sample


def test_a_crlf_checkout_matches_the_manifest_and_apply_writes_nothing(windows_sample):
    before = snapshot(windows_sample)
    check = run_cli("apply", "--check", str(windows_sample / "robot.yaml"))
    assert check.code == 0, check.out + check.err
    assert "the project matches the manifest" in check.out
    assert "edited by hand" not in check.out
    applied = run_cli("apply", str(windows_sample / "robot.yaml"))
    assert applied.code == 0, applied.out + applied.err
    assert "wrote 0 files, removed 0" in applied.out
    assert snapshot(windows_sample) == before


def test_a_real_hand_edit_in_a_crlf_checkout_is_still_one(windows_sample):
    script = windows_sample / "unity/Assets/RosGenerated/Scripts/OdomSubscriber.cs"
    script.write_bytes(script.read_bytes() + b"// mine\r\n")
    check = run_cli("apply", "--check", str(windows_sample / "robot.yaml"))
    assert check.code == 1
    assert "edited by hand (apply will stop; apply --force overwrites): " in check.out
    assert "Assets/RosGenerated/Scripts/OdomSubscriber.cs" in check.out
    assert check.out.count("edited by hand (") == 1


def test_a_change_in_a_crlf_checkout_is_written_with_lf_and_shown_as_a_small_diff(windows_sample):
    manifest = windows_sample / "robot.yaml"
    manifest.write_bytes(manifest.read_bytes().replace(b"rate: 10", b"rate: 20"))
    plan = run_cli("plan", str(manifest))
    assert plan.code == 0, plan.err
    assert "-  Rate: 10\n+  Rate: 20\n" in plan.out
    assert plan.out.count("\n-") < 10, plan.out  # not every line of a CRLF file
    applied = run_cli("apply", str(manifest))
    assert applied.code == 0, applied.out + applied.err
    scene = windows_sample / "unity/Assets/Scenes/Main.unity"
    assert _crlf(scene), "the scene patcher keeps the scene's line endings"
    check = run_cli("apply", "--check", str(manifest))
    assert check.code == 0, check.out


def test_a_ros2_project_checked_out_with_crlf_is_in_sync(tmp_path):
    made = tmp_path / "made"
    init = run_cli("init", str(made / "robot2"), "--ros", "2")
    assert init.code == 0, init.err
    first = run_cli("apply", str(made / "robot2" / "robot.yaml"))
    assert first.code == 0, first.out + first.err
    checkout = tmp_path / "checkout"
    checkout.mkdir()
    project = _windows_checkout(checkout, made / "robot2")
    settings = project / "ProjectSettings" / "ProjectSettings.asset"
    assert _crlf(settings)
    before = snapshot(project)
    check = run_cli("apply", "--check", str(project / "robot.yaml"))
    assert check.code == 0, check.out + check.err
    assert snapshot(project) == before
