"""View models: everything a template prints, computed in Python.

Each view names its template in ``template``; templates only lay the values out. Strings here
are final C# text (escaped identifiers, type names, literals, ``///`` lines).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import ClassVar

__all__ = [
    "ActionView",
    "ActionWrapperView",
    "ConstantView",
    "FileHeader",
    "MemberView",
    "MessageClassView",
    "MessageView",
    "SizeCheck",
    "View",
    "doc_lines",
]


# C# ends a line at any of these, so inside a /// line they would turn the rest into code.
_CS_NEWLINES = "\r\n\u0085\u2028\u2029"
# XML 1.0 allows no other control characters, not even as character references.
_XML_FORBIDDEN = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff\ud800-\udfff]")
# Any character _xml_escape changes; most comment lines hold none, and one search says so.
_XML_CHANGED = re.compile(
    "[&<>\r\n\u0085\u2028\u2029\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff\ud800-\udfff]"
)


def _xml_escape(text: str) -> str:
    """One comment line as XML text on one C# line: markup escaped, line breaks made spaces,
    characters XML cannot hold replaced by U+FFFD."""
    if _XML_CHANGED.search(text) is None:
        return text
    for char in _CS_NEWLINES:
        text = text.replace(char, " ")
    text = _XML_FORBIDDEN.sub("\ufffd", text)
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def doc_lines(comment: tuple[str, ...] | list[str]) -> tuple[str, ...]:
    """A comment as an XML doc ``<summary>``, one ``///`` line per line; () when empty."""
    if not comment:
        return ()
    lines = [_xml_escape(line.rstrip()) for line in comment]
    while lines and not lines[-1]:
        lines.pop()
    while lines and not lines[0]:
        lines.pop(0)
    if not lines:
        return ()
    body = tuple(f"/// {line}" if line else "///" for line in lines)
    return ("/// <summary>", *body, "/// </summary>")


@dataclass(frozen=True, slots=True)
class FileHeader:
    """The top of a generated file: provenance, ROS version guard, namespace and usings."""

    source: str
    identity: str
    define: str
    namespace: str
    usings: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class ConstantView:
    """One constant; ``spaced`` when a blank line separates it from the one before."""

    name: str
    cs_type: str
    value: str
    doc: tuple[str, ...] = ()
    spaced: bool = False


@dataclass(frozen=True, slots=True)
class SizeCheck:
    """A setter guard: ``condition`` (on ``value``) means the array breaks its size rule."""

    field: str
    condition: str
    message: str


@dataclass(frozen=True, slots=True)
class MemberView:
    """One auto-property (or a checked property over ``check.field``); ``spaced`` when a blank
    line separates it from the one before."""

    name: str
    cs_type: str
    init: str
    doc: tuple[str, ...] = ()
    check: SizeCheck | None = None
    spaced: bool = False


@dataclass(frozen=True, slots=True)
class MessageClassView:
    """What a message class shows whichever runtime it is for: its name, its ROS name (a C#
    literal), its doc lines, its constants and its constructor's parameter list."""

    class_name: str
    ros_name: str
    doc: tuple[str, ...]
    constants: tuple[ConstantView, ...]
    parameters: str


@dataclass(frozen=True, slots=True)
class MessageView(MessageClassView):
    """A class deriving from ROS#'s ``Message``: messages and service halves. ``base`` is that
    class as the file names it; ``members`` are the auto-properties, one per field."""

    template: ClassVar[str] = "rossharp/Message.cs.jinja"
    header: FileHeader
    base: str
    members: tuple[MemberView, ...]


@dataclass(frozen=True, slots=True)
class ActionWrapperView:
    """``<A>ActionGoal``/``ActionResult``/``ActionFeedback`` on ROS#'s generic bases.

    ``payload`` names both the member that holds the part and the constructor parameter that
    sets it.
    """

    template: ClassVar[str] = "rossharp/ActionWrapper.cs.jinja"
    header: FileHeader
    class_name: str
    base: str
    ros_name: str
    doc: tuple[str, ...]
    payload: str
    payload_type: str
    parameters: str
    base_arguments: str


@dataclass(frozen=True, slots=True)
class ActionView:
    """``<A>Action`` on ROS#'s ``Action<…>`` base."""

    template: ClassVar[str] = "rossharp/Action.cs.jinja"
    header: FileHeader
    class_name: str
    base: str
    ros_name: str
    doc: tuple[str, ...]
    parts: tuple[tuple[str, str], ...]
    parameters: str
    base_arguments: str


View = MessageView | ActionWrapperView | ActionView
