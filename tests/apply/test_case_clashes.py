"""Two files or folders apply would write whose names differ only in letter case are refused
before anything is written: on Windows and macOS they are one."""

from __future__ import annotations

from pathlib import Path

import pytest
from robot_helpers import HEADER, apply, apply_refused, init_project

from unityscaffold.apply._case_clashes import check_case_clashes
from unityscaffold.errors import UserError


def _urdf(first: str, second: str) -> str:
    visual = '<visual><geometry><box size="1 1 1"/></geometry><material name="{}"/></visual>'
    return f"""<robot name="bot">
  <material name="{first}"><color rgba="0 0 0.8 1"/></material>
  <material name="{second}"><color rgba="0.8 0 0 1"/></material>
  <link name="a">{visual.format(first)}</link>
  <link name="b">{visual.format(second)}</link>
  <joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>
</robot>
"""


def _project(tmp_path: Path, urdf: str) -> Path:
    return init_project(tmp_path, {"ros/bot.urdf": urdf, "robot.yaml": HEADER})


def test_two_urdf_materials_named_apart_only_by_case_are_numbered_apart(tmp_path: Path) -> None:
    """ROS# would make one file of them on Windows and macOS, two on Linux: the second in
    ROS#'s order is numbered, as Unity numbers a copy (docs/unity-yaml.md)."""
    project = _project(tmp_path, _urdf("Blue", "blue"))
    run = apply(project)
    assert run.code == 0, run
    materials = project / "Assets/Urdf/bot/Materials"
    assert {p.name for p in materials.glob("*.mat")} == {"Default.mat", "Blue.mat", "blue 1.mat"}


def test_two_textures_named_apart_only_by_case_are_refused_and_nothing_is_written(
    tmp_path: Path,
) -> None:
    material = '<material name="{0}"><texture filename="package://desc/{0}.png"/></material>'
    urdf = _urdf("Skin", "skin").replace(
        '<material name="Skin"><color rgba="0 0 0.8 1"/></material>', material.format("Skin")
    )
    urdf = urdf.replace(
        '<material name="skin"><color rgba="0.8 0 0 1"/></material>', material.format("skin")
    )
    project = init_project(
        tmp_path,
        {
            "ros/bot.urdf": urdf,
            "robot.yaml": HEADER + "    packages: {desc: ros/desc}\n",
            "ros/desc/Skin.png": "S",
            "ros/desc/skin.png": "s",
        },
    )
    run = apply_refused(project)
    assert "Assets/Urdf/bot/desc/Skin.png" in run.err, run.err
    assert "Assets/Urdf/bot/desc/skin.png" in run.err, run.err
    assert "differ only in letter case" in run.err, run.err


def test_materials_with_different_names_are_applied(tmp_path: Path) -> None:
    project = _project(tmp_path, _urdf("Blue", "red"))
    run = apply(project)
    assert run.code == 0, run
    materials = project / "Assets/Urdf/bot/Materials"
    assert {p.name for p in materials.glob("*.mat")} >= {"Blue.mat", "red.mat"}


@pytest.mark.parametrize(
    ("paths", "told"),
    [
        (["Assets/A/x.cs", "Assets/a/y.cs"], "folders Assets/A and Assets/a"),
        (["Assets/M/x.asset", "Assets/M/X.asset"], "files Assets/M/X.asset and Assets/M/x.asset"),
    ],
)
def test_a_clash_names_both_spellings_and_whether_they_are_files_or_folders(
    tmp_path: Path, paths: list[str], told: str
) -> None:
    with pytest.raises(UserError, match=told):
        check_case_clashes(tmp_path, [tmp_path / p for p in paths])


def test_one_spelling_used_twice_and_paths_beside_the_project_pass(tmp_path: Path) -> None:
    root = tmp_path / "unity"
    paths = ["Assets/A/x.cs", "Assets/A/y.cs", "Assets/A.meta"]
    check_case_clashes(root, [root / p for p in paths] + [tmp_path / "robot.lock.json"])
