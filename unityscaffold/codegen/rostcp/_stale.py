"""Warnings for shipped classes that do not match the distro's definition, and for the shipped
classes that hold one of those (a ``MarkerArray`` is garbled by its ``Marker``s)."""

from __future__ import annotations

from unityscaffold.codegen._identity import Identities
from unityscaffold.codegen.rostcp._classes import TcpClass
from unityscaffold.codegen.rostcp._shipped import difference
from unityscaffold.interfaces.model import Dialect, MessageSpec

__all__ = ["stale_warnings"]

_WHAT_TO_DO = (
    "the connector decodes by ROS name with one class per name, so no second class is "
    "generated beside it: use a message type of your own package with these fields, or fix "
    "the class in a local copy of the package (Packages/com.unity.robotics.ros-tcp-connector)"
)


def _effect(found: str) -> str:
    if found.startswith("starts with"):
        return "a message sent as constructed differs from ROS's default: set these fields"
    if found.startswith("writes no byte"):
        return (
            "the endpoint's ROS 2 node cannot read what Unity sends (a published message is "
            "dropped, a service request stops its service thread); receiving works"
        )
    return (
        "messages of this type, and of every type that holds it, are garbled between Unity "
        f"and ROS; {_WHAT_TO_DO}"
    )


def _holds(spec: MessageSpec, specs: dict[str, MessageSpec], stale: set[str]) -> str | None:
    """The first stale type ``spec`` holds, at any depth."""
    seen: set[str] = set()
    pending = [spec]
    while pending:
        current = pending.pop()
        for field in current.fields:
            base = field.type.base
            if base in stale and field.type.is_message:
                return base
            if base in specs and base not in seen:
                seen.add(base)
                pending.append(specs[base])
    return None


def stale_warnings(
    items: list[TcpClass], dialect: Dialect, ids: Identities
) -> tuple[dict[str, str], dict[str, str]]:
    """Class full name -> warning, for each shipped class that differs or holds one that does
    (wire differences only: a different default does not spread); and class full name ->
    message full name for the warnings about defaults alone."""
    warnings: dict[str, str] = {}
    defaults: dict[str, str] = {}
    stale: set[str] = set()
    for item in items:
        if item.shipped is None or item.spec is None:
            continue
        found = difference(item.shipped, item.spec, dialect)
        if found is None:
            continue
        if found.startswith("starts with"):
            defaults[item.cs_class.full_name] = item.spec.full_name
        else:
            stale.add(item.spec.full_name)
        warnings[item.cs_class.full_name] = (
            f"ROS-TCP-Connector's {item.cs_class.full_name} does not match "
            f"{item.spec.full_name} as defined here ({ids.label(item.identity_of)}): it "
            f"{found}; {_effect(found)}"
        )
    specs = {i.spec.full_name: i.spec for i in items if i.spec is not None}
    for item in items:
        if item.shipped is None or item.spec is None or item.cs_class.full_name in warnings:
            continue
        held = _holds(item.spec, specs, stale)
        if held is not None:
            warnings[item.cs_class.full_name] = (
                f"ROS-TCP-Connector's {item.cs_class.full_name} holds {held}, whose class "
                f"does not match its definition here: messages of {item.spec.full_name} are "
                f"garbled between Unity and ROS; {_WHAT_TO_DO}"
            )
    unregistered = _unregistered(items)
    warnings.update(unregistered)
    return warnings, {k: v for k, v in defaults.items() if k not in unregistered}


def _unregistered(items: list[TcpClass]) -> dict[str, str]:
    """The connector's shipped action wrappers (``nav_msgs/GetMapActionGoal`` …) have no
    ``Register``: ROSConnection finds neither their ROS name nor their decoder."""
    return {
        item.cs_class.full_name: (
            f"ROS-TCP-Connector's {item.cs_class.full_name} never registers itself (it has no "
            "Register()), so ROSConnection cannot subscribe to it or decode it: a ROS 1 action "
            f"client or server of {item.interface.full_name} receives nothing; send only, or "
            "use an action of your own package (its generated classes register)"
        )
        for item in items
        if item.shipped is not None and item.shipped.subtopic == "-"
    }
