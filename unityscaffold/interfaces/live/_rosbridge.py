"""ROS 1 or ROS 2 through rosbridge: rosapi services over a WebSocket (``websockets.sync``).

``/rosapi/topics_and_raw_types`` gives topics, types and full definitions in one call;
``/rosapi/publishers`` and ``/rosapi/subscribers`` tell which way a topic flows;
``/rosapi/services`` and ``/rosapi/service_type`` list services; in ROS 2,
``/rosapi/action_servers`` lists actions (``_rosapi_actions``). Definitions rosapi gives only
field by field (a topic's when its full text did not come, a service's) are asked for last
(``_rosapi_details``). The connection itself is ``_rosbridge_client``.
"""

from __future__ import annotations

from collections.abc import Callable

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live._rosapi_actions import rosapi_actions
from unityscaffold.interfaces.live._rosapi_details import fill_details
from unityscaffold.interfaces.live._rosbridge_client import RosbridgeClient, strings
from unityscaffold.interfaces.live.model import (
    Direction,
    DiscoveredAction,
    DiscoveredService,
    DiscoveredTopic,
    Discovery,
    NameFilter,
    Progress,
)
from unityscaffold.interfaces.model import Dialect

__all__ = ["discover_rosbridge", "list_rosbridge_types"]


def _dialect(types: list[str], hint: Dialect | None) -> Dialect:
    if any("/msg/" in t for t in types):
        return Dialect.ROS2
    if types:
        return Dialect.ROS1
    return hint or Dialect.ROS1


def list_rosbridge_types(url: str, *, timeout: float) -> list[tuple[str, str]]:
    service = "/rosapi/topics"
    with RosbridgeClient(url, timeout=timeout) as client:
        values = client.call(service)
        topics = strings(client, values, "topics", service)
        types = strings(client, values, "types", service)
    if len(topics) != len(types):
        raise client.malformed(service, "topics and types differ in length")
    return sorted(zip(topics, types, strict=True))


def discover_rosbridge(
    url: str,
    *,
    timeout: float,
    names: NameFilter,
    dialect: Dialect | None = None,
    progress: Progress | None = None,
    known: Callable[[Dialect], Callable[[str], bool]] | None = None,
) -> Discovery:
    """Topics with full definitions, services (definitions rebuilt for types ``known`` says
    are not local) and, in ROS 2, actions, as the bridge's rosapi reports them."""
    with RosbridgeClient(url, timeout=timeout) as client:
        raw = _raw_topics(client)
        found_dialect = _dialect([t for _, t, _ in raw], dialect)
        chosen = [item for item in raw if names.accepts(item[0])]
        every_service = _service_names(client)
        service_names = [s for s in every_service if names.accepts(s)]
        total = len(chosen) + len(service_names)
        topics, warnings = [], []
        ask = True  # stop asking which way topics flow once the bridge cannot say
        for done, (name, kind, text) in enumerate(chosen, start=1):
            direction = Direction.UNKNOWN
            if ask:
                try:
                    direction = _direction(client, name)
                except UserError as error:
                    ask = False
                    warnings.append(f"cannot tell which way topics flow: {error.message}")
            topics.append(DiscoveredTopic(name, kind, direction, None, _full_text(text)))
            if progress is not None:
                progress(done, total, name)
        services = []
        for done, name in enumerate(service_names, start=len(chosen) + 1):
            services.append(_service(client, name, found_dialect))
            if progress is not None:
                progress(done, total, name)
        actions: list[DiscoveredAction] = []
        newer = "/rosapi/action_type" in every_service  # a rosapi past 2.1.0 (_rosapi_details)
        if found_dialect is Dialect.ROS2:
            actions, action_warnings = rosapi_actions(client, names, has_action_type=newer)
            warnings += action_warnings
        is_known = known(found_dialect) if known is not None else (lambda _: True)
        typed = [s for s in services if s.type]
        safe = found_dialect is Dialect.ROS1 or newer
        details = fill_details(client, found_dialect, topics, typed, is_known, safe=safe)
    return Discovery(
        found_dialect,
        url,
        tuple(details.topics),
        tuple(details.services),
        tuple(sorted({*warnings, *details.warnings})),
        tuple(actions),
        files=tuple(sorted(details.files.items())),
    )


def _full_text(text: str) -> str | None:
    """rosapi's full text, ``None`` when it sent none: an empty one, or the comment rosapi
    2.x writes in its place when it cannot read a type's files."""
    if not text.strip() or text.startswith("# failed to get full definition text for"):
        return None
    return text


def _raw_topics(client: RosbridgeClient) -> list[tuple[str, str, str]]:
    service = "/rosapi/topics_and_raw_types"
    values = client.call(service)
    lists = [
        strings(client, values, key, service) for key in ("topics", "types", "typedefs_full_text")
    ]
    if len({len(item) for item in lists}) != 1:
        raise client.malformed(service, "topics, types and typedefs_full_text differ in length")
    return list(zip(*lists, strict=True))


def _service_names(client: RosbridgeClient) -> list[str]:
    service = "/rosapi/services"
    return sorted(strings(client, client.call(service), "services", service))


def _direction(client: RosbridgeClient, name: str) -> Direction:
    return Direction.from_graph(
        bool(_nodes(client, "publishers", name)), bool(_nodes(client, "subscribers", name))
    )


def _nodes(client: RosbridgeClient, which: str, topic: str) -> list[str]:
    service = f"/rosapi/{which}"
    return strings(client, client.call(service, {"topic": topic}), which, service)


def _service(client: RosbridgeClient, name: str, dialect: Dialect) -> DiscoveredService:
    service = "/rosapi/service_type"
    kind = client.call(service, {"service": name}).get("type")
    if not isinstance(kind, str):
        raise client.malformed(service, "type is not a string")
    if dialect is Dialect.ROS1 or not kind:
        return DiscoveredService(name, kind)
    # ROS 2 lists services that only have callers too; rosapi names a server's node only
    service = "/rosapi/service_node"
    node = client.call(service, {"service": name}).get("node")
    if not isinstance(node, str):
        raise client.malformed(service, "node is not a string")
    return DiscoveredService(name, kind, role="client" if node else "server")
