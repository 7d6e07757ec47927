"""The classes ROS-TCP-Connector 0.7 ships, and whether one still matches a distro's definition.

The connector's ``MessageRegistry`` holds one decoder per ROS name (and subtopic): a class
generated beside a shipped one would race it, so shipped classes are referenced, never
generated. Those classes were written for Noetic (some by hand, with a ROS 2 branch); where a
distro's definition has since changed, messages of that type are garbled on the wire, and
``difference`` says how.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

from unityscaffold.codegen._types import primitive_type
from unityscaffold.codegen.naming import CsClass
from unityscaffold.codegen.rostcp._shipped_data import CLASSES, FIELDS
from unityscaffold.interfaces.model import ArrayKind, Dialect, Field, MessageSpec

__all__ = ["ROOT_NAMESPACE", "ShippedClass", "difference", "shipped_classes"]

ROOT_NAMESPACE = "RosMessageTypes"
# Wire-identical C# types: the connector maps ROS 2's byte to sbyte, we map it to byte.
_SAME_WIRE = {"sbyte": "byte"}
_PART_SUBTOPICS = ("Response", "Goal", "Result", "Feedback")


@dataclass(frozen=True, slots=True)
class ShippedClass:
    """One shipped class: its ROS registration and its fields (``name:type[=default]``)."""

    cs_class: CsClass
    ros_name: str
    subtopic: str
    fields: tuple[str, ...]


def _definition_name(cls: CsClass, ros_name: str, subtopic: str) -> str:
    """The ROS 1 style name of what ``cls`` stands for: a service's request, response or an
    action part registers its service's or action's name (with a subtopic)."""
    if subtopic in _PART_SUBTOPICS:
        return ros_name + subtopic
    if cls.name == ros_name.rsplit("/", 1)[-1] + "Request":
        return ros_name + "Request"
    return ros_name


@cache
def shipped_classes(dialect: Dialect) -> dict[str, ShippedClass]:
    """Definition name (``pkg/Name``, ``pkg/SrvRequest``, ``pkg/ActGoal``) -> shipped class."""
    table: dict[str, ShippedClass] = {}
    fields = FIELDS[int(dialect)]
    for key, (ros_name, subtopic) in CLASSES[int(dialect)].items():
        namespace, _, name = key.partition("/")
        cls = CsClass(f"{ROOT_NAMESPACE}.{namespace}", name)
        table[_definition_name(cls, ros_name, subtopic)] = ShippedClass(
            cls, ros_name, subtopic, fields[key]
        )
    return table


def _token(field: Field, dialect: Dialect) -> str:
    """``field`` in the table's notation, wire-identical types spelled alike."""
    ref = field.type
    if ref.is_message:
        package, _, name = ref.base.partition("/")
        base = f"{package}/{name.rsplit('/', 1)[-1]}"
    elif ref.base in ("time", "duration"):
        base = "std_msgs/Time" if ref.base == "time" else "builtin_interfaces/Duration"
    else:
        base = primitive_type(ref.base, dialect) or ref.base
    base = _SAME_WIRE.get(base, base)
    if ref.array is ArrayKind.FIXED:
        return f"{base}[{ref.size}]"
    return base + ("[]" if ref.is_array else "")


def _theirs(entry: str) -> tuple[str, str, str | None]:
    name, _, rest = entry.partition(":")
    token, _, default = rest.partition("=")
    base, bracket, count = token.partition("[")
    return name, _SAME_WIRE.get(base, base) + bracket + count, default or None


def _default_differs(field: Field, shipped: str | None) -> bool:
    ours = field.default if field.default is not None else 0
    if isinstance(ours, tuple | str) or field.type.is_array or field.type.is_message:
        return False
    theirs = float({"true": "1", "false": "0"}.get(shipped or "0", shipped or "0"))
    return float(ours) != theirs


def difference(shipped: ShippedClass, spec: MessageSpec, dialect: Dialect) -> str | None:
    """How ``shipped`` differs from ``spec`` on the wire or in its default instance, or None."""
    if shipped.cs_class.namespace.endswith(".BuiltinInterfaces"):
        return None  # the time primitives ROS 1's time/duration become: same bytes, by design
    if dialect is Dialect.ROS2 and not spec.fields:
        return "writes no byte for this empty message, where ROS 2's CDR needs one"
    theirs = [_theirs(e) for e in shipped.fields]
    ours = [(f.name, _token(f, dialect)) for f in spec.fields]
    if [t for _, t, _ in theirs] != [t for _, t in ours]:
        mine = {n for n, _ in ours}
        missing = [n for n, _ in ours if n not in {t[0] for t in theirs}]
        extra = [n for n, _, _ in theirs if n not in mine]
        parts = [f"lacks {', '.join(missing)}"] if missing else []
        parts += [f"has {', '.join(extra)}, which this definition does not"] if extra else []
        return "; ".join(parts or ["declares fields of other types or in another order"])
    defaults = [
        f"{name} = {default or 0}"
        for field, (name, _, default) in zip(spec.fields, theirs, strict=True)
        if _default_differs(field, default)
    ]
    if defaults:
        return f"starts with {', '.join(defaults)}, not this definition's default"
    return None
