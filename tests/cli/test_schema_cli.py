"""The manifest's JSON Schema reaches the user: ``scaffold schema`` prints or writes it, ``init``
copies it beside robot.yaml and points the YAML language server at it, and the sample's first
line names a file that exists and is the shipped schema."""

from __future__ import annotations

import json
import re
from pathlib import Path

from helpers import run_cli

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
