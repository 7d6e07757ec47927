"""View models of the connector's classes: everything a template prints, computed in Python.

Each view names its template in ``template``; templates only lay the values out. Every type a
file names is written ``global::``-qualified, so no package namespace (a ``Unity`` or ``System``
segment) and no custom root namespace can capture a name.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from unityscaffold.codegen._views import MessageClassView

__all__ = ["ActionView", "FieldView", "Header", "MessageView", "WrapperView"]

RUNTIME = "global::Unity.Robotics.ROSTCPConnector.MessageGeneration"
"""The connector's message runtime namespace (``Message``, ``MessageSerializer``, …)."""


@dataclass(frozen=True, slots=True)
class Header:
    """The top of a generated file: provenance, ROS version guard, namespace."""

    source: str
    identity: str
    define: str
    namespace: str


@dataclass(frozen=True, slots=True)
class FieldView:
    """One serialized field: its declaration, what the default constructor assigns, the
    statements that read and write it, and its ``ToString`` text."""

    name: str
    cs_type: str
    init: str
    read: str
    writes: tuple[str, ...]
    text: str
    doc: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class MessageView(MessageClassView):
    """A message, service half or action part: public fields, as the connector generates."""

    template: ClassVar[str] = "rostcp/Message.cs.jinja"
    header: Header
    register: str
    fields: tuple[FieldView, ...]
    #: ROS 2 only, for a message without fields: CDR writes one zero byte for it.
    placeholder_byte: bool
    runtime: str = RUNTIME


@dataclass(frozen=True, slots=True)
class WrapperView:
    """``XActionGoal``/``XActionResult``/``XActionFeedback`` on the connector's generic bases,
    which hold ``header`` and ``goal_id`` or ``status``."""

    template: ClassVar[str] = "rostcp/ActionWrapper.cs.jinja"
    header: Header
    class_name: str
    base: str
    ros_name: str
    inherited: tuple[tuple[str, str], ...]
    part_name: str
    part_class: str
    runtime: str = RUNTIME


@dataclass(frozen=True, slots=True)
class ActionView:
    """``XAction``: the three wrappers, on the connector's ``Action<…>`` base."""

    template: ClassVar[str] = "rostcp/Action.cs.jinja"
    header: Header
    class_name: str
    base: str
    ros_name: str
    parts: tuple[tuple[str, str], ...]
    runtime: str = RUNTIME


View = MessageView | WrapperView | ActionView
