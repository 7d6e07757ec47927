"""The ROS 2 dialect: ``.msg``, ``.srv`` and ``.action`` files exactly as rosidl_adapter reads them.

Where it differs from ROS 1: tabs are spaces; a comment starts at the first ``#`` anywhere; a
line splits at its first space into type and the rest; the rest is ``NAME=VALUE`` (constant)
or ``name [default]``; strings may be bounded (``string<=N``) and arrays bounded (``T[<=N]``);
constant and default string values lose one pair of outer quotes; names follow stricter
patterns; there is no ``Header`` shorthand; service and action separators are exact ``---`` lines.
"""

from __future__ import annotations

import itertools
import re

from unityscaffold.errors import DiagnosticSink, LocatedError, SourceLocation
from unityscaffold.interfaces._comments import CommentTracker, clean_block
from unityscaffold.interfaces.model import (
    MAX_SIZE,
    ROS2_PRIMITIVES,
    ActionSpec,
    ArrayKind,
    Constant,
    Dialect,
    Field,
    MessageSpec,
    Scalar,
    ServiceSpec,
    TypeRef,
    Value,
)
from unityscaffold.interfaces.suffixes import (
    ROS2_ACTION_PARTS,
    ROS2_EVENT,
    ROS2_FEEDBACK,
    ROS2_FEEDBACK_MESSAGE,
    ROS2_GET_RESULT,
    ROS2_GOAL,
    ROS2_REQUEST,
    ROS2_RESPONSE,
    ROS2_RESULT,
    ROS2_SEND_GOAL,
)

__all__ = ["parse_action", "parse_message", "parse_service"]

# rosidl accepts these "for compatibility" although no ROS 2 tool can generate code for them.
_COMPAT_PRIMITIVES = ("time", "duration")
_PACKAGE_OR_FIELD = re.compile(r"^(?!.*__)(?!.*_$)[a-z][a-z0-9_]*$")
_MESSAGE_NAME = re.compile(r"^[A-Z][A-Za-z0-9]*$")
# rosidl's pattern is ^[A-Z]([A-Z0-9_]?[A-Z0-9]+)*$, which backtracks exponentially on a long
# name that fails at its end; this one accepts the same names in linear time.
_CONSTANT_NAME = re.compile(r"\A[A-Z](?:_?[A-Z0-9])*\Z")
_FIELD_PATTERN_TEXT = "lower case letters, digits and single '_' (not at the end)"


class _Problem(Exception):
    """A bad token: ``col`` is its 1-based column in the line."""

    def __init__(self, col: int, message: str, expected: str | None = None) -> None:
        super().__init__(message)
        self.col, self.message, self.expected = col, message, expected


# --- types ----------------------------------------------------------------------------------


def _array_part(token: str, col: int) -> tuple[str, ArrayKind, int | None]:
    if not token.endswith("]"):
        return token, ArrayKind.NONE, None
    open_at = token.rfind("[")
    if open_at < 0:
        raise _Problem(col, f"'{token}' ends with ']' but has no '['")
    inside, base = token[open_at + 1 : -1], token[:open_at]
    if inside == "":
        return base, ArrayKind.UNBOUNDED, None
    bounded = inside.startswith("<=")
    size = _positive(inside[2:] if bounded else inside)
    if size is None:
        raise _Problem(
            col + open_at + 1,
            f"invalid array size '{inside}' in '{token}'",
            expected=f"an integer from 1 to {MAX_SIZE}, optionally prefixed with '<='",
        )
    return base, ArrayKind.BOUNDED if bounded else ArrayKind.FIXED, size


def _positive(text: str) -> int | None:
    """A size or bound as rosidl reads it (Python's ``int()``, so ``+5`` and ``5_0`` too), or
    None when it is not an integer from 1 to MAX_SIZE (which C# can index; rosidl has no upper
    limit)."""
    try:
        number = int(text)
    except ValueError:  # also past Python's limit on digits, as in rosidl
        return None
    return number if 0 < number <= MAX_SIZE else None


