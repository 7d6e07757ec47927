"""Build the view of one connector message class from the interface model (no text, no I/O).

Fields are read and written with the connector's own ``MessageSerializer`` and
``MessageDeserializer`` calls. Where its generator falls short, ours does not: a fixed array of
strings or messages starts with N real elements (its ``new T[N]`` holds nulls, and serializing a
default instance throws), ROS 2 defaults are assigned, constants are escaped C# literals, and a
ROS 2 message without fields is written as the one byte CDR requires (its classes write none).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from unityscaffold.codegen import _literals
from unityscaffold.codegen._build import initial_value
from unityscaffold.codegen._types import primitive_type
from unityscaffold.codegen._views import ConstantView, doc_lines
from unityscaffold.codegen.naming import CsClass, escape_identifier
from unityscaffold.codegen.rostcp._views import FieldView, Header, MessageView
from unityscaffold.errors import LocatedError, SourceLocation, UserError, located_at
from unityscaffold.interfaces.model import ArrayKind, Constant, Dialect, Field, MessageSpec

__all__ = ["MessageContext", "build_message"]

#: Members every connector message has or inherits: a field or constant of the same name would
#: hide or clash with one (CS0102, CS0108, CS0114).
RESERVED_MEMBERS = (
    "Deserialize",
    "DeserializeLength",
    "DeserializeString",
    "Equals",
    "Finalize",
    "GetHashCode",
    "GetType",
    "MemberwiseClone",
    "ReferenceEquals",
    "Register",
    "RosMessageName",
    "Serialize",
    "SerializationStatements",
    "SerializeString",
    "SerializeTo",
    "ToString",
    "k_RosMessageName",
)


@dataclass(frozen=True, slots=True)
class MessageContext:
    """What every message of one ``generate`` call shares: the ROS version and how a field's
    message type (or ROS 1 ``time``/``duration``) becomes a class."""

    dialect: Dialect
    class_of: Callable[[str, SourceLocation | None], CsClass]

    @property
    def define(self) -> str:
        return "ROS2" if self.dialect is Dialect.ROS2 else "!ROS2"


def _where(spec: MessageSpec, item: Field | Constant | None = None) -> SourceLocation:
    if item is not None and item.location is not None:
        return item.location
    return SourceLocation(spec.source or spec.full_name)


def _count(field: Field) -> str:
    if field.type.array is ArrayKind.FIXED:
        return str(field.type.size)
    return "deserializer.ReadLength()"


def _read(field: Field, name: str, element: str, primitive: str | None) -> str:
    target = f"this.{name}"
    if not field.type.is_array:
        if primitive is None:
            return f"{target} = {element}.Deserialize(deserializer);"
        return f"deserializer.Read(out {target});"
    count = _count(field)
    if primitive is None:
        return f"deserializer.Read(out {target}, {element}.Deserialize, {count});"
    if primitive == "string":
        return f"deserializer.Read(out {target}, {count});"
    return f"deserializer.Read(out {target}, sizeof({primitive}), {count});"


def _writes(field: Field, name: str) -> tuple[str, ...]:
    write = f"serializer.Write(this.{name});"
    if field.type.is_array and field.type.array is not ArrayKind.FIXED:
        return (f"serializer.WriteLength(this.{name});", write)
    return (write,)


def _field(ctx: MessageContext, spec: MessageSpec, field: Field, name: str) -> FieldView:
    ref = field.type
    if ref.base == "wstring":
        raise LocatedError.at(
            _where(spec, field),
            f"field '{field.name}' is a wstring, which ROS-TCP-Connector cannot send or receive",
            hint="its serializer knows UTF-8 strings only; use string",
        )
    primitive = primitive_type(ref.base, ctx.dialect)
    element = primitive or ctx.class_of(ref.base, _where(spec, field)).qualified
    try:
        init = initial_value(field.type, element, primitive, field.default)
    except ValueError as exc:
        message = f"default value of '{field.name}': {exc}"
        raise LocatedError.at(_where(spec, field), message) from None
    label = _literals.string_literal(f"\n{field.name}: ")
    # Join<T> named: for an array of messages Join(string, params object[]) would also fit.
    join = f'global::System.String.Join<{element}>(", ", this.{name})'
    value = join if ref.is_array else f"this.{name}"
    return FieldView(
        name=name,
        cs_type=element + ("[]" if ref.is_array else ""),
        init=init,
        read=_read(field, name, element, primitive),
        writes=_writes(field, name),
        text=f"{label} + {value}",
        doc=doc_lines(field.comment),
    )


def _constant(
    ctx: MessageContext, spec: MessageSpec, constant: Constant, name: str, spaced: bool
) -> ConstantView:
    cs_type, value = _literals.constant_value(constant, ctx.dialect, _where(spec, constant))
    doc = doc_lines(constant.comment)
    return ConstantView(name, cs_type, value, doc, spaced and bool(doc))


def _identifiers(spec: MessageSpec, class_name: str) -> dict[str, str]:
    """Each field's and constant's C# identifier; a LocatedError for one that clashes."""
    identifiers: dict[str, str] = {}
    seen = {name: f"the member {name} every connector message has" for name in RESERVED_MEMBERS}
    seen[class_name] = "the class"
    items: list[Constant | Field] = [*spec.constants, *spec.fields]
    for item in items:
        try:
            identifiers[item.name] = escape_identifier(item.name)
        except UserError:
            with located_at(_where(spec, item)):
                raise
        if item.name in seen:
            raise LocatedError.at(
                _where(spec, item),
                f"'{item.name}' has the same C# name as {seen[item.name]} ({class_name})",
                hint="C# allows one member per name and none named like its class; "
                "rename the field",
            )
        seen[item.name] = f"member '{item.name}'"
    return identifiers


def build_message(
    ctx: MessageContext,
    spec: MessageSpec,
    cls: CsClass,
    ros_name: str,
    register: str,
    provenance: tuple[str, str],
) -> MessageView:
    """The view of ``spec`` as class ``cls``, registered as ``ros_name`` (``register`` is the
    text after ``Deserialize`` in ``Register``: empty or ``, …MessageSubtopic.Response``)."""
    names = _identifiers(spec, cls.name)
    fields = tuple(_field(ctx, spec, f, names[f.name]) for f in spec.fields)
    constants = tuple(
        _constant(ctx, spec, c, names[c.name], index > 0) for index, c in enumerate(spec.constants)
    )
    source, identity = provenance
    return MessageView(
        header=Header(source, identity, ctx.define, cls.namespace),
        class_name=cls.name,
        ros_name=_literals.string_literal(ros_name),
        register=register,
        doc=doc_lines(spec.comment),
        constants=constants,
        fields=fields,
        parameters=", ".join(f"{f.cs_type} {f.name}" for f in fields),
        placeholder_byte=ctx.dialect is Dialect.ROS2 and not spec.fields,
    )
