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
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from unityscaffold.cli import _app, _noop, _recorder, main
from unityscaffold.resources import template_environment

REPO = Path(__file__).resolve().parents[2]
SAMPLE = REPO / "sample_project"
GENERATED = Path("unity/Assets/RosGenerated")
SCRIPT = GENERATED / "Scripts/ScanSubscriber.cs"
SCENE = Path("unity/Assets/Scenes/Main.unity")

Result = tuple[int, bytes, bytes]


@pytest.fixture
def sample(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    # made beforehand: a run that makes its cache folder changes the folder above it, and
    # a run that saw something change is not recorded
    (tmp_path / "cache" / "unityscaffold").mkdir(parents=True)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.delenv("UNITYSCAFFOLD_NO_CACHE", raising=False)
    monkeypatch.delenv("UNITYSCAFFOLD_NO_REPLAY", raising=False)
    copy = tmp_path / "sample_project"
    shutil.copytree(SAMPLE, copy)
    monkeypatch.chdir(copy)
    # jinja's environment (and the cache folder it compiles templates into) is made once per
    # process: made again here, it uses this test's folder, as a command of its own would
    template_environment.cache_clear()
    yield copy
    template_environment.cache_clear()


@pytest.fixture
def planned(monkeypatch: pytest.MonkeyPatch) -> list[list[str]]:
    """The command lines that were planned, not replayed."""
    calls: list[list[str]] = []
    real = _app.run_cli

    def spy(args: list[str]) -> int:
        calls.append(args)
        return real(args)

    monkeypatch.setattr(_app, "run_cli", spy)
    return calls


def scaffold(capsysbinary: pytest.CaptureFixture[bytes], *args: str) -> Result:
    code = main(list(args))
    captured = capsysbinary.readouterr()
    return code, captured.out, captured.err


def settle() -> None:
    """Let the file system's clock pass the racy window (the record trusts older files only)."""
    time.sleep(0.12)


def records(sample: Path) -> list[Path]:
    return sorted((sample.parent / "cache" / "unityscaffold" / "noop").glob("*.rec"))


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
    settle()
    first = scaffold(capsysbinary, *args)
    assert first[0] == 0 and len(records(sample)) == 1
    again = scaffold(capsysbinary, *args)
    assert again == first
    assert planned == [list(args)]  # the second run was replayed


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
    "lock: rewritten with the same bytes": _same_bytes_again("robot.lock.json"),
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
    settle()
    assert scaffold(capsysbinary, *args)[0] == 0
    assert len(records(sample)) == 1
    EDITS[what](sample)
    after = scaffold(capsysbinary, *args)
    assert planned == [list(args)] * 2  # not replayed
    monkeypatch.setenv("UNITYSCAFFOLD_NO_REPLAY", "1")
    assert after == scaffold(capsysbinary, *args)


def test_an_edit_of_the_same_size_with_the_mtime_set_back_is_still_seen(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], planned: list[list[str]]
) -> None:
    script = sample / SCRIPT
    settle()
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


def test_a_run_that_writes_fails_or_is_racy_leaves_no_record(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], monkeypatch: pytest.MonkeyPatch
) -> None:
    _append(SCRIPT, "// mine\n")(sample)
    settle()
    assert scaffold(capsysbinary, "apply", "--check")[0] == 1  # drift
    assert scaffold(capsysbinary, "apply", "--force")[0] == 0  # writes
    assert records(sample) == []
    settle()
    # every file counts as changed after the run started: nothing is trusted
    monkeypatch.setattr(_recorder.time, "time_ns", lambda: 0)
    assert scaffold(capsysbinary, "apply")[0] == 0
    assert records(sample) == []


@pytest.mark.parametrize("variable", ["UNITYSCAFFOLD_NO_CACHE", "UNITYSCAFFOLD_NO_REPLAY"])
def test_the_record_can_be_turned_off(
    sample: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    planned: list[list[str]],
    monkeypatch: pytest.MonkeyPatch,
    variable: str,
) -> None:
    monkeypatch.setenv(variable, "1")
    settle()
    first = scaffold(capsysbinary, "apply")
    assert scaffold(capsysbinary, "apply") == first
    assert records(sample) == [] and len(planned) == 2


def _changed(index: int, value: object) -> Callable[[bytes], bytes]:
    def damage(data: bytes) -> bytes:
        record = list(marshal.loads(data))
        record[index] = value
        return marshal.dumps(tuple(record))

    return damage


