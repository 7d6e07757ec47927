"""The typed model of ROS interfaces shared by both dialects.

Names: a message's ``full_name`` is ``pkg/Name`` in ROS 1 and ``pkg/msg/Name`` (or ``pkg/srv/…``,
``pkg/action/…`` for the parts of services and actions) in ROS 2, the form each ROS version puts
on the wire. A ``TypeRef`` to a message holds that full name in ``base``.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import TypeAlias

from unityscaffold.errors import SourceLocation

__all__ = [
    "MAX_SIZE",
    "ROS1_BUILTINS",
    "ROS1_PRIMITIVES",
    "ROS2_PRIMITIVES",
    "ActionSpec",
    "ArrayKind",
    "Constant",
    "Dialect",
    "Field",
    "Interface",
    "InterfaceKind",
    "MessageSpec",
    "ServiceSpec",
    "TypeRef",
    "Value",
]


class Dialect(enum.IntEnum):
    ROS1 = 1
    ROS2 = 2

    @property
    def label(self) -> str:
        return f"ROS {int(self)}"


class InterfaceKind(enum.Enum):
    MSG = "msg"
    SRV = "srv"
    ACTION = "action"

    @property
    def suffix(self) -> str:
        return "." + self.value


class ArrayKind(enum.Enum):
    NONE = "none"
    FIXED = "fixed"
    BOUNDED = "bounded"
    UNBOUNDED = "unbounded"


ROS1_PRIMITIVES: tuple[str, ...] = (
    "bool",
    "int8",
    "uint8",
    "int16",
    "uint16",
    "int32",
    "uint32",
    "int64",
    "uint64",
    "float32",
    "float64",
    "string",
    "byte",
    "char",
)
ROS1_BUILTINS: tuple[str, ...] = (*ROS1_PRIMITIVES, "time", "duration")
ROS2_PRIMITIVES: tuple[str, ...] = (
    "bool",
    "byte",
    "char",
    "float32",
    "float64",
    "int8",
    "uint8",
    "int16",
    "uint16",
    "int32",
    "uint32",
    "int64",
    "uint64",
    "string",
    "wstring",
)

MAX_SIZE = 2**31 - 1
"""The largest array size or string bound we accept: C# arrays and strings are indexed by
``int``, so a larger one could never become C#. Both dialects refuse more, at the definition."""

Scalar: TypeAlias = bool | int | float | str
Value: TypeAlias = Scalar | tuple[Scalar, ...]


@dataclass(frozen=True, slots=True)
class TypeRef:
    """The type of a field: a builtin or a message, maybe an array of it.

    ``base`` is a builtin name (``float64``, ``string``, ``time``) or the full name of a message.
    ``size`` is N for ``T[N]`` and ``T[<=N]``; ``string_bound`` is N for ``string<=N``.
    """

    base: str
    array: ArrayKind = ArrayKind.NONE
    size: int | None = None
    string_bound: int | None = None

    @property
    def is_builtin(self) -> bool:
        return "/" not in self.base

    @property
    def is_message(self) -> bool:
        return "/" in self.base

    @property
    def is_array(self) -> bool:
        return self.array is not ArrayKind.NONE

    @property
    def package(self) -> str | None:
        return self.base.split("/", 1)[0] if self.is_message else None

    @property
    def short_name(self) -> str:
        return self.base.rsplit("/", 1)[-1]

    @property
    def element(self) -> TypeRef:
        """The same type without its array part."""
        return TypeRef(self.base, string_bound=self.string_bound)

    def array_suffix(self) -> str:
        if self.array is ArrayKind.NONE:
            return ""
        if self.array is ArrayKind.FIXED:
            return f"[{self.size}]"
        if self.array is ArrayKind.BOUNDED:
            return f"[<={self.size}]"
        return "[]"

    def __str__(self) -> str:
        bound = f"<={self.string_bound}" if self.string_bound is not None else ""
        return f"{self.base}{bound}{self.array_suffix()}"


