"""A `robots:` entry naming a `.xacro`: expanded in process by PyPI's `xacro` (the `xacro`
extra), `$(find)` resolved through the entry's `packages` only, `args` passed on, `$(env)` and
`$(optenv)` answered by the entry's `env` only; the robot is the one its plain URDF makes, an
edit to an included file or to `env` is never replayed as a no-op, and a xacro mistake is a
located error that writes nothing."""

from __future__ import annotations

import importlib.util
import shutil
import sys
from pathlib import Path

import pytest
from helpers import require, snapshot
from robot_helpers import (
    BOT_URDF,
    HEADER,
    ROBOTS,
    apply,
    apply_manifest,
    apply_refused,
    apply_writes_nothing,
    init_project,
)

from tests.cli.noop_support import records, scaffold
from unityscaffold.cli import _app

require(importlib.util.find_spec("xacro"), "xacro (the `xacro` extra)")

XACRO = "ros/bot_description/urdf/bot.urdf.xacro"
MAIN = """<?xml version="1.0"?>
<robot name="$(arg name)" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="name" default="wrong"/>
  <xacro:include filename="$(find bot_description)/urdf/parts.xacro"/>
  <material name="blue"><color rgba="0 0 ${blue} 1"/></material>
  <gazebo>
    <plugin name="p"/>
  </gazebo>
  <link name="base">
    <xacro:inertial mass="2"/>
    <visual><geometry><box size="1 2 3"/></geometry><material name="blue"/></visual>
    <collision><geometry><cylinder radius="${radius}" length="2"/></geometry></collision>
  </link>
  <link name="arm">
    <xacro:inertial mass="1"/>
    <visual><origin xyz="0 0 ${radius}"/><geometry><sphere radius="0.1"/></geometry></visual>
    <collision><geometry><sphere radius="0.1"/></geometry></collision>
  </link>
  <joint name="j" type="revolute"><origin xyz="0 0 1"/><parent link="base"/><child link="arm"/>
    <axis xyz="0 1 0"/><limit effort="1" velocity="1" lower="-1" upper="1"/></joint>
</robot>
"""
PARTS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="radius" value="0.5"/>
  <xacro:property name="blue" value="${0.4 * 2}"/>
  <xacro:macro name="inertial" params="mass">
    <inertial><mass value="${mass}"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="2" iyz="0" izz="3"/></inertial>
  </xacro:macro>
</robot>
"""
ENTRY = (
    f"  - urdf: {XACRO}\n"
    "    packages: {bot_description: ros/bot_description}\n"
    "    args: {name: bot}\n"
)
MANIFEST = ROBOTS + ENTRY


@pytest.fixture
def project(tmp_path: Path) -> Path:
    files = {"ros/bot.urdf": BOT_URDF, XACRO: MAIN, "ros/bot_description/urdf/parts.xacro": PARTS}
    return init_project(tmp_path, files)


def test_a_xacro_robot_makes_the_project_its_plain_urdf_makes(project: Path) -> None:
    assert apply_manifest(project, HEADER).code == 0
    from_urdf = snapshot(project)
    check = apply_manifest(project, MANIFEST, "--check")
    assert check.code == 0, check.out + check.err
    run = apply_manifest(project, MANIFEST)
    assert run.code == 0, run.err
    assert {k: v for k, v in snapshot(project).items() if k != "robot.yaml"} == {
        k: v for k, v in from_urdf.items() if k != "robot.yaml"
    }


def recording(project: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The no-op record switched on, in a cache folder of the test's own (returned), with
    ``project`` as the current folder: as a user's repeated `scaffold apply` runs."""
    cache = project.parent / "cache"
    (cache / "unityscaffold").mkdir(parents=True)
    monkeypatch.setenv("XDG_CACHE_HOME", str(cache))
    monkeypatch.delenv("UNITYSCAFFOLD_NO_CACHE", raising=False)
    monkeypatch.delenv("UNITYSCAFFOLD_NO_REPLAY", raising=False)
    monkeypatch.chdir(project)
    return cache


