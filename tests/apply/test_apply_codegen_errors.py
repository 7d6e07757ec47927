"""A C# generation problem during apply points at the manifest entry that brings the type in,
with a hint in apply's terms (the manifest key ``namespace:``, not ``msgs gen``'s flag)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from helpers import run_cli, snapshot

REPO = Path(__file__).resolve().parents[2]
SHIPPED_HINT = "choose another root namespace with the manifest key `namespace:`"
RENAME_HINT = "ROS# names classes by package namespace and type name; rename one of the types"


@pytest.fixture
def sample(tmp_path: Path) -> Path:
    copy = tmp_path / "sample_project"
    shutil.copytree(REPO / "sample_project", copy)
    return copy


def _add_message(sample: Path, package: str, name: str) -> None:
    folder = sample / "ros_ws" / "src" / package / "msg"
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"{name}.msg").write_text("float64 x\n")


def _add_topics(sample: Path, *types: str) -> list[str]:
    """One subscribed topic per type, after the sample's topics; returns their lines."""
    manifest = sample / "robot.yaml"
    lines = [
        f"  - {{name: /extra{i}, type: {t}, direction: subscribe, gameobject: Robot}}"
        for i, t in enumerate(types)
    ]
    text = manifest.read_text()
    manifest.write_text(text.replace("\nservices:\n", "\n" + "\n".join(lines) + "\nservices:\n"))
    return lines


def _located(sample: Path, line: str, message: str, hint: str) -> str:
    manifest = sample / "robot.yaml"
    number = manifest.read_text().split("\n").index(line) + 1
    col = line.index("type: ") + len("type: ") + 1
    return (
        f"{manifest}:{number}:{col}: error: {message}\n"
        f"    {line}\n"
        f"    {' ' * (col - 1)}^\n"
        f"  hint: {hint}\n"
    )


def _apply_fails(sample: Path) -> str:
    before = snapshot(sample)
    run = run_cli("apply", str(sample / "robot.yaml"))
    assert run.code == 2, run.out + run.err
    assert snapshot(sample) == before
    return run.err


def test_a_type_taking_a_class_ros_sharp_ships_points_at_its_entry(sample):
    _add_message(sample, "geometry", "Wrench")
    (line,) = _add_topics(sample, "geometry/Wrench")
    message = (
        "geometry/Wrench would become RosSharp.RosBridgeClient.MessageTypes.Geometry.Wrench, "
        "a class ROS# already ships for geometry_msgs/Wrench"
    )
    assert _apply_fails(sample) == _located(sample, line, message, SHIPPED_HINT)


def test_the_namespace_key_the_hint_names_resolves_it(sample):
    _add_message(sample, "geometry", "Wrench")
    _add_topics(sample, "geometry/Wrench")
    manifest = sample / "robot.yaml"
    manifest.write_text(
        manifest.read_text().replace("\ninterfaces:", "\nnamespace: Bot.Ros\ninterfaces:")
    )
    run = run_cli("apply", "--dry-run", str(manifest))
    assert run.code == 0, run.err


def test_two_entries_whose_types_clash_point_at_the_second(sample):
    _add_message(sample, "clash_msgs", "Thing")
    _add_message(sample, "clash_actions", "Thing")
    _, second = _add_topics(sample, "clash_msgs/Thing", "clash_actions/Thing")
    message = (
        "clash_actions/Thing and clash_msgs/Thing would both become C# class "
        "RosSharp.RosBridgeClient.MessageTypes.Clash.Thing"
    )
    assert _apply_fails(sample) == _located(sample, second, message, RENAME_HINT)


def test_a_clash_with_a_type_every_generation_needs_points_at_the_entry(sample):
    _add_message(sample, "std", "Header")
    (line,) = _add_topics(sample, "std/Header")
    message = (
        "std/Header and std_msgs/Header would both become C# class "
        "RosSharp.RosBridgeClient.MessageTypes.Std.Header"
    )
    assert _apply_fails(sample) == _located(sample, line, message, RENAME_HINT)


@pytest.mark.parametrize(
    ("args", "hint"),
    [
        (["geometry/Wrench"], "generate into another root namespace with --namespace"),
        (
            ["clash_msgs/Thing", "clash_actions/Thing"],
            "ROS# names classes by package namespace and type name; rename one type, "
            "or generate them separately with --namespace",
        ),
    ],
)
def test_msgs_gen_words_the_same_clashes_with_its_flag(sample, tmp_path, args, hint):
    for package, name in (
        ("geometry", "Wrench"),
        ("clash_msgs", "Thing"),
        ("clash_actions", "Thing"),
    ):
        _add_message(sample, package, name)
    out = tmp_path / "out"
    run = run_cli(
        "msgs",
        "gen",
        "--ros",
        "1",
        "--path",
        str(sample / "ros_ws" / "src"),
        "--out",
        str(out),
        *args,
    )
    assert run.code == 2, run.out + run.err
    assert run.err.endswith(f"\n  hint: {hint}\n"), run.err
    assert run.err.startswith("error: ")
    assert not out.exists()
