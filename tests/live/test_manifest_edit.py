"""Adding discovered topics and services to a manifest keeps every other byte."""

from __future__ import annotations

import dataclasses
import difflib
from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError
from unityscaffold.interfaces.live import Direction, DiscoveredService, DiscoveredTopic, Discovery
from unityscaffold.interfaces.live._actions import group_actions
from unityscaffold.interfaces.live.model import DiscoveredAction
from unityscaffold.interfaces.model import Dialect
from unityscaffold.manifest import load_manifest, starter_manifest
from unityscaffold.manifest.edit import edit_manifest, manifest_fragment
from unityscaffold.manifest.runtime import Runtime

EXAMPLE = """\
# My robot
version: 1
ros: 1            # or 2
project: .        # Unity project root, relative to this file
interfaces:       # extra folders searched for .msg/.srv/.action
  - ../robot_ws/src
connector: {scene: Assets/Scenes/Main.unity, gameobject: RosConnector, url: ws://localhost:9090}
topics:
  - {name: /cmd_vel, type: geometry_msgs/Twist, direction: publish, gameobject: Robot}
  - {name: /odom, type: nav_msgs/Odometry, direction: subscribe, gameobject: Robot}   # odometry
services:
  - {name: /reset, type: std_srvs/Trigger, role: client, gameobject: Robot}

# trailing comment
"""

FOUND = Discovery(
    Dialect.ROS1,
    "http://127.0.0.1:11311",
    (
        DiscoveredTopic("/imu", "sensor_msgs/Imu", Direction.SUBSCRIBE),
        DiscoveredTopic("/odom", "nav_msgs/Odometry", Direction.SUBSCRIBE),
        DiscoveredTopic("/mystery", "std_msgs/String"),
    ),
    (
        DiscoveredService("/reset", "std_srvs/Trigger"),
        DiscoveredService("/calibrate", "scaffold_test_msgs/Calibrate"),
    ),
)


def added_lines(before: str, after: str) -> list[str]:
    diff = difflib.ndiff(before.splitlines(), after.splitlines())
    assert not [line for line in diff if line.startswith("- ")], "a line was changed or removed"
    return [
        line[2:]
        for line in difflib.ndiff(before.splitlines(), after.splitlines())
        if line.startswith("+ ")
    ]


def test_new_entries_are_appended_and_nothing_else_changes() -> None:
    edit = edit_manifest(EXAMPLE, FOUND, cache_entry="ros_definitions")
    assert [" ".join(line.split()) for line in added_lines(EXAMPLE, edit.text)] == [
        "- ros_definitions",
        "- {name: /imu, type: sensor_msgs/Imu, direction: subscribe, gameobject: RosConnector}",
        "- {name: /mystery, type: std_msgs/String, gameobject: RosConnector}"
        " # TODO: direction: publish (Unity sends) or subscribe (Unity receives)",
        "- {name: /calibrate, type: scaffold_test_msgs/Calibrate, role: client, "
        "gameobject: RosConnector}",
    ]
    assert "\n  - {name: /imu," in edit.text  # indented like the entries already listed
    assert edit.added_topics == ("/imu", "/mystery")
    assert edit.added_services == ("/calibrate",)
    assert edit.already_listed == ("/odom", "/reset")


def test_a_second_edit_changes_nothing() -> None:
    once = edit_manifest(EXAMPLE, FOUND, cache_entry="ros_definitions")
    twice = edit_manifest(once.text, FOUND, cache_entry="./ros_definitions")
    assert not twice.changed
    assert twice.text == once.text


@pytest.mark.parametrize(
    ("style", "text"),
    [
        (
            "offset 0",
            "version: 1\nros: 1\ntopics:\n- name: /a\n  type: std_msgs/String\n"
            "  direction: publish\n",
        ),
        (
            "indent 4",
            "version: 1\nros: 1\ntopics:\n    -   name: /a\n        type: std_msgs/String\n"
            "        direction: publish\n",
        ),
    ],
)
def test_block_style_lists_keep_their_indentation(style: str, text: str) -> None:
    edit = edit_manifest(text, FOUND, cache_entry="defs")
    listed = text[text.index("topics:") :]
    assert listed in edit.text, style
    new_topics = edit.text[edit.text.index(listed) + len(listed) :].split("services:")[0]
    dash = listed.splitlines()[1].split("name")[0]
    assert new_topics.startswith(f"{dash}name: /imu\n"), new_topics
    assert f"{dash}name: /mystery  # TODO: direction" in new_topics
    assert "{" not in new_topics  # block entries, like the ones already listed


