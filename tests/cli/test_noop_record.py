"""The no-op record: a repeated ``apply``/``plan`` on an unchanged project replays the output
of the run that verified it, and any change to anything that run read makes it plan again,
with the same output as a run without the record."""

from __future__ import annotations

import marshal
import os
import random
import shutil
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from tests.cli.noop_support import (
    GENERATED,
    REPO,
    SCENE,
    SCRIPT,
    records,
    scaffold,
)
from unityscaffold.cli import _noop, _recorder
from unityscaffold.resources import template_environment


def _records(sample: Path) -> list[Path]:
    return records(sample.parent / "cache")


@pytest.mark.parametrize(
    "args",
    [
        ("apply",),
        ("apply", "--quiet"),
        ("apply", "--check"),
        ("apply", "--dry-run"),
        ("apply", "--json"),
        ("plan",),
        ("plan", "--json"),
        ("apply", "robot.yaml"),
    ],
)
def test_a_repeated_no_op_replays_the_same_bytes_without_planning(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], planned: list[list[str]], args
) -> None:
    first = scaffold(capsysbinary, *args)
    assert first[0] == 0 and len(_records(sample)) == 1
    again = scaffold(capsysbinary, *args)
    assert again == first
    assert planned == [list(args)]  # the second run was replayed


def test_files_written_again_with_the_same_bytes_are_still_replayed(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], planned: list[list[str]]
) -> None:
    # a checkout or a save that changes times but not bytes: what the run read is the same
    first = scaffold(capsysbinary, "apply", "--check")
    for name in ("robot.yaml", "robot.lock.json", str(SCRIPT), str(SCENE)):
        _same_bytes_again(name)(sample)
    assert scaffold(capsysbinary, "apply", "--check") == first
    assert len(planned) == 1


def _append(relative: str | Path, text: str) -> Callable[[Path], None]:
    def edit(root: Path) -> None:
        with open(root / relative, "a", encoding="utf-8", newline="") as handle:
            handle.write(text)

    return edit


def _replace(relative: str | Path, old: str, new: str) -> Callable[[Path], None]:
    def edit(root: Path) -> None:
        path = root / relative
        text = path.read_text(encoding="utf-8")
        assert old in text
        path.write_text(text.replace(old, new, 1), encoding="utf-8", newline="")

    return edit


def _create(relative: str | Path, text: str = "x\n") -> Callable[[Path], None]:
    def edit(root: Path) -> None:
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")

    return edit


def _remove(relative: str | Path) -> Callable[[Path], None]:
    return lambda root: (root / relative).unlink()


def _same_bytes_again(relative: str | Path) -> Callable[[Path], None]:
    return lambda root: (root / relative).write_bytes((root / relative).read_bytes())


META_LINE = "fileFormatVersion: 2\nguid: 0123456789abcdef0123456789abcdef\n"
EDITS: dict[str, Callable[[Path], None]] = {
    "manifest: a comment": _append("robot.yaml", "# a comment\n"),
    "manifest: a topic renamed": _replace("robot.yaml", "/scan", "/scan2"),
    "lock: removed": _remove("robot.lock.json"),
    "journal of an interrupted run": _create("robot.lock.pending.json", "{}\n"),
    "interface definition": _append(
        "ros_ws/src/diffbot_msgs/msg/WheelState.msg", "# a new comment\n"
    ),
    "new interface package": _create("ros_ws/src/more_msgs/msg/Extra.msg", "int32 x\n"),
    "scene": _replace(SCENE, "Robot", "Robot2"),
    "generated script": _append(SCRIPT, "// mine\n"),
    "generated script removed": _remove(SCRIPT),
    "generated .meta": _replace(Path(f"{SCRIPT}.meta"), "guid: ", "guid: 0"),
    "user half of a script": _append(GENERATED / "Scripts/ScanSubscriber.User.cs", "// mine\n"),
    "leftover temporary file": _create(GENERATED / "Scripts/.ScanSubscriber.cs.999-0.tmp"),
    "stray file in the output folder": _create(GENERATED / "Messages/Stray.cs"),
    "project script with a .meta": _create("unity/Assets/Mine/Mover.cs.meta", META_LINE),
    "installed package": _create(
        "unity/Library/PackageCache/com.example.ros@1.0.0/Runtime/Thing.cs.meta", META_LINE
    ),
    "project settings": _append("unity/ProjectSettings/ProjectSettings.asset", "\n"),
    "package manifest": _append("unity/Packages/manifest.json", "\n"),
    "schema copy the manifest names": _create("../unityscaffold/schema/robot.schema.json", "{}\n"),
}


