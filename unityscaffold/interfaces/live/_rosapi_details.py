"""Definitions rosapi gives field by field: ``/rosapi/message_details`` for a topic whose full
text did not come, ``/rosapi/service_request_details`` and ``service_response_details`` for a
service type no local package defines (rosbridge never sends a ``.srv`` text).

A rebuilt text has the fields only (no comments; rosapi gives constants without their types,
so a type with constants is refused rather than guessed), and nothing reported by the bridge
checks it, so a service type found locally is left to its file.

rosapi up to 2.1.0 ends when asked for these on ROS 2 Iron or newer (a ``KeyError:
'check_fields'`` in its node, rosbridge_suite issue #976, fixed by pull request #1031), and
with it every other rosapi service, the robot's users' included. So in ROS 2 they are asked only
of a rosapi known to have the fix: one that offers ``/rosapi/action_type`` (pull request #1046,
merged after #1031). These calls come last anyway, and after a first failure nothing more is
asked: every remaining definition is a warning.
"""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Callable
from typing import Any

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live._rosbridge_client import RosbridgeClient
from unityscaffold.interfaces.live._typedefs import full_text_from_typedefs, texts_from_typedefs
from unityscaffold.interfaces.live.model import DiscoveredService, DiscoveredTopic
from unityscaffold.interfaces.model import Dialect

__all__ = ["Details", "fill_details"]

Known = Callable[[str], bool]


@dataclasses.dataclass
class Details:
    """What the details calls added: topics and services with definitions, the messages the
    rebuilt services use (as ``(path under the cache, text)``), and what went wrong."""

    topics: list[DiscoveredTopic]
    services: list[DiscoveredService]
    files: dict[str, str] = dataclasses.field(default_factory=dict)
    warnings: list[str] = dataclasses.field(default_factory=list)
    broken: str | None = None  # why rosapi is not asked (any more)


_UNSAFE = (
    "rosapi 2.1.0 and older end when asked for it on Jazzy (rosbridge_suite issue #976), and "
    "this rosapi has no /rosapi/action_type, which the fixed ones have, so it was not asked"
)


def fill_details(
    client: RosbridgeClient,
    dialect: Dialect,
    topics: list[DiscoveredTopic],
    services: list[DiscoveredService],
    known: Known,
    *,
    safe: bool,
) -> Details:
    """``safe``: whether asking cannot end rosapi (ROS 1, or a rosapi with the fix)."""
    found = Details(list(topics), list(services), broken=None if safe else _UNSAFE)
    for index, topic in enumerate(found.topics):
        if topic.definition is None:
            text = _ask(
                found,
                dialect,
                topic.name,
                topic.type,
                functools.partial(_message, client, topic.type),
            )
            if text is not None:
                found.topics[index] = dataclasses.replace(topic, definition=text)
    for index, service in enumerate(found.services):
        if known(service.type):
            continue
        kind = service.type
        answer = _ask(found, dialect, service.name, kind, functools.partial(_service, client, kind))
        if answer is not None:
            text, files = answer
            found.services[index] = dataclasses.replace(service, definition=text)
            for path, body in files.items():
                found.files.setdefault(path, body)
    return found


def _ask(found: Details, dialect: Dialect, name: str, kind: str, call: Callable[[], Any]) -> Any:
    """``call()``'s answer, or ``None`` with a warning; the first failure stops all asking."""
    if found.broken is None:
        try:
            return call()
        except UserError as error:
            found.broken = f"not asked, rosapi failed before ({error.message})"
            found.warnings.append(f"no definition of {kind} for {name}: {error.message}")
            return None
    found.warnings.append(
        f"no definition of {kind} for {name}: {found.broken}; add the folder with its package "
        "to the manifest's interfaces"
        + (", or discover with --ros2" if dialect is Dialect.ROS2 else "")
    )
    return None


def _typedefs(client: RosbridgeClient, service: str, kind: str) -> list[Any]:
    typedefs = client.call(service, {"type": kind}).get("typedefs")
    if not isinstance(typedefs, list) or not typedefs:
        raise client.malformed(service, "typedefs is not a list of TypeDefs")
    return typedefs


def _message(client: RosbridgeClient, kind: str) -> str:
    service = "/rosapi/message_details"
    try:
        return full_text_from_typedefs(kind, _typedefs(client, service, kind))
    except ValueError as exc:
        raise client.malformed(service, str(exc)) from None


def _service(client: RosbridgeClient, kind: str) -> tuple[str, dict[str, str]]:
    """The ``.srv`` text and the ``.msg`` files of the messages its halves use."""
    halves, files = [], {}
    for half in ("request", "response"):
        service = f"/rosapi/service_{half}_details"
        try:
            texts = texts_from_typedefs(_typedefs(client, service, kind))
        except ValueError as exc:
            raise client.malformed(service, str(exc)) from None
        items = iter(texts.items())
        halves.append(next(items)[1])  # the half itself comes first
        for name, text in items:
            package, _, short = name.partition("/")
            files[f"{package}/msg/{short}.msg"] = text
    return f"{halves[0]}---\n{halves[1]}", files
