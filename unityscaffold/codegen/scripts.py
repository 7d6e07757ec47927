"""Per-topic, per-service and per-action MonoBehaviours for ROS#: a regenerated half and a user
half.

Each script is a C# partial class split over two files: ``<Class>.cs`` holds the plumbing
(serialized fields, subscribing, the hand-off to Unity's main thread) and is regenerated freely;
``<Class>.User.cs`` holds the user's logic, is created once and never rewritten. Unity ties the
script asset (and so the scene component) to ``<Class>.cs``, whose name matches the class.

The scripts reference their RosConnector through a serialized field instead of ROS#'s
``[RequireComponent]`` pattern, so they can live on any GameObject.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from unityscaffold.codegen._literals import string_literal as csharp_string
from unityscaffold.resources import template_environment

__all__ = [
    "SCRIPTS_NAMESPACE",
    "ActionClientScript",
    "ActionServerScript",
    "PublisherScript",
    "RenderedScript",
    "Script",
    "ServiceClientScript",
    "ServiceServerScript",
    "SubscriberScript",
    "render_script",
]

SCRIPTS_NAMESPACE = "RosGenerated"
"""Namespace of the generated MonoBehaviours, apart from users' own classes."""
RESPONSE_TIMEOUT = 10.0
"""A client's ``ResponseTimeout`` initializer in the templates (``10f``), in seconds."""


def _float_literal(value: float) -> str:
    text = repr(float(value))
    return f"{text}f"


@dataclass(frozen=True, slots=True)
class _Script:
    class_name: str
    ros_type: str
    manifest: str
    namespace: str = SCRIPTS_NAMESPACE

    @property
    def plumbing_file(self) -> str:
        return f"{self.class_name}.cs"

    @property
    def user_file(self) -> str:
        return f"{self.class_name}.User.cs"

    def unowned_fields(self) -> list[tuple[str, float]]:
        """Serialized fields the manifest does not set, at their C# initializer, in declaration
        order after ``serialized_fields``: a new component is written with them (as Unity would
        write it), an existing one keeps what was set in Unity's Inspector."""
        return []


@dataclass(frozen=True, slots=True)
class _TopicScript(_Script):
    topic: str = ""
    message_type: str = ""

    @property
    def topic_literal(self) -> str:
        return csharp_string(self.topic)


@dataclass(frozen=True, slots=True)
class PublisherScript(_TopicScript):
    template: ClassVar[str] = "rossharp/scripts/Publisher.cs.jinja"
    user_template: ClassVar[str] = "rossharp/scripts/PublisherUser.cs.jinja"
    rate: float = 0.0

    @property
    def what(self) -> str:
        return f"publisher of {self.topic}"

    @property
    def rate_literal(self) -> str:
        return _float_literal(self.rate)

    @property
    def rate_text(self) -> str:
        return f"{self.rate:g}"

    def serialized_fields(self) -> list[tuple[str, str | int | float]]:
        """Field values the scene holds, in declaration order (``Connector`` set by apply)."""
        return [("Topic", self.topic), ("Rate", float(self.rate))]


@dataclass(frozen=True, slots=True)
class SubscriberScript(_TopicScript):
    template: ClassVar[str] = "rossharp/scripts/Subscriber.cs.jinja"
    user_template: ClassVar[str] = "rossharp/scripts/SubscriberUser.cs.jinja"
    throttle: int = 0
    queue: int = 1

    @property
    def what(self) -> str:
        return f"subscriber of {self.topic}"

    def serialized_fields(self) -> list[tuple[str, str | int | float]]:
        return [("Topic", self.topic), ("Throttle", int(self.throttle)), ("Queue", int(self.queue))]


@dataclass(frozen=True, slots=True)
class _ServiceScript(_Script):
    service: str = ""
    request_type: str = ""
    response_type: str = ""

    @property
    def service_literal(self) -> str:
        return csharp_string(self.service)

    @property
    def request_short(self) -> str:
        return self.request_type.rsplit(".", 1)[-1]

    def serialized_fields(self) -> list[tuple[str, str | int | float]]:
        return [("ServiceName", self.service)]