@pytest.mark.parametrize("what", sorted(EDITS))
@pytest.mark.parametrize("args", [("apply", "--check"), ("plan",)])
def test_an_edit_to_anything_the_run_read_makes_it_plan_again_with_the_same_output(
    sample: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    planned: list[list[str]],
    monkeypatch: pytest.MonkeyPatch,
    what: str,
    args: tuple[str, ...],
) -> None:
    assert scaffold(capsysbinary, *args)[0] == 0
    assert len(_records(sample)) == 1
    EDITS[what](sample)
    after = scaffold(capsysbinary, *args)
    assert planned == [list(args)] * 2  # not replayed
    monkeypatch.setenv("UNITYSCAFFOLD_NO_REPLAY", "1")
    assert after == scaffold(capsysbinary, *args)


def test_an_edit_of_the_same_size_with_the_mtime_set_back_is_still_seen(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], planned: list[list[str]]
) -> None:
    script = sample / SCRIPT
    assert scaffold(capsysbinary, "apply", "--check")[0] == 0
    before = script.stat()
    data = script.read_bytes()
    script.write_bytes(data.replace(b"Scan", b"Scam", 1))
    os.utime(script, ns=(before.st_atime_ns, before.st_mtime_ns))
    after = script.stat()
    assert (after.st_size, after.st_mtime_ns) == (before.st_size, before.st_mtime_ns)
    code, out, _ = scaffold(capsysbinary, "apply", "--check")
    assert code == 1 and b"edited by hand" in out
    assert len(planned) == 2


def test_a_run_that_writes_or_fails_leaves_no_record(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes]
) -> None:
    _append(SCRIPT, "// mine\n")(sample)
    assert scaffold(capsysbinary, "apply", "--check")[0] == 1  # drift
    assert scaffold(capsysbinary, "apply", "--force")[0] == 0  # writes
    assert _records(sample) == []


