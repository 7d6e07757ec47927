"""Without a MANIFEST argument, apply, plan and discover use the nearest robot.yaml from the
current folder upward, stopping at the repository's root as git does; every command's --help
shows examples."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import command_paths, run_cli

from unityscaffold.cli import one_line_paragraphs


@pytest.fixture
def project(tmp_path: Path) -> Path:
    root = tmp_path / "robot"
    assert run_cli("init", str(root), "--ros", "1").code == 0
    (root / ".git").mkdir()  # the repository's root, where the search stops
    assert run_cli("apply", str(root / "robot.yaml")).code == 0
    return root


def test_apply_check_finds_the_manifest_in_a_folder_above(
    project: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(project / "Assets" / "Scenes")
    clean = run_cli("apply", "--check", "--quiet")
    assert (clean.code, clean.err) == (0, "")
    plan = run_cli("plan")
    assert plan.code == 0 and "the project matches the manifest" in plan.out
    text = (project / "robot.yaml").read_text()
    (project / "robot.yaml").write_text(text.replace("timeout: 10", "timeout: 20"))
    drift = run_cli("apply", "--check", "--quiet")
    assert drift.code == 1
    # named as the user would type it from here
    assert "run `scaffold apply ../../robot.yaml`" in drift.err


def test_files_of_a_manifest_found_above_are_named_from_the_project(
    project: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (project / "robot.lock.json").unlink()
    monkeypatch.chdir(project / "Assets")
    run = run_cli("plan")
    assert run.code == 0, run.err
    assert "  create  robot.lock.json\n" in run.out
    header, files = run.out.split("\n---", 1)[0].split("\n", 1)
    assert header.startswith("../robot.yaml: ")  # the manifest as typed from here
    assert ".." not in files


@pytest.mark.parametrize("given", [None, "../robot.yaml", "../other.yaml"])
def test_the_plan_header_names_the_manifest_as_the_user_would_type_it(
    given: str | None, project: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (project / "other.yaml").write_text((project / "robot.yaml").read_text())
    monkeypatch.chdir(project / "Assets")
    run = run_cli("plan", *([given] if given else []))
    assert run.code == 0, run.err
    assert run.out.startswith(f"{given or '../robot.yaml'}: Unity project {project} (ROS 1)\n")


def test_the_search_stops_at_the_repository_root(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "robot.yaml").write_text("version: 1\nros: 1\n")  # outside the repository
    inner = tmp_path / "repo" / "sub"
    inner.mkdir(parents=True)
    (tmp_path / "repo" / ".git").mkdir()
    monkeypatch.chdir(inner)
    run = run_cli("plan")
    assert run.code == 2
    assert "manifest robot.yaml does not exist" in run.err
    assert "looks for robot.yaml here and in the folders above" in run.err


def test_a_manifest_given_is_used_as_given(project: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(project / "Assets")
    run = run_cli("plan", "missing.yaml")
    assert run.code == 2 and "manifest missing.yaml does not exist" in run.err


# every command but the groups (the root is helped), as the app has them: a new one is
# checked at once
HELPED = [list(path) for path, group in command_paths().items() if not group or not path]


@pytest.mark.parametrize("command", HELPED, ids=lambda c: " ".join(c) or "scaffold")
def test_every_command_help_has_examples(command: list[str]) -> None:
    run = run_cli(*command, "--help")
    assert run.code == 0, run.err
    assert "Example" in run.out
    assert f"scaffold {' '.join(command)}".strip() in run.out.split("Example", 1)[1]


@pytest.mark.parametrize("command", HELPED, ids=lambda c: " ".join(c) or "scaffold")
def test_every_help_example_fits_80_columns_indented_on_its_own_lines(
    command: list[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Each example starts on its own line, indented under 'Examples:', and a long one goes on
    over lines of its own after a '\\' rather than being wrapped where the terminal ends."""
    monkeypatch.setenv("COLUMNS", "80")
    run = run_cli(*command, "--help")
    block = run.out.split("Example", 1)[1].split("\n", 1)[1].split("╭", 1)[0]
    lines = [line.rstrip() for line in block.splitlines()]
    examples, previous = 0, ""
    for line in lines:
        assert len(line) <= 80
        if previous.endswith("\\"):
            assert line.startswith("       "), line  # the example goes on, further indented
        elif line.startswith("   scaffold "):
            examples += 1
        elif line:
            # prose after the examples, a paragraph of its own: not the tail of a wrapped one
            assert previous == "" and not line.startswith("  "), line
            break
        previous = line
    assert examples and not previous.endswith("\\")


def test_help_prose_is_one_line_per_paragraph_and_examples_keep_their_lines() -> None:
    doc = """Make it so.

        Running it again changes nothing (see
        --force); your code stays.

        Examples:

          scaffold apply
          scaffold apply --check
        """
    assert one_line_paragraphs(doc) == (
        "Make it so.\n\n"
        "Running it again changes nothing (see --force); your code stays.\n\n"
        "Examples:\n\n"
        "  scaffold apply\n"
        "  scaffold apply --check"
    )


def test_apply_help_does_not_break_its_prose_where_the_docstring_does(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setenv("COLUMNS", "400")  # wide enough for a paragraph on one line
    run = run_cli("apply", "--help")
    assert run.code == 0
    # the docstring breaks its lines after '(see --force);' and before 'GameObjects are known'
    assert "stop it (see --force); your code belongs in the *.User.cs files" in run.out
    assert "never rewritten. GameObjects are known by identity" in run.out


def test_a_command_in_a_deleted_folder_says_so_without_a_traceback(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    gone = tmp_path / "gone"
    gone.mkdir()
    monkeypatch.chdir(gone)
    gone.rmdir()
    run = run_cli("apply")
    assert run.code == 2 and "Traceback" not in run.err
    assert run.err.startswith("error: the current folder no longer exists\n  hint: cd to")
