"""ROS 1 or ROS 2 through rosbridge: rosapi services over a WebSocket (``websockets.sync``).

``/rosapi/topics_and_raw_types`` gives topics, types and full definitions in one call;
``/rosapi/publishers`` and ``/rosapi/subscribers`` tell which way a topic flows;
``/rosapi/services`` and ``/rosapi/service_type`` list services; ``/rosapi/message_details``
stands in when a bridge sends an empty definition. Every call has a deadline, and every way a
bridge can misbehave (silence, a dropped connection, an error status, a malformed reply)
becomes a ``UserError`` naming the bridge and the call.
"""

from __future__ import annotations

import contextlib
import itertools
import json
import time
from types import TracebackType
from typing import Any

from websockets.exceptions import ConnectionClosed, InvalidHandshake, InvalidURI
from websockets.sync.client import ClientConnection, connect

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live._typedefs import full_text_from_typedefs
from unityscaffold.interfaces.live.model import (
    Direction,
    DiscoveredService,
    DiscoveredTopic,
    Discovery,
    NameFilter,
    Progress,
    is_url,
)
from unityscaffold.interfaces.model import Dialect

__all__ = ["RosbridgeClient", "discover_rosbridge", "list_rosbridge_types"]


class RosbridgeClient:
    """A rosbridge v2 connection that calls services and waits for their answers."""

    def __init__(self, url: str, *, timeout: float) -> None:
        if not is_url(url, ("ws", "wss")):
            raise UserError(f"not a rosbridge URL: {url!r}", hint="use ws://HOST:9090")
        self.url, self.timeout = url, timeout
        self._ids = itertools.count(1)
        self._socket: ClientConnection | None = None
        self._stack = contextlib.ExitStack()

    def __enter__(self) -> RosbridgeClient:
        try:
            # Entered as a context manager: websockets 16+ deprecates bare connect().
            self._socket = self._stack.enter_context(
                connect(
                    self.url,
                    open_timeout=self.timeout,
                    close_timeout=self.timeout,
                    max_size=64 * 1024 * 1024,
                )
            )
        except ConnectionRefusedError:
            raise UserError(f"no rosbridge at {self.url} (connection refused)") from None
        except TimeoutError:
            raise UserError(
                f"rosbridge at {self.url} did not accept a WebSocket connection "
                f"within {self.timeout:g} s"
            ) from None
        except (InvalidHandshake, InvalidURI) as exc:
            raise UserError(f"{self.url} is not a rosbridge WebSocket: {exc}") from None
        except OSError as exc:
            raise UserError(f"no rosbridge at {self.url} ({exc.strerror or exc})") from None
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        trace: TracebackType | None,
    ) -> None:
        self._stack.close()

    def call(self, service: str, args: dict[str, Any] | None = None) -> dict[str, Any]:
        """Call ``service`` and return its response values."""
        assert self._socket is not None, "use RosbridgeClient as a context manager"
        call_id = f"call_service:{service}:{next(self._ids)}"
        request = {"op": "call_service", "id": call_id, "service": service, "args": args or {}}
        deadline = time.monotonic() + self.timeout
        try:
            self._socket.send(json.dumps(request))
            while True:
                reply = self._receive(service, deadline)
                values = self._answer(reply, call_id, service)
                if values is not None:
                    return values
        except ConnectionClosed:
            raise UserError(
                f"rosbridge at {self.url} closed the connection while {service} was pending"
            ) from None

    def _receive(self, service: str, deadline: float) -> dict[str, Any]:
        assert self._socket is not None
        try:
            raw = self._socket.recv(timeout=max(0.0, deadline - time.monotonic()))
        except TimeoutError:
            raise UserError(
                f"rosbridge at {self.url} did not answer {service} within {self.timeout:g} s"
            ) from None
        try:
            reply = json.loads(raw)
        except (ValueError, TypeError):
            raise self.malformed(service, "not JSON") from None
        if not isinstance(reply, dict):
            raise self.malformed(service, "not a JSON object")
        return reply

    def _answer(self, reply: dict[str, Any], call_id: str, service: str) -> dict[str, Any] | None:
        """The values if ``reply`` answers this call; ``None`` for unrelated traffic."""
        if (
            reply.get("op") == "status"
            and reply.get("level") == "error"
            and reply.get("id") in (None, call_id)
        ):
            raise UserError(
                f"rosbridge at {self.url} reported an error for {service}: "
                f"{reply.get('msg', '(no message)')}"
            )
        if reply.get("op") != "service_response" or reply.get("id") != call_id:
            return None
        values = reply.get("values")
        if reply.get("result") is False:
            raise UserError(f"rosbridge at {self.url}: {service} failed: {values}")
        if not isinstance(values, dict):
            raise self.malformed(service, "values is not an object")
        return values

    def malformed(self, service: str, why: str) -> UserError:
        return UserError(f"rosbridge at {self.url} sent a malformed reply to {service}: {why}")


