"""Notes for ROS 2 manifest entries that rosbridge 2.x will let down, each at the entry's line:
a type with a field rosbridge cannot carry (``interfaces.rosbridge2``), and an action client,
whose cancels rosbridge reads late unless it is launched to send goals in threads of their own.
"""

from __future__ import annotations

from unityscaffold.interfaces.model import (
    ActionSpec,
    Dialect,
    Interface,
    MessageSpec,
    ServiceSpec,
)
from unityscaffold.interfaces.registry import Registry
from unityscaffold.interfaces.rosbridge2 import describe, uncarried_fields
from unityscaffold.manifest.model import Action, Manifest, Role, Service, Topic

CANCEL_NOTE = (
    "rosbridge 2.x runs a client's goals one after the other on the connection's own thread,"
    " so it reads this client's cancel only once the goal has ended"
    " (https://github.com/RobotWebTools/rosbridge_suite/issues/909): launch rosbridge with"
    " send_action_goals_in_new_thread:=true for CancelGoal to reach the action server in time"
)


def _parts(spec: Interface) -> tuple[MessageSpec, ...]:
    """The messages an entry's type sends over rosbridge: the message, a service's halves, an
    action's goal, result and feedback."""
    if isinstance(spec, ServiceSpec):
        return (spec.request, spec.response)
    if isinstance(spec, ActionSpec):
        return (spec.goal, spec.result, spec.feedback)
    return (spec,)


def rosbridge2_notes(manifest: Manifest, registry: Registry) -> list[str]:
    """One note per ROS 2 entry that rosbridge 2.x cannot fully serve (none for ROS 1)."""
    if manifest.ros is not Dialect.ROS2:
        return []
    notes = []
    entries: list[Topic | Service | Action] = [
        *manifest.topics,
        *manifest.services,
        *manifest.actions,
    ]
    for entry in entries:
        spec = registry.find(entry.type)
        if spec is None:  # an unknown type is an error elsewhere
            continue
        fields = tuple(f for part in _parts(spec) for f in uncarried_fields(registry, part))
        where = f"{entry.locations.of('type')}: {entry.name} ({entry.type})"
        if fields:
            notes.append(f"{where}: {describe(fields)}")
        if isinstance(entry, Action) and entry.role is Role.CLIENT:
            notes.append(f"{where}: {CANCEL_NOTE}")
    return notes
