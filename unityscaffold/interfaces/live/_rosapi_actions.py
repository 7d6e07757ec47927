"""ROS 2 actions through rosbridge 2.x's rosapi.

``/rosapi/action_servers`` names each action that has a server (its hidden ``_action/feedback``
and ``_action/status`` topics are there); Unity is then its client. The type comes from
``/rosapi/action_type`` where rosapi has it (added upstream after 2.1.0, rosbridge_suite
pull request #1046). rosapi 2.1.0 lists hidden names nowhere, so there the action's
``_action/get_result`` service is called with an argument its request does not have:
rosbridge looks the service's type up in the graph, fails to fill the request, and names the
request type in its refusal (``Message type pkg/action/X_GetResult_Request does not have a
field ...``). Nothing reaches the action server.
"""

from __future__ import annotations

import re

from unityscaffold.interfaces.live._rosbridge_client import RosbridgeClient, strings
from unityscaffold.interfaces.live.model import DiscoveredAction, NameFilter

__all__ = ["rosapi_actions"]

_PROBE_FIELD = "unityscaffold_type_probe"
_REFUSAL = re.compile(
    rf"Message type ([A-Za-z]\w*/action/[A-Za-z]\w*)_GetResult_Request does not have a field "
    rf"{_PROBE_FIELD}"
)


def rosapi_actions(
    client: RosbridgeClient, names: NameFilter
) -> tuple[list[DiscoveredAction], list[str]]:
    """The actions rosapi lists servers of, each with its type, and what could not be typed."""
    service = "/rosapi/action_servers"
    listed = client.try_call(service)
    if isinstance(listed, str):
        return [], [f"cannot list actions: {service} failed: {listed}"]
    actions, warnings = [], []
    typed_by_rosapi = True
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
        actions.append(DiscoveredAction(name, kind, "client", ()))
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
    match = _REFUSAL.search(refusal) if isinstance(refusal, str) else None
    return match.group(1) if match else None