def test_an_edit_to_an_included_file_is_seen_by_the_next_check(
    project: Path, monkeypatch: pytest.MonkeyPatch, capsysbinary: pytest.CaptureFixture[bytes]
) -> None:
    cache = recording(project, monkeypatch)
    planned: list[list[str]] = []
    real = _app.run_cli
    monkeypatch.setattr(_app, "run_cli", lambda args: planned.append(args) or real(args))
    (project / "robot.yaml").write_text(MANIFEST)
    assert scaffold(capsysbinary, "apply")[0] == 0
    assert scaffold(capsysbinary, "apply", "--check")[0] == 0
    assert scaffold(capsysbinary, "apply", "--check")[0] == 0
    assert records(cache) and len(planned) == 2  # the clean check was recorded and replayed
    parts = project / "ros/bot_description/urdf/parts.xacro"
    parts.write_text(PARTS.replace('value="0.5"', 'value="0.25"'))
    code, out, _ = scaffold(capsysbinary, "apply", "--check")
    assert len(planned) == 3 and code == 1 and b"bot" in out, out


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (
            lambda p: p.replace('${radius}" length', '${radus}" length'),
            f"{XACRO}: error: xacro: name 'radus' is not defined",
        ),
        (
            lambda p: p.replace("urdf/parts.xacro", "urdf/part.xacro"),
            f"{XACRO}: error: xacro: No such file or directory",
        ),
        (
            lambda p: p.replace("$(find bot_description)", "$(find other)"),
            "error: $(find other): package 'other' is not in this robot's `packages` "
            "(listed: bot_description)",
        ),
        (
            lambda p: p.replace("$(arg name)", "$(arg nam)"),
            f"{XACRO}: error: xacro: Undefined substitution argument nam",
        ),
        (
            lambda p: p.replace("$(arg name)", "$(env HOME)"),
            f"{XACRO}:2:14: error: $(env HOME): variable 'HOME' has no value in this robot's "
            "`env` (given: none); the machine's environment is never read",
        ),
        (
            lambda p: p.replace("$(arg name)", "$(cwd)"),
            f"{XACRO}:2:14: error: $(cwd) (the folder apply runs in) would make the URDF "
            "depend on this machine",
        ),
        (
            lambda p: p.replace("</robot>", "</robt>"),
            f"{XACRO}:21:3: error: not well-formed XML: mismatched tag",
        ),
        (
            lambda p: p.replace('type="revolute"', 'type="spinning"'),
            f"{XACRO} (expanded by xacro):",
        ),
    ],
)
def test_a_xacro_mistake_is_a_located_error_and_nothing_is_written(
    project: Path, change, message: str
) -> None:
    xacro = project / XACRO
    xacro.write_text(change(MAIN))
    run = apply_refused(project, MANIFEST)
    assert message in run.err, run.err
    assert "Traceback" not in run.err and "hint:" in run.err


