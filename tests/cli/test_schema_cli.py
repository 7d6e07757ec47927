"""The manifest's JSON Schema reaches the user: ``scaffold schema`` prints or writes it, ``init``
copies it beside robot.yaml and points the YAML language server at it, and the sample's first
line names a file that exists and is the shipped schema."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from helpers import run_cli

from unityscaffold.manifest.modeline import stale_schema
from unityscaffold.resources import schema_text

REPO = Path(__file__).resolve().parent.parent.parent
MODELINE = re.compile(r"\A# yaml-language-server: \$schema=(\S+)\n")


def test_schema_prints_the_shipped_schema() -> None:
    run = run_cli("schema")
    assert run.code == 0, run.err
    assert run.out == schema_text()
    assert json.loads(run.out)["title"] == "unityscaffold robot.yaml"


def test_schema_output_writes_the_file_once(tmp_path: Path) -> None:
    target = tmp_path / "robot.schema.json"
    first = run_cli("schema", "-o", str(target))
    assert (first.code, first.out) == (0, f"wrote {target}\n")
    assert target.read_text(encoding="utf-8") == schema_text()
    again = run_cli("schema", "--output", str(target))
    assert (again.code, again.out) == (0, f"unchanged {target}\n")


def test_schema_output_to_a_folder_is_refused_with_a_hint(tmp_path: Path) -> None:
    run = run_cli("schema", "-o", str(tmp_path))
    assert run.code == 2
    assert run.err == (
        f"error: cannot write {tmp_path}: a folder of that name exists\n"
        "  hint: name a file, not a folder, or move that folder away\n"
    )


def test_schema_output_where_no_folder_can_be_made_is_refused_with_a_hint(tmp_path: Path) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("")
    run = run_cli("schema", "-o", str(blocker / "sub" / "robot.schema.json"))
    assert run.code == 2 and "Traceback" not in run.err
    assert f"error: cannot write {blocker / 'sub' / 'robot.schema.json'}" in run.err
    assert "  hint: " in run.err
    assert blocker.read_text() == ""


def test_init_copies_the_schema_and_the_manifest_points_at_it(tmp_path: Path) -> None:
    project = tmp_path / "robot"
    assert run_cli("init", str(project)).code == 0
    manifest = (project / "robot.yaml").read_text(encoding="utf-8")
    match = MODELINE.match(manifest)
    assert match, manifest.splitlines()[0]
    assert match[1] == "robot.schema.json"
    assert (project / match[1]).read_text(encoding="utf-8") == schema_text()
    assert "scaffold schema -o robot.schema.json" in manifest


def test_the_samples_modeline_names_the_shipped_schema() -> None:
    manifest = REPO / "sample_project" / "robot.yaml"
    match = MODELINE.match(manifest.read_text(encoding="utf-8"))
    assert match
    assert (manifest.parent / match[1]).read_text(encoding="utf-8") == schema_text()


def test_apply_notes_a_schema_copy_that_an_upgrade_left_behind(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    project = tmp_path / "robot"
    assert run_cli("init", str(project), "--ros", "1").code == 0
    monkeypatch.chdir(project)
    fresh = run_cli("apply")
    assert fresh.code == 0 and "note:" not in fresh.err
    copy = project / "robot.schema.json"
    old = json.loads(copy.read_text())
    del old["properties"]["connector"]  # as if written by an older scaffold
    copy.write_text(json.dumps(old))
    stale = run_cli("plan")
    assert stale.code == 0
    assert (
        "note: robot.schema.json (the schema editors check robot.yaml with) is older than "
        "this scaffold's schema; refresh it with `scaffold schema -o robot.schema.json`"
    ) in stale.err
    assert run_cli("apply", "--quiet").err == ""  # quiet stays quiet
    assert run_cli("schema", "-o", "robot.schema.json").code == 0
    assert "note:" not in run_cli("apply", "--check").err
    copy.unlink()
    assert "robot.schema.json (the schema editors check robot.yaml with) is missing" in (
        run_cli("plan").err
    )


@pytest.mark.parametrize(
    ("first_line", "named"),
    [
        ("# yaml-language-server: $schema=robot.schema.json\n", "robot.schema.json"),
        ("\ufeff# yaml-language-server: $schema=../s.json\n", "../s.json"),
        ("# yaml-language-server: $schema=https://example.org/s.json\n", None),
        ("version: 1\n", None),
    ],
)
def test_stale_schema_reads_the_first_line_only(
    tmp_path: Path, first_line: str, named: str | None
) -> None:
    manifest = tmp_path / "robot.yaml"
    manifest.write_text(first_line + "version: 1\n", encoding="utf-8")
    found = stale_schema(manifest)  # the named file does not exist: stale when local
    assert found == (None if named is None else tmp_path / named)
