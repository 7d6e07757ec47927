"""C# names for ROS# code: classes (``CsClass``), namespaces from package names, identifiers.

Small pure functions; the package rule is ROS#'s ``MsgAutoGenUtilities.ResolvePackageName``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from unityscaffold.errors import UserError

__all__ = [
    "CSHARP_KEYWORDS",
    "MAX_CLASS_NAME",
    "MAX_IDENTIFIER",
    "ROSSHARP_MESSAGE",
    "ROSSHARP_ROOT_NAMESPACE",
    "ClassClash",
    "CsClass",
    "check_class_name",
    "class_name",
    "escape_identifier",
    "is_identifier",
    "namespace_segment",
    "pascal_case",
    "rossharp_class",
    "validate_namespace",
]


class ClassClash(UserError):
    """Two things would become the same C# class: two ROS types, or (``with_shipped``) a type
    and a class ROS# ships.

    The hint names no option: another root namespace is what keeps a type apart from ROS#'s
    classes, and that is a flag of ``msgs gen`` but a manifest key for ``apply``, so each
    command words its own hint.
    """

    def __init__(self, message: str, *, with_shipped: bool) -> None:
        hint = (
            "generate into another root namespace"
            if with_shipped
            else "ROS# names classes by package namespace and type name; rename one of the types"
        )
        super().__init__(message, hint=hint)
        self.with_shipped = with_shipped


@dataclass(frozen=True, slots=True, order=True)
class CsClass:
    """A C# class: its namespace (full) and name."""

    namespace: str
    name: str

    @property
    def full_name(self) -> str:
        return f"{self.namespace}.{self.name}"

    @property
    def qualified(self) -> str:
        return f"global::{self.full_name}"


ROSSHARP_ROOT_NAMESPACE = "RosSharp.RosBridgeClient.MessageTypes"
ROSSHARP_MESSAGE = CsClass("RosSharp.RosBridgeClient", "Message")


def rossharp_class(segment: str, name: str) -> CsClass:
    """A class in ROS#'s own message namespace (its runtime assembly)."""
    return CsClass(f"{ROSSHARP_ROOT_NAMESPACE}.{segment}", name)


_RESERVED = frozenset(
    """
abstract as base bool break byte case catch char checked class const continue decimal default
delegate do double else enum event explicit extern false finally fixed float for foreach goto if
implicit in int interface internal is lock long namespace new null object operator out override
params private protected public readonly ref return sbyte sealed short sizeof stackalloc static
string struct switch this throw true try typeof uint ulong unchecked unsafe ushort using virtual
void volatile while
""".split()
)
_CONTEXTUAL = frozenset(
    """
add alias and ascending args async await by descending dynamic equals file from get global group
init into join let managed nameof nint not notnull nuint on or orderby partial record remove
required scoped select set unmanaged value var when where with yield
""".split()
)
CSHARP_KEYWORDS: frozenset[str] = _RESERVED | _CONTEXTUAL
"""Reserved and contextual C# keywords; a ROS name on this list gets an ``@`` prefix."""

_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_PACKAGE_MARKERS = ("_msgs", "_srvs", "_actions")


MAX_IDENTIFIER = 511
"""The longest member name we generate: mcs refuses identifiers over 512 characters (CS0645),
and a field with a size check gets a backing field one ``_`` longer."""
MAX_CLASS_NAME = 247
"""The longest class name we generate: its file ``Name.cs.meta`` must fit the 255 bytes file
systems allow for a name."""


def is_identifier(name: str) -> bool:
    """Whether ``name`` is an ASCII C# identifier (keywords included: they can be escaped)."""
    return _IDENTIFIER.fullmatch(name) is not None


def escape_identifier(name: str) -> str:
    """``name`` as a C# identifier: keywords get ``@`` (the JSON name stays ``name``)."""
    if not is_identifier(name):
        raise UserError(
            f"'{name}' cannot become a C# identifier",
            hint="C# names use letters, digits and '_' and do not start with a digit",
        )
    if len(name) > MAX_IDENTIFIER:
        raise UserError(
            f"'{name[:20]}…' ({len(name)} characters) is too long for a C# identifier",
            hint=f"C# compilers take names of at most {MAX_IDENTIFIER} characters; rename it",
        )
    return f"@{name}" if name in CSHARP_KEYWORDS else name


def pascal_case(snake: str) -> str:
    """``unique_identifier`` -> ``UniqueIdentifier``: each ``_``-separated part capitalised."""
    return "".join(part[:1].upper() + part[1:] for part in snake.split("_") if part)


def namespace_segment(package: str) -> str:
    """The namespace segment ROS# uses for ``package`` (``geometry_msgs`` -> ``Geometry``).

    A name containing ``_msgs``, ``_srvs`` or ``_actions`` loses everything from its last ``_``
    and is PascalCased (``foo_msgs_ext`` -> ``FooMsgs``); another name with ``_`` is PascalCased
    whole; any other name is capitalised.
    """
    if any(marker in package for marker in _PACKAGE_MARKERS):
        segment = pascal_case(package[: package.rindex("_")])
    elif "_" in package:
        segment = pascal_case(package)
    else:
        segment = package[:1].upper() + package[1:]
    if not is_identifier(segment) or segment in CSHARP_KEYWORDS:
        raise UserError(
            f"package '{package}' cannot become a C# namespace (got '{segment}')",
            hint="ROS package names start with a letter and hold only letters, digits and '_' "
            "(REP 144); rename the package (its folder and package.xml): every class is in a "
            "namespace named after its package, whatever the root namespace",
        )
    return segment


def class_name(ros_name: str) -> str:
    """A ROS type name as a C# class name: its first letter capitalised, as ROS# does."""
    name = ros_name[:1].upper() + ros_name[1:]
    if not is_identifier(name):
        raise UserError(
            f"type name '{ros_name}' cannot become a C# class name",
            hint="C# names use letters, digits and '_' and do not start with a digit; rename "
            "the file (ROS type names are CamelCase: letters and digits, a letter first)",
        )
    return name


def check_class_name(name: str) -> str:
    """``name`` if a class of that name fits in a file name, else a UserError."""
    if len(name) > MAX_CLASS_NAME:
        raise UserError(
            f"the C# class '{name[:20]}…' would have {len(name)} characters, more than its file"
            f" name can hold ({MAX_CLASS_NAME})",
            hint="rename the type",
        )
    return name


def validate_namespace(namespace: str) -> str:
    """A user-given root namespace: dot-separated identifiers, none a reserved keyword."""
    parts = namespace.split(".")
    bad = [p for p in parts if not is_identifier(p) or p in _RESERVED]
    if bad:
        raise UserError(
            f"'{namespace}' is not a C# namespace name",
            hint="use dot-separated identifiers such as MyRobot.Messages",
        )
    return namespace