def test_empty_flow_lists_and_missing_keys_are_filled() -> None:
    text = (
        "version: 1\nros: 1\nproject: .\n\n# Extra folders:\n# interfaces:\n#   - ../ws\n\n"
        "connector: {url: ws://localhost:9090}\ntopics: []\n# - {name: /example}\n"
    )
    edit = edit_manifest(text, FOUND, cache_entry="ros_definitions")
    assert "interfaces:\n  - ros_definitions\nconnector:" in edit.text
    assert "topics:\n  - {name: /imu," in edit.text
    assert "# - {name: /example}" in edit.text


def test_a_manifest_for_the_other_ros_is_refused_at_its_ros_key() -> None:
    with pytest.raises(LocatedError) as caught:
        edit_manifest("version: 1\nros: 2\n", FOUND, cache_entry="d", path="robot.yaml")
    assert caught.value.render().startswith("robot.yaml:2:6: error: the manifest is for ROS 2")


@pytest.mark.parametrize("text", ["- a\n- b\n", "topics: {a: 1}\n", "topics: [\n"])
def test_malformed_manifests_are_located_errors(text: str) -> None:
    with pytest.raises(LocatedError):
        edit_manifest(text, FOUND, cache_entry="d", path="robot.yaml")


def test_the_fragment_lists_everything_discovered() -> None:
    fragment = manifest_fragment(FOUND, cache_entry="ros_definitions")
    assert fragment.splitlines()[:4] == [
        "# discovered from http://127.0.0.1:11311",
        "ros: 1",
        "interfaces:",
        "  - ros_definitions",
    ]
    assert fragment.count("gameobject: RosConnector") == 5


def test_a_list_with_nothing_found_keeps_its_commented_examples_usable(tmp_path) -> None:
    """init's starter after a discovery that finds topics but no services: 'services:' stays
    as written, so uncommenting its example gives a valid manifest (not 'services: []')."""
    starter = starter_manifest(1, "Assets/Scenes/Main.unity")
    found = Discovery(Dialect.ROS1, "http://127.0.0.1:11311", FOUND.topics[:1], ())
    edit = edit_manifest(starter, found, cache_entry="ros_definitions")
    assert edit.added_topics == ("/imu",) and edit.added_services == ()
    assert "services: []" not in edit.text
    assert "\nservices:\n#  - {name: /reset" in edit.text
    uncommented = edit.text.replace("#  - {name: /reset", "  - {name: /reset")
    path = tmp_path / "robot.yaml"
    path.write_text(uncommented, encoding="utf-8")
    manifest = load_manifest(path)
    assert [s.name for s in manifest.services] == ["/reset"]
    assert [t.name for t in manifest.topics] == ["/imu"]


def test_nothing_found_leaves_the_manifest_as_it_was() -> None:
    starter = starter_manifest(2, "Assets/Scenes/Main.unity")
    edit = edit_manifest(
        starter.replace("ros: 2", "ros: 1"), Discovery(Dialect.ROS1, "x", (), ()), cache_entry="d"
    )
    assert "topics: []" not in edit.text and "services: []" not in edit.text


@pytest.mark.parametrize("own_comment", ["", "  # ours"])
@pytest.mark.parametrize("gap", ["", "\n", "\n# next come topics\n"])
def test_an_entry_goes_inside_a_list_followed_by_blank_lines_or_comments(
    own_comment: str, gap: str
) -> None:
    # ruamel keeps what follows a list on its last item: appending there put the new entry
    # after the blank line that ends `interfaces:`, outside the list as a reader sees it
    text = (
        f"version: 1\nros: 1\ninterfaces:\n  - ros_ws/src{own_comment}\n{gap}"
        "topics:\n  - {name: /odom, type: nav_msgs/Odometry, direction: subscribe}\n"
        f"{gap}services:\n  - {{name: /reset, type: std_srvs/Trigger, role: client}}\n"
    )
    edit = edit_manifest(text, FOUND, cache_entry="ros_definitions")
    assert f"  - ros_ws/src{own_comment}\n  - ros_definitions\n{gap}topics:\n" in edit.text
    assert "  - {name: /mystery, type: std_msgs/String, gameobject: RosConnector}" in edit.text
    assert (
        "gameobject: RosConnector}\n" + gap + "services:\n" in edit.text
        or "(Unity receives)\n" + gap + "services:\n" in edit.text
    )


def _action_topics(name: str, package: str, short: str) -> list[DiscoveredTopic]:
    types = {
        "goal": f"{package}/{short}ActionGoal",
        "cancel": "actionlib_msgs/GoalID",
        "status": "actionlib_msgs/GoalStatusArray",
        "feedback": f"{package}/{short}ActionFeedback",
        "result": f"{package}/{short}ActionResult",
    }
    return [DiscoveredTopic(f"{name}/{part}", kind) for part, kind in types.items()]


