"""What ROS appends to a service's or action's name to name the messages (and services) in it.

ROS 1 (genmsg, genaction): service ``S`` defines ``SRequest`` and ``SResponse``; action ``A``
defines ``AGoal``, ``AResult``, ``AFeedback`` and genaction's wrappers ``AAction``,
``AActionGoal``, ``AActionResult`` and ``AActionFeedback``.

ROS 2 (rosidl): service ``S`` defines ``S_Request``, ``S_Response`` and ``S_Event``; action ``A``
defines ``A_Goal``, ``A_Result``, ``A_Feedback``, ``A_FeedbackMessage`` and the services
``A_SendGoal`` and ``A_GetResult``.
"""

from __future__ import annotations

from typing import Final

from unityscaffold.interfaces.model import InterfaceKind

__all__ = [
    "ROS1_ACTION",
    "ROS1_ACTION_FEEDBACK",
    "ROS1_ACTION_GOAL",
    "ROS1_ACTION_PARTS",
    "ROS1_ACTION_RESULT",
    "ROS1_ACTION_WRAPPERS",
    "ROS1_FEEDBACK",
    "ROS1_GOAL",
    "ROS1_PART_SUFFIXES",
    "ROS1_REQUEST",
    "ROS1_RESPONSE",
    "ROS1_RESULT",
    "ROS1_SERVICE_PARTS",
    "ROS2_ACTION_PARTS",
    "ROS2_EVENT",
    "ROS2_FEEDBACK",
    "ROS2_FEEDBACK_MESSAGE",
    "ROS2_GET_RESULT",
    "ROS2_GOAL",
    "ROS2_REQUEST",
    "ROS2_RESPONSE",
    "ROS2_RESULT",
    "ROS2_SEND_GOAL",
]

ROS1_REQUEST: Final = "Request"
ROS1_RESPONSE: Final = "Response"
ROS1_GOAL: Final = "Goal"
ROS1_RESULT: Final = "Result"
ROS1_FEEDBACK: Final = "Feedback"
ROS1_ACTION: Final = "Action"
ROS1_ACTION_GOAL: Final = "ActionGoal"
ROS1_ACTION_RESULT: Final = "ActionResult"
ROS1_ACTION_FEEDBACK: Final = "ActionFeedback"

ROS1_SERVICE_PARTS: Final = (ROS1_REQUEST, ROS1_RESPONSE)
ROS1_ACTION_PARTS: Final = (ROS1_GOAL, ROS1_RESULT, ROS1_FEEDBACK)
"""The three messages a ROS 1 ``.action`` file spells out, in file order."""
ROS1_ACTION_WRAPPERS: Final = (
    ROS1_ACTION,
    ROS1_ACTION_GOAL,
    ROS1_ACTION_RESULT,
    ROS1_ACTION_FEEDBACK,
)
"""The four messages genaction adds around them."""
ROS1_PART_SUFFIXES: Final = (
    (InterfaceKind.ACTION, ROS1_ACTION_FEEDBACK),
    (InterfaceKind.ACTION, ROS1_ACTION_RESULT),
    (InterfaceKind.ACTION, ROS1_ACTION_GOAL),
    (InterfaceKind.SRV, ROS1_RESPONSE),
    (InterfaceKind.SRV, ROS1_REQUEST),
    (InterfaceKind.ACTION, ROS1_FEEDBACK),
    (InterfaceKind.ACTION, ROS1_RESULT),
    (InterfaceKind.ACTION, ROS1_ACTION),
    (InterfaceKind.ACTION, ROS1_GOAL),
)
"""Every ROS 1 service or action message suffix with its owner's kind, longest suffix first
(so ``XActionGoal`` is taken for action ``X``'s wrapper, not for action ``XAction``'s goal)."""

ROS2_REQUEST: Final = "_Request"
ROS2_RESPONSE: Final = "_Response"
ROS2_EVENT: Final = "_Event"
ROS2_GOAL: Final = "_Goal"
ROS2_RESULT: Final = "_Result"
ROS2_FEEDBACK: Final = "_Feedback"
ROS2_FEEDBACK_MESSAGE: Final = "_FeedbackMessage"
ROS2_SEND_GOAL: Final = "_SendGoal"
ROS2_GET_RESULT: Final = "_GetResult"

ROS2_ACTION_PARTS: Final = (ROS2_GOAL, ROS2_RESULT, ROS2_FEEDBACK)
"""The three messages a ROS 2 ``.action`` file spells out, in file order."""
