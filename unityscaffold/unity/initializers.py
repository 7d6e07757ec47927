"""The value Unity serializes for a script's field before anything sets it.

That is the field's C# initializer when it has one, else the zero of its type: ``0``, ``""``
for a string (Unity writes a null string as empty), ``{fileID: 0}`` for an object reference,
``[]`` for an array or ``List<>``, zeros for a Unity struct (a ``Quaternion`` field too),
the enum's ``0``, and an empty ``m_PersistentCalls`` for a ``UnityEvent``. An initializer is
evaluated only when it is a literal or one of Unity's named constants (``Vector3.one``,
``Color.white``, ``new Vector3(0, 1, 0)``, ``new float[] {1, 2}``): anything else (a method
call, arithmetic, another field) gives None, and the caller leaves that field to Unity rather
than guess.

Initializers come from ``unity/csharp.py``, whose text keeps a string literal as
``"<hex of its UTF-8 bytes>"`` (``"$"`` for an interpolated one).
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from unityscaffold.unity.csharp import split_top
from unityscaffold.unity.values import Enum, FieldValue, InlineMap, ObjectRef

__all__ = ["field_default", "zero_value"]

_KEYS = {
    "Vector2": "xy",
    "Vector3": "xyz",
    "Vector4": "xyzw",
    "Quaternion": "xyzw",
    "Color": "rgba",
}
_CONSTANTS: dict[str, tuple[float, ...]] = {
    "Vector2.zero": (0, 0),
    "Vector2.one": (1, 1),
    "Vector2.up": (0, 1),
    "Vector2.down": (0, -1),
    "Vector2.left": (-1, 0),
    "Vector2.right": (1, 0),
    "Vector3.zero": (0, 0, 0),
    "Vector3.one": (1, 1, 1),
    "Vector3.up": (0, 1, 0),
    "Vector3.down": (0, -1, 0),
    "Vector3.left": (-1, 0, 0),
    "Vector3.right": (1, 0, 0),
    "Vector3.forward": (0, 0, 1),
    "Vector3.back": (0, 0, -1),
    "Vector4.zero": (0, 0, 0, 0),
    "Vector4.one": (1, 1, 1, 1),
    "Quaternion.identity": (0, 0, 0, 1),
    "Color.white": (1, 1, 1, 1),
    "Color.black": (0, 0, 0, 1),
    "Color.red": (1, 0, 0, 1),
    "Color.green": (0, 1, 0, 1),
    "Color.blue": (0, 0, 1, 1),
    "Color.cyan": (0, 1, 1, 1),
    "Color.magenta": (1, 0, 1, 1),
    "Color.yellow": (1, 0.921568632, 0.0156862754, 1),
    "Color.gray": (0.5, 0.5, 0.5, 1),
    "Color.grey": (0.5, 0.5, 0.5, 1),
    "Color.clear": (0, 0, 0, 0),
}
_INT = re.compile(r"(-?)\s*(0[xX][0-9a-fA-F_]+|\d[\d_]*)(?:[uU][lL]?|[lL][uU]?)?")
_FLOAT = re.compile(r"-?\s*(?:\d[\d_]*\.?[\d_]*|\.\d[\d_]*)(?:[eE][-+]?\d+)?[fFdDmM]?")
_STRING = re.compile(r'"([0-9a-f]*)"')
_EMPTY_STRING = frozenset({"string.Empty", "String.Empty", "System.String.Empty"})
_NEW = re.compile(r"new\s+([\w.]+)\s*\((.*)\)", re.S)
_EMPTY_LIST = re.compile(r"new\s+[\w.<>,\s]+(?:\[\s*0?\s*\]|\(\s*\))\s*(?:\{\s*\})?|\{\s*\}")
_LIST = re.compile(r"(?:new\s+[\w.<>,\s]*(?:\[\s*\]|\(\s*\))?\s*)?\{(.*)\}", re.S)
_SIZED = re.compile(r"new\s+[\w.]+\s*\[\s*(\d+)\s*\]")
_EVENT = re.compile(r"(?:UnityEngine\.)?(?:Events\.)?UnityEvent(?:<.*>)?")


def zero_value(kind: str, csharp: str = "") -> FieldValue | None:
    """What Unity writes for a field of ``kind`` nobody set (None: not known here)."""
    if kind.endswith("[]"):
        return []
    if kind.startswith("ref:"):
        return ObjectRef(0)
    if kind.startswith("enum:"):
        return Enum(0)
    if kind in _KEYS:
        return InlineMap(tuple((k, 0) for k in _KEYS[kind]))
    simple: dict[str, FieldValue] = {"int": 0, "float": 0.0, "bool": False, "string": ""}
    if kind in simple:
        return simple[kind]
    if kind.startswith("raw:") and _EVENT.fullmatch(csharp or kind[4:]):
        return {"m_PersistentCalls": {"m_Calls": []}}
    return None  # Color32, Rect, Bounds, a nested class: not written from here


def field_default(
    kind: str,
    initializer: str | None,
    enums: Mapping[str, Mapping[str, int]],
    csharp: str = "",
) -> FieldValue | None:
    """The value Unity writes for a new component's field of ``kind`` with ``initializer``
    (its C# text after ``=``, or None); None when it cannot be worked out exactly."""
    text = (initializer or "").strip()
    if not text or (text == "null" and not kind.startswith(("int", "float", "bool", "enum"))):
        return zero_value(kind, csharp)
    if kind.endswith("[]"):
        return _list(kind[:-2], text, enums)
    if kind.startswith("raw:"):
        zero = zero_value(kind, csharp)
        new = _NEW.fullmatch(text)
        # new UnityEvent() is what Unity makes of a null event too
        return zero if zero is not None and new is not None and not new.group(2).strip() else None
    if kind.startswith("enum:"):
        return _enum(kind[5:], text, enums.get(kind[5:], {}))
    if kind in _KEYS:
        return _struct(kind, text)
    return _scalar(kind, text)


def _scalar(kind: str, text: str) -> FieldValue | None:
    if kind == "bool":
        return {"true": True, "false": False}.get(text)
    if kind == "int":
        match = _INT.fullmatch(text)
        if match is None:
            return None
        value = int(match.group(2).replace("_", ""), 0)
        return -value if match.group(1) else value
    if kind == "float":
        if _FLOAT.fullmatch(text) is None:
            return None
        return float(re.sub(r"[\s_fFdDmM]", "", text))
    if kind == "string":
        if text in _EMPTY_STRING:
            return ""
        match = _STRING.fullmatch(text)
        return bytes.fromhex(match.group(1)).decode("utf-8") if match else None
    return None


def _enum(name: str, text: str, members: Mapping[str, int]) -> FieldValue | None:
    bare = name.rsplit(".", 1)[-1]
    cast = re.fullmatch(rf"\(\s*[\w.]*{re.escape(bare)}\s*\)\s*(.+)", text)
    if cast is not None:
        number = _scalar("int", cast.group(1).strip())
        return Enum(number) if isinstance(number, int) else None
    if text == "0":
        return Enum(0)
    qualified = re.fullmatch(rf"(?:[\w.]*\.)?{re.escape(bare)}\.(\w+)", text)
    if qualified is None or qualified.group(1) not in members:
        return None
    return Enum(members[qualified.group(1)])


def _struct(kind: str, text: str) -> FieldValue | None:
    keys = _KEYS[kind]
    named = re.sub(r"^UnityEngine\.", "", text)
    if named in _CONSTANTS and named.startswith(f"{kind}."):
        values: list[float] = list(_CONSTANTS[named])
    else:
        new = _NEW.fullmatch(text)
        if new is None or new.group(1).rsplit(".", 1)[-1] != kind:
            return None
        args = [_scalar("float", a) for a in split_top(new.group(2))]
        if len(args) > len(keys) or not all(isinstance(a, float) for a in args):
            return None
        # a Color's alpha defaults to 1 in its three-argument constructor
        fill = [1.0] if kind == "Color" and len(args) == 3 else []
        values = [a for a in args if isinstance(a, float)] + fill
        values += [0.0] * (len(keys) - len(values))
    return InlineMap(tuple(zip(keys, values, strict=True)))


def _list(element: str, text: str, enums: Mapping[str, Mapping[str, int]]) -> FieldValue | None:
    if _EMPTY_LIST.fullmatch(text):
        return []
    sized = _SIZED.fullmatch(text)
    if sized is not None:
        zero = zero_value(element)
        return None if zero is None else [zero] * int(sized.group(1))
    listed = _LIST.fullmatch(text)
    if listed is None:
        return None
    items = [field_default(element, item, enums) for item in split_top(listed.group(1))]
    if any(item is None for item in items):
        return None
    return [item for item in items if item is not None]