def test_actionlib_topic_sets_become_actions_and_partial_sets_stay_topics(tmp_path: Path) -> None:
    recorded = Discovery(
        Dialect.ROS1,
        "run.bag",
        (
            # A complete set whose roles nobody shows (a bag): client, with a TODO.
            *_action_topics("/move_base", "move_base_msgs", "MoveBase"),
            # One topic short, and one with another action's type: plain topics.
            *_action_topics("/dock", "diffbot_msgs", "Dock")[:4],
            *_action_topics("/mixed", "diffbot_msgs", "Dock")[:4],
            DiscoveredTopic("/mixed/result", "move_base_msgs/MoveBaseActionResult"),
        ),
    )
    found = group_actions(recorded)
    assert [(a.name, a.type, a.role) for a in found.actions] == [
        ("/move_base", "move_base_msgs/action/MoveBase", None)
    ]
    assert [t.name for t in found.topics] == sorted(
        t.name for t in recorded.topics if not t.name.startswith("/move_base/")
    )
    edited = edit_manifest(EXAMPLE, found, cache_entry="ros_definitions")
    assert edited.added_actions == ("/move_base",)
    assert (
        "actions:\n  - {name: /move_base, type: move_base_msgs/action/MoveBase, role: client, "
        "gameobject: RosConnector}  # TODO: role: client (Unity sends goals) or server (Unity "
        "carries them out)\n"
    ) in edited.text
    # What discover writes into init's starter loads as a manifest with that action.
    starter = starter_manifest(1, "Assets/Scenes/Main.unity")
    path = tmp_path / "robot.yaml"
    only_action = dataclasses.replace(found, topics=())  # topics without direction get a TODO
    path.write_text(edit_manifest(starter, only_action, cache_entry="d").text, encoding="utf-8")
    assert [(a.name, a.role.value) for a in load_manifest(path).actions] == [
        ("/move_base", "client")
    ]
    ros2 = dataclasses.replace(recorded, dialect=Dialect.ROS2)
    assert group_actions(ros2) == ros2  # ROS 2 actions are not topics of this shape


def test_an_action_whose_topics_are_listed_already_is_not_added_again() -> None:
    """A manifest discovered before actions were recognised lists their five topics: adding
    the action too would make a second set of scripts on the same topics."""
    found = group_actions(
        Discovery(Dialect.ROS1, "run.bag", tuple(_action_topics("/dock", "diffbot_msgs", "Dock")))
    )
    listed = EXAMPLE.replace(
        "topics:\n",
        "topics:\n  - {name: /dock/goal, type: diffbot_msgs/DockActionGoal, direction: publish}\n",
    )
    edited = edit_manifest(listed, found, cache_entry="ros_definitions")
    assert edited.added_actions == () and edited.already_listed == ("/dock",)
    assert "actions:" not in edited.text


def test_entries_discovered_for_the_connector_runtime_go_on_its_rosconnection(
    tmp_path: Path,
) -> None:
    starter = starter_manifest(1, "Assets/Scenes/Main.unity", runtime=Runtime.TCP_CONNECTOR)
    directed = tuple(t for t in FOUND.topics if t.direction is not Direction.UNKNOWN)
    found = dataclasses.replace(FOUND, topics=directed, services=())
    edited = edit_manifest(starter, found, cache_entry="d")
    assert "RosConnector" not in edited.text
    path = tmp_path / "robot.yaml"
    (tmp_path / "d").mkdir()
    path.write_text(edited.text, encoding="utf-8")
    manifest = load_manifest(path)
    assert manifest.runtime is Runtime.TCP_CONNECTOR
    assert [(t.name, t.gameobject) for t in manifest.topics] == [
        ("/imu", "ROSConnection"),
        ("/odom", "ROSConnection"),
    ]


def test_ros2_actions_are_not_added_to_a_connector_manifest() -> None:
    starter = starter_manifest(2, "Assets/Scenes/Main.unity", runtime=Runtime.TCP_CONNECTOR)
    action = DiscoveredAction("/fibonacci", "test_msgs/action/Fibonacci", "client", ())
    found = Discovery(Dialect.ROS2, "graph", actions=(action,))
    edited = edit_manifest(starter, found, cache_entry="d")
    assert edited.added_actions == () and edited.already_listed == ("/fibonacci",)
    assert "test_msgs/action/Fibonacci, role" not in edited.text