def test_a_file_changed_while_the_run_goes_on_leaves_no_record(
    sample: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    planned: list[list[str]],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # the manifest edited (and saved again as it was) after the run read it: the run may have
    # read either, so what it said is not known to belong to what is there now
    from unityscaffold.cli import apply as apply_cli

    real = apply_cli.stale_schema
    manifest = sample / "robot.yaml"
    text = manifest.read_bytes()

    def edited_meanwhile(path: Path) -> Path | None:
        manifest.write_bytes(text + b"# meanwhile\n")
        return real(path)

    monkeypatch.setattr(apply_cli, "stale_schema", edited_meanwhile)
    assert scaffold(capsysbinary, "apply", "--check")[0] == 0
    assert _records(sample) == []
    monkeypatch.setattr(apply_cli, "stale_schema", real)
    assert scaffold(capsysbinary, "apply", "--check")[0] == 0  # the comment changes nothing
    assert len(_records(sample)) == 1


@pytest.mark.parametrize("variable", ["UNITYSCAFFOLD_NO_CACHE", "UNITYSCAFFOLD_NO_REPLAY"])
def test_the_record_can_be_turned_off(
    sample: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    planned: list[list[str]],
    monkeypatch: pytest.MonkeyPatch,
    variable: str,
) -> None:
    monkeypatch.setenv(variable, "1")
    first = scaffold(capsysbinary, "apply")
    assert scaffold(capsysbinary, "apply") == first
    assert _records(sample) == [] and len(planned) == 2


def _changed(index: int, value: object) -> Callable[[bytes], bytes]:
    """A record with one part replaced, checksummed again (so only its content is wrong)."""

    def damage(data: bytes) -> bytes:
        record = _noop._decode(data)
        assert record is not None
        changed = list(record)
        changed[index] = value
        return _recorder._encode(tuple(changed))

    return damage


def _other_format(data: bytes) -> bytes:
    record = _noop._decode(data)
    body = _noop._MAGIC.replace(b"%d" % _noop._FORMAT, b"1") + marshal.dumps(record)
    return _noop._checksum(body) + body


def _unreadable(data: bytes) -> bytes:
    body = _noop._MAGIC + b"\xff not marshal"
    return _noop._checksum(body) + body


@pytest.mark.parametrize(
    "damage",
    [
        lambda data: data[: len(data) // 2],  # cut short
        lambda data: b"not a record",
        lambda data: b"",
        _other_format,  # as another version of the scaffold wrote it
        _unreadable,  # checksummed, but not what the record is made of
        _changed(0, "another command"),  # the key
        _changed(1, [(1, 7)]),  # the output
        _changed(2, [("/", 7)]),  # what the run looked at
        _changed(2, [("/", 9, ())]),
    ],
)
def test_a_corrupt_or_foreign_record_means_the_usual_way(
    sample: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    planned: list[list[str]],
    damage: Callable[[bytes], bytes],
) -> None:
    first = scaffold(capsysbinary, "apply")
    [record] = _records(sample)
    record.write_bytes(damage(record.read_bytes()))
    assert scaffold(capsysbinary, "apply") == first
    assert len(planned) == 2


def test_a_whole_process_replay_loads_neither_typer_nor_the_pipeline(
    sample: Path, tmp_path: Path
) -> None:
    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path / "cache")}
    env["PYTHONPATH"] = os.pathsep.join([str(REPO), env.get("PYTHONPATH", "")])
    # Bytecode goes to a folder of its own: a first run in a fresh checkout would otherwise
    # make __pycache__ folders inside the code's folders, changing their stat, and so plan
    # once more before its record holds (what this test is about is the replay's imports).
    env["PYTHONPYCACHEPREFIX"] = str(tmp_path / "bytecode")
    command = [sys.executable, "-X", "importtime", "-m", "unityscaffold", "apply"]

    def scaffold_process() -> subprocess.CompletedProcess[str]:
        return subprocess.run(command, env=env, capture_output=True, text=True, check=True)

    first = scaffold_process()
    assert "typer" in first.stderr and "unityscaffold.apply" in first.stderr
    again = scaffold_process()
    assert again.stdout == first.stdout
    assert "typer" not in again.stderr and "unityscaffold.apply" not in again.stderr


def test_a_run_that_starts_a_process_leaves_no_record(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], monkeypatch: pytest.MonkeyPatch
) -> None:
    from unityscaffold.cli import apply as apply_cli

    real = apply_cli.stale_schema

    def asking_another_process(manifest: Path) -> Path | None:
        subprocess.run([sys.executable, "-c", "pass"], check=True)
        return real(manifest)

    monkeypatch.setattr(apply_cli, "stale_schema", asking_another_process)
    assert scaffold(capsysbinary, "apply")[0] == 0
    assert _records(sample) == []


