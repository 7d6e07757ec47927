"""ROS 2 actions through rosbridge 2.x's rosapi.

``/rosapi/action_servers`` names each action whose hidden ``_action/feedback`` and
``_action/status`` topics exist. An action client makes them too, so the list holds actions the
robot only calls as well as ones it serves, and rosapi lists the endpoints of hidden topics
nowhere: the role is left open (the manifest gets ``role: client`` with a TODO). The type comes from
``/rosapi/action_type`` where rosapi has it (added upstream after 2.1.0, rosbridge_suite
pull request #1046). rosapi 2.1.0 lists hidden names nowhere, so there the action's
``_action/get_result`` service is called with an argument its request does not have:
rosbridge looks the service's type (``pkg/action/X_GetResult``) up in the graph and refuses,
naming it: 2.1.0 because it loads service classes from ``pkg.srv`` only (``Unable to import srv
class X_GetResult from package pkg``), a bridge that can load it because the request has no
such field (``Message type pkg/action/X_GetResult_Request does not have a field ...``).
Nothing reaches the action server.
"""

from __future__ import annotations

import re

from unityscaffold.interfaces.live._rosbridge_client import RosbridgeClient, strings
from unityscaffold.interfaces.live.model import DiscoveredAction, NameFilter

__all__ = ["rosapi_actions"]

_PROBE_FIELD = "unityscaffold_type_probe"
_REFUSALS = (
    re.compile(
        rf"Message type (?P<package>[A-Za-z]\w*)/action/(?P<name>[A-Za-z]\w*)_GetResult_Request "
        rf"does not have a field {_PROBE_FIELD}"
    ),
    re.compile(
        r"Unable to import srv class (?P<name>[A-Za-z]\w*)_GetResult from package "
        r"(?P<package>[A-Za-z]\w*)\."
    ),
)


def rosapi_actions(
    client: RosbridgeClient, names: NameFilter, *, has_action_type: bool
) -> tuple[list[DiscoveredAction], list[str]]:
    """The actions rosapi lists, each with its type, and what could not be typed;
    ``has_action_type``: whether rosapi offers ``/rosapi/action_type``."""
    service = "/rosapi/action_servers"
    listed = client.try_call(service)
    if isinstance(listed, str):
        return [], [f"cannot list actions: {service} failed: {listed}"]
    actions, warnings = [], []
    typed_by_rosapi = has_action_type
    for name in sorted(strings(client, listed, "action_servers", service)):
        if not names.accepts(name):
            continue
        kind = _action_type(client, name) if typed_by_rosapi else None
        if kind is None:
            typed_by_rosapi = False  # rosapi has no /rosapi/action_type: ask no more
            kind = _probed_type(client, name)
        if kind is None:
            warnings.append(
                f"{name}: rosapi lists it as an action server but neither /rosapi/action_type "
                "nor its _action/get_result service told its type; add it to the manifest's "
                "actions by hand (ros2 action list -t shows the type)"
            )
            continue
        actions.append(DiscoveredAction(name, kind, None, ()))
    return actions, warnings


def _action_type(client: RosbridgeClient, name: str) -> str | None:
    values = client.try_call("/rosapi/action_type", {"action": name})
    if isinstance(values, str):
        return None
    kind = values.get("type")
    if not isinstance(kind, str):
        raise client.malformed("/rosapi/action_type", "type is not a string")
    return kind or None


def _probed_type(client: RosbridgeClient, name: str) -> str | None:
    refusal = client.try_call(f"{name}/_action/get_result", {_PROBE_FIELD: 0})
    if not isinstance(refusal, str):
        return None
    for pattern in _REFUSALS:
        if match := pattern.search(refusal):
            return f"{match['package']}/action/{match['name']}"
    return None
