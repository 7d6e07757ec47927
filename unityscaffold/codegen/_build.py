"""Build the view of one generated class from the interface model (no text, no I/O)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from unityscaffold.codegen import _literals
from unityscaffold.codegen._references import KnownClasses, References
from unityscaffold.codegen._types import ROS1_TIME_TYPES, primitive_type
from unityscaffold.codegen._views import (
    ConstantView,
    FileHeader,
    MemberView,
    MessageView,
    SizeCheck,
    doc_lines,
)
from unityscaffold.codegen.naming import CsClass, escape_identifier
from unityscaffold.errors import LocatedError, SourceLocation, UserError, located_at
from unityscaffold.interfaces.model import ArrayKind, Constant, Dialect, Field, MessageSpec, TypeRef

__all__ = ["INLINE_ELEMENTS", "FileContext", "build_message", "initial_value"]

INLINE_ELEMENTS = 64
"""A fixed array of messages or strings up to this size is initialised element by element
(``new T[] { new T(), … }``); a larger one with ``Array.ConvertAll``, so that the generated
text does not grow with the size."""


@dataclass(frozen=True, slots=True)
class FileContext:
    """What every file of one ``generate`` call shares."""

    dialect: Dialect
    known: KnownClasses
    message_base: CsClass
    qualify_runtime: bool
    class_of: Callable[[str, SourceLocation | None], CsClass]
    time_class: Callable[[str], CsClass]

    @property
    def define(self) -> str:
        return "ROS2" if self.dialect is Dialect.ROS2 else "!ROS2"


def _where(spec: MessageSpec, field: Field | None = None) -> SourceLocation:
    if field is not None and field.location is not None:
        return field.location
    return SourceLocation(spec.source or spec.full_name)


def _element_class(
    ctx: FileContext, ref: TypeRef, spec: MessageSpec, field: Field
) -> CsClass | None:
    if ref.is_message:
        return ctx.class_of(ref.base, _where(spec, field))
    if ctx.dialect is Dialect.ROS1 and ref.base in ROS1_TIME_TYPES:
        return ctx.time_class(ref.base)
    return None


def initial_value(ref: TypeRef, element: str, primitive: str | None, default: object) -> str:
    """The expression the default constructor assigns (both runtimes' classes): ``default``, or
    a zero, an empty string, a new message, and for an array its elements or none."""
    if default is not None:
        assert primitive is not None
        if isinstance(default, tuple):
            return _literals.array_literal(default, primitive)
        return _literals.literal(default, primitive)  # type: ignore[arg-type]
    if primitive is None:
        single = f"new {element}()"
    elif primitive == "string":
        single = '""'
    else:
        single = _literals.zero_literal(primitive)
    if ref.array is ArrayKind.NONE:
        return single
    if ref.array is ArrayKind.FIXED and ref.size:
        if primitive is not None and primitive != "string":
            return f"new {element}[{ref.size}]"
        if ref.size <= INLINE_ELEMENTS:
            return f"new {element}[] {{ {', '.join([single] * ref.size)} }}"
        # Larger arrays get an expression of constant length instead of N copies of it.
        return f"global::System.Array.ConvertAll(new {element}[{ref.size}], _ => {single})"
    return f"new {element}[0]"


def _check(ref: TypeRef, name: str, field_name: str) -> SizeCheck | None:
    if ref.array is ArrayKind.FIXED:
        condition = f"value != null && value.Length != {ref.size}"
        text = f"{field_name} must have exactly {ref.size} elements, not "
    elif ref.array is ArrayKind.BOUNDED:
        condition = f"value != null && value.Length > {ref.size}"
        text = f"{field_name} must have at most {ref.size} elements, not "
    else:
        return None
    backing = "_" + name.lstrip("@")
    return SizeCheck(backing, condition, f"{_literals.string_literal(text)} + value.Length")


def _member(
    ctx: FileContext,
    refs: References,
    spec: MessageSpec,
    field: Field,
    cls: CsClass | None,
    name: str,
    previous: MemberView | None,
) -> MemberView:
    """``field`` as member ``name``; ``cls`` is its element's class (None for a primitive)."""
    ref = field.type
    primitive = primitive_type(ref.base, ctx.dialect)
    element = (
        primitive
        if cls is None
        else refs.name(cls, qualified=ctx.qualify_runtime and ref.base in ROS1_TIME_TYPES)
    )
    assert element is not None
    cs_type = element + ("[]" if ref.is_array else "")
    try:
        init = initial_value(ref, element, primitive, field.default)
    except ValueError as exc:
        message = f"default value of '{field.name}': {exc}"
        raise LocatedError.at(_where(spec, field), message) from None
    doc = doc_lines(field.comment)
    check = _check(ref, name, field.name)
    # A member with a comment or a checked setter stands apart from its neighbours.
    spaced = previous is not None and bool(
        doc or check or previous.doc or previous.check is not None
    )
    return MemberView(name, cs_type, init, doc, check, spaced)


def _constant(
    ctx: FileContext,
    spec: MessageSpec,
    constant: Constant,
    name: str,
    previous: ConstantView | None,
) -> ConstantView:
    where = constant.location or _where(spec)
    cs_type, value = _literals.constant_value(constant, ctx.dialect, where)
    doc = doc_lines(constant.comment)
    spaced = previous is not None and bool(doc or previous.doc)  # a comment stands apart
    return ConstantView(name, cs_type, value, doc, spaced)


# Members of System.Object, which every message class inherits: a field or constant of the same
# name would hide one (CS0108, CS0114).
_INHERITED = (
    "Equals",
    "Finalize",
    "GetHashCode",
    "GetType",
    "MemberwiseClone",
    "ReferenceEquals",
    "ToString",
)


_INHERITED_NAMES = {name: f"the inherited member {name}()" for name in _INHERITED}


def _check_names(spec: MessageSpec, class_name: str) -> dict[str, str]:
    """Each field's and constant's C# identifier, by name; a LocatedError for one that has
    none or clashes."""
    identifiers: dict[str, str] = {}
    seen = {
        "RosMessageName": "the RosMessageName constant",
        class_name: "the class",
        **_INHERITED_NAMES,
    }
    items: list[Constant | Field] = [*spec.constants, *spec.fields]
    for item in items:
        try:
            identifiers[item.name] = escape_identifier(item.name)
        except UserError:
            # placed only when it fails: a context manager per field is a cost every class pays
            with located_at(item.location or _where(spec)):
                raise
        if item.name in seen:
            raise LocatedError.at(
                item.location or _where(spec),
                f"'{item.name}' has the same C# name as {seen[item.name]} of class {class_name}",
                hint="C# allows one member per name, none named like its class, "
                "and none named like a member every class inherits; rename the field",
            )
        seen[item.name] = f"member '{item.name}'"
    return identifiers


def _references(
    ctx: FileContext, spec: MessageSpec, elements: list[CsClass | None]
) -> list[tuple[CsClass, bool]]:
    """The classes ``spec``'s file names, given each field's element class (or None)."""
    wanted = [(ctx.message_base, ctx.qualify_runtime)]
    for field, cls in zip(spec.fields, elements, strict=True):
        if cls is not None:
            wanted.append((cls, ctx.qualify_runtime and field.type.base in ROS1_TIME_TYPES))
    return wanted


def build_message(
    ctx: FileContext, spec: MessageSpec, cls: CsClass, ros_name: str, source: str, identity: str
) -> MessageView:
    """The view of a message (or service half) ``spec`` as class ``cls``."""
    identifiers = _check_names(spec, cls.name)
    elements = [_element_class(ctx, f.type, spec, f) for f in spec.fields]
    refs = References(cls.namespace, ctx.known, _references(ctx, spec, elements))
    members: list[MemberView] = []
    for field, element in zip(spec.fields, elements, strict=True):
        previous = members[-1] if members else None
        name = identifiers[field.name]
        members.append(_member(ctx, refs, spec, field, element, name, previous))
    constants: list[ConstantView] = []
    for constant in spec.constants:
        before = constants[-1] if constants else None
        name = identifiers[constant.name]
        constants.append(_constant(ctx, spec, constant, name, before))
    header = FileHeader(source, identity, ctx.define, cls.namespace, refs.usings)
    return MessageView(
        header=header,
        class_name=cls.name,
        base=refs.name(ctx.message_base, qualified=ctx.qualify_runtime),
        ros_name=_literals.string_literal(ros_name),
        doc=doc_lines(spec.comment),
        constants=tuple(constants),
        members=tuple(members),
        parameters=", ".join(f"{m.cs_type} {m.name}" for m in members),
    )
