"""The edits behind ``SceneDocument``: create GameObjects, attach/update/remove components.

Each edit works on a file's ``Documents`` through their public methods; ``SceneDocument`` finds
the targets first. An edit checks that its target is ours to change (not a stripped placeholder
or an object inside a prefab instance), then works as line operations on the documents involved.
"""

from __future__ import annotations

import re
from collections.abc import Container, Sequence

from unityscaffold.errors import LocatedError, UserError
from unityscaffold.unity import _fields as F
from unityscaffold.unity import _textops as T
from unityscaffold.unity._builders import (
    component_item,
    new_gameobject,
    new_monobehaviour,
    new_rect_transform,
    new_transform,
)
from unityscaffold.unity._classids import TRANSFORM_CLASSES
from unityscaffold.unity._documents import Documents
from unityscaffold.unity._emit import emit_field, value_equals
from unityscaffold.unity._fileids import stable_file_id
from unityscaffold.unity._split import Doc
from unityscaffold.unity._validate import check_exemplar
from unityscaffold.unity.index import GameObject, SceneComponent
from unityscaffold.unity.values import FieldValue, ScriptRef, Verbatim

__all__ = [
    "component_id_parts",
    "create_path",
    "ensure_component",
    "remove_component",
    "set_fields",
]

_FIELD_NAME_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(?: [A-Za-z0-9_]+)*")
_STRUCTURAL = frozenset(
    {
        "m_GameObject",
        "m_Script",
        "m_Component",
        "m_Father",
        "m_Children",
        "m_PrefabInstance",
        "m_CorrespondingSourceObject",
        "m_PrefabAsset",
        "m_PrefabParentObject",
        "m_PrefabInternal",
        "serializedVersion",
    }
)
_PREFAB_HINT = "edit the prefab asset instead, or unpack the prefab instance in Unity first"


class _Taken:
    """fileIDs already used: the file's, plus ones picked earlier in the same edit."""

    def __init__(self, ids: Container[int], *extra: int) -> None:
        self.ids, self.extra = ids, set(extra)

    def __contains__(self, value: object) -> bool:
        return value in self.extra or value in self.ids


def _refuse(docs: Documents, doc: Doc, message: str, hint: str | None = None) -> LocatedError:
    return LocatedError.at(docs.location(doc), f"{doc.header}: {message}", hint=hint)


def _require_doc_editable(docs: Documents, doc: Doc) -> None:
    if doc.stripped:
        raise _refuse(
            docs,
            doc,
            "is a placeholder (stripped) for an object inside a prefab "
            "instance; its data lives in the prefab asset",
            _PREFAB_HINT,
        )
    source = F.ref_value(doc, "m_CorrespondingSourceObject") or F.ref_value(
        doc, "m_PrefabParentObject"
    )
    if source:
        raise _refuse(
            docs,
            doc,
            "belongs to a prefab instance (its m_CorrespondingSourceObject "
            "is set); changes would become overrides",
            _PREFAB_HINT,
        )


def _require_editable(docs: Documents, go: GameObject) -> None:
    doc = docs.get(go.file_id)
    if go.prefab_instance_id and doc is not None and doc.class_id == 1001:
        raise _refuse(
            docs,
            doc,
            f"'{go.path}' is a prefab instance; adding to it needs a "
            "prefab override, which is not supported",
            _PREFAB_HINT,
        )
    if doc is not None:
        _require_doc_editable(docs, doc)


def _exemplar(docs: Documents, class_id: int) -> Doc | None:
    """An existing object of the class, not from a prefab, whose layout new ones copy; one that
    is not valid YAML is refused, located, rather than copied with its fault."""
    for doc in docs.in_order:
        if doc.class_id == class_id and not doc.stripped:
            source = F.ref_value(doc, "m_CorrespondingSourceObject") or F.ref_value(
                doc, "m_PrefabParentObject"
            )
            if not source:
                _require_sound(docs, doc)
                return doc
    return None


def _require_sound(docs: Documents, doc: Doc) -> None:
    if doc.cache.get("sound"):  # the cache goes with any edit of the document's text
        return
    problems = check_exemplar(docs.path, docs.prolog, docs.in_order, doc)
    if problems:
        raise LocatedError(problems)
    doc.cache["sound"] = True


def _emit(docs: Documents, name: str, value: FieldValue) -> list[str]:
    if not _FIELD_NAME_RE.fullmatch(name):
        raise UserError(f"'{name}' is not a serialized field name")
    if name in _STRUCTURAL:
        raise UserError(f"'{name}' is maintained by Unity's object structure and cannot be set")
    try:
        return emit_field(
            name, value, 2, quote_trailing_bracket=docs.era.qualified_class_identifier
        )
    except (TypeError, ValueError) as exc:
        raise UserError(f"field '{name}': {exc}") from None


def _block_end(docs: Documents, go_doc: Doc) -> int:
    """Index just after a GameObject's own document and its components' (prefab order)."""
    ordered = docs.in_order
    wanted = {go_doc.file_id, *F.list_refs(go_doc, "m_Component")}
    return max(i for i, d in enumerate(ordered) if d.file_id in wanted) + 1


