"""A project reached through a symbolic link is the same project: apply writes it, a second
apply writes nothing and ``--check`` passes, whichever way it is named; a link loop is a user
error; writes still stay inside the project's real folder."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from helpers import run_cli, snapshot

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture
def linked(tmp_path: Path) -> Path:
    """``tmp/real`` (the sample: manifest and project), ``tmp/u`` a link to its Unity project,
    ``tmp/l`` a link to the whole sample; the sample generates message classes of its own."""
    shutil.copytree(REPO / "sample_project", tmp_path / "real")
    (tmp_path / "u").symlink_to(tmp_path / "real" / "unity", target_is_directory=True)
    (tmp_path / "l").symlink_to(tmp_path / "real", target_is_directory=True)
    return tmp_path


def _applies_then_matches(manifest: str | Path) -> None:
    first = run_cli("apply", str(manifest))
    assert first.code == 0, first.out + first.err
    again = run_cli("apply", str(manifest))
    assert again.code == 0 and again.out.endswith("wrote 0 files, removed 0\n"), again.out
    check = run_cli("apply", "--check", str(manifest))
    assert check.code == 0, check.out + check.err


def test_a_project_named_through_a_link_applies_and_then_matches(linked: Path) -> None:
    elsewhere = linked / "m"
    elsewhere.mkdir()
    text = (linked / "real" / "robot.yaml").read_text()
    text = text.replace("project: unity ", "project: ../u ", 1)
    text = text.replace("  - ros_ws/src", "  - ../real/ros_ws/src", 1)
    (elsewhere / "robot.yaml").write_text(text)
    _applies_then_matches(elsewhere / "robot.yaml")
    assert (linked / "real/unity/Assets/RosGenerated/Messages").is_dir()


def test_a_manifest_named_through_a_linked_folder_applies_and_then_matches(linked: Path) -> None:
    _applies_then_matches(linked / "l" / "robot.yaml")


def test_running_inside_a_linked_folder_applies_and_then_matches(
    linked: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(linked / "l")
    _applies_then_matches("robot.yaml")


def test_dot_dot_after_a_link_is_the_links_targets_parent(linked: Path) -> None:
    # 'c/..' is the Unity project when c links to a folder inside it, not tmp/ as text says
    (linked / "c").symlink_to(linked / "real" / "unity" / "Assets", target_is_directory=True)
    text = (linked / "real" / "robot.yaml").read_text()
    text = text.replace("project: unity ", "project: c/.. ", 1)
    text = text.replace("  - ros_ws/src", "  - real/ros_ws/src", 1)
    (linked / "robot.yaml").write_text(text)
    _applies_then_matches(linked / "robot.yaml")


def test_a_project_link_that_loops_is_a_located_user_error(linked: Path) -> None:
    (linked / "loop").symlink_to(linked / "loop")
    manifest = linked / "real" / "robot.yaml"
    manifest.write_text(manifest.read_text().replace("project: unity ", "project: ../loop ", 1))
    before = snapshot(linked / "real")
    run = run_cli("apply", str(manifest))
    assert run.code == 2, run.out + run.err
    assert f"{manifest}:6:10: error: invalid value for 'project'" in run.err, run.err
    assert snapshot(linked / "real") == before


def test_an_output_link_leading_out_of_the_linked_project_is_still_refused(linked: Path) -> None:
    outside = linked / "outside"
    outside.mkdir()
    scripts = linked / "real" / "unity" / "Assets" / "RosGenerated" / "Scripts"
    shutil.rmtree(scripts)
    scripts.symlink_to(outside, target_is_directory=True)
    run = run_cli("apply", str(linked / "l" / "robot.yaml"))
    assert run.code == 2, run.out + run.err
    assert "outside the Unity project" in run.err
    assert not any(outside.iterdir())
