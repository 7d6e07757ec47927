"""Which C# type each ROS builtin becomes, per ROS version.

As ROS#: ``int8``->``sbyte`` … ``float64``->``double``, ROS 1 ``byte``->``sbyte`` and
``char``->``byte``, ROS 1 ``time``/``duration``->ROS#'s hand-written ``Std.Time``/``Std.Duration``.
Deviation: a ROS 2 ``byte`` is an unsigned octet on the wire (rosbridge sends 0..255), so it
becomes C# ``byte``, where ROS# uses ``sbyte``. ROS 2 ``char`` is ``byte`` and ``wstring``
is ``string``.
"""

from __future__ import annotations

from unityscaffold.interfaces.model import Dialect

__all__ = ["ROS1_TIME_TYPES", "primitive_type"]

_COMMON = {
    "bool": "bool",
    "int8": "sbyte",
    "uint8": "byte",
    "int16": "short",
    "uint16": "ushort",
    "int32": "int",
    "uint32": "uint",
    "int64": "long",
    "uint64": "ulong",
    "float32": "float",
    "float64": "double",
    "string": "string",
    "char": "byte",
}
_PRIMITIVES = {
    Dialect.ROS1: {**_COMMON, "byte": "sbyte"},
    Dialect.ROS2: {**_COMMON, "byte": "byte", "wstring": "string"},
}
ROS1_TIME_TYPES: dict[str, str] = {"time": "Time", "duration": "Duration"}
"""ROS 1 builtins that map to ROS#'s hand-written classes in namespace ``Std``."""


def primitive_type(base: str, dialect: Dialect) -> str | None:
    """The C# keyword type for a ROS primitive, or None for anything else (time, messages)."""
    return _PRIMITIVES[dialect].get(base)
