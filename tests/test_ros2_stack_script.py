"""scripts/ros2_stack.py caches the ROS 2 stack under a digest of what its build reads: a change
to a built interface package gives another stack folder (a cache never changes an answer), and
undoing it finds the first one again."""

from __future__ import annotations

import fcntl
import os
import shutil
import time
from pathlib import Path

import pytest
from helpers import require

from tests.runtime.bridge import vendor_folder
from tests.runtime.ros2 import stack_module


def test_the_stack_folder_follows_the_built_packages_files(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    vendor = vendor_folder("UNITYSCAFFOLD_ROSBRIDGE2", "rosbridge_suite-ros2")
    require(vendor, "rosbridge_suite's ROS 2 sources (UNITYSCAFFOLD_ROSBRIDGE2)")
    assert vendor
    copy = tmp_path / "rosbridge"
    for package in ("rosbridge_msgs", "rosapi_msgs"):
        shutil.copytree(vendor / package, copy / package)
    monkeypatch.setenv("UNITYSCAFFOLD_ROSBRIDGE2", str(copy))
    monkeypatch.setenv("UNITYSCAFFOLD_ROS2_CACHE", str(tmp_path / "cache"))
    module = stack_module()
    before = module.stack_root()
    assert before.parent == tmp_path / "cache" and before.name.startswith("ros2-jazzy-")
    message = copy / "rosbridge_msgs" / "msg" / "ConnectedClient.msg"
    message.write_text(message.read_text() + "int32 added\n")
    assert module.stack_root() != before
    message.write_text(message.read_text().replace("int32 added\n", ""))
    assert module.stack_root() == before


def test_a_new_build_removes_only_the_stacks_nothing_used_lately(tmp_path: Path) -> None:
    module = stack_module()
    old = time.time() - (module.STALE_DAYS + 1) * 86400
    stacks = {}
    for name in ("kept", "stale", "recent", "half-built", "building"):
        folder = tmp_path / f"ros2-jazzy-{name}"
        (folder / "venv").mkdir(parents=True)
        if name != "half-built":
            (folder / ".complete").write_text(folder.name + "\n")
        stacks[name] = folder
    for name in ("stale", "building"):
        os.utime(stacks[name] / ".complete", (old, old))
    os.utime(stacks["half-built"], (old, old))
    other = tmp_path / "noop"  # not a stack: never looked at
    other.mkdir()
    lock = stacks["building"].with_name(stacks["building"].name + ".lock")
    with lock.open("w") as held:
        fcntl.flock(held, fcntl.LOCK_EX)  # a build of that key is running
        module._prune_stale(stacks["kept"])
    left = sorted(p.name for p in tmp_path.iterdir() if p.is_dir())
    assert left == ["noop", "ros2-jazzy-building", "ros2-jazzy-kept", "ros2-jazzy-recent"]