@pytest.mark.parametrize(
    "damage",
    [
        lambda data: data[: len(data) // 2],  # cut short
        lambda data: b"not a record",
        _changed(0, "another command"),  # the key
        _changed(1, "zero"),  # the status
        _changed(2, [(1, 7)]),  # the output
        _changed(3, [("/", 7)]),  # the paths
    ],
)
def test_a_corrupt_or_foreign_record_means_the_usual_way(
    sample: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    planned: list[list[str]],
    damage: Callable[[str], str],
) -> None:
    settle()
    first = scaffold(capsysbinary, "apply")
    [record] = records(sample)
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

    settle()
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
    settle()
    assert scaffold(capsysbinary, "apply")[0] == 0
    assert records(sample) == []


def _mutate(path: Path) -> Callable[[], None]:
    """Change ``path`` in the least visible way its kind allows; returns the undo."""
    if path.is_dir():
        probe = path / ".probe"
        probe.write_bytes(b"")
        return probe.unlink
    if not path.exists():
        path.write_bytes(b"")
        return path.unlink
    before = path.stat()
    data = path.read_bytes()
    middle = len(data) // 2
    changed = data[:middle] + bytes([data[middle] ^ 1]) + data[middle + 1 :] if data else b"x"
    path.write_bytes(changed)
    if len(changed) == len(data):  # same size: the mtime set back too, so only ctime tells
        os.utime(path, ns=(before.st_atime_ns, before.st_mtime_ns))

    def undo() -> None:
        path.write_bytes(data)

    return undo


def test_any_path_the_record_holds_changed_in_any_way_makes_the_run_plan_again(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], planned: list[list[str]]
) -> None:
    args = ("apply", "--check")
    settle()
    expected = scaffold(capsysbinary, *args)
    [record] = records(sample)
    inside = str(sample) + os.sep
    candidates = sorted(
        {
            path
            for path, how, facts in marshal.loads(record.read_bytes())[3]
            if how != 2 and path.startswith(inside) and Path(path).parent.is_dir()
        }
    )
    assert len(candidates) > 50
    for path in random.Random(11).sample(candidates, 15):
        calls = len(planned)
        assert scaffold(capsysbinary, *args) == expected
        assert len(planned) == calls  # replayed
        undo = _mutate(Path(path))
        scaffold(capsysbinary, *args)
        assert len(planned) == calls + 1, f"a change of {path} was not seen"
        undo()
        settle()
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
    settle()
    assert scaffold(capsysbinary, *args)[0] == 0
    assert len(records(sample)) == 1
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

    settle()
    assert "matches the manifest" in scaffold_from(REPO)
    assert "is in line" in scaffold_from(other)


def test_a_cache_folder_inside_a_searched_folder_is_left_out_without_a_traceback(
    sample: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    planned: list[list[str]],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    cache = sample / "ros_ws" / "src" / "cache"  # the interface search walks ros_ws/src
    (cache / "unityscaffold" / "noop").mkdir(parents=True)
    monkeypatch.setenv("XDG_CACHE_HOME", str(cache))
    template_environment.cache_clear()
    settle()
    first = scaffold(capsysbinary, "apply")
    assert first[0] == 0 and len(list((cache / "unityscaffold" / "noop").glob("*.rec"))) == 1
    assert scaffold(capsysbinary, "apply") == first
    assert len(planned) == 1


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
        settle()
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

    settle()
    assert scaffold_process().returncode == 0
    assert scaffold_process().returncode == 0
    (first_on_path / "typer.py").write_text("raise SystemExit(7)\n", encoding="utf-8")
    assert scaffold_process().returncode == 7


def test_a_file_with_whole_second_times_is_trusted_only_seconds_later(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], monkeypatch: pytest.MonkeyPatch
) -> None:
    # the manifest on a file system that keeps whole seconds (FAT, some shares), the rest not:
    # an edit later in the same second would leave its times as they are
    manifest = str(sample / "robot.yaml")
    real = _noop._probe

    def whole_seconds(path: str, how: int) -> tuple[int, ...]:
        facts = real(path, how)
        if os.path.abspath(path) != manifest or len(facts) != 6:
            return facts
        mode, size, mtime, ctime, inode, device = facts
        second = 1_000_000_000
        return (mode, size, mtime - mtime % second, ctime - ctime % second, inode, device)

    monkeypatch.setattr(_recorder, "_probe", whole_seconds)
    _append("robot.yaml", "# edited\n")(sample)
    settle()
    assert scaffold(capsysbinary, "apply", "--check")[0] == 0
    assert records(sample) == []


def test_a_record_is_readable_by_its_user_only(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], monkeypatch: pytest.MonkeyPatch
) -> None:
    # its key holds the whole environment, tokens and passwords included
    monkeypatch.setenv("SOME_TOKEN", "secret")
    settle()
    assert scaffold(capsysbinary, "apply")[0] == 0
    [record] = records(sample)
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
    settle()
    assert scaffold(capsysbinary, "apply")[0] == 0
    assert records(sample) == []
