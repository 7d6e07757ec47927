"""The role each generated class plays in its ROS interface, and the class name it gets.

A message gives one class (``message``); a service two (``request``, ``response``); an action
seven: its three parts (``goal``, ``result``, ``feedback``), the three wrappers ROS#'s generic
bases carry them in (``action_goal``, ``action_result``, ``action_feedback``) and ``action``.
"""

from __future__ import annotations

import enum
from typing import Final

from unityscaffold.interfaces.suffixes import (
    ROS1_ACTION,
    ROS1_ACTION_FEEDBACK,
    ROS1_ACTION_GOAL,
    ROS1_ACTION_RESULT,
    ROS1_FEEDBACK,
    ROS1_GOAL,
    ROS1_REQUEST,
    ROS1_RESPONSE,
    ROS1_RESULT,
)

__all__ = ["ACTION_ROLES", "CLASS_SUFFIX", "MESSAGE_ROLES", "WRAPPER_PAYLOAD", "ClassRole"]


class ClassRole(str, enum.Enum):
    """A generated class's role; its value is the key of ``GeneratedCode.classes`` entries."""

    MESSAGE = "message"
    REQUEST = "request"
    RESPONSE = "response"
    GOAL = "goal"
    RESULT = "result"
    FEEDBACK = "feedback"
    ACTION_GOAL = "action_goal"
    ACTION_RESULT = "action_result"
    ACTION_FEEDBACK = "action_feedback"
    ACTION = "action"

    def __str__(self) -> str:
        return self.value


MESSAGE_ROLES: Final = frozenset(
    {
        ClassRole.MESSAGE,
        ClassRole.REQUEST,
        ClassRole.RESPONSE,
        ClassRole.GOAL,
        ClassRole.RESULT,
        ClassRole.FEEDBACK,
    }
)
"""The roles whose class derives from ROS#'s ``Message`` and holds the ROS fields."""

ACTION_ROLES: Final = (
    ClassRole.GOAL,
    ClassRole.RESULT,
    ClassRole.FEEDBACK,
    ClassRole.ACTION_GOAL,
    ClassRole.ACTION_RESULT,
    ClassRole.ACTION_FEEDBACK,
    ClassRole.ACTION,
)
"""An action's seven classes, in the order they are generated."""

WRAPPER_PAYLOAD: Final = {
    ClassRole.ACTION_GOAL: ClassRole.GOAL,
    ClassRole.ACTION_RESULT: ClassRole.RESULT,
    ClassRole.ACTION_FEEDBACK: ClassRole.FEEDBACK,
}
"""Each action wrapper and the part it carries."""

CLASS_SUFFIX: Final = {
    ClassRole.REQUEST: ROS1_REQUEST,
    ClassRole.RESPONSE: ROS1_RESPONSE,
    ClassRole.GOAL: ROS1_GOAL,
    ClassRole.RESULT: ROS1_RESULT,
    ClassRole.FEEDBACK: ROS1_FEEDBACK,
    ClassRole.ACTION_GOAL: ROS1_ACTION_GOAL,
    ClassRole.ACTION_RESULT: ROS1_ACTION_RESULT,
    ClassRole.ACTION_FEEDBACK: ROS1_ACTION_FEEDBACK,
    ClassRole.ACTION: ROS1_ACTION,
}
"""What a service's or action's class name adds to the interface's name. ROS# names the
classes as ROS 1 names the messages, for ROS 2 too (``AddTwoIntsRequest``, ``FibonacciGoal``)."""
