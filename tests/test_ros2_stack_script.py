"""scripts/ros2_stack.py caches the ROS 2 stack under a digest of what its build reads: a change
to a built interface package gives another stack folder (a cache never changes an answer), and
undoing it finds the first one again."""

from __future__ import annotations

import shutil
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
