"""The key table's ``runtime`` key and its two ``connector:`` sections: ROS#'s RosConnector
(``runtime: ros-sharp``, the default) and ROS-TCP-Connector's ROSConnection
(``runtime: ros-tcp-connector``), with the schema rules that tie each to its runtime."""

from __future__ import annotations

from typing import Any

from unityscaffold.manifest._keys import (
    BOOL,
    DEFAULT_TIMEOUT,
    FLOAT32_MAX,
    FLOAT32_TINY,
    GAMEOBJECT_VALUE,
    HOST,
    INT32_MAX,
    ROS_NAME,
    SCENE_VALUE,
    URL,
    Key,
    Section,
    list_of,
    ref,
)
from unityscaffold.manifest.model import Protocol, Serializer
from unityscaffold.manifest.runtime import Runtime, TcpConnection

__all__ = ["CONNECTOR", "RUNTIME", "RUNTIME_RULES", "TCP_CONNECTOR"]

_TCP = Runtime.TCP_CONNECTOR.value
_DEFAULTS = TcpConnection()

RUNTIME = Key(
    "runtime",
    "The Unity library generated scripts talk to ROS through: `ros-sharp` (Siemens' ROS# over "
    "rosbridge) or `ros-tcp-connector` (Unity's ROS-TCP-Connector with its ROS-TCP-Endpoint "
    "node). It decides the `connector:` keys.",
    {"enum": [r.value for r in Runtime]},
    default=Runtime.ROS_SHARP.value,
)

_ROSSHARP_KEYS = ("url", "timeout", "serializer", "protocol")
_TCP_KEYS = (
    "host",
    "port",
    "connect_on_start",
    "keepalive",
    "network_timeout",
    "sleep",
    "show_hud",
    "tf_topics",
    "listen_for_tf",
)


def _scene(what: str) -> Key:
    return Key(
        "scene",
        f"Scene of the {what}, relative to the project. Default: the top-level `scene`.",
        SCENE_VALUE,
    )


CONNECTOR = Section(
    "connector",
    "connector",
    "ROS#'s RosConnector component (runtime: ros-sharp).",
    (
        _scene("RosConnector"),
        Key(
            "gameobject",
            "Hierarchy path of the GameObject holding the RosConnector; created if missing.",
            GAMEOBJECT_VALUE,
            default="RosConnector",
        ),
        Key(
            "url",
            "rosbridge WebSocket URL (`RosBridgeServerUrl`).",
            {"type": "string", "pattern": URL},
            default="ws://localhost:9090",
        ),
        Key(
            "timeout",
            "Connection timeout in seconds (`SecondsTimeout`).",
            {"type": "integer", "minimum": 1, "maximum": INT32_MAX},
            default=DEFAULT_TIMEOUT,
        ),
        Key(
            "serializer",
            "JSON serializer (`Serializer`): `microsoft` is System.Text.Json.",
            {"enum": [s.key for s in Serializer]},
            default=Serializer.MICROSOFT.key,
        ),
        Key(
            "protocol",
            "WebSocket implementation (`protocol`).",
            {"enum": [p.key for p in Protocol]},
            default=Protocol.WEBSOCKET_SHARP.key,
        ),
    ),
    foreign=tuple(
        (
            key,
            f"'{key}' is a setting of ROS-TCP-Connector's ROSConnection; set `runtime: {_TCP}` "
            "to use that runtime (ROS#'s RosConnector takes url, timeout, serializer, protocol)",
        )
        for key in _TCP_KEYS
    ),
)

# A positive C# float (seconds); NaN passes every comparison, so "not above the largest
# float" is what refuses it in a JSON Schema validator.
_SECONDS = {
    "type": "number",
    "minimum": FLOAT32_TINY,
    "maximum": FLOAT32_MAX,
    "not": {"exclusiveMinimum": FLOAT32_MAX},
}