def _type_ref(token: str, package: str, col: int) -> TypeRef:
    base, array, size = _array_part(token, col)
    if base in ROS2_PRIMITIVES or base in _COMPAT_PRIMITIVES:
        return TypeRef(base, array, size)
    for string_type in ("string", "wstring"):
        if base.startswith(string_type + "<="):
            bound = _positive(base[len(string_type) + 2 :])
            if bound is None:
                raise _Problem(
                    col + len(string_type) + 2,
                    f"invalid string bound in '{base}'",
                    expected=f"{string_type}<=N with N an integer from 1 to {MAX_SIZE}",
                )
            return TypeRef(string_type, array, size, string_bound=bound)
    parts = base.split("/")
    if len(parts) > 2 or not parts[-1]:
        raise _Problem(col, f"'{base}' is not a valid type name", expected="Name or pkg/Name")
    pkg, name = (parts[0], parts[1]) if len(parts) == 2 else (package, parts[0])
    if not _PACKAGE_OR_FIELD.match(pkg):
        raise _Problem(col, f"'{pkg}' is not a valid package name", expected=_FIELD_PATTERN_TEXT)
    if not _MESSAGE_NAME.match(name):
        raise _Problem(
            col + len(base) - len(name),
            f"'{name}' is not a valid message name",
            expected="an upper case letter followed by letters and digits",
        )
    return TypeRef(f"{pkg}/msg/{name}", array, size)


# --- values ---------------------------------------------------------------------------------


def _int_range(type_name: str) -> tuple[int, int]:
    if type_name in ("byte", "char"):
        return 0, 255
    unsigned = type_name.startswith("u")
    bits = int(type_name[4 if unsigned else 3 :])
    return (0, 2**bits - 1) if unsigned else (-(2 ** (bits - 1)), 2 ** (bits - 1) - 1)


def _unquote(text: str) -> str:
    for quote in ('"', "'"):
        # As in rosidl, a lone quote is both the opening and the closing one: the empty string.
        if text.startswith(quote) and text.endswith(quote):
            inner = text[1:-1]
            if re.search(rf"(?<!\\){quote}", inner):
                raise ValueError("inner quotes must be escaped with '\\'")
            return inner.replace("\\" + quote, quote)
    return text


def primitive_value(ref: TypeRef, text: str) -> Scalar:
    """Convert one value as rosidl_adapter does; raises ValueError with the expected form."""
    kind = ref.base
    if kind == "bool":
        if text.lower() not in ("true", "false", "1", "0"):
            raise ValueError("expected true, false, 1 or 0")
        return text.lower() in ("true", "1")
    if kind in ("float32", "float64"):
        try:
            return float(text)
        except ValueError:
            raise ValueError("expected a floating point number using '.'") from None
    if kind in ("string", "wstring"):
        value = _unquote(text)
        if ref.string_bound is not None and len(value) > ref.string_bound:
            raise ValueError(f"longer than the bound of {ref.string_bound} characters")
        return value
    low, high = _int_range(kind)
    try:
        number = int(text)
    except ValueError:
        try:
            number = int(text, 0)
        except ValueError:
            raise ValueError(f"expected an integer in {low}..{high}") from None
    if not low <= number <= high:
        raise ValueError(f"{number} is out of range {low}..{high}")
    return number


def _string_elements(text: str) -> list[str]:
    """Split the inside of a string array default, honouring quotes (rosidl's walk)."""
    items: list[str] = []
    rest = text
    while rest.strip():
        rest = rest.lstrip(" ")
        if rest.startswith(","):
            raise ValueError("unexpected ',' in the array")
        quote = rest[0] if rest[0] in "\"'" else None
        if quote:
            end = 1
            while True:
                end = rest.find(quote, end)
                if end < 0:
                    raise ValueError("a quoted element is not closed")
                if rest[end - 1] != "\\":
                    break
                end += 1
            items.append(rest[1:end].replace("\\" + quote, quote))
            rest = rest[end + 1 :]
        else:
            comma = rest.find(",")
            items.append(rest if comma < 0 else rest[:comma])
            rest = "" if comma < 0 else rest[comma:]
        rest = rest.lstrip(" ")
        if rest.startswith(","):
            rest = rest[1:]
    return items


