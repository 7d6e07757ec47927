"""Reading ``connector:``: ROS#'s RosConnector or ROS-TCP-Connector's ROSConnection, by the
manifest's ``runtime``; a key of the other runtime's component is refused with why."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from unityscaffold.manifest import _spec as spec
from unityscaffold.manifest._entries import Context, locations, read_gameobject, read_scene
from unityscaffold.manifest._read import Reader
from unityscaffold.manifest._yaml import YMap, YScalar
from unityscaffold.manifest.model import Connector, Protocol, Serializer
from unityscaffold.manifest.runtime import Runtime, TcpConnection

__all__ = ["ConnectorPlace", "read_connector"]


@dataclass(frozen=True, slots=True)
class ConnectorPlace:
    """What the connector inherits from the top level: the project and the default scene."""

    project_root: Path
    scene: str | None


def read_connector(r: Reader, top: YMap, runtime: Runtime, place: ConnectorPlace) -> Connector:
    section = spec.TCP_CONNECTOR if runtime is Runtime.TCP_CONNECTOR else spec.CONNECTOR
    entry = top.get("connector")
    m = YMap((), top.location)
    if entry is not None and not (isinstance(entry.value, YScalar) and entry.value.value is None):
        m = r.mapping(entry.value, section) or m
    default_go = section.key("gameobject").default
    assert isinstance(default_go, str)
    ctx = Context(place.project_root, place.scene, top.get("scene") is not None, True, default_go)
    defaults = {k.name: k.default for k in spec.CONNECTOR.keys}
    serializer = protocol = None
    url, timeout, tcp = str(defaults["url"]), spec.DEFAULT_TIMEOUT, None  # ROS#'s, unused
    if runtime is Runtime.TCP_CONNECTOR:
        tcp = _tcp(r, m)
    else:
        serializer = r.choice(m, "serializer", [s.key for s in Serializer])
        protocol = r.choice(m, "protocol", [p.key for p in Protocol])
        url = (
            r.text(
                m,
                "url",
                "a rosbridge URL such as ws://localhost:9090",
                spec.URL,
                hint="rosbridge listens on ws:// (or wss://) host:port",
            )
            or url
        )
        timeout = r.integer(m, "timeout", 1, "seconds") or timeout
    return Connector(
        scene=read_scene(r, m, ctx, "connector") or "",
        gameobject=read_gameobject(r, m, default_go) or "",
        url=url,
        timeout=timeout,
        serializer=next(s for s in Serializer if s.key == (serializer or defaults["serializer"])),
        protocol=next(p for p in Protocol if p.key == (protocol or defaults["protocol"])),
        locations=locations(m),
        tcp=tcp,
    )


def _tcp(r: Reader, m: YMap) -> TcpConnection:
    d = TcpConnection()
    host = r.text(
        m,
        "host",
        "an IPv4 address or a host name, such as 192.168.1.10",
        spec.HOST,
        hint="only the address: the port goes in `port`, and there is no scheme (no tcp://)",
    )
    port = r.integer(m, "port", 1)
    if port is not None and port > 65535:
        r.invalid(m.get("port"), "a TCP port from 1 to 65535")  # type: ignore[arg-type]
        port = None

    def flag(key: str, default: bool) -> bool:
        value = r.boolean(m, key)
        return default if value is None else value

    def seconds(key: str, default: float) -> float:
        value = r.positive_number(m, key, "seconds")
        return default if value is None else value

    return TcpConnection(
        host=host or d.host,
        port=port or d.port,
        connect_on_start=flag("connect_on_start", d.connect_on_start),
        keepalive=seconds("keepalive", d.keepalive),
        network_timeout=seconds("network_timeout", d.network_timeout),
        sleep=seconds("sleep", d.sleep),
        show_hud=flag("show_hud", d.show_hud),
        tf_topics=_tf_topics(r, m, d.tf_topics),
        listen_for_tf=flag("listen_for_tf", d.listen_for_tf),
    )


def _tf_topics(r: Reader, m: YMap, default: tuple[str, ...]) -> tuple[str, ...]:
    if m.get("tf_topics") is None:
        return default
    topics = []
    for node in r.items(m, "tf_topics"):
        value = node.value if isinstance(node, YScalar) else None
        if not isinstance(value, str) or not re.search(spec.ROS_NAME, value):
            r.error(node.location, "invalid tf topic", expected="a ROS topic name such as /tf")
            continue
        topics.append(value)
    return tuple(topics)