def _mutate(path: Path, how: int) -> Callable[[], None]:
    """Change ``path`` in the least visible way that what the run learnt of it (looking at it
    ``how``) allows; returns the undo."""
    if not path.exists():
        path.write_bytes(b"")
        return path.unlink
    if how == _noop._LIST:
        probe = path / ".probe"
        probe.write_bytes(b"")
        return probe.unlink
    before = path.stat()
    if path.is_dir():  # only probed: its permissions
        path.chmod(before.st_mode ^ 0o001)
        return lambda: path.chmod(before.st_mode)
    data = path.read_bytes()
    if how != _noop._READ:  # probed, not read: its size
        path.write_bytes(data + b"\n")
    else:  # the same size and the mtime set back: only the bytes tell
        middle = len(data) // 2
        changed = data[:middle] + bytes([data[middle] ^ 1]) + data[middle + 1 :] if data else b"x"
        path.write_bytes(changed)
        os.utime(path, ns=(before.st_atime_ns, before.st_mtime_ns))

    def undo() -> None:
        path.write_bytes(data)

    return undo


def test_anything_the_run_learnt_changed_in_any_way_makes_the_run_plan_again(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], planned: list[list[str]]
) -> None:
    args = ("apply", "--check")
    expected = scaffold(capsysbinary, *args)
    [record] = _records(sample)
    decoded = _noop._decode(record.read_bytes())
    assert decoded is not None
    inside = str(sample) + os.sep
    candidates = sorted(
        {
            (path, how)
            for path, how, facts in decoded[2]
            if path.startswith(inside) and Path(path).parent.is_dir()
        }
    )
    assert len(candidates) > 50
    assert {how for _, how in candidates} == {_noop._STAT, _noop._LSTAT, _noop._LIST, _noop._READ}
    for path, how in random.Random(11).sample(candidates, 20):
        calls = len(planned)
        assert scaffold(capsysbinary, *args) == expected
        assert len(planned) == calls  # replayed
        undo = _mutate(Path(path), how)
        scaffold(capsysbinary, *args)
        assert len(planned) == calls + 1, f"a change of {path} (looked at {how}) was not seen"
        undo()
        assert scaffold(capsysbinary, *args) == expected  # plans again and records


def test_a_folder_found_missing_by_os_access_is_seen_when_it_appears(
    sample: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    planned: list[list[str]],
    monkeypatch: pytest.MonkeyPatch,
    tmp_path: Path,
) -> None:
    # a prefix's share folder is searched one level deep: each folder there is asked with
    # os.access whether it has msg/, and nothing lists the folder itself
    shadow = tmp_path / "prefix" / "share" / "sensor_msgs"
    shadow.mkdir(parents=True)
    monkeypatch.setenv("CMAKE_PREFIX_PATH", str(tmp_path / "prefix"))
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    args = ("apply", "--check", "--ros-env")
    assert scaffold(capsysbinary, *args)[0] == 0
    assert len(_records(sample)) == 1
    _create("msg/LaserScan.msg", "float32 range_min\n")(shadow)
    after = scaffold(capsysbinary, *args)
    assert b"does not match sensor_msgs/LaserScan as defined here" in after[1]
    assert len(planned) == 2


def test_a_record_made_by_another_copy_of_unityscaffold_is_not_replayed(
    sample: Path, tmp_path: Path
) -> None:
    # the same command line, folder and environment, but the code imported from elsewhere
    # (an editable install pointed at another checkout): that code's output, not the record's
    other = tmp_path / "other"
    shutil.copytree(
        REPO / "unityscaffold", other / "unityscaffold", ignore=shutil.ignore_patterns("*.pyc")
    )
    report = other / "unityscaffold" / "apply" / "report.py"
    report.write_text(
        report.read_text(encoding="utf-8").replace("matches the manifest", "is in line"),
        encoding="utf-8",
    )
    code = "import sys; sys.path.insert(0, sys.argv.pop()); from unityscaffold.cli import main; "
    code += "sys.exit(main(['apply']))"

    def scaffold_from(tree: Path) -> str:
        return subprocess.run(
            [sys.executable, "-c", code, str(tree)],
            capture_output=True,
            text=True,
            check=True,
        ).stdout

    assert "matches the manifest" in scaffold_from(REPO)
    assert "is in line" in scaffold_from(other)


