"""ROS 2 definitions checked against the RIHS01 hashes the graph reported.

Each hash names one type (a topic's message, a service's request or response, an action's
feedback message or its goal and result services' halves). The definition that will be
generated from, the cache's rebuilt text or a local package's file, must hash the same, or the
generated classes would not talk to the robot: that is an error, never a warning.
"""

from __future__ import annotations

from unityscaffold.errors import LocatedError, UserError
from unityscaffold.interfaces.identity_ros2 import Ros2Identity
from unityscaffold.interfaces.live.model import Discovery
from unityscaffold.interfaces.registry import Registry

__all__ = ["check_type_hashes"]


def check_type_hashes(discovery: Discovery, rebuilt: Registry, wider: Registry) -> int:
    """Raise ``UserError`` at the first type whose definition hashes otherwise; return how
    many hashes were checked (a type no definition was found for is warned about elsewhere).

    A type rebuilt from what the system sent is read from ``rebuilt`` (the cache alone), any
    other from ``wider`` (cache, the manifest's interfaces, the environment)."""
    sent = {t.type for t in discovery.topics if t.definition}
    identities = {id(rebuilt): Ros2Identity(rebuilt), id(wider): Ros2Identity(wider)}
    checked = 0
    for type_name, reported, used_by in discovery.type_hashes:
        registry = rebuilt if type_name in sent else wider
        try:
            spec = registry.find(type_name)
            if spec is None:
                continue
            computed = identities[id(registry)].type_hash(spec)
        except (LocatedError, UserError):
            continue  # a definition that does not parse is reported by the caller's lookup
        checked += 1
        if computed != reported:
            raise _mismatch(type_name, used_by, reported, computed, spec.source, discovery.origin)
    return checked


def _mismatch(
    type_name: str, used_by: str, reported: str, computed: str, source: str | None, origin: str
) -> UserError:
    where = source or "the local definition"
    return UserError(
        f"RIHS01 type hash mismatch for {type_name} (used by {used_by}): {origin} reported "
        f"{reported}, {where} gives {computed}",
        hint=f"the robot was built with another version of {type_name}: put the robot's "
        "package in the manifest's interfaces (ahead of any other copy) or install it",
    )
