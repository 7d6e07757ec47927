"""A xacro's `$(env)` and `$(optenv)` read the robot entry's `env`, never the machine's.

What the substitutions mean is roslaunch's, which xacro follows
(https://wiki.ros.org/roslaunch/XML#substitution_args): "$(optenv ENVIRONMENT_VARIABLE
default_value): substitute the value of an environment variable if it is set. If default_value
is provided, it will be used if the environment variable is not set. If default_value is not
provided, an empty string will be used"; "$(env ENVIRONMENT_VARIABLE): ... launch will fail if
environment variable is not set". The xacro files mirror Clearpath's Husky
(husky_description/urdf/husky.urdf.xacro: `<xacro:arg name="laser_enabled"
default="$(optenv HUSKY_LMS1XX_ENABLED 0)"/>`, `$(optenv HUSKY_IMU_XYZ 0.19 0 0.149)`) and
Jackal (jackal_description/urdf/accessories.urdf.xacro: `<xacro:if value="$(optenv JACKAL_LASER
0)">`), https://github.com/husky/husky and https://github.com/jackal/jackal.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest
from helpers import build_tree, require

from unityscaffold.errors import LocatedError
from unityscaffold.urdf import parse_urdf, read_urdf

require(importlib.util.find_spec("xacro"), "xacro (the `xacro` extra)")

HUSKY = """<?xml version="1.0"?>
<robot name="husky" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="laser_enabled" default="$(optenv HUSKY_LMS1XX_ENABLED 0)"/>
  <xacro:arg name="imu_xyz" default="$(optenv HUSKY_IMU_XYZ 0.19 0 0.149)"/>
  <xacro:property name="laser_prefix" value="$(optenv HUSKY_LMS1XX_PREFIX front)"/>
  <link name="base_link$(optenv HUSKY_SUFFIX)"/>
  <link name="imu_link"/>
  <joint name="imu_joint" type="fixed">
    <origin xyz="$(arg imu_xyz)"/>
    <parent link="base_link$(optenv HUSKY_SUFFIX)"/><child link="imu_link"/>
  </joint>
  <xacro:if value="$(arg laser_enabled)">
    <link name="${laser_prefix}_laser"/>
    <joint name="laser_joint" type="fixed">
      <parent link="base_link$(optenv HUSKY_SUFFIX)"/><child link="${laser_prefix}_laser"/>
    </joint>
  </xacro:if>