def test_without_the_xacro_package_the_error_names_the_extra_to_install(
    project: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(sys.modules, "xacro", None)  # what an import finds when it is missing
    run = apply_refused(project, MANIFEST)
    assert "robot.yaml:6:11: error:" in run.err and "the xacro package is not installed" in run.err
    assert "pip install 'unityscaffold[xacro]'" in run.err


def test_xacros_warnings_are_notes_naming_the_file_and_never_reach_stderr(
    project: Path,
) -> None:
    parts = project / "ros/bot_description/urdf/parts.xacro"
    parts.write_text(
        PARTS.replace(
            '<xacro:property name="radius"',
            '<xacro:property name="pi" value="3"/>\n  <xacro:property name="radius"',
        )
    )
    run = apply_manifest(project, MANIFEST)
    assert run.code == 0, run.err
    assert run.err == ""
    assert f"note: {parts}: xacro warns: redefining global symbol: pi" in run.out, run.out


# Husky's way of making a part optional (husky_description/urdf/husky.urdf.xacro,
# https://github.com/husky/husky): an argument whose default is $(optenv VAR default)
OPTIONAL_ARM = (
    MAIN.replace(
        '<xacro:arg name="name" default="wrong"/>',
        '<xacro:arg name="name" default="wrong"/>\n'
        '  <xacro:arg name="arm_enabled" default="$(optenv BOT_ARM_ENABLED 0)"/>',
    )
    .replace('  <link name="arm">', '  <xacro:if value="$(arg arm_enabled)">\n  <link name="arm">')
    .replace("</joint>\n</robot>", "</joint>\n  </xacro:if>\n</robot>")
)


def scene_links(project: Path) -> list[str]:
    """The names of the UrdfLink objects' GameObjects, as the scene lists them."""
    text = (project / "Assets/Scenes/Main.unity").read_text()
    return [name for name in ("base", "arm") if f"  m_Name: {name}\n" in text]


def test_optenv_takes_its_default_and_the_entrys_env_its_value(
    project: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (project / XACRO).write_text(OPTIONAL_ARM)
    monkeypatch.setenv("BOT_ARM_ENABLED", "1")  # the machine's value, never read
    assert apply_manifest(project, MANIFEST).code == 0
    assert scene_links(project) == ["base"]  # $(optenv BOT_ARM_ENABLED 0): no arm
    apply_writes_nothing(project)
    assert apply_manifest(project, MANIFEST, "--check").code == 0
    with_arm = MANIFEST + "    env: {BOT_ARM_ENABLED: '1'}\n"
    check = apply_manifest(project, with_arm, "--check")
    assert check.code == 1, check.out + check.err  # the changed env changes the import
    assert apply_manifest(project, with_arm).code == 0
    assert scene_links(project) == ["base", "arm"]
    apply_writes_nothing(project)
    assert apply_manifest(project, with_arm, "--check").code == 0


def test_a_changed_env_value_is_never_replayed_as_a_no_op(
    project: Path, monkeypatch: pytest.MonkeyPatch, capsysbinary: pytest.CaptureFixture[bytes]
) -> None:
    cache = recording(project, monkeypatch)
    (project / XACRO).write_text(OPTIONAL_ARM)
    manifest = project / "robot.yaml"
    manifest.write_text(MANIFEST + "    env: {BOT_ARM_ENABLED: '0'}\n")
    assert scaffold(capsysbinary, "apply")[0] == 0
    assert scaffold(capsysbinary, "apply", "--check")[0] == 0
    assert scaffold(capsysbinary, "apply", "--check")[0] == 0
    assert records(cache)  # the clean check was recorded
    manifest.write_text(MANIFEST + "    env: {BOT_ARM_ENABLED: '1'}\n")
    code, out, _ = scaffold(capsysbinary, "apply", "--check")
    assert code == 1 and b"robot bot (" in out, out


def test_env_without_its_variable_is_an_error_naming_the_env_key(project: Path) -> None:
    (project / XACRO).write_text(MAIN.replace('<plugin name="p"/>', '<plugin name="$(env P)"/>'))
    run = apply_refused(project, MANIFEST)
    # line 7, column 19: the `$(env` of `    <plugin name="$(env P)"/>`
    assert (
        f"{XACRO}:7:19: error: $(env P): variable 'P' has no value in this robot's `env` "
        "(given: none); the machine's environment is never read" in run.err
    ), run.err
    assert "hint: give it one in the entry: env: {P: <value>}" in run.err
    assert apply_manifest(project, MANIFEST + "    env: {P: p}\n").code == 0


def test_a_find_left_in_the_urdf_keeps_the_project_portable(project: Path) -> None:
    """TIAGo's and OpenManipulator's xacros put `$(find pkg)/config/….yaml` into a Gazebo
    plugin, which ROS# keeps as the UrdfPlugin's text: with the checkout's own folder there, a
    clone at another path (a teammate's, CI's) would see drift. It stays `$(find pkg)`."""
    plugin = '<plugin name="p"><parameters>$(find bot_description)/config/c.yaml</parameters>'
    (project / XACRO).write_text(MAIN.replace('<plugin name="p"/>', plugin + "</plugin>"))
    assert apply_manifest(project, MANIFEST).code == 0
    scene = (project / "Assets/Scenes/Main.unity").read_text()
    assert "<parameters>$(find bot_description)/config/c.yaml</parameters>" in scene
    assert str(project) not in scene
    moved = project.parent / "elsewhere"
    shutil.copytree(project, moved, symlinks=True)
    check = apply(moved, "--check")
    assert check.code == 0, check.out + check.err