@dataclass(frozen=True, slots=True)
class ServiceClientScript(_ServiceScript):
    template: ClassVar[str] = "rossharp/scripts/ServiceClient.cs.jinja"
    user_template: ClassVar[str] = "rossharp/scripts/ServiceClientUser.cs.jinja"

    @property
    def what(self) -> str:
        return f"client of {self.service}"

    def unowned_fields(self) -> list[tuple[str, float]]:
        return [("ResponseTimeout", RESPONSE_TIMEOUT)]


@dataclass(frozen=True, slots=True)
class ServiceServerScript(_ServiceScript):
    template: ClassVar[str] = "rossharp/scripts/ServiceServer.cs.jinja"
    user_template: ClassVar[str] = "rossharp/scripts/ServiceServerUser.cs.jinja"

    @property
    def what(self) -> str:
        return f"server of {self.service}"


@dataclass(frozen=True, slots=True)
class _ActionScript(_Script):
    """An action's script. ROS 2 uses ROS#'s action operations on ``RosSocket``; ROS 1 has
    none, so its scripts speak actionlib's protocol on the five topics under the name."""

    action: str = ""
    ros2: bool = False
    goal_type: str = ""
    result_type: str = ""
    feedback_type: str = ""
    action_goal_type: str = ""
    action_result_type: str = ""
    action_feedback_type: str = ""

    @property
    def action_literal(self) -> str:
        return csharp_string(self.action)

    @property
    def goal_short(self) -> str:
        return self.goal_type.rsplit(".", 1)[-1]

    @property
    def status_type(self) -> str:
        """C#'s type of a goal status: actionlib_msgs' is uint8, action_msgs' int8."""
        return "sbyte" if self.ros2 else "byte"

    @property
    def status_class(self) -> str:
        """ROS#'s goal status class, whose constants name the status codes."""
        if self.ros2:
            return "RosSharp.RosBridgeClient.MessageTypes.Action.GoalStatus"
        return "RosSharp.RosBridgeClient.MessageTypes.Actionlib.GoalStatus"

    @property
    def dialect_suffix(self) -> str:
        return "Ros2" if self.ros2 else "Ros1"

    def serialized_fields(self) -> list[tuple[str, str | int | float]]:
        return [("ActionName", self.action)]


@dataclass(frozen=True, slots=True)
class ActionClientScript(_ActionScript):
    user_template: ClassVar[str] = "rossharp/scripts/ActionClientUser.cs.jinja"

    @property
    def template(self) -> str:
        return f"rossharp/scripts/ActionClient{self.dialect_suffix}.cs.jinja"

    @property
    def what(self) -> str:
        return f"client of the action {self.action}"

    def unowned_fields(self) -> list[tuple[str, float]]:
        return [("ResponseTimeout", RESPONSE_TIMEOUT)] if self.ros2 else []


@dataclass(frozen=True, slots=True)
class ActionServerScript(_ActionScript):
    user_template: ClassVar[str] = "rossharp/scripts/ActionServerUser.cs.jinja"

    @property
    def template(self) -> str:
        return f"rossharp/scripts/ActionServer{self.dialect_suffix}.cs.jinja"

    @property
    def what(self) -> str:
        return f"server of the action {self.action}"


Script = (
    PublisherScript
    | SubscriberScript
    | ServiceClientScript
    | ServiceServerScript
    | ActionClientScript
    | ActionServerScript
)


@dataclass(frozen=True, slots=True)
class RenderedScript:
    """The two files of one script, by file name."""

    plumbing_name: str
    plumbing: str
    user_name: str
    user: str


def render_script(view: Script) -> RenderedScript:
    env = template_environment()
    plumbing = env.get_template(view.template).render(view=view)
    user = env.get_template(view.user_template).render(view=view)
    return RenderedScript(view.plumbing_file, plumbing, view.user_file, user)
