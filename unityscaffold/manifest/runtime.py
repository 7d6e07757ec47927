"""Which Unity-side ROS library a manifest targets, and the settings of Unity's
ROS-TCP-Connector (its ``ROSConnection`` component).

``runtime: ros-sharp`` (the default) is Siemens' ROS# over rosbridge; ``runtime:
ros-tcp-connector`` is Unity's ROS-TCP-Connector with its ROS-TCP-Endpoint node. The two
take different ``connector:`` keys (``TcpConnection`` holds the connector's), and a few topic
keys belong to one of them only (``RUNTIME_ONLY``).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

__all__ = ["RUNTIME_ONLY", "Runtime", "TcpConnection"]


class Runtime(enum.Enum):
    """The Unity library generated scripts talk to ROS through."""

    ROS_SHARP = "ros-sharp"
    TCP_CONNECTOR = "ros-tcp-connector"

    @property
    def label(self) -> str:
        """How messages name it."""
        return "ROS#" if self is Runtime.ROS_SHARP else "ROS-TCP-Connector"


@dataclass(frozen=True, slots=True)
class TcpConnection:
    """``ROSConnection``'s serialized settings (v0.7), by the manifest's names.

    ``host`` is ``m_RosIPAddress`` (an IPv4 address or a host name), ``port`` ``m_RosPort``;
    times are seconds, as the component keeps them.
    """

    host: str = "127.0.0.1"
    port: int = 10000
    connect_on_start: bool = True
    keepalive: float = 1.0
    network_timeout: float = 2.0
    sleep: float = 0.01
    show_hud: bool = True
    tf_topics: tuple[str, ...] = ("/tf",)
    listen_for_tf: bool = True


#: Topic keys that only one runtime has, with why the other refuses them.
RUNTIME_ONLY: dict[str, tuple[Runtime, str]] = {
    "throttle": (
        Runtime.ROS_SHARP,
        "ROS-TCP-Connector has no throttle: its endpoint passes on every message; drop the "
        "key, or skip messages in OnMessage",
    ),
    "latch": (
        Runtime.TCP_CONNECTOR,
        "rosbridge (ROS#) has no latched publishers; latch is a ros-tcp-connector key",
    ),
}