@dataclass(frozen=True, slots=True)
class Field:
    """One field of a message. ``default`` exists in ROS 2 only.

    ``type_text`` is the type as the dialect's reference tool keeps it after resolving names
    (genmsg puts it, array suffix included, into the md5 text of builtin fields).
    """

    type: TypeRef
    name: str
    default: Value | None = None
    type_text: str = ""
    comment: tuple[str, ...] = ()
    location: SourceLocation | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Constant:
    """A constant of a primitive type.

    ``value`` is the parsed value; ``text`` is the value as the dialect's reference tool keeps it
    (for ROS 1, genmsg's ``val_text``, which is what enters the md5sum).
    """

    type: str
    name: str
    value: Scalar
    text: str
    comment: tuple[str, ...] = ()
    location: SourceLocation | None = field(default=None, compare=False, repr=False)


class _Named:
    """The names every interface has; ``subfolder`` is where ROS 2 puts it (``msg``, ``srv``…)."""

    __slots__ = ()
    package: str
    name: str
    dialect: Dialect
    subfolder: str

    @property
    def full_name(self) -> str:
        """The wire name: ``pkg/Name`` in ROS 1, ``pkg/<subfolder>/Name`` in ROS 2."""
        if self.dialect is Dialect.ROS1:
            return f"{self.package}/{self.name}"
        return f"{self.package}/{self.subfolder}/{self.name}"

    @property
    def short_full_name(self) -> str:
        """``pkg/Name``, the form users type in either dialect."""
        return f"{self.package}/{self.name}"


@dataclass(frozen=True, slots=True)
class MessageSpec(_Named):
    """A message, or one part of a service or action (``owner`` names that service or action).

    ``text`` is the message's own definition text exactly as the reference tool keeps it (for a
    ROS 1 service half or action part: genmsg's/genaction's text), used for the full definition.
    """

    package: str
    name: str
    dialect: Dialect
    fields: tuple[Field, ...] = ()
    constants: tuple[Constant, ...] = ()
    text: str = ""
    comment: tuple[str, ...] = ()
    source: str | None = None
    subfolder: str = "msg"
    owner: str | None = None

    @property
    def kind(self) -> InterfaceKind:
        return InterfaceKind.MSG

    def dependencies(self) -> tuple[str, ...]:
        """Full names of the message types this one uses directly, in field order, unique."""
        seen: dict[str, None] = {}
        for f in self.fields:
            if f.type.is_message:
                seen.setdefault(f.type.base, None)
        return tuple(seen)


@dataclass(frozen=True, slots=True)
class ServiceSpec(_Named):
    """A service: its request and response halves (ROS 2 also derives an ``_Event`` message)."""

    package: str
    name: str
    dialect: Dialect
    request: MessageSpec
    response: MessageSpec
    text: str = ""
    source: str | None = None
    event: MessageSpec | None = None
    subfolder: str = "srv"
    owner: str | None = None

    @property
    def kind(self) -> InterfaceKind:
        return InterfaceKind.SRV

    @property
    def parts(self) -> tuple[MessageSpec, ...]:
        extra = (self.event,) if self.event is not None else ()
        return (self.request, self.response, *extra)


@dataclass(frozen=True, slots=True)
class ActionSpec(_Named):
    """An action: the three parts a user writes, and the messages and services derived from them.

    ROS 1 (genaction): ``derived`` holds ``XAction``, ``XActionGoal``, ``XActionResult`` and
    ``XActionFeedback``. ROS 2 (rosidl): ``derived`` holds ``X_FeedbackMessage`` and ``services``
    holds ``X_SendGoal`` and ``X_GetResult``.
    """

    package: str
    name: str
    dialect: Dialect
    goal: MessageSpec
    result: MessageSpec
    feedback: MessageSpec
    text: str = ""
    source: str | None = None
    derived: tuple[MessageSpec, ...] = ()
    services: tuple[ServiceSpec, ...] = ()
    subfolder: str = "action"

    @property
    def kind(self) -> InterfaceKind:
        return InterfaceKind.ACTION

    @property
    def messages(self) -> tuple[MessageSpec, ...]:
        """Every message this action defines, its own parts first."""
        nested = tuple(p for s in self.services for p in s.parts)
        return (self.goal, self.result, self.feedback, *self.derived, *nested)


Interface: TypeAlias = MessageSpec | ServiceSpec | ActionSpec
