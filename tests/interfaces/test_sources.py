"""Package discovery: a folder is a package when it has a msg/, srv/ or action/ folder."""

from __future__ import annotations

import sys
from pathlib import Path

from helpers import require

from unityscaffold.interfaces.model import ActionSpec, Dialect
from unityscaffold.interfaces.registry import Registry
from unityscaffold.interfaces.sources import SearchRoot, find_packages


def test_a_package_needs_a_msg_srv_or_action_folder_not_a_file_of_that_name(
    tmp_path: Path,
) -> None:
    for name, child in [("has_msg", "msg"), ("has_srv", "srv"), ("has_action", "action")]:
        (tmp_path / name / child).mkdir(parents=True)
    (tmp_path / "file_named_msg").mkdir()
    (tmp_path / "file_named_msg" / "msg").write_text("not a folder")
    (tmp_path / "empty").mkdir()
    (tmp_path / "has_msg" / "nested" / "srv").mkdir(parents=True)  # not searched: not recursive
    found = find_packages([SearchRoot(tmp_path, "test", recursive=False)])
    assert [p.name for p in found] == ["has_action", "has_msg", "has_srv"]


def test_a_recursive_root_finds_packages_below_packages_and_skips_build_folders(
    tmp_path: Path,
) -> None:
    (tmp_path / "src" / "outer" / "msg").mkdir(parents=True)
    (tmp_path / "src" / "outer" / "inner" / "action").mkdir(parents=True)
    (tmp_path / "build" / "copied" / "msg").mkdir(parents=True)
    found = find_packages([SearchRoot(tmp_path, "test")])
    assert [p.name for p in found] == ["outer", "inner"]


def test_the_builtin_ros2_action_is_jazzys_test_msgs_fibonacci_and_resolves_without_ros() -> None:
    """ROS 2's standard packages define no action; the built-in set carries test_msgs's
    Fibonacci (scripts/update_builtin.py), byte for byte as the Jazzy wheel installs it."""
    wheel = Path(sys.prefix) / "share" / "test_msgs" / "action" / "Fibonacci.action"
    require(wheel.is_file(), "the PyPI wheel ros-jazzy-test-msgs (the `test` extra)")
    builtin = Registry.load(Dialect.ROS2, [], use_environment=False)
    action = builtin.get("test_msgs/action/Fibonacci")
    assert isinstance(action, ActionSpec)
    assert action.source is not None and "/builtin/ros2/" in Path(action.source).as_posix()
    assert Path(action.source).read_bytes() == wheel.read_bytes()
    # Of test_msgs (a grammar torture set), nothing else is built in.
    assert [n for n in builtin.known_names() if n.startswith("test_msgs/")] == [
        "test_msgs/action/Fibonacci"
    ]