def default_value(ref: TypeRef, text: str) -> Value:
    """Parse a field's default value text; raises ValueError."""
    if ref.is_message:
        raise ValueError("fields of message types cannot have default values")
    if not ref.is_array:
        return primitive_value(ref, text)
    if not (text.startswith("[") and text.endswith("]")):
        raise ValueError("an array default must start with '[' and end with ']'")
    inside = text[1:-1]
    if ref.base in ("string", "wstring"):
        items = _string_elements(inside)
    else:
        items = inside.split(",") if inside else []
    if ref.array is ArrayKind.FIXED and len(items) != ref.size:
        raise ValueError(f"the array needs exactly {ref.size} elements, not {len(items)}")
    if ref.array is ArrayKind.BOUNDED and len(items) > (ref.size or 0):
        raise ValueError(f"the array allows at most {ref.size} elements, not {len(items)}")
    return tuple(primitive_value(ref.element, item.strip()) for item in items)


# --- lines ----------------------------------------------------------------------------------


def _declaration(code: str, package: str) -> Field | Constant:
    """One declaration line (comment removed, right-stripped); raises _Problem."""
    if code[:1] == " ":
        raise _Problem(
            1,
            "a declaration must start at the beginning of the line",
            expected="'TYPE NAME' without leading whitespace",
        )
    type_text, _, rest = code.partition(" ")
    rest_col = len(type_text) + 2 + (len(rest) - len(rest.lstrip()))
    rest = rest.lstrip()
    if not rest:
        raise _Problem(
            len(code) + 1,
            f"'{type_text}' is not followed by a name",
            expected="'TYPE NAME', 'TYPE NAME DEFAULT' or 'TYPE NAME=VALUE'",
        )
    if "=" in rest:
        return _constant(type_text, rest, rest_col)
    name, _, default_text = rest.partition(" ")
    default_text = default_text.lstrip()
    ref = _type_ref(type_text, package, 1)
    if not _PACKAGE_OR_FIELD.match(name):
        raise _Problem(
            rest_col, f"'{name}' is not a valid field name", expected=_FIELD_PATTERN_TEXT
        )
    default = None
    if default_text:
        try:
            default = default_value(ref, default_text)
        except ValueError as exc:
            raise _Problem(
                code.rfind(default_text) + 1,
                f"invalid default value '{default_text}' for {ref}: {exc}",
            ) from None
    return Field(ref, name, default=default, type_text=type_text)


def _constant(type_text: str, rest: str, rest_col: int) -> Constant:
    name, _, value_text = rest.partition("=")
    name, value_text = name.rstrip(), value_text.lstrip()
    if type_text not in ROS2_PRIMITIVES and type_text not in _COMPAT_PRIMITIVES:
        raise _Problem(
            1,
            f"constants must have a primitive type, not '{type_text}'",
            expected="one of " + ", ".join(ROS2_PRIMITIVES),
        )
    if not _CONSTANT_NAME.match(name):
        raise _Problem(
            rest_col,
            f"'{name}' is not a valid constant name",
            expected="upper case letters, digits and single '_'",
        )
    try:
        value = primitive_value(TypeRef(type_text), value_text)
    except ValueError as exc:
        raise _Problem(
            rest_col + len(rest) - len(value_text),
            f"invalid {type_text} constant value '{value_text}': {exc}",
        ) from None
    return Constant(type_text, name, value, value_text)


def _finish_field(item: Field, docs: list[str], where: SourceLocation) -> Field:
    return Field(item.type, item.name, item.default, item.type_text, clean_block(docs), where)


