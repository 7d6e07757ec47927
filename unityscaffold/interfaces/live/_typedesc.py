"""A full definition text from a node's answer to Jazzy's ``~/get_type_description``.

A node sends each type's ``.msg`` file as it was built (``encoding: msg``) when its type
support embeds the sources, which Jazzy's generators do, less the file's final newline, which
is put back. A type without a source (``implicit``:
an action's parts, or a node built without sources) is written back from its field
descriptions: names and types only, which is all the RIHS01 hash covers, so the hash check
still proves the text right; constants and default values are not in the description and are
lost, which the caller reports.
"""

from __future__ import annotations

from unityscaffold.interfaces.live._graph import TypeReply

__all__ = ["full_text_from_reply", "is_message_name"]

_SEPARATOR = "\n" + "=" * 80 + "\n"
_PLAIN = {
    2: "int8",
    3: "uint8",
    4: "int16",
    5: "uint16",
    6: "int32",
    7: "uint32",
    8: "int64",
    9: "uint64",
    10: "float32",
    11: "float64",
    13: "char",
    15: "bool",
    16: "byte",
    17: "string",
    18: "wstring",
    21: "string",  # bounded: string<=N
    22: "wstring",
}
_NESTED = 1
_ARRAY_STEP = 48  # +48 fixed array, +96 bounded, +144 unbounded
_PLACEHOLDER = "structure_needs_at_least_one_member"


def is_message_name(name: str) -> bool:
    """Whether ``name`` is ``pkg/msg/Type``, the only kind a ``.msg`` file can hold."""
    parts = name.split("/")
    return len(parts) == 3 and parts[1] == "msg"


def _field_line(name: str, type_id: int, capacity: int, string_capacity: int, nested: str) -> str:
    array, base_id = divmod(type_id, _ARRAY_STEP)
    if base_id == _NESTED:
        package, _, short = nested.partition("/msg/")
        base = f"{package}/{short}"
    elif base_id in _PLAIN:
        base = _PLAIN[base_id]
        if base_id in (21, 22):
            base += f"<={string_capacity}"
    else:
        raise ValueError(f"field {name} has type id {type_id}, which no .msg type has")
    suffix = ("", f"[{capacity}]", f"[<={capacity}]", "[]")[array] if array < 4 else None
    if suffix is None:
        raise ValueError(f"field {name} has type id {type_id}, which no .msg type has")
    return f"{base}{suffix} {name}\n"


def _own_text(type_name: str, reply: TypeReply) -> tuple[str, bool]:
    """``type_name``'s text, and whether it was rebuilt from fields (losing constants)."""
    encoding, text = reply.sources.get(type_name, ("implicit", ""))
    if encoding == "msg" and text:
        return text if text.endswith("\n") else text + "\n", False
    fields = reply.fields.get(type_name)
    if fields is None:
        raise ValueError(f"the answer describes no type {type_name}")
    if [f[0] for f in fields] == [_PLACEHOLDER]:
        return "", True
    return "".join(_field_line(*f) for f in fields), True


def full_text_from_reply(root: str, reply: TypeReply) -> tuple[str, list[str]]:
    """``root``'s full definition (its text, then each message it uses after a separator line
    and ``MSG: pkg/msg/Type``), and the types written back from fields alone.

    Raises ``ValueError`` when the answer lacks a type or describes something no ``.msg``
    file can say.
    """
    text, rebuilt = _own_text(root, reply)
    parts, lossy = [text], [root] if rebuilt else []
    for name in sorted(reply.fields):
        if name == root:
            continue
        if not is_message_name(name):
            raise ValueError(f"{root} uses {name}, which is no message type")
        text, rebuilt = _own_text(name, reply)
        parts.append(f"{_SEPARATOR}MSG: {name}\n{text}")
        if rebuilt:
            lossy.append(name)
    return "".join(parts), lossy