</robot>
"""


def expected(
    *, base: str = "base_link", xyz: str = "0.19 0 0.149", laser: str | None = None
) -> bytes:
    """The URDF the `xacro` command prints for HUSKY with the given values (by the rules in
    this module's docstring)."""
    extra = (
        f'<link name="{laser}_laser"/>\n<joint name="laser_joint" type="fixed">'
        f'<parent link="{base}"/><child link="{laser}_laser"/></joint>\n'
        if laser is not None
        else ""
    )
    return (
        f'<robot name="husky">\n<link name="{base}"/>\n<link name="imu_link"/>\n'
        f'<joint name="imu_joint" type="fixed"><origin xyz="{xyz}"/>'
        f'<parent link="{base}"/><child link="imu_link"/></joint>\n{extra}</robot>\n'
    ).encode()


@pytest.fixture
def husky(tmp_path: Path) -> Path:
    return build_tree(tmp_path, {"husky.urdf.xacro": HUSKY}) / "husky.urdf.xacro"


def test_optenv_takes_its_default_and_never_the_machines_variable(
    husky: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # set on the machine, as a Husky owner's shell has them: the import must not see them
    monkeypatch.setenv("HUSKY_LMS1XX_ENABLED", "1")
    monkeypatch.setenv("HUSKY_SUFFIX", "_machine")
    monkeypatch.setenv("HUSKY_IMU_XYZ", "9 9 9")
    # defaults: laser 0 (no laser link), imu "0.19 0 0.149" (the words after the name, joined
    # by spaces), $(optenv HUSKY_SUFFIX) without a default: the empty string
    assert read_urdf(husky) == parse_urdf(expected())


def test_the_entrys_env_gives_optenv_its_value(husky: Path) -> None:
    env = {"HUSKY_LMS1XX_ENABLED": "1", "HUSKY_SUFFIX": "_2", "HUSKY_IMU_XYZ": "0 0 1"}
    assert read_urdf(husky, xacro_env=env) == parse_urdf(
        expected(base="base_link_2", xyz="0 0 1", laser="front")
    )


def test_an_empty_value_is_a_value_not_a_missing_variable(husky: Path) -> None:
    # set but empty: $(optenv) takes the empty value, not its default
    robot = read_urdf(husky, xacro_env={"HUSKY_LMS1XX_ENABLED": "1", "HUSKY_LMS1XX_PREFIX": ""})
    assert robot == parse_urdf(expected(laser=""))  # the laser link is "_laser"


def test_env_reads_the_entrys_value(tmp_path: Path) -> None:
    xacro = build_tree(
        tmp_path, {"r.urdf.xacro": HUSKY.replace("$(optenv HUSKY_SUFFIX)", "$(env HUSKY_SUFFIX)")}
    )
    robot = read_urdf(xacro / "r.urdf.xacro", xacro_env={"HUSKY_SUFFIX": "_x"})
    assert robot == parse_urdf(expected(base="base_link_x"))


def test_env_of_a_variable_the_entry_leaves_out_is_an_error_at_its_place(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("HUSKY_SUFFIX", "_machine")  # the machine's value is not a way out
    root = build_tree(
        tmp_path, {"r.urdf.xacro": HUSKY.replace("$(optenv HUSKY_SUFFIX)", "$(env HUSKY_SUFFIX)")}
    )
    with pytest.raises(LocatedError) as caught:
        read_urdf(root / "r.urdf.xacro", xacro_env={"OTHER": "1"})
    (diagnostic,) = caught.value.diagnostics
    # line 6, column 24: `$(env` in `  <link name="base_link$(env HUSKY_SUFFIX)"/>`
    assert (diagnostic.location.path, diagnostic.location.line, diagnostic.location.col) == (
        str(root / "r.urdf.xacro"),
        6,
        24,
    )
    assert diagnostic.message == (
        "$(env HUSKY_SUFFIX): variable 'HUSKY_SUFFIX' has no value in this robot's `env` "
        "(given: OTHER); the machine's environment is never read"
    )
    assert diagnostic.hint == "give it one in the entry: env: {HUSKY_SUFFIX: <value>}"


def test_env_in_an_included_file_is_located_in_that_file(tmp_path: Path) -> None:
    # Jackal's accessories.urdf.xacro is included by jackal.urdf.xacro
    root = build_tree(
        tmp_path,
        {
            "jackal.urdf.xacro": '<robot name="jackal" xmlns:xacro="http://www.ros.org/wiki/xacro">'
            '\n<link name="base_link"/>\n<xacro:include filename="accessories.urdf.xacro"/>\n'
            "</robot>\n",
            "accessories.urdf.xacro": '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
            '  <xacro:if value="$(optenv JACKAL_LASER 0)">\n'
            '    <link name="$(env JACKAL_LASER_MOUNT)_laser"/>\n'
            "  </xacro:if>\n</robot>\n",
        },
    )
    plain = read_urdf(root / "jackal.urdf.xacro")  # JACKAL_LASER's default 0: no laser
    assert plain == parse_urdf(b'<robot name="jackal"><link name="base_link"/></robot>')
    with pytest.raises(LocatedError) as caught:
        read_urdf(root / "jackal.urdf.xacro", xacro_env={"JACKAL_LASER": "1"})
    location = caught.value.location
    assert (location.path, location.line, location.col) == (
        str(root / "accessories.urdf.xacro"),
        3,
        17,
    )


def test_a_found_folder_left_in_the_urdf_is_written_back_as_find(tmp_path: Path) -> None:
    """xacro answers `$(find pkg)` with the package's folder (to read what it includes); in
    the URDF that folder becomes `$(find pkg)` again, where a path goes on or the text ends,
    so the URDF is the same wherever the repository is. `$(find desc)2/x` names a folder that
    only starts with the package's, not the package: it is left as xacro wrote it (and, like
    any absolute path a URDF names, ties the scene to this checkout's place)."""
    xacro = (
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="a"><visual>'
        '<geometry><mesh filename="file://$(find desc)/m.stl"/></geometry></visual></link>'
        "<gazebo><p>$(find desc)</p><q>$(find desc)2/x</q></gazebo></robot>"
    )
    root = build_tree(tmp_path, {"desc/r.urdf.xacro": xacro})
    robot = read_urdf(root / "desc/r.urdf.xacro", packages={"desc": root / "desc"})
    assert robot.links[0].visuals[0].geometry.filename == "file://$(find desc)/m.stl"  # type: ignore[union-attr]
    (plugin,) = robot.plugins
    assert "<p>$(find desc)</p>" in plugin.text and f"<q>{root}/desc2/x</q>" in plugin.text