def _finish_constant(item: Constant, docs: list[str], where: SourceLocation) -> Constant:
    return Constant(item.type, item.name, item.value, item.text, clean_block(docs), where)


def _duplicates(
    items: list[tuple[Field | Constant, list[str], SourceLocation]],
    raw: dict[int, str],
    out: DiagnosticSink,
) -> None:
    seen: set[tuple[type, str]] = set()
    for item, _, where in items:
        key = (type(item), item.name)
        if key in seen:
            kind = "field" if isinstance(item, Field) else "constant"
            at = SourceLocation(where.path, where.line, 1, raw.get(where.line))
            out.error(at, f"duplicate {kind} name '{item.name}'")
        seen.add(key)


def _message(
    lines: list[tuple[int, str]],
    text: str,
    package: str,
    name: str,
    path: str,
    out: DiagnosticSink,
    *,
    subfolder: str = "msg",
    owner: str | None = None,
) -> MessageSpec:
    docs = CommentTracker()
    items: list[tuple[Field | Constant, list[str], SourceLocation]] = []
    for number, raw in lines:
        line = raw.replace("\t", " ").rstrip()
        code, hash_sign, _ = line.partition("#")
        if not line:
            docs.blank_line()
        elif hash_sign and not code.strip():
            docs.comment_line(line, line[len(code) :])
        else:
            try:
                item = _declaration(code.rstrip(), package)
            except _Problem as bad:
                where = SourceLocation(path, number, bad.col, raw)
                out.error(where, bad.message, expected=bad.expected)
                continue
            comment = line[len(code) :] if hash_sign else None
            items.append((item, docs.declaration(comment), SourceLocation(path, number, 1)))
    _duplicates(items, dict(lines), out)
    fields = tuple(_finish_field(f, c, w) for f, c, w in items if isinstance(f, Field))
    constants = tuple(_finish_constant(k, c, w) for k, c, w in items if isinstance(k, Constant))
    return MessageSpec(
        package,
        name,
        Dialect.ROS2,
        fields,
        constants,
        text,
        docs.message_doc,
        path,
        subfolder,
        owner,
    )


def _numbered(text: str) -> list[tuple[int, str]]:
    return [(i + 1, line) for i, line in enumerate(text.splitlines())]


def parse_message(text: str, package: str, name: str, path: str = "<string>") -> MessageSpec:
    """Parse a ROS 2 ``.msg`` text; raises ``LocatedError`` listing every bad line."""
    out = DiagnosticSink()
    spec = _message(_numbered(text), text, package, name, path, out)
    out.raise_if_errors()
    return spec


def _sections(
    text: str, count: int, path: str, what: str, expected: str
) -> list[list[tuple[int, str]]]:
    lines = _numbered(text)
    cuts = [i for i, (_, line) in enumerate(lines) if line == "---"]
    if len(cuts) != count - 1:
        at = lines[cuts[count - 1]][0] if len(cuts) >= count else max(1, len(lines))
        raise LocatedError.at(
            SourceLocation(path, at, 1),
            f"{what} needs exactly {count - 1} separator line(s) '---', found {len(cuts)}",
            expected=expected,
            hint="in ROS 2 the separator is a line holding exactly '---'",
        )
    bounds = [-1, *cuts, len(lines)]
    return [lines[a + 1 : b] for a, b in itertools.pairwise(bounds)]


def _derived(package: str, name: str, fields: tuple[Field, ...], owner: str) -> MessageSpec:
    return MessageSpec(package, name, Dialect.ROS2, fields, subfolder="action", owner=owner)


def _derived_service(
    package: str, name: str, request: tuple[Field, ...], response: tuple[Field, ...], owner: str
) -> ServiceSpec:
    """A service rosidl derives for an action (no file of its own), such as ``_SendGoal``."""
    return _with_event(
        ServiceSpec(
            package,
            name,
            Dialect.ROS2,
            _derived(package, name + ROS2_REQUEST, request, owner),
            _derived(package, name + ROS2_RESPONSE, response, owner),
            subfolder="action",
            owner=owner,
        )
    )


