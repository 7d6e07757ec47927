"""Emit a serialized field as Unity lays it out, and compare a stored value with a requested one.

Layout rules: two-space indents, indentless sequences, ``key: `` for an empty string, ``[]`` for
an empty list, flow mappings for references and vectors, block mappings for structs.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from unityscaffold.unity._scalars import format_float, format_string, to_float32
from unityscaffold.unity.values import AssetRef, Enum, FieldValue, InlineMap, ObjectRef

__all__ = ["emit_field", "flow_text", "value_equals"]


def flow_text(value: FieldValue) -> str | None:
    """One-line text of a scalar or flow value; None for lists and structs."""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, Enum):
        return str(int(value.value))
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return format_float(value)
    if isinstance(value, ObjectRef):
        return f"{{fileID: {value.file_id}}}"
    if isinstance(value, AssetRef):
        return f"{{fileID: {value.file_id}, guid: {value.guid}, type: {value.type}}}"
    if isinstance(value, InlineMap):
        return "{" + ", ".join(f"{k}: {flow_text(v)}" for k, v in value.items) + "}"
    return None


def emit_field(
    key: str, value: FieldValue, indent: int = 2, *, quote_trailing_bracket: bool = False
) -> list[str]:
    """Lines (without line breaks) for ``key: value`` at ``indent`` spaces."""
    pad = " " * indent
    if isinstance(value, str):
        text = format_string(
            value,
            column=indent + len(key) + 2,
            indent=indent + 2,
            quote_trailing_bracket=quote_trailing_bracket,
        )
        return f"{pad}{key}: {text}".split("\n")
    flow = flow_text(value)
    if flow is not None:
        return [f"{pad}{key}: {flow}"]
    if isinstance(value, Mapping):
        if not value:
            return [f"{pad}{key}: {{}}"]
        lines = [f"{pad}{key}:"]
        for sub_key, sub_value in value.items():
            lines += emit_field(
                sub_key, sub_value, indent + 2, quote_trailing_bracket=quote_trailing_bracket
            )
        return lines
    if isinstance(value, Sequence):
        if not value:
            return [f"{pad}{key}: []"]
        lines = [f"{pad}{key}:"]
        for item in value:
            lines += _emit_item(item, indent, quote_trailing_bracket)
        return lines
    raise TypeError(f"cannot serialize {type(value).__name__} for field {key!r}")


def _emit_item(item: FieldValue, indent: int, quote_trailing_bracket: bool) -> list[str]:
    pad = " " * indent
    if isinstance(item, str):
        text = format_string(
            item,
            column=indent + 2,
            indent=indent + 2,
            quote_trailing_bracket=quote_trailing_bracket,
        )
        return f"{pad}- {text}".rstrip(" ").split("\n") if text else [f"{pad}- "]
    flow = flow_text(item)
    if flow is not None:
        return [f"{pad}- {flow}"]
    if isinstance(item, Mapping) and item:
        lines: list[str] = []
        for sub_key, sub_value in item.items():
            lines += emit_field(
                sub_key, sub_value, indent + 2, quote_trailing_bracket=quote_trailing_bracket
            )
        return [f"{pad}- {lines[0][indent + 2 :]}", *lines[1:]]
    raise TypeError(f"cannot serialize a list item of type {type(item).__name__}")


def value_equals(stored: object, value: FieldValue) -> bool:
    """Whether ``stored`` (as read by a string-only YAML loader) already means ``value``."""
    try:
        return _equals(stored, value)
    except (TypeError, ValueError, KeyError):
        return False


def _equals(stored: object, value: FieldValue) -> bool:
    if isinstance(value, (bool, int, Enum)):
        number = int(value.value) if isinstance(value, Enum) else int(value)
        return isinstance(stored, str) and int(stored) == number
    if isinstance(value, float):
        return isinstance(stored, str) and _same_float32(_read_float(stored), value)
    if isinstance(value, str):
        return stored == value or (stored is None and value == "")
    if isinstance(value, ObjectRef):
        return (
            isinstance(stored, dict)
            and set(stored) == {"fileID"}
            and int(stored["fileID"]) == value.file_id
        )
    if isinstance(value, AssetRef):
        return (
            isinstance(stored, dict)
            and set(stored) == {"fileID", "guid", "type"}
            and (int(stored["fileID"]), stored["guid"], int(stored["type"]))
            == (value.file_id, value.guid, value.type)
        )
    if isinstance(value, InlineMap):
        return (
            isinstance(stored, dict)
            and list(stored) == [k for k, _ in value.items]
            and all(_equals(stored[k], v) for k, v in value.items)
        )
    if isinstance(value, Mapping):
        return (
            isinstance(stored, dict)
            and list(stored) == list(value)
            and all(_equals(stored[k], v) for k, v in value.items())
        )
    if isinstance(value, Sequence):
        return (
            isinstance(stored, list)
            and len(stored) == len(value)
            and all(_equals(s, v) for s, v in zip(stored, value, strict=True))
        )
    return False


def _read_float(text: str) -> float:
    special = {"Infinity": math.inf, "-Infinity": -math.inf, "NaN": math.nan}
    return special[text] if text in special else float(text)


def _same_float32(a: float, b: float) -> bool:
    a32, b32 = to_float32(a), to_float32(b)
    if math.isnan(a32) or math.isnan(b32):
        return math.isnan(a32) and math.isnan(b32)
    return a32 == b32 and math.copysign(1.0, a32) == math.copysign(1.0, b32)