def test_a_cache_folder_inside_a_searched_folder_is_observed_like_any_other(
    sample: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    planned: list[list[str]],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    cache = sample / "ros_ws" / "src" / "cache"  # the interface search walks ros_ws/src
    (cache / "unityscaffold" / "noop").mkdir(parents=True)
    monkeypatch.setenv("XDG_CACHE_HOME", str(cache))
    template_environment.cache_clear()
    # the search lists the cache's folders, which change as the first runs fill them
    # (compiled templates, then a record): those runs plan; once they are stable, it replays
    runs = [scaffold(capsysbinary, "apply") for _ in range(4)]
    assert runs == [runs[0]] * 4 and runs[0][0] == 0
    assert len(planned) < 4
    assert len(list((cache / "unityscaffold" / "noop").glob("*.rec"))) == 1


def test_a_deleted_current_folder_means_the_usual_way(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    gone = tmp_path / "gone"
    gone.mkdir()
    monkeypatch.chdir(gone)
    gone.rmdir()
    assert _noop.replay(["apply"]) is None
    assert _recorder.Recorder.start(["apply"]) is None


def test_a_temporary_file_of_a_running_writer_is_not_replayed_once_the_writer_is_gone(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], planned: list[list[str]]
) -> None:
    # whether a writer still runs is asked of the system, not of a file: its temporary file is
    # left alone while it runs, and is a leftover to remove once it has gone
    writer = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    try:
        _create(GENERATED / f"Scripts/.ScanSubscriber.cs.{writer.pid}-0.tmp")(sample)
        first = scaffold(capsysbinary, "apply", "--check")
        assert first[0] == 0
    finally:
        writer.kill()
        writer.wait()
    after = scaffold(capsysbinary, "apply", "--check")
    assert after[0] == 1 and b"remove  Assets/RosGenerated/Scripts/.ScanSub" in after[1]
    assert len(planned) == 2


def test_a_module_added_to_a_folder_on_the_import_path_is_seen(
    sample: Path, tmp_path: Path
) -> None:
    # a later import may find it before what the recorded run imported (pip install --user)
    first_on_path = tmp_path / "site"
    first_on_path.mkdir()
    code = "import sys; sys.path.insert(0, sys.argv.pop()); sys.path.insert(1, sys.argv.pop()); "
    code += "from unityscaffold.cli import main; sys.exit(main(['apply']))"
    command = [sys.executable, "-c", code, str(REPO), str(first_on_path)]

    def scaffold_process() -> subprocess.CompletedProcess[str]:
        return subprocess.run(command, capture_output=True, text=True, check=False)

    assert scaffold_process().returncode == 0
    assert scaffold_process().returncode == 0
    (first_on_path / "typer.py").write_text("raise SystemExit(7)\n", encoding="utf-8")
    assert scaffold_process().returncode == 7


def test_a_record_is_readable_by_its_user_only(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], monkeypatch: pytest.MonkeyPatch
) -> None:
    # its key holds the whole environment, tokens and passwords included
    monkeypatch.setenv("SOME_TOKEN", "secret")
    assert scaffold(capsysbinary, "apply")[0] == 0
    [record] = _records(sample)
    assert b"secret" in record.read_bytes()
    assert record.stat().st_mode & 0o077 == 0
    assert record.parent.stat().st_mode & 0o077 == 0


def test_a_run_that_changes_its_folder_leaves_no_record(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], monkeypatch: pytest.MonkeyPatch
) -> None:
    # relative paths read after it are relative to another folder than the key's
    from unityscaffold.cli import apply as apply_cli

    real = apply_cli.stale_schema

    def moving_away_and_back(manifest: Path) -> Path | None:
        here = os.getcwd()
        os.chdir(sample.parent)
        os.chdir(here)
        return real(manifest)

    monkeypatch.setattr(apply_cli, "stale_schema", moving_away_and_back)
    assert scaffold(capsysbinary, "apply")[0] == 0
    assert _records(sample) == []
