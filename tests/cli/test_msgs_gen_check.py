"""``msgs gen --check``, ``--quiet`` and ``--json``: a CI check that writes nothing and exits 1
when the output folder is stale, quiet runs that print only what matters, and a JSON report."""

from __future__ import annotations

import json
from pathlib import Path

from helpers import build_tree, run_cli, snapshot

DEFINITIONS = {
    "robot_msgs/package.xml": "<package><name>robot_msgs</name></package>\n",
    "robot_msgs/msg/Status.msg": "# Robot status\nuint8 mode\nstring text\n",
    "robot_msgs/msg/Report.msg": "Status status\nfloat64 battery\n",
}


def _gen(tmp_path: Path, *args: str):
    src = build_tree(tmp_path / "src", DEFINITIONS)
    out = tmp_path / "out"
    return out, run_cli(
        "msgs", "gen", "robot_msgs", "--ros", "1", "--no-env", "--path", str(src),
        "-o", str(out), *args,
    )  # fmt: skip


def test_check_on_a_missing_output_exits_1_and_writes_nothing(tmp_path: Path) -> None:
    out, run = _gen(tmp_path, "--check")
    assert run.code == 1
    assert not out.exists()
    assert "create    Robot/msg/Status.cs\n" in run.out
    assert "2 classes generated, 0 skipped; files: 6 would be created" in run.out
    assert "run the same command without --check" in run.out.splitlines()[-1]


def test_check_passes_after_gen_and_fails_on_a_hand_edit(tmp_path: Path) -> None:
    out, first = _gen(tmp_path)
    assert first.code == 0, first.err
    _, clean = _gen(tmp_path, "--check")
    assert clean.code == 0, clean.out
    assert "0 would be created, 0 would be updated, 6 unchanged" in clean.out
    status = out / "Robot/msg/Status.cs"
    status.write_text(status.read_text() + "// edited\n")
    before = snapshot(out)
    _, stale = _gen(tmp_path, "--check")
    assert stale.code == 1
    assert "update    Robot/msg/Status.cs" in stale.out
    assert snapshot(out) == before


def test_quiet_prints_nothing_on_success_and_the_difference_on_a_failed_check(
    tmp_path: Path,
) -> None:
    _, failed = _gen(tmp_path, "--check", "--quiet")
    assert failed.code == 1
    assert failed.out == ""
    assert "create    Robot/msg/Report.cs\n" in failed.err
    assert "run the same command without --check" in failed.err
    out, written = _gen(tmp_path, "-q")
    assert (written.code, written.out, written.err) == (0, "", "")
    assert (out / "Robot/msg/Report.cs").is_file()
    _, passed = _gen(tmp_path, "--check", "-q")
    assert (passed.code, passed.out, passed.err) == (0, "", "")


def test_json_reports_files_classes_and_whether_the_output_is_up_to_date(tmp_path: Path) -> None:
    _, stale = _gen(tmp_path, "--check", "--json")
    assert stale.code == 1
    data = json.loads(stale.out)
    assert (data["check"], data["up_to_date"]) == (True, False)
    assert {"path": "Robot/msg/Status.cs", "change": "create", "reason": None} in data["files"]
    assert {
        "type": "robot_msgs/Status",
        "class": "RosSharp.RosBridgeClient.MessageTypes.Robot.Status",
        "path": "Robot/msg/Status.cs",
    } in data["generated"]
    assert data["skipped"] == []
    _, written = _gen(tmp_path, "--json")
    assert written.code == 0
    assert json.loads(written.out)["check"] is False
    _, clean = _gen(tmp_path, "--check", "--json")
    assert clean.code == 0
    assert json.loads(clean.out)["up_to_date"] is True
    assert {f["change"] for f in json.loads(clean.out)["files"]} == {"unchanged"}
