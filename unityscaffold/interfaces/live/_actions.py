"""ROS 1 actions among discovered topics: actionlib's five topics become one action.

An actionlib action ``/ns`` of type ``pkg/X`` is five topics: ``/ns/goal`` (``pkg/XActionGoal``),
``/ns/cancel`` (``actionlib_msgs/GoalID``), ``/ns/status`` (``actionlib_msgs/GoalStatusArray``),
``/ns/feedback`` (``pkg/XActionFeedback``) and ``/ns/result`` (``pkg/XActionResult``). Only a
complete set with these types is taken for an action; anything less stays plain topics.
"""

from __future__ import annotations

import dataclasses
import re

from unityscaffold.interfaces.live.model import (
    Direction,
    DiscoveredAction,
    DiscoveredTopic,
    Discovery,
)
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.suffixes import (
    ROS1_ACTION_FEEDBACK,
    ROS1_ACTION_GOAL,
    ROS1_ACTION_RESULT,
)

__all__ = ["ACTION_TOPICS", "group_actions"]

ACTION_TOPICS = ("goal", "cancel", "status", "feedback", "result")
"""The topics under an action's name, in the order ``DiscoveredAction.topics`` holds them."""

_FIXED_TYPES = {"cancel": "actionlib_msgs/GoalID", "status": "actionlib_msgs/GoalStatusArray"}
_WRAPPERS = {
    "goal": ROS1_ACTION_GOAL,
    "feedback": ROS1_ACTION_FEEDBACK,
    "result": ROS1_ACTION_RESULT,
}
_GOAL_TYPE = re.compile(rf"^([A-Za-z]\w*)/(?:msg/)?([A-Za-z]\w*){ROS1_ACTION_GOAL}$")


def group_actions(discovery: Discovery) -> Discovery:
    """``discovery`` with every complete actionlib topic set replaced by one action (ROS 1)."""
    if discovery.dialect is not Dialect.ROS1:
        return discovery
    by_name = {topic.name: topic for topic in discovery.topics}
    actions = []
    for topic in discovery.topics:
        if topic.name.endswith("/goal") and (action := _action_at(topic, by_name)) is not None:
            actions.append(action)
    if not actions:
        return discovery
    taken = {topic.name for action in actions for topic in action.topics}
    return dataclasses.replace(
        discovery,
        topics=tuple(t for t in discovery.topics if t.name not in taken),
        actions=(*discovery.actions, *actions),
    )


def _action_at(
    goal: DiscoveredTopic, by_name: dict[str, DiscoveredTopic]
) -> DiscoveredAction | None:
    match = _GOAL_TYPE.match(goal.type)
    namespace = goal.name[: -len("/goal")]
    if match is None or not namespace:
        return None
    package, short = match.groups()
    wanted = {key: f"{package}/{short}{suffix}" for key, suffix in _WRAPPERS.items()}
    wanted.update(_FIXED_TYPES)
    topics = []
    for key in ACTION_TOPICS:
        topic = by_name.get(f"{namespace}/{key}")
        if topic is None or topic.type.replace("/msg/", "/") != wanted[key]:
            return None
        topics.append(topic)
    role = _role(by_name[f"{namespace}/status"], goal)
    return DiscoveredAction(namespace, f"{package}/action/{short}", role, tuple(topics))


def _role(status: DiscoveredTopic, goal: DiscoveredTopic) -> str | None:
    """Unity's role: a client when the ROS system publishes the status (it runs the server), a
    server when it only sends goals (a client without a server), unknown otherwise."""
    if status.direction is Direction.SUBSCRIBE:
        return "client"
    if goal.direction is Direction.SUBSCRIBE:
        return "server"
    return None