def _strings(client: RosbridgeClient, values: dict[str, Any], key: str, service: str) -> list[str]:
    value = values.get(key)
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise client.malformed(service, f"{key} is not a list of strings")
    return value


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
        topics = _strings(client, values, "topics", service)
        types = _strings(client, values, "types", service)
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
) -> Discovery:
    """Topics with full definitions and services, as the bridge's rosapi reports them."""
    with RosbridgeClient(url, timeout=timeout) as client:
        raw = _raw_topics(client)
        found_dialect = _dialect([t for _, t, _ in raw], dialect)
        chosen = [item for item in raw if names.accepts(item[0])]
        service_names = [s for s in _service_names(client) if names.accepts(s)]
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
            topic, warning = _topic(client, name, kind, text, direction)
            topics.append(topic)
            warnings += warning
            if progress is not None:
                progress(done, total, name)
        services = []
        for done, name in enumerate(service_names, start=len(chosen) + 1):
            services.append(_service(client, name))
            if progress is not None:
                progress(done, total, name)
    return Discovery(
        found_dialect,
        url,
        tuple(topics),
        tuple(s for s in services if s.type),
        tuple(sorted(set(warnings))),
    )


def _raw_topics(client: RosbridgeClient) -> list[tuple[str, str, str]]:
    service = "/rosapi/topics_and_raw_types"
    values = client.call(service)
    lists = [
        _strings(client, values, key, service) for key in ("topics", "types", "typedefs_full_text")
    ]
    if len({len(item) for item in lists}) != 1:
        raise client.malformed(service, "topics, types and typedefs_full_text differ in length")
    return list(zip(*lists, strict=True))


def _service_names(client: RosbridgeClient) -> list[str]:
    service = "/rosapi/services"
    return sorted(_strings(client, client.call(service), "services", service))


def _direction(client: RosbridgeClient, name: str) -> Direction:
    return Direction.from_graph(
        bool(_nodes(client, "publishers", name)), bool(_nodes(client, "subscribers", name))
    )


def _topic(
    client: RosbridgeClient, name: str, kind: str, text: str, direction: Direction
) -> tuple[DiscoveredTopic, list[str]]:
    warnings: list[str] = []
    if not text.strip():
        try:
            text = _details(client, kind)
        except UserError as error:
            warnings.append(f"no definition of {kind} for {name}: {error.message}")
            text = ""
    return DiscoveredTopic(name, kind, direction, None, text or None), warnings


def _nodes(client: RosbridgeClient, which: str, topic: str) -> list[str]:
    service = f"/rosapi/{which}"
    return _strings(client, client.call(service, {"topic": topic}), which, service)


def _details(client: RosbridgeClient, kind: str) -> str:
    service = "/rosapi/message_details"
    typedefs = client.call(service, {"type": kind}).get("typedefs")
    if not isinstance(typedefs, list):
        raise client.malformed(service, "typedefs is not a list")
    try:
        return full_text_from_typedefs(kind, typedefs)
    except ValueError as exc:
        raise client.malformed(service, str(exc)) from None


def _service(client: RosbridgeClient, name: str) -> DiscoveredService:
    service = "/rosapi/service_type"
    kind = client.call(service, {"service": name}).get("type")
    if not isinstance(kind, str):
        raise client.malformed(service, "type is not a string")
    return DiscoveredService(name, kind)