def _prefab_go_slot(docs: Documents, go_id: int) -> int:
    ordered = docs.in_order
    gos = [i for i, d in enumerate(ordered) if d.class_id == 1 and not d.stripped]
    later = [i for i in gos if ordered[i].file_id > go_id]
    if later:
        return later[0]
    return _block_end(docs, ordered[gos[-1]]) if gos else len(ordered)


def create_path(
    docs: Documents, parent: GameObject | None, names: Sequence[str], start: int, ui: bool = False
) -> int:
    """Create ``names[start:]`` under ``parent`` (the existing ``names[:start]``, or the root);
    return the fileID of the last GameObject created, which gets a RectTransform if ``ui``."""
    parent_id: int | None = None
    if parent is not None:
        _require_editable(docs, parent)
        parent_id = parent.file_id
    made: int | None = None  # the Transform of the level made last
    for level in range(start, len(names)):
        last = level == len(names) - 1
        path = "/".join(names[: level + 1])
        parent_id, made = _create(docs, parent_id, path, names[level], ui and last, made)
    assert parent_id is not None
    return parent_id


def _create(
    docs: Documents, parent_id: int | None, path: str, name: str, ui: bool, parent_tr_id: int | None
) -> tuple[int, int]:
    """Make one GameObject and its Transform; return their fileIDs. ``parent_tr_id`` is the
    parent's Transform when this edit just made the parent: the hierarchy, out of date since
    then, is not rebuilt to find it (a whole-file pass per level of a new path)."""
    era = docs.era
    go_id = stable_file_id(("GameObject", path), _Taken(docs))
    tr_id = stable_file_id(("Transform", path), _Taken(docs, go_id))
    parent_tr: Doc | None = None
    if parent_tr_id is not None:
        parent_tr = docs.require(parent_tr_id)
        order = len(F.list_refs(parent_tr, "m_Children"))
    elif parent_id is None:
        hierarchy = docs.hierarchy
        roots = hierarchy.roots
        if not docs.is_scene and roots:
            raise UserError(
                f"{docs.path}: a prefab has a single root; '{path}' would be another",
                hint=f"create it under '{hierarchy.paths[roots[0]]}'",
            )
        order = len(roots)
    else:
        hierarchy = docs.hierarchy
        transform_id = hierarchy.nodes[parent_id].transform_id
        parent_tr = docs.get(transform_id) if transform_id is not None else None
        if parent_tr is None:
            raise UserError(f"{docs.path}: '{hierarchy.paths[parent_id]}' has no Transform")
        order = len(F.list_refs(parent_tr, "m_Children"))
    father = parent_tr.file_id if parent_tr is not None else 0
    tr_class = 224 if ui else 4
    go_text = new_gameobject(era, _exemplar(docs, 1), go_id, name, tr_id)
    if ui:  # the UI layer, as Unity gives a GameObject created under a Canvas
        go_text = go_text.replace(component_item(era, 4, tr_id), component_item(era, 224, tr_id))
        go_text = go_text.replace("\n  m_Layer: 0\n", "\n  m_Layer: 5\n")
    new_tr = new_rect_transform if ui else new_transform
    tr_text = new_tr(
        era, _exemplar(docs, tr_class), tr_id, go_id, father, order if era.root_order else None
    )
    index = None if docs.is_scene else _prefab_go_slot(docs, go_id)
    docs.insert(Doc(1, go_id, False, go_text), index)
    docs.insert(Doc(tr_class, tr_id, False, tr_text), None if index is None else index + 1)
    if parent_tr is not None:
        if F.field_span(parent_tr, "m_Children") is None:
            # Older Unity versions and some prefabs leave the key out of a childless Transform;
            # it goes where Unity writes it, before m_Father.
            before = "m_Father" if F.field_span(parent_tr, "m_Father") is not None else None
            T.insert_field(parent_tr, ["  m_Children: []"], before=before)
        T.append_list_item(parent_tr, "m_Children", f"  - {{fileID: {tr_id}}}")
        docs.touch(parent_tr)
    elif era.scene_roots:
        _append_scene_root(docs, tr_id)
    docs.invalidate()
    return go_id, tr_id


def _append_scene_root(docs: Documents, file_id: int) -> None:
    roots_doc = docs.scene_roots()
    assert roots_doc is not None  # the caller checked the era
    T.append_list_item(roots_doc, "m_Roots", f"  - {{fileID: {file_id}}}")
    docs.touch(roots_doc)


