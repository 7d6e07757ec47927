"""Property: whatever arguments the command line gets, ``scaffold`` ends with 0, 1 or 2 and
never prints a traceback (exit 3 is for bugs).

Argument lists are drawn from the commands, their options and values that are valid, wrong or
odd (paths that are folders, files of the wrong kind, names with ``/`` or ``..``, numbers out of
range), run in-process in a folder holding a copy of the sample project, the same reached
through symbolic links and a link that loops (no value leads out of it: ``init --force`` writes
where it is told). Live sources point at a closed
local port with a short timeout, so nothing waits on the network. Derandomized: CI sees the
same examples on every run.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from helpers import command_paths, run_cli
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

SAMPLE = Path(__file__).resolve().parents[2] / "sample_project"
# every command, the groups and the root too, as the app has them: a new one is drawn from at once
COMMANDS = [list(path) for path in command_paths()]
OPTIONS = [
    "--check", "--dry-run", "--quiet", "--force", "--json", "--follow-renames", "--ros-env",
    "--ros", "--path", "--no-env", "--package", "-p", "--out", "-o", "--namespace", "--live",
    "--timeout", "--master", "--rosbridge", "--bag", "--print", "-g", "--gameobject", "--script",
    "--guid", "--dll-class", "--set", "--create", "-",
]  # fmt: skip
VALUES = [
    "s/robot.yaml", "s", "s/unity", "s/unity/Assets/Scenes/Main.unity", "s/robot.lock.json",
    "s/ros_ws/src", "s/unity/Assets/RosGenerated/Scripts/CmdVelPublisher.cs", "s/unity/Assets/x",
    "robot.yaml", "1", "2", "3", "0", "-1", "nan", "inf", "1e400", "", " ", ".", "s/..",
    "x=1", "=", "a=", "Range=12.5", "Rate=abc", "Robot", "Robot/Lidar", "/Robot", "Robot//x",
    "é", "std_msgs/String", "std_msgs/msg/String", "std_msgs", "nav_msgs/GetMap",
    "diffbot_msgs/action/Dock", "x/y/z/w", "http://127.0.0.1:1", "ws://127.0.0.1:1", "http://",
    "ws://[::1", "nosuch.bag", "0123456789abcdef0123456789abcdef", "A..B", "My.class",
    "a" * 300, "--", "out",
]  # fmt: skip
# the sample through links: the whole of it, its Unity project from inside, and a link loop
LINKED = [
    "l/robot.yaml", "l", "l/unity", "l/unity/Assets/Scenes/Main.unity", "s/u", "s/linked.yaml",
    "s/u/Assets/Scenes/Main.unity", "s/u/Assets/Gen", "l/unity/Assets/Gen", "loop",
    "loop/robot.yaml",
]  # fmt: skip
VALUES += LINKED
ARGUMENTS = st.tuples(
    st.sampled_from(COMMANDS),
    st.lists(
        st.one_of(
            st.sampled_from(VALUES).map(lambda v: [v]),
            st.tuples(st.sampled_from(OPTIONS), st.sampled_from(VALUES)).map(list),
        ),
        max_size=5,
    ),
).map(lambda t: [*t[0], *(a for pair in t[1] for a in pair)])


@pytest.fixture(scope="module")
def workdir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("cli")
    shutil.copytree(SAMPLE, root / "s")
    (root / "s" / "unity" / "Assets" / "x").write_text("not a scene\n")
    (root / "l").symlink_to(root / "s", target_is_directory=True)
    (root / "s" / "u").symlink_to(root / "s" / "unity", target_is_directory=True)
    manifest = (root / "s" / "robot.yaml").read_text()
    (root / "s" / "linked.yaml").write_text(manifest.replace("project: unity ", "project: u ", 1))
    (root / "loop").symlink_to(root / "loop")
    return root


@settings(
    max_examples=120,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
@given(args=ARGUMENTS)
def test_any_arguments_end_in_0_1_or_2_without_a_traceback(
    workdir: Path, args: list[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(workdir)
    if any(a in args for a in ("--live", "--master", "--rosbridge")):
        args += ["--timeout", "0.5"]
    run = run_cli(*args)
    assert run.code in (0, 1, 2), (args, run.err[-2000:])
    assert "Traceback" not in run.out + run.err, args


# The paths through links, each where a command takes a path: the draw above seldom puts one
# alone after a command that writes, where exit 3 was (a project named through a link).
PATH_COMMANDS = [
    ["apply"], ["apply", "--check"], ["apply", "--dry-run"], ["plan"], ["scene", "ls"],
    ["msgs", "gen", "std_msgs/String", "--ros", "1", "--out"], ["init", "--force", "--ros", "2"],
]  # fmt: skip


@settings(
    max_examples=40,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
@given(command=st.sampled_from(PATH_COMMANDS), path=st.sampled_from(LINKED))
def test_any_path_through_a_link_ends_in_0_1_or_2_without_a_traceback(
    workdir: Path, command: list[str], path: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(workdir)
    run = run_cli(*command, path)
    assert run.code in (0, 1, 2), (command, path, run.err[-2000:])
    assert "Traceback" not in run.out + run.err, (command, path)
