"""Every ROS 1 msg and srv Debian ships: md5sum and full text equal what genmsg computes now."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError
from unityscaffold.interfaces.identity_ros1 import Ros1Identity
from unityscaffold.interfaces.model import Dialect, MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry

REFERENCE_SCRIPT = Path(__file__).with_name("genmsg_reference.py")


@pytest.fixture(scope="module")
def genmsg_results(genmsg_python, ros1_share) -> dict:
    output = subprocess.run(
        [str(genmsg_python), str(REFERENCE_SCRIPT), str(ros1_share)],
        capture_output=True,
        text=True,
        check=True,
        timeout=120,
    ).stdout
    return json.loads(output)


@pytest.fixture(scope="module")
def identity(ros1_share) -> Ros1Identity:
    packages = sorted(
        {p.parent for p in ros1_share.glob("*/msg")} | {p.parent for p in ros1_share.glob("*/srv")}
    )
    registry = Registry.load(Dialect.ROS1, packages, use_environment=False, use_builtin=False)
    return Ros1Identity(registry)


def test_genmsg_covers_the_whole_debian_set(genmsg_results):
    # The reference note counts 154 msg + 29 srv in Debian bookworm's packages.
    assert len(genmsg_results) >= 183


def _lookup(registry: Registry, name: str, expected: dict):
    """genmsg keys services as pkg/Name; a package may also have an action of that name."""
    if "request" in expected:
        package, short = name.split("/")
        return registry.get(f"{package}/srv/{short}")
    return registry.get(name)


def test_every_message_md5sum_and_full_text_equal_genmsg(genmsg_results, identity):
    mismatches = []
    for name, expected in genmsg_results.items():
        spec = _lookup(identity.registry, name, expected)
        if not isinstance(spec, MessageSpec):
            continue
        got = (identity.md5sum(spec), identity.full_text(spec))
        if got != (expected["md5sum"], expected["definition"]):
            mismatches.append(name)
    assert mismatches == []


def test_every_service_md5sum_and_halves_equal_genmsg(genmsg_results, identity):
    mismatches = []
    services = 0
    for name, expected in genmsg_results.items():
        spec = _lookup(identity.registry, name, expected)
        if not isinstance(spec, ServiceSpec):
            continue
        services += 1
        if identity.md5sum(spec) != expected["md5sum"]:
            mismatches.append(name)
        for key in ("request", "response"):
            half = getattr(spec, key)
            want = expected[key]
            if (half.full_name, identity.md5sum(half), identity.full_text(half)) != (
                want["type"],
                want["md5sum"],
                want["definition"],
            ):
                mismatches.append(f"{name} {key}")
    assert services >= 29
    assert mismatches == []


@pytest.mark.parametrize(
    ("name", "md5"),
    [
        ("std_msgs/Header", "2176decaecbce78abc3b96ef049fabed"),
        ("std_msgs/String", "992ce8a1687cec8c8bd883ec73ca41d1"),
        ("sensor_msgs/Imu", "6a62c6daae103f4ff57a132d6f95cec2"),
        ("std_srvs/Empty", "d41d8cd98f00b204e9800998ecf8427e"),
    ],
)
def test_known_md5sums_from_the_builtin_definitions(name, md5):
    registry = Registry.load(Dialect.ROS1, use_environment=False)
    assert Ros1Identity(registry).md5sum(registry.get(name)) == md5


def test_action_messages_equal_the_files_debian_generated(ros1_share):
    """genaction's seven texts, rebuilt from the .action file, equal Debian's .msg files."""
    registry = Registry.load(
        Dialect.ROS1,
        [
            ros1_share / "nav_msgs",
            ros1_share / "actionlib_msgs",
            ros1_share / "std_msgs",
            ros1_share / "geometry_msgs",
        ],
        use_environment=False,
        use_builtin=False,
    )
    action = registry.get("nav_msgs/action/GetMap")
    assert action.kind.value == "action"
    for message in action.messages:
        shipped = (ros1_share / "nav_msgs" / "msg" / f"{message.name}.msg").read_text()
        assert message.text == shipped, message.name


def test_a_message_that_contains_itself_has_no_md5_and_says_where(tmp_path):
    """Definitions from a live system reach the md5 without a closure check first."""
    folder = tmp_path / "loop_msgs" / "msg"
    folder.mkdir(parents=True)
    (folder / "A.msg").write_text("int32 x\nA again\n")
    registry = Registry.load(Dialect.ROS1, [tmp_path], use_environment=False, use_builtin=False)
    identity = Ros1Identity(registry)
    with pytest.raises(LocatedError) as caught:
        identity.md5sum(registry.message("loop_msgs/A"))
    assert caught.value.render().startswith(
        f"{folder / 'A.msg'}:2:1: error: types refer to each other in a cycle: "
        "loop_msgs/A -> loop_msgs/A\n"
    )
    assert [d.full_name for d in identity.dependencies(registry.message("loop_msgs/A"))] == [
        "loop_msgs/A"
    ]
