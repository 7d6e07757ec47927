"""Package discovery: a folder is a package when it has a msg/, srv/ or action/ folder."""

from __future__ import annotations

from pathlib import Path

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
