"""ROS#'s scripts: an embedded package's own .meta files, else the catalog of the release pinned
in Packages/manifest.json, else a clear error; a copy in Unity's cache changes no GUID, and its
release is told by its content (a note when it is not the pinned one)."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest
from helpers import build_tree, require

from unityscaffold.apply._rossharp import RosSharp, pinned_version
from unityscaffold.errors import UserError
from unityscaffold.unity.project import script_index

GIT = "https://github.com/siemens/ros-sharp.git?path=/com.siemens.ros-sharp"
VENDOR = Path(__file__).resolve().parents[3] / "shared" / "vendor" / "ros-sharp"
GUIDS = VENDOR / "script-guids.tsv"
VENDOR_2_2_1 = VENDOR / "2.2.1" / "com.siemens.ros-sharp"


def _project(root: Path, pin: str | None, installed: dict[str, str] | None = None) -> RosSharp:
    deps = {"com.siemens.ros-sharp": f"{GIT}#{pin}"} if pin else {}
    files = {"Assets/.keep": "", "Packages/manifest.json": json.dumps({"dependencies": deps})}
    for name, guid in (installed or {}).items():
        base = f"Library/PackageCache/com.siemens.ros-sharp@1a2b/Runtime/RosBridgeClient/{name}.cs"
        files[base] = "// ROS#\n"
        files[base + ".meta"] = f"fileFormatVersion: 2\nguid: {guid}\n"
    build_tree(root, files)
    return RosSharp.of(root, script_index(root))


def test_a_copy_in_unitys_cache_never_changes_the_guids(tmp_path):
    rossharp = _project(tmp_path, "2.2.1", {"RosConnector": "0123456789abcdef0123456789abcdef"})
    assert rossharp.script("RosConnector").guid == "ff98778ae051cfd40a6e4effdf851ebd"


def test_an_embedded_packages_own_meta_gives_the_guids(tmp_path):
    embedded = "Packages/com.siemens.ros-sharp"
    build_tree(
        tmp_path,
        {
            "Assets/.keep": "",
            "Packages/manifest.json": json.dumps({"dependencies": {}}),
            f"{embedded}/package.json": json.dumps({"version": "2.2.1"}),
            f"{embedded}/Runtime/RosConnector.cs": "// ROS#\n",
            f"{embedded}/Runtime/RosConnector.cs.meta": "fileFormatVersion: 2\n"
            "guid: 0123456789abcdef0123456789abcdef\n",
        },
    )
    rossharp = RosSharp.of(tmp_path, script_index(tmp_path))
    assert rossharp.script("RosConnector").guid == "0123456789abcdef0123456789abcdef"
    assert rossharp.script("TwistSubscriber").guid == "81c5dfb51482c2e47b602e8096d45712"


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


def test_an_installed_package_of_the_pinned_release_is_not_noted(tmp_path):
    rossharp = _installed(tmp_path, "2.2.1", "2.2.1", "0123456789abcdef0123456789abcdef")
    assert rossharp.script("RosConnector").guid == "ff98778ae051cfd40a6e4effdf851ebd"
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


def _release_table(release: str) -> dict[str, str]:
    """``path inside the package -> GUID`` of every script of ``release``, from the vendored
    table of ROS#'s releases."""
    require(GUIDS.is_file(), f"ROS#'s script GUID table ({GUIDS})")
    with GUIDS.open(encoding="utf-8", newline="") as handle:
        return {
            row["path"].removeprefix("com.siemens.ros-sharp/"): row["guid"]
            for row in csv.DictReader(handle, delimiter="\t")
            if row["release"] == release
        }


def _cached(root: Path, pin: str, scripts: dict[str, str], says: str) -> RosSharp:
    """A project pinning ``pin`` whose Library/PackageCache holds a copy with ``scripts``
    (path -> GUID) and a package.json that says ``says``."""
    cache = "Library/PackageCache/com.siemens.ros-sharp@5e6f"
    files = {
        "Assets/.keep": "",
        "Packages/manifest.json": json.dumps(
            {"dependencies": {"com.siemens.ros-sharp": f"{GIT}#{pin}"}}
        ),
        f"{cache}/package.json": json.dumps({"version": says}),
    }
    for path, guid in scripts.items():
        files[f"{cache}/{path}.meta"] = f"fileFormatVersion: 2\nguid: {guid}\n"
    build_tree(root, files)
    return RosSharp.of(root, script_index(root))


def test_rossharp_2_2_1_whose_package_json_says_2_2_0_is_known_by_its_guids(tmp_path):
    rossharp = _cached(tmp_path, "2.2.1", _release_table("2.2.1"), says="2.2.0")
    assert rossharp.installed_version == "2.2.1"
    assert rossharp.notes == ()


def test_the_vendored_rossharp_2_2_1_package_is_known_as_2_2_1(tmp_path):
    require((VENDOR_2_2_1 / "Runtime").is_dir(), f"ROS# 2.2.1's package ({VENDOR_2_2_1})")
    assert json.loads((VENDOR_2_2_1 / "package.json").read_text())["version"] == "2.2.0"
    build_tree(
        tmp_path,
        {
            "Assets/.keep": "",
            "Packages/manifest.json": json.dumps(
                {"dependencies": {"com.siemens.ros-sharp": f"{GIT}#2.2.1"}}
            ),
        },
    )
    (tmp_path / "Library" / "PackageCache").mkdir(parents=True)
    (tmp_path / "Library" / "PackageCache" / "com.siemens.ros-sharp@ea80").symlink_to(VENDOR_2_2_1)
    rossharp = RosSharp.of(tmp_path, script_index(tmp_path))
    assert (rossharp.installed_version, rossharp.notes) == ("2.2.1", ())


def test_a_copy_of_2_2_0_under_a_2_2_1_pin_is_noted_whatever_its_package_json_says(tmp_path):
    rossharp = _cached(tmp_path, "2.2.1", _release_table("2.2.0"), says="2.2.1")
    assert rossharp.notes == (
        "ROS# 2.2.0 is installed in Library/PackageCache but Packages/manifest.json pins 2.2.1: "
        "using 2.2.1's script GUIDs (Unity installs 2.2.1 when it next opens the project)",
    )
    assert rossharp.script("RosConnector").guid == "ff98778ae051cfd40a6e4effdf851ebd"


def test_samples_do_not_count_in_a_copys_content(tmp_path):
    scripts = _release_table("2.2.1")
    scripts["Samples~/Extra/Extra.cs"] = "00112233445566778899aabbccddeeff"
    assert _cached(tmp_path, "2.2.1", scripts, says="2.2.0").installed_version == "2.2.1"


@pytest.mark.parametrize("release", ["2.0.0", "2.1.0", "2.1.1", "2.2.0", "2.2.1"])
def test_every_release_is_known_by_its_content_whatever_its_package_json_says(tmp_path, release):
    rossharp = _cached(tmp_path, "2.2.1", _release_table(release), says="9.9.9")
    assert rossharp.installed_version == release


def test_a_copy_the_catalog_does_not_know_is_taken_at_its_package_jsons_word(tmp_path):
    rossharp = _cached(tmp_path, "2.2.1", {"Runtime/X.cs": "0" * 31 + "1"}, says="3.0.0")
    assert rossharp.installed_version == "3.0.0"