def ensure_component(
    docs: Documents,
    target: GameObject,
    existing: SceneComponent | None,
    script: ScriptRef,
    fields: Sequence[tuple[str, FieldValue]],
    key: str | None = None,
    defaults: Sequence[tuple[str, FieldValue | Verbatim]] = (),
) -> int:
    """Update ``existing`` (``target``'s component running ``script``) or attach a new one
    (whose fileID derives from ``key`` too when given); return the component's fileID.

    A new component gets every field of ``defaults`` (the script's serialized fields in order,
    at the values Unity gives a new one), ``fields`` replacing theirs; an existing one only
    ``fields``: the bytes of fields the manifest does not set stay the user's."""
    _require_editable(docs, target)
    if existing is not None:
        set_fields(docs, docs.require(existing.file_id), fields)
        return existing.file_id
    go_doc = docs.require(target.file_id)
    lines = _new_fields(docs, fields, defaults)
    comp_id = stable_file_id(component_id_parts(target, script, key), _Taken(docs))
    era = docs.era
    text = new_monobehaviour(era, _exemplar(docs, 114), comp_id, target.file_id, script, lines)
    index = None if docs.is_scene else _block_end(docs, go_doc)
    docs.insert(Doc(114, comp_id, False, text), index)
    T.append_list_item(go_doc, "m_Component", component_item(era, 114, comp_id))
    docs.touch(go_doc)
    return comp_id


def _new_fields(
    docs: Documents,
    fields: Sequence[tuple[str, FieldValue]],
    defaults: Sequence[tuple[str, FieldValue | Verbatim]],
) -> list[str]:
    """The lines of a new component's fields: ``defaults`` in their order, ``fields`` replacing
    the values they set, then any of ``fields`` that ``defaults`` does not list."""
    given = {name: _emit(docs, name, value) for name, value in fields}
    lines = []
    for name, default in defaults:
        if name in given:
            lines += given.pop(name)
        elif isinstance(default, Verbatim):
            lines += default.text.split("\n")
        else:
            lines += _emit(docs, name, default)
    return lines + [line for name, _ in fields if name in given for line in given[name]]


def component_id_parts(target: GameObject, script: ScriptRef, key: str | None) -> tuple[str, ...]:
    """What a new MonoBehaviour's fileID derives from (an instance's ``id`` included)."""
    parts = ("MonoBehaviour", target.path, script.guid, str(script.file_id))
    return (*parts, key) if key is not None else parts


def set_fields(docs: Documents, doc: Doc, fields: Sequence[tuple[str, FieldValue]]) -> bool:
    _require_doc_editable(docs, doc)
    order = [name for name, _ in fields]
    changed = False
    for position, (name, value) in enumerate(fields):
        lines = _emit(docs, name, value)
        if F.field_span(doc, name) is not None:
            # bytes as they would be written (the usual re-apply) need no YAML parse to compare
            same = F.field_text(doc, name) == "".join(line + "\n" for line in lines)
            if same or value_equals(F.parse_field(doc, name), value):
                continue
            T.replace_field(doc, name, lines)
        else:
            before = [n for n in order[:position] if F.field_span(doc, n) is not None]
            after = [n for n in order[position + 1 :] if F.field_span(doc, n) is not None]
            T.insert_field(
                doc,
                lines,
                after=before[-1] if before else None,
                before=after[0] if after and not before else None,
            )
        changed = True
    if changed:
        docs.touch(doc)
        if "m_Script" in order:  # the owner's index of scripts (SceneDocument) is stale
            owner = docs.get(F.ref_value(doc, "m_GameObject") or 0)
            if owner is not None:
                owner.cache.clear()
    return changed


def remove_component(docs: Documents, file_id: int) -> bool:
    doc = docs.get(file_id)
    if doc is None:
        return False
    if doc.class_id in TRANSFORM_CLASSES:
        raise UserError(f"{docs.path}: {doc.header} is a Transform; remove its GameObject instead")
    _require_doc_editable(docs, doc)
    owner = docs.get(F.ref_value(doc, "m_GameObject") or 0)
    if owner is not None and T.remove_list_item(owner, "m_Component", file_id):
        docs.touch(owner)
    docs.remove(doc)
    needle = f"{{fileID: {file_id}}}"
    for other in docs.in_order:
        if needle in other.text:
            T.set_text(other, other.text.replace(needle, "{fileID: 0}"))
            docs.touch(other)
    return True


def remove_empty_gameobject(docs: Documents, go_id: int) -> bool:
    """Remove a GameObject that holds only its Transform, has no children, and that nothing
    else in the file refers to; False (nothing changed) otherwise."""
    go = docs.get(go_id)
    if go is None or go.class_id != 1 or go.stripped:
        return False
    components = F.list_refs(go, "m_Component")
    transform = docs.get(components[0]) if len(components) == 1 else None
    if transform is None or transform.class_id not in TRANSFORM_CLASSES:
        return False
    if F.list_refs(transform, "m_Children"):
        return False
    father = docs.get(F.ref_value(transform, "m_Father") or 0)
    roots = docs.scene_roots()
    holders = {go.file_id, transform.file_id}
    allowed = {id(go), id(transform), id(father), id(roots)}
    for other in docs.in_order:
        if id(other) in allowed:
            continue
        if any(f"{{fileID: {i}}}" in other.text for i in holders):
            return False  # something else uses it: not apply's to take away
    if father is not None and T.remove_list_item(father, "m_Children", transform.file_id):
        docs.touch(father)
    if roots is not None and T.remove_list_item(roots, "m_Roots", transform.file_id):
        docs.touch(roots)
    docs.remove(transform)
    docs.remove(go)
    docs.invalidate()
    return True