TCP_CONNECTOR = Section(
    "connector",
    "tcpConnector",
    "ROS-TCP-Connector's ROSConnection component (runtime: ros-tcp-connector).",
    (
        _scene("ROSConnection"),
        Key(
            "gameobject",
            "Hierarchy path of the GameObject holding the ROSConnection; created if missing.",
            GAMEOBJECT_VALUE,
            default="ROSConnection",
        ),
        Key(
            "host",
            "Address of the ROS-TCP-Endpoint node: an IPv4 address or a host name "
            "(`m_RosIPAddress`).",
            {"type": "string", "pattern": HOST},
            default=_DEFAULTS.host,
        ),
        Key(
            "port",
            "TCP port of the ROS-TCP-Endpoint node (`m_RosPort`).",
            {"type": "integer", "minimum": 1, "maximum": 65535},
            default=_DEFAULTS.port,
        ),
        Key(
            "connect_on_start",
            "Connect when the scene starts (`m_ConnectOnStart`).",
            BOOL,
            default=_DEFAULTS.connect_on_start,
        ),
        Key(
            "keepalive",
            "Seconds without sending after which a keepalive is sent (`m_KeepaliveTime`).",
            _SECONDS,
            default=_DEFAULTS.keepalive,
        ),
        Key(
            "network_timeout",
            "Seconds to wait for the endpoint before the connection counts as lost "
            "(`m_NetworkTimeoutSeconds`).",
            _SECONDS,
            default=_DEFAULTS.network_timeout,
        ),
        Key(
            "sleep",
            "Seconds the connection thread sleeps between reads (`m_SleepTimeSeconds`).",
            _SECONDS,
            default=_DEFAULTS.sleep,
        ),
        Key(
            "show_hud",
            "Show the connector's on-screen HUD (`m_ShowHUD`).",
            BOOL,
            default=_DEFAULTS.show_hud,
        ),
        Key(
            "tf_topics",
            "Topics of tf2_msgs/TFMessage the connector listens to (`m_TFTopics`).",
            list_of({"type": "string", "pattern": ROS_NAME}),
            default=list(_DEFAULTS.tf_topics),
        ),
        Key(
            "listen_for_tf",
            "Subscribe to `tf_topics` when the scene starts (`listenForTFMessages`).",
            BOOL,
            default=_DEFAULTS.listen_for_tf,
        ),
    ),
    foreign=tuple(
        (
            key,
            f"'{key}' is a setting of ROS#'s RosConnector (rosbridge); under runtime: {_TCP} the "
            "endpoint's address is `host` and `port`",
        )
        for key in _ROSSHARP_KEYS
    ),
)

_IS_TCP = {"properties": {"runtime": {"const": _TCP}}, "required": ["runtime"]}


def _topic_rule(direction: str, refused: tuple[str, ...]) -> dict[str, Any]:
    return {
        "if": {"properties": {"direction": {"const": direction}}, "required": ["direction"]},
        "then": {"properties": {key: False for key in refused}},
    }


#: The top level's rules that depend on ``runtime``: which ``connector:`` section applies, the
#: topic keys each runtime has, no shipped classes generated again under the connector (its
#: registry holds one class per ROS name), and no ROS 2 actions through ROS-TCP-Endpoint.
RUNTIME_RULES: tuple[dict[str, Any], ...] = (
    {
        "if": _IS_TCP,
        "then": {
            "properties": {
                "connector": {"anyOf": [ref(TCP_CONNECTOR.ref), {"type": "null"}]},
                "include_shipped": {"const": False},
                "topics": {
                    "items": {
                        "properties": {"throttle": False},
                        "allOf": [_topic_rule("subscribe", ("queue",))],
                    }
                },
            }
        },
        "else": {
            "properties": {
                "connector": {"anyOf": [ref(CONNECTOR.ref), {"type": "null"}]},
                "topics": {
                    "items": {
                        "properties": {"latch": False},
                        "allOf": [_topic_rule("publish", ("queue",))],
                    }
                },
            }
        },
    },
    {
        "if": {
            "properties": {"runtime": {"const": _TCP}, "ros": {"const": 2}},
            "required": ["runtime", "ros"],
        },
        "then": {"properties": {"actions": {"maxItems": 0}}},
    },
)
