"""``.msg`` texts rebuilt from rosapi ``TypeDef`` lists, for rosbridges that send no full text.

A TypeDef lists field names, field types and array lengths (-1 scalar, 0 unbounded, N fixed),
but constants only by name and value, without their types; a type with constants therefore
cannot be rebuilt faithfully and is refused. ROS 2 rosapi names primitives in IDL terms.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from unityscaffold.errors import UserError

__all__ = ["full_text_from_typedefs", "texts_from_typedefs"]

_IDL_TO_MSG = {
    "double": "float64",
    "float": "float32",
    "boolean": "bool",
    "octet": "byte",
    "long": "int32",
    "unsigned long": "uint32",
    "long long": "int64",
    "unsigned long long": "uint64",
    "short": "int16",
    "unsigned short": "uint16",
}
_SEPARATOR = "\n" + "=" * 80 + "\n"


def _short(type_name: str) -> str:
    return type_name.replace("/msg/", "/")


def _field_line(field_type: str, name: str, array_length: int) -> str:
    base = _IDL_TO_MSG.get(field_type, _short(field_type))
    suffix = "" if array_length < 0 else "[]" if array_length == 0 else f"[{array_length}]"
    return f"{base}{suffix} {name}\n"


def _text(typedef: Mapping[str, Any]) -> str:
    names = _strings(typedef, "fieldnames")
    types = _strings(typedef, "fieldtypes")
    lengths = typedef.get("fieldarraylen", [-1] * len(names))
    if not isinstance(lengths, list) or not all(
        isinstance(n, int) and not isinstance(n, bool) for n in lengths
    ):
        raise ValueError("TypeDef field fieldarraylen is not a list of integers")
    if not (len(names) == len(types) == len(lengths)):
        raise ValueError(f"TypeDef of {typedef.get('type')} has lists of different lengths")
    if _strings(typedef, "constnames"):
        raise UserError(
            f"cannot rebuild {typedef.get('type')} from /rosapi/message_details: "
            "rosapi does not report the types of its constants",
            hint="add the package that defines it to the manifest's interfaces",
        )
    return "".join(_field_line(t, n, a) for t, n, a in zip(types, names, lengths, strict=True))


def _strings(typedef: Mapping[str, Any], key: str) -> list[str]:
    value = typedef.get(key, [])
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise ValueError(f"TypeDef field {key} is not a list of strings")
    return value


def texts_from_typedefs(typedefs: Sequence[Any]) -> dict[str, str]:
    """Each TypeDef's ``.msg`` text by type name (``pkg/Type``), in the list's order.

    Raises ``ValueError`` for malformed TypeDefs, ``UserError`` for ones that cannot be rebuilt.
    """
    texts: dict[str, str] = {}
    for typedef in typedefs:
        if not isinstance(typedef, Mapping) or not isinstance(typedef.get("type"), str):
            raise ValueError("a TypeDef is not an object with a type")
        name = _short(typedef["type"])
        if name in ("time", "duration"):
            continue  # rosapi mocks these builtins as secs/nsecs records
        texts.setdefault(name, _text(typedef))
    return texts


def full_text_from_typedefs(root: str, typedefs: Sequence[Any]) -> str:
    """A full definition text (as rosapi's ``typedefs_full_text`` would give) for ``root``.

    Raises ``ValueError`` for malformed TypeDefs, ``UserError`` for ones that cannot be rebuilt.
    """
    texts = texts_from_typedefs(typedefs)
    root_name = _short(root)
    if root_name not in texts:
        raise ValueError(f"the TypeDefs do not include {root}")
    parts = [texts.pop(root_name)]
    parts += [f"{_SEPARATOR}MSG: {name}\n{text}" for name, text in texts.items()]
    return "".join(parts)
