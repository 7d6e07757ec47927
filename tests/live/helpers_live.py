"""Shared helpers of the discovery tests: run the CLI in-process and snapshot folders."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from unityscaffold.cli import main

MANIFEST = """\
# Robot manifest (comments must survive discovery)
version: 1
ros: 1            # ROS version
project: .
connector: {gameobject: RosConnector, url: ws://localhost:9090}
topics:
  - {name: /imu, type: sensor_msgs/Imu, direction: subscribe, gameobject: Robot}  # hand-written
services: []
"""


@dataclass(frozen=True)
class Ros1System:
    """A running ROS 1 master with the test node (see the ``ros1_system`` fixture)."""

    url: str
    env: dict[str, str]
    truth: dict[str, Any]
    ghost_topic: str


@dataclass(frozen=True)
class Run:
    code: int
    out: str
    err: str


def run_cli(capsys: pytest.CaptureFixture[str], *argv: str) -> Run:
    capsys.readouterr()
    code = main(list(argv))
    captured = capsys.readouterr()
    return Run(code, captured.out, captured.err)


def snapshot(folder: Path) -> dict[str, str]:
    """Every file (hidden ones too) under ``folder`` with the sha256 of its content."""
    return {
        str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest()
        for p in sorted(folder.rglob("*"))
        if p.is_file()
    }


def assert_clean_failure(run: Run, folder: Path, before: dict[str, str], message: str) -> None:
    assert run.code == 2, run
    assert "Traceback" not in run.out + run.err
    assert message in run.err, run.err
    assert snapshot(folder) == before
