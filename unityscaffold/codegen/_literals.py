"""C# literals for ROS constants and default values.

Each literal has the C# type of the member it initialises: ``f`` for float32, ``.0`` or an
exponent for float64, ``L``/``UL`` for 64-bit integers, ``float.NaN``/``double.PositiveInfinity``
for non-finite values, and strings with every character outside printable ASCII escaped.
"""

from __future__ import annotations

import math
import re
import struct
from collections.abc import Sequence

from unityscaffold.codegen._types import primitive_type
from unityscaffold.errors import LocatedError, SourceLocation
from unityscaffold.interfaces.model import Constant, Dialect, Scalar

__all__ = ["array_literal", "constant_value", "literal", "string_literal", "zero_literal"]

_INT_RANGES = {
    "sbyte": (-(2**7), 2**7 - 1),
    "byte": (0, 2**8 - 1),
    "short": (-(2**15), 2**15 - 1),
    "ushort": (0, 2**16 - 1),
    "int": (-(2**31), 2**31 - 1),
    "uint": (0, 2**32 - 1),
    "long": (-(2**63), 2**63 - 1),
    "ulong": (0, 2**64 - 1),
}
_INT_SUFFIXES = {"long": "L", "ulong": "UL", "uint": "U"}
_ESCAPES = {
    "\\": "\\\\",
    '"': '\\"',
    "\0": "\\0",
    "\a": "\\a",
    "\b": "\\b",
    "\f": "\\f",
    "\n": "\\n",
    "\r": "\\r",
    "\t": "\\t",
    "\v": "\\v",
}


# Printable ASCII but the quote and the backslash: such text is its own literal, and most is.
_PLAIN_TEXT = re.compile(r"[ !#-\[\]-~]*")


def string_literal(text: str) -> str:
    """A regular C# string literal; non-ASCII characters become ``\\uXXXX`` (UTF-16 units)."""
    if _PLAIN_TEXT.fullmatch(text):
        return f'"{text}"'
    out = []
    for char in text:
        if char in _ESCAPES:
            out.append(_ESCAPES[char])
        elif " " <= char <= "~":
            out.append(char)
        else:
            data = char.encode("utf-16-be")
            out += [f"\\u{data[i] << 8 | data[i + 1]:04X}" for i in range(0, len(data), 2)]
    return '"' + "".join(out) + '"'


def _fits_float32(value: float) -> bool:
    try:
        return not math.isinf(struct.unpack("<f", struct.pack("<f", value))[0])
    except OverflowError:
        return False


def _float_literal(value: float, cs_type: str) -> str:
    if math.isnan(value):
        return f"{cs_type}.NaN"
    if math.isinf(value):
        return f"{cs_type}.{'Positive' if value > 0 else 'Negative'}Infinity"
    text = repr(float(value))
    if cs_type == "float":
        if not _fits_float32(value):
            # C# refuses a float literal that rounds to infinity (CS0594).
            raise ValueError(f"{text} does not fit in a C# float (at most 3.4028235e+38)")
        return text + "f"
    return text if ("." in text or "e" in text) else text + ".0"


def _int_literal(value: int, cs_type: str) -> str:
    low, high = _INT_RANGES[cs_type]
    if not low <= value <= high:
        raise ValueError(f"{value} does not fit in a C# {cs_type} ({low}..{high})")
    return f"{value}{_INT_SUFFIXES.get(cs_type, '')}"


def literal(value: Scalar, cs_type: str) -> str:
    """The C# literal of ``value`` as a ``cs_type`` (a C# built-in type keyword)."""
    if cs_type == "bool":
        return "true" if value else "false"
    if cs_type == "string":
        return string_literal(str(value))
    if cs_type in ("float", "double"):
        return _float_literal(float(value), cs_type)
    if cs_type in _INT_RANGES:
        if isinstance(value, bool):
            value = int(value)
        if isinstance(value, float):
            if not value.is_integer():
                raise ValueError(f"{value} is not an integer")
            value = int(value)
        if isinstance(value, str):
            value = int(value, 0)
        return _int_literal(value, cs_type)
    raise ValueError(f"no C# literal for type {cs_type}")


_ZEROS = {cs_type: literal(0, cs_type) for cs_type in ("bool", "float", "double", *_INT_RANGES)}


def zero_literal(cs_type: str) -> str:
    """``literal(0, cs_type)``, looked up: every numeric member's constructor assigns one."""
    found = _ZEROS.get(cs_type)
    return found if found is not None else literal(0, cs_type)


def array_literal(values: Sequence[Scalar], cs_type: str) -> str:
    """``new T[] { a, b }`` (``new T[0]`` when empty) for an array default value."""
    if not values:
        return f"new {cs_type}[0]"
    return f"new {cs_type}[] {{ {', '.join(literal(v, cs_type) for v in values)} }}"


def constant_value(constant: Constant, dialect: Dialect, where: SourceLocation) -> tuple[str, str]:
    """The C# type and literal of ``constant``; a LocatedError at ``where`` for a constant C#
    cannot declare or a value its type cannot hold."""
    cs_type = primitive_type(constant.type, dialect)
    if cs_type is None:
        raise LocatedError.at(
            where,
            f"constant '{constant.name}' has type {constant.type}, which C# constants cannot have",
        )
    try:
        return cs_type, literal(constant.value, cs_type)
    except ValueError as exc:
        raise LocatedError.at(where, f"constant '{constant.name}': {exc}") from None
