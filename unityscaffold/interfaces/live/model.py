"""What discovery found: topics, services, their definitions, and what went wrong on the way.

Directions are from Unity's point of view, because that is what the manifest records: a topic
the ROS system publishes is one Unity should ``subscribe`` to, and a topic the ROS system only
subscribes to is one Unity should ``publish``.
"""

from __future__ import annotations

import enum
import re
import urllib.parse
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from unityscaffold.errors import UserError
from unityscaffold.interfaces.model import Dialect

__all__ = [
    "Direction",
    "DiscoveredAction",
    "DiscoveredService",
    "DiscoveredTopic",
    "Discovery",
    "NameFilter",
    "Progress",
    "is_url",
]

# Called as ``progress(done, total, name)`` while probing; library code never prints.
Progress = Callable[[int, int, str], None]

# Plumbing every ROS node or bridge brings along; nobody wants a Unity script for these.
# rosbridge 2.x publishes /client_count and /connected_clients itself.
_SYSTEM_NAMES = re.compile(
    r"^/rosout(_agg)?$|^/parameter_events$|^/rosapi(/|$)|^/rosbridge_websocket(/|$)"
    r"|^/client_count$|^/connected_clients$"
    r"|/(get_loggers|set_logger_level|describe_parameters|get_parameters|get_parameter_types"
    r"|list_parameters|set_parameters|set_parameters_atomically|get_type_description)$"
)


def is_url(url: str, schemes: tuple[str, ...]) -> bool:
    """Whether ``url`` has one of ``schemes``, a host, and no port or one in 0..65535."""
    try:
        parsed = urllib.parse.urlsplit(url)
        port = parsed.port  # raises ValueError for one that is not a number in 0..65535
    except ValueError:
        return False
    return parsed.scheme in schemes and bool(parsed.hostname) and (port is None or port >= 0)


class Direction(enum.Enum):
    """What Unity should do with a topic."""

    SUBSCRIBE = "subscribe"
    PUBLISH = "publish"
    UNKNOWN = "unknown"

    @classmethod
    def from_graph(cls, has_publishers: bool, has_subscribers: bool) -> Direction:
        if has_publishers:
            return cls.SUBSCRIBE
        if has_subscribers:
            return cls.PUBLISH
        return cls.UNKNOWN


@dataclass(frozen=True, slots=True)
class DiscoveredTopic:
    """A topic; ``md5`` and ``definition`` (the full text) are ``None`` when not reported."""

    name: str
    type: str
    direction: Direction = Direction.UNKNOWN
    md5: str | None = None
    definition: str | None = None

    def to_json(self) -> dict[str, Any]:
        return {
            "name": self.name,
            "type": self.type,
            "direction": self.direction.value,
            "md5sum": self.md5,
            "definition": self.definition,
        }


@dataclass(frozen=True, slots=True)
class DiscoveredService:
    """A service; ROS 1 nodes report the md5 but never the ``.srv`` text. ``role`` is Unity's:
    ``client`` when the system serves it, ``server`` when the system only calls it (a ROS 2
    graph shows callers too)."""

    name: str
    type: str
    md5: str | None = None
    definition: str | None = None
    role: str = "client"

    def to_json(self) -> dict[str, Any]:
        return {
            "name": self.name,
            "type": self.type,
            "role": self.role,
            "md5sum": self.md5,
            "definition": self.definition,
        }


@dataclass(frozen=True, slots=True)
class DiscoveredAction:
    """An action: in ROS 1 actionlib's five topics under ``name``, found together; in ROS 2
    one graph entry (its hidden topics and services are not listed).

    ``role`` is Unity's (``client`` when the ROS system serves the action, ``server`` when it
    only sends goals), ``None`` when the graph cannot tell. ``topics`` are ROS 1's five topics
    as discovered (goal, cancel, status, feedback, result), for their definitions and md5sums;
    empty in ROS 2.
    """

    name: str
    type: str
    role: str | None
    topics: tuple[DiscoveredTopic, ...]

    def to_json(self) -> dict[str, Any]:
        return {
            "name": self.name,
            "type": self.type,
            "role": self.role,
            "topics": [t.to_json() for t in self.topics],
        }


@dataclass(frozen=True, slots=True)
class Discovery:
    """Everything one source reported, sorted by name."""

    dialect: Dialect
    origin: str  # the master or rosbridge URL, or the bag file
    topics: tuple[DiscoveredTopic, ...] = ()
    services: tuple[DiscoveredService, ...] = ()
    warnings: tuple[str, ...] = ()
    actions: tuple[DiscoveredAction, ...] = ()
    # ROS 2: (type, RIHS01 hash, the topic, service or action it was reported for)
    type_hashes: tuple[tuple[str, str, str], ...] = ()
    # ROS 2: definition files as a local package holds them, (path under the cache, text)
    files: tuple[tuple[str, str], ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "topics", tuple(sorted(self.topics, key=lambda t: t.name)))
        object.__setattr__(self, "services", tuple(sorted(self.services, key=lambda s: s.name)))
        object.__setattr__(self, "actions", tuple(sorted(self.actions, key=lambda a: a.name)))

    def to_json(self) -> dict[str, Any]:
        return {
            "ros": int(self.dialect),
            "source": self.origin,
            "topics": [t.to_json() for t in self.topics],
            "services": [s.to_json() for s in self.services],
            "actions": [a.to_json() for a in self.actions],
            "type_hashes": [{"type": t, "hash": h, "used_by": n} for t, h, n in self.type_hashes],
            "definition_files": [path for path, _ in self.files],
            "warnings": list(self.warnings),
        }


@dataclass(frozen=True, slots=True)
class NameFilter:
    """``--select``/``--exclude`` regular expressions (searched, not anchored) and system names."""

    select: re.Pattern[str] | None = None
    exclude: re.Pattern[str] | None = None
    include_system: bool = False

    @classmethod
    def of(
        cls, select: str | None = None, exclude: str | None = None, *, include_system: bool = False
    ) -> NameFilter:
        return cls(_compile(select, "--select"), _compile(exclude, "--exclude"), include_system)

    def accepts(self, name: str) -> bool:
        if not self.include_system and _SYSTEM_NAMES.search(name):
            return False
        if self.select is not None and not self.select.search(name):
            return False
        return self.exclude is None or not self.exclude.search(name)


def _compile(pattern: str | None, option: str) -> re.Pattern[str] | None:
    if pattern is None:
        return None
    try:
        return re.compile(pattern)
    except re.error as exc:
        raise UserError(f"{option} {pattern!r} is not a valid regular expression: {exc}") from None
