"""Typed values for serialized fields, and the reference to a script class.

Plain Python values map as Unity writes them: ``bool`` → ``0``/``1``, ``int`` → decimal,
``float`` → shortest float32 digits, ``str`` → Unity's quoting, ``list``/``tuple`` → a block
sequence, ``dict`` → a nested block mapping (a serialized struct). The wrappers below cover
what plain values cannot say.
"""

from __future__ import annotations

import re
import struct
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TypeAlias

from unityscaffold.unity._md4 import md4

__all__ = [
    "MONOSCRIPT_FILE_ID",
    "AssetRef",
    "Enum",
    "FieldValue",
    "InlineMap",
    "ObjectRef",
    "ScriptRef",
    "Verbatim",
    "script_file_id_for_dll_class",
]

#: fileID of the MonoScript inside a ``.cs`` file (class ID 115 × 100000).
MONOSCRIPT_FILE_ID = 11500000

_GUID_RE = re.compile(r"[0-9a-f]{32}")


@dataclass(frozen=True, slots=True)
class ObjectRef:
    """A reference to an object in the same file: ``{fileID: N}``; ``ObjectRef(0)`` is null."""

    file_id: int


@dataclass(frozen=True, slots=True)
class Verbatim:
    """A field's default exactly as Unity writes it for a new component (key and indent
    included, lines joined by ``\\n``): a layout read off a file Unity saved, kept byte for byte."""

    text: str


@dataclass(frozen=True, slots=True)
class AssetRef:
    """A reference to another asset: ``{fileID: F, guid: G, type: T}``."""

    file_id: int
    guid: str
    type: int = 3

    def __post_init__(self) -> None:
        if not _GUID_RE.fullmatch(self.guid):
            raise ValueError(f"not a Unity GUID (32 lowercase hex digits): {self.guid!r}")


@dataclass(frozen=True, slots=True)
class Enum:
    """An enum field's underlying integer (written like an int; the wrapper documents intent)."""

    value: int


@dataclass(frozen=True, slots=True)
class InlineMap:
    """A flow mapping of scalars, as Unity writes vectors and colours: ``{x: 0, y: 1, z: 0}``."""

    items: tuple[tuple[str, bool | int | float | Enum], ...]

    @classmethod
    def of(cls, **items: bool | int | float | Enum) -> InlineMap:
        return cls(tuple(items.items()))


FieldValue: TypeAlias = (
    bool
    | int
    | float
    | str
    | Enum
    | ObjectRef
    | AssetRef
    | InlineMap
    | Sequence["FieldValue"]
    | Mapping[str, "FieldValue"]
)


@dataclass(frozen=True, slots=True)
class ScriptRef:
    """The script class of a MonoBehaviour, as ``m_Script`` names it.

    ``guid`` is the ``.cs`` file's (or the DLL's) meta GUID; ``file_id`` is 11500000 for a ``.cs``
    file or the MD4-derived value for a class inside a DLL (see :meth:`for_dll_class`).
    ``class_name``/``namespace``/``assembly`` are optional and only used to fill
    ``m_EditorClassIdentifier`` in files that use the qualified ``Asm::Ns.Class`` form.
    """

    guid: str
    file_id: int = MONOSCRIPT_FILE_ID
    type: int = 3
    class_name: str | None = None
    namespace: str = ""
    assembly: str | None = None

    def __post_init__(self) -> None:
        if not _GUID_RE.fullmatch(self.guid):
            raise ValueError(f"not a Unity GUID (32 lowercase hex digits): {self.guid!r}")

    @classmethod
    def for_dll_class(
        cls, dll_guid: str, namespace: str, class_name: str, assembly: str | None = None
    ) -> ScriptRef:
        """The reference to ``namespace.class_name`` compiled into the DLL with ``dll_guid``."""
        file_id = script_file_id_for_dll_class(namespace, class_name)
        return cls(dll_guid, file_id, 3, class_name, namespace, assembly)


def script_file_id_for_dll_class(namespace: str, class_name: str) -> int:
    """Unity's fileID for a MonoBehaviour class inside a DLL.

    The first four bytes, read as a little-endian signed int32, of
    MD4(``"s\\0\\0\\0" + namespace + class_name``) with UTF-8 text and no separator.
    """
    digest = md4(b"s\0\0\0" + (namespace + class_name).encode("utf-8"))
    value: int = struct.unpack("<i", digest[:4])[0]
    return value
