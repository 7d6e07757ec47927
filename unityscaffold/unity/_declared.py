"""Edits for declared objects: built-in components and instances told apart by a key.

A built-in component is recognised by GameObject + class (the first one of that class), or, when
the manifest gives it an ``id``, by the fileID that id derives; a keyed MonoBehaviour likewise.
So several of one class on one GameObject stay distinct and stable across runs.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from unityscaffold.errors import UserError
from unityscaffold.unity import _fields as F
from unityscaffold.unity import _textops as T
from unityscaffold.unity._builders import component_item, new_builtin
from unityscaffold.unity._documents import Documents
from unityscaffold.unity._edits import (
    _block_end,
    _require_editable,
    _Taken,
    component_id_parts,
    set_fields,
)
from unityscaffold.unity._fileids import candidate_file_ids, stable_file_id
from unityscaffold.unity._split import Doc
from unityscaffold.unity.builtins import BuiltinClass
from unityscaffold.unity.index import GameObject
from unityscaffold.unity.values import FieldValue, ScriptRef

__all__ = ["ensure_builtin", "find_builtin", "find_keyed_component"]


def _builtin_parts(target: GameObject, builtin: BuiltinClass, key: str | None) -> tuple[str, ...]:
    parts = (builtin.name, target.path)
    return (*parts, key) if key is not None else parts


def _find_derived(
    docs: Documents, parts: Sequence[str], owner: int, matches: Callable[[Doc], bool]
) -> int | None:
    """The document a keyed object got from ``parts``, if it is still on ``owner``."""
    for file_id in candidate_file_ids(parts):
        doc = docs.get(file_id)
        if doc is None:
            return None
        if F.ref_value(doc, "m_GameObject") == owner and matches(doc):
            return file_id
    return None  # pragma: no cover - candidate_file_ids never ends


def find_builtin(
    docs: Documents, target: GameObject, builtin: BuiltinClass, key: str | None
) -> int | None:
    """The component ``builtin`` (``key``'s one when given) on ``target``, or None."""
    if key is not None:
        parts = _builtin_parts(target, builtin, key)
        return _find_derived(docs, parts, target.file_id, lambda d: d.class_id == builtin.class_id)
    for file_id in target.component_ids:
        doc = docs.get(file_id)
        if doc is not None and doc.class_id == builtin.class_id:
            return file_id
    return None


def find_keyed_component(
    docs: Documents, target: GameObject, script: ScriptRef, key: str
) -> int | None:
    """The instance of ``script`` on ``target`` that apply made for ``key``, or None."""
    parts = component_id_parts(target, script, key)

    def runs_script(doc: Doc) -> bool:
        found = F.script_of(doc) if doc.class_id == 114 else None
        return found is not None and (found[0], found[1]) == (script.file_id, script.guid)

    return _find_derived(docs, parts, target.file_id, runs_script)


def ensure_builtin(
    docs: Documents,
    target: GameObject,
    builtin: BuiltinClass,
    key: str | None,
    fields: Sequence[tuple[str, FieldValue]],
) -> int:
    """Set ``fields`` on the built-in component of ``target`` or add a new one; its fileID."""
    _require_editable(docs, target)
    existing = find_builtin(docs, target, builtin, key)
    if existing is None:
        if not docs.era.modern_prefab_fields or docs.era.root_order:
            raise UserError(
                f"{docs.path}: built-in components are written as Unity 2022.3 writes them, "
                f"and this file was written by Unity {docs.era.label}",
                hint=f"add the {builtin.name} in Unity, or upgrade the project to 2022.3",
            )
        go_doc = docs.require(target.file_id)
        existing = stable_file_id(_builtin_parts(target, builtin, key), _Taken(docs))
        text = new_builtin(existing, target.file_id, builtin)
        index = None if docs.is_scene else _block_end(docs, go_doc)
        docs.insert(Doc(builtin.class_id, existing, False, text), index)
        T.append_list_item(
            go_doc, "m_Component", component_item(docs.era, builtin.class_id, existing)
        )
        docs.touch(go_doc)
    set_fields(docs, docs.require(existing), fields)
    return existing
