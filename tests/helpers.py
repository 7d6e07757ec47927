"""Small helpers shared by tests: build file trees inline and run the CLI in-process."""

from __future__ import annotations

import contextlib
import io
import os
from dataclasses import dataclass
from pathlib import Path

import pytest

from unityscaffold.cli import main

IN_CI = os.environ.get("CI", "").lower() == "true"


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


@dataclass(frozen=True)
class Run:
    code: int
    out: str
    err: str


def run_cli(*args: str) -> Run:
    """Run ``scaffold ARGS`` in-process, capturing its output."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(list(args))
        except SystemExit as exc:  # click may still exit for --help
            code = int(exc.code or 0)
    return Run(code, out.getvalue(), err.getvalue())
