"""The per-topic, per-service and per-action MonoBehaviours for Unity's ROS-TCP-Connector.

The same scripts as ``scripts`` (same class names, files, user halves and user API:
``UpdateMessage``/``Publish``, ``OnMessage``, ``Call``/``OnResponse``, ``HandleRequest``,
``SendGoal``/``OnFeedback``/``OnResult``), talking to the connector's ``ROSConnection``
through a ``Connection`` field instead of ROS#'s RosConnector. ROSConnection calls back on
Unity's main thread, so no hand-off queue is needed. Only ROS 1 actions exist here (actionlib
over five topics): the connector's ROS 2 endpoint carries no actions.

A ROS 2 message without fields is one byte in CDR; the connector's shipped classes for them
(``std_msgs/Empty``, ``std_srvs/Trigger``'s request, ``std_srvs/Empty``) write none, and
ROS-TCP-Endpoint's ROS 2 node cannot read that (a published message is dropped, a service
request stops its service thread). Sending does not go through the connector's registry, so
the scripts send such a message as a small unregistered class of their own that writes the one
byte (``empty_cdr``), under ``#if ROS2``; receiving with the shipped class works as it is.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from unityscaffold.codegen.scripts import (
    ActionClientScript,
    ActionServerScript,
    PublisherScript,
    ServiceClientScript,
    ServiceServerScript,
    SubscriberScript,
)

__all__ = [
    "CONNECTION_FIELD",
    "DEFAULT_QUEUE",
    "TcpActionClientScript",
    "TcpActionServerScript",
    "TcpPublisherScript",
    "TcpServiceClientScript",
    "TcpServiceServerScript",
    "TcpSubscriberScript",
]

CONNECTION_FIELD = "Connection"
"""The scripts' serialized field that holds their ``ROSConnection``."""
DEFAULT_QUEUE = 10
"""ROSConnection's default queue size of a publisher (``k_DefaultPublisherQueueSize``)."""
_DIR = "tcpconnector/scripts"


@dataclass(frozen=True, slots=True)
class TcpPublisherScript(PublisherScript):
    """``empty_cdr``: a ROS 2 message without fields, sent as CDR's one byte (see the module)."""

    template: ClassVar[str] = f"{_DIR}/Publisher.cs.jinja"
    queue: int = DEFAULT_QUEUE
    latch: bool = False
    empty_cdr: bool = False

    @property
    def latch_literal(self) -> str:
        return "true" if self.latch else "false"

    def serialized_fields(self) -> list[tuple[str, str | int | float]]:
        return [
            ("Topic", self.topic),
            ("Rate", float(self.rate)),
            ("Queue", int(self.queue)),
            ("Latch", bool(self.latch)),
        ]


@dataclass(frozen=True, slots=True)
class TcpSubscriberScript(SubscriberScript):
    template: ClassVar[str] = f"{_DIR}/Subscriber.cs.jinja"

    def serialized_fields(self) -> list[tuple[str, str | int | float]]:
        return [("Topic", self.topic)]


@dataclass(frozen=True, slots=True)
class TcpServiceClientScript(ServiceClientScript):
    """``empty_cdr``: a ROS 2 request without fields, sent as CDR's one byte."""

    template: ClassVar[str] = f"{_DIR}/ServiceClient.cs.jinja"
    empty_cdr: bool = False


@dataclass(frozen=True, slots=True)
class TcpServiceServerScript(ServiceServerScript):
    """``empty_cdr``: a ROS 2 response without fields, sent as CDR's one byte."""

    template: ClassVar[str] = f"{_DIR}/ServiceServer.cs.jinja"
    user_template: ClassVar[str] = f"{_DIR}/ServiceServerUser.cs.jinja"
    empty_cdr: bool = False


@dataclass(frozen=True, slots=True)
class TcpActionClientScript(ActionClientScript):
    @property
    def template(self) -> str:
        return f"{_DIR}/ActionClient.cs.jinja"

    @property
    def status_class(self) -> str:
        return "RosMessageTypes.Actionlib.GoalStatusMsg"

    def unowned_fields(self) -> list[tuple[str, float]]:
        # the seconds to wait for the server, as the ROS# ROS 1 client waits SecondsTimeout
        return [("ResponseTimeout", 10.0)]


@dataclass(frozen=True, slots=True)
class TcpActionServerScript(ActionServerScript):
    @property
    def template(self) -> str:
        return f"{_DIR}/ActionServer.cs.jinja"
