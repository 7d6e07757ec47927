"""What the no-op record's tests share: a copy of the sample project with a cache folder of its
own, a spy on planning, and a way to run ``scaffold`` in this process."""

from __future__ import annotations

import shutil
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from unityscaffold.cli import _app, main
from unityscaffold.resources import template_environment

REPO = Path(__file__).resolve().parents[2]
SAMPLE = REPO / "sample_project"
GENERATED = Path("unity/Assets/RosGenerated")
SCRIPT = GENERATED / "Scripts/ScanSubscriber.cs"
SCENE = Path("unity/Assets/Scenes/Main.unity")

Result = tuple[int, bytes, bytes]


def copy_sample(destination: Path, cache: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A copy of the sample project at ``destination``, its caches in ``cache``, as the
    current folder."""
    # made beforehand: a run that makes its cache folder changes the folder above it
    (cache / "unityscaffold").mkdir(parents=True, exist_ok=True)
    monkeypatch.setenv("XDG_CACHE_HOME", str(cache))
    monkeypatch.delenv("UNITYSCAFFOLD_NO_CACHE", raising=False)
    monkeypatch.delenv("UNITYSCAFFOLD_NO_REPLAY", raising=False)
    shutil.copytree(SAMPLE, destination)
    monkeypatch.chdir(destination)
    # jinja's environment (and the cache folder it compiles templates into) is made once per
    # process: made again here, it uses this test's folder, as a command of its own would
    template_environment.cache_clear()
    return destination


@pytest.fixture
def sample(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    yield copy_sample(tmp_path / "sample_project", tmp_path / "cache", monkeypatch)
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


def unrecorded(
    capsysbinary: pytest.CaptureFixture[bytes], monkeypatch: pytest.MonkeyPatch, *args: str
) -> Result:
    """What ``scaffold`` says with the record turned off: what it must say with it too."""
    with monkeypatch.context() as off:
        off.setenv("UNITYSCAFFOLD_NO_REPLAY", "1")
        return scaffold(capsysbinary, *args)


def settle() -> None:
    """Let the file system's clock pass a tick, so files written so far look older than a run
    (were ``stat`` trusted, it would be trusted for them)."""
    time.sleep(0.12)


def records(cache: Path) -> list[Path]:
    """The records in the cache folder ``cache`` (``$XDG_CACHE_HOME``)."""
    return sorted((cache / "unityscaffold" / "noop").glob("*.rec"))
