"""Small helpers shared by tests: build file trees inline, run the CLI in-process, and compare
output with golden files and snapshots (showing a text diff when they differ)."""

from __future__ import annotations

import contextlib
import difflib
import io
import os
import signal
import struct
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from unityscaffold.cli import main

IN_CI = os.environ.get("CI", "").lower() == "true"
#: Debian's Python, the one that sees Debian's ROS 1 packages (genmsg, rospy).
SYSTEM_PYTHON = Path("/usr/bin/python3")
UPDATE_VARIABLE = "UNITYSCAFFOLD_UPDATE"


def require(available: object, what: str) -> None:
    """Skip (locally) or fail (in CI, where .ci/run must install it) when ``what`` is missing."""
    if available:
        return
    if IN_CI:
        pytest.fail(f"{what} is missing: .ci/run must install it")
    pytest.skip(f"{what} is not installed")


def snapshot(root: Path) -> dict[str, bytes]:
    """Every file under ``root`` with its bytes, to show that nothing was written."""
    return {
        p.relative_to(root).as_posix(): p.read_bytes()
        for p in sorted(root.rglob("*"))
        if p.is_file()
    }


def build_tree(root: Path, files: dict[str, str]) -> Path:
    """Write ``{relative path: text}`` under ``root`` and return ``root``."""
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return root


def binary_stl(path: Path, facets: int) -> Path:
    """A binary STL file of ``facets`` copies of one triangle (the unit vectors' tips)."""
    one = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1) + bytes(2)
    path.write_bytes(bytes(80) + struct.pack("<I", facets) + one * facets)
    return path


@dataclass(frozen=True)
class Run:
    code: int
    out: str
    err: str


def init_with_unreadable_script(root: Path) -> Path:
    """A new ROS 2 project at ``root`` with ``Assets/Scripts/Blind.cs``, a script apply cannot
    read (its .meta is there, but the C# is an unclosed class), so its fields are written as
    given."""
    assert run_cli("init", str(root), "--ros", "2").code == 0
    return build_tree(
        root,
        {
            "Assets/Scripts/Blind.cs": "public class Blind : MonoBehaviour {\n",
            "Assets/Scripts/Blind.cs.meta": (
                "fileFormatVersion: 2\nguid: 0123456789abcdef0123456789abcdef\n"
            ),
        },
    )


def run_cli(*args: str) -> Run:
    """Run ``scaffold ARGS`` in-process, capturing its output."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(list(args))
        except SystemExit as exc:  # click may still exit for --help
            code = int(exc.code or 0)
    return Run(code, out.getvalue(), err.getvalue())


def updating() -> bool:
    """True when ``UNITYSCAFFOLD_UPDATE=1``: golden files and snapshots are rewritten from the
    current output instead of compared. Review the resulting ``git diff`` before committing."""
    return os.environ.get(UPDATE_VARIABLE) == "1"


def text_diff(expected: str | bytes, actual: str | bytes, name: str) -> str:
    """A unified diff from ``expected`` to ``actual`` (two versions of ``name``), for a failure."""
    if isinstance(expected, bytes) or isinstance(actual, bytes):
        try:
            expected = expected.decode("utf-8") if isinstance(expected, bytes) else expected
            actual = actual.decode("utf-8") if isinstance(actual, bytes) else actual
        except UnicodeDecodeError:
            return f"{name}: binary contents differ"
    lines = difflib.unified_diff(
        expected.splitlines(keepends=True),
        actual.splitlines(keepends=True),
        f"{name} (expected)",
        f"{name} (actual)",
    )
    # A difference in line endings or a final newline alone would show as an empty diff.
    return "".join(lines) or f"{name}: differs only in line endings or the final newline"


def tree_differences(actual: Path, expected: Path) -> str:
    """Every difference between two folders: missing and extra files, then a diff per file."""
    got, want = snapshot(actual), snapshot(expected)
    problems = [f"missing: {name}" for name in sorted(want.keys() - got.keys())]
    problems += [f"unexpected: {name}" for name in sorted(got.keys() - want.keys())]
    problems += [
        text_diff(want[name], got[name], name)
        for name in sorted(want.keys() & got.keys())
        if want[name] != got[name]
    ]
    return "\n".join(problems)


UPDATE_HINT = f"if the change is intended, rerun with {UPDATE_VARIABLE}=1 and review git diff"


def assert_same_tree(actual: Path, expected: Path, hint: str = UPDATE_HINT) -> None:
    """Fail with a readable report unless ``actual`` holds exactly the files of ``expected``."""
    problems = tree_differences(actual, expected)
    if problems:
        pytest.fail(f"{actual} differs from {expected} ({hint}):\n{problems}", pytrace=False)


@contextlib.contextmanager
def deadline(seconds: int, what: str) -> Iterator[None]:
    """Fail with ``TimeoutError`` when the block runs past ``seconds``: a guard against a hang
    (a walk that does not end), not a speed check (speed is bench/'s job)."""

    def expire(*_: object) -> None:
        raise TimeoutError(f"still running after {seconds} s: {what}")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def command_paths() -> dict[tuple[str, ...], bool]:
    """Every command of ``scaffold`` (the root too) as its words, and whether it is a group."""
    import typer

    from unityscaffold.cli import build_app

    found: dict[tuple[str, ...], bool] = {}

    def walk(command: Any, path: tuple[str, ...]) -> None:
        subcommands = getattr(command, "commands", None)  # only groups have them
        found[path] = subcommands is not None
        for name, sub in (subcommands or {}).items():
            walk(sub, (*path, name))

    walk(typer.main.get_command(build_app([])), ())
    return found
