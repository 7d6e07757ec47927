"""ROS#'s scripts: the installed package's .meta files when it is of the pinned release, else the
catalog of the release pinned in Packages/manifest.json, else a clear error."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from helpers import build_tree

from unityscaffold.apply._rossharp import RosSharp, pinned_version
from unityscaffold.errors import UserError
from unityscaffold.unity.project import script_index

GIT = "https://github.com/siemens/ros-sharp.git?path=/com.siemens.ros-sharp"


def _project(root: Path, pin: str | None, installed: dict[str, str] | None = None) -> RosSharp:
    deps = {"com.siemens.ros-sharp": f"{GIT}#{pin}"} if pin else {}
    files = {"Assets/.keep": "", "Packages/manifest.json": json.dumps({"dependencies": deps})}
    for name, guid in (installed or {}).items():
        base = f"Library/PackageCache/com.siemens.ros-sharp@1a2b/Runtime/RosBridgeClient/{name}.cs"
        files[base] = "// ROS#\n"
        files[base + ".meta"] = f"fileFormatVersion: 2\nguid: {guid}\n"
    build_tree(root, files)
    return RosSharp.of(root, script_index(root))


def test_the_installed_packages_meta_wins(tmp_path):
    rossharp = _project(tmp_path, "2.2.1", {"RosConnector": "0123456789abcdef0123456789abcdef"})
    assert rossharp.script("RosConnector").guid == "0123456789abcdef0123456789abcdef"


@pytest.mark.parametrize(
    ("pin", "guid"),
    [
        ("2.2.1", "ff98778ae051cfd40a6e4effdf851ebd"),
        ("v2.2.0", "9fb7d56afaa30534e9a7dc10102f9a83"),
        ("2.1.0", "9fb7d56afaa30534e9a7dc10102f9a83"),
        ("2.0.0", "ff98778ae051cfd40a6e4effdf851ebd"),
    ],
)
def test_without_the_package_on_disk_the_pinned_releases_table_is_used(tmp_path, pin, guid):
    assert _project(tmp_path, pin).script("RosConnector").guid == guid


def test_pinned_version_reads_the_git_tag(tmp_path):
    _project(tmp_path, "2.2.1")
    assert pinned_version(tmp_path) == "2.2.1"


def test_no_ros_sharp_at_all_says_what_to_install(tmp_path):
    with pytest.raises(UserError) as caught:
        _project(tmp_path, None).script("RosConnector")
    assert "ROS# is not installed" in caught.value.message
    assert '"com.siemens.ros-sharp"' in (caught.value.hint or "")


def _installed(root: Path, pin: str, version: str, guid: str) -> RosSharp:
    cache = "Library/PackageCache/com.siemens.ros-sharp@1a2b"
    build_tree(
        root,
        {
            "Assets/.keep": "",
            "Packages/manifest.json": json.dumps(
                {"dependencies": {"com.siemens.ros-sharp": f"{GIT}#{pin}"}}
            ),
            f"{cache}/package.json": json.dumps({"version": version}),
            f"{cache}/Runtime/RosConnector.cs": "// ROS#\n",
            f"{cache}/Runtime/RosConnector.cs.meta": f"fileFormatVersion: 2\nguid: {guid}\n",
        },
    )
    return RosSharp.of(root, script_index(root))


def test_an_installed_package_of_the_pinned_release_gives_the_guids(tmp_path):
    rossharp = _installed(tmp_path, "2.2.1", "2.2.1", "0123456789abcdef0123456789abcdef")
    assert rossharp.script("RosConnector").guid == "0123456789abcdef0123456789abcdef"
    assert rossharp.notes == ()


def test_an_installed_package_of_another_release_is_reported_and_the_pin_wins(tmp_path):
    rossharp = _installed(tmp_path, "2.2.1", "2.2.0", "0123456789abcdef0123456789abcdef")
    assert rossharp.script("RosConnector").guid == "ff98778ae051cfd40a6e4effdf851ebd"
    assert rossharp.notes == (
        "ROS# 2.2.0 is installed in Library/PackageCache but Packages/manifest.json pins 2.2.1: "
        "using 2.2.1's script GUIDs (Unity installs 2.2.1 when it next opens the project)",
    )


def test_every_stock_script_resolves_from_the_catalog_of_the_pin(tmp_path):
    rossharp = _project(tmp_path, "2.1.0")
    assert rossharp.script("LaserScanSubscriber").guid == "17bf2b1630e251a41a397262f2c3b502"
    assert rossharp.script("UrdfLink").namespace == "RosSharp.Urdf"


def test_a_release_the_catalog_does_not_know_says_so(tmp_path):
    with pytest.raises(UserError) as caught:
        _project(tmp_path, "9.9.9").script("RosConnector")
    assert "pins ROS# 9.9.9, which the catalog of ROS#'s scripts does not know" in (
        caught.value.message
    )