def _with_event(service: ServiceSpec) -> ServiceSpec:
    """Add the ``_Event`` message that rosidl derives for every service since Iron."""
    prefix = f"{service.package}/{service.subfolder}/{service.name}"
    event = MessageSpec(
        service.package,
        service.name + ROS2_EVENT,
        Dialect.ROS2,
        fields=(
            Field(TypeRef("service_msgs/msg/ServiceEventInfo"), "info"),
            Field(TypeRef(prefix + ROS2_REQUEST, ArrayKind.BOUNDED, 1), "request"),
            Field(TypeRef(prefix + ROS2_RESPONSE, ArrayKind.BOUNDED, 1), "response"),
        ),
        source=service.source,
        subfolder=service.subfolder,
        owner=service.full_name,
    )
    return ServiceSpec(
        service.package,
        service.name,
        service.dialect,
        service.request,
        service.response,
        service.text,
        service.source,
        event,
        service.subfolder,
        service.owner,
    )


def parse_service(text: str, package: str, name: str, path: str = "<string>") -> ServiceSpec:
    """Parse a ROS 2 ``.srv`` text into ``<Name>_Request``, ``_Response`` and ``_Event``."""
    request_lines, response_lines = _sections(text, 2, path, "a service", "REQUEST\n---\nRESPONSE")
    owner = f"{package}/srv/{name}"
    out = DiagnosticSink()
    request, response = (
        _message(
            lines,
            "\n".join(line for _, line in lines),
            package,
            name + suffix,
            path,
            out,
            subfolder="srv",
            owner=owner,
        )
        for lines, suffix in ((request_lines, ROS2_REQUEST), (response_lines, ROS2_RESPONSE))
    )
    out.raise_if_errors()
    return _with_event(ServiceSpec(package, name, Dialect.ROS2, request, response, text, path))


def parse_action(text: str, package: str, name: str, path: str = "<string>") -> ActionSpec:
    """Parse a ROS 2 ``.action`` text and derive rosidl's messages and services."""
    sections = _sections(text, 3, path, "an action", "GOAL\n---\nRESULT\n---\nFEEDBACK")
    owner = f"{package}/action/{name}"
    out = DiagnosticSink()
    goal, result, feedback = (
        _message(
            lines,
            "\n".join(line for _, line in lines),
            package,
            name + suffix,
            path,
            out,
            subfolder="action",
            owner=owner,
        )
        for lines, suffix in zip(sections, ROS2_ACTION_PARTS, strict=True)
    )
    out.raise_if_errors()
    prefix = f"{package}/action/{name}"
    goal_id = Field(TypeRef("unique_identifier_msgs/msg/UUID"), "goal_id")
    send_goal = _derived_service(
        package,
        name + ROS2_SEND_GOAL,
        (goal_id, Field(TypeRef(prefix + ROS2_GOAL), "goal")),
        (
            Field(TypeRef("bool"), "accepted"),
            Field(TypeRef("builtin_interfaces/msg/Time"), "stamp"),
        ),
        owner,
    )
    get_result = _derived_service(
        package,
        name + ROS2_GET_RESULT,
        (goal_id,),
        (Field(TypeRef("int8"), "status"), Field(TypeRef(prefix + ROS2_RESULT), "result")),
        owner,
    )
    feedback_message = _derived(
        package,
        name + ROS2_FEEDBACK_MESSAGE,
        (goal_id, Field(TypeRef(prefix + ROS2_FEEDBACK), "feedback")),
        owner,
    )
    return ActionSpec(
        package,
        name,
        Dialect.ROS2,
        goal,
        result,
        feedback,
        text=text,
        source=path,
        derived=(feedback_message,),
        services=(send_goal, get_result),
    )
