"""The edits behind ``SceneDocument``: create GameObjects, attach/update/remove components.

Each edit checks first that its target is ours to change (not a stripped placeholder or an
object inside a prefab instance), then works as line operations on the documents involved.
"""

from __future__ import annotations

import re
from collections.abc import Container, Sequence
from typing import TYPE_CHECKING

from unityscaffold.errors import LocatedError, UserError
from unityscaffold.unity import _fields as F
from unityscaffold.unity import _textops as T
from unityscaffold.unity._emit import emit_field, value_equals
from unityscaffold.unity._split import Doc
from unityscaffold.unity._templates import (
    component_item,
    new_gameobject,
    new_monobehaviour,
    new_transform,
)
from unityscaffold.unity.fileids import stable_file_id
from unityscaffold.unity.generation import SCENE_ROOTS_CLASS, TRANSFORM_CLASSES
from unityscaffold.unity.index import Component, GameObject
from unityscaffold.unity.values import FieldValue, ScriptRef

if TYPE_CHECKING:
    from unityscaffold.unity.scene import SceneDocument

__all__ = ["ensure_component", "ensure_gameobject", "remove_component", "set_fields"]

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


def _refuse(scene: SceneDocument, doc: Doc, message: str, hint: str | None = None) -> LocatedError:
    return LocatedError.at(scene._location(doc), f"{doc.header}: {message}", hint=hint)


def _require_doc_editable(scene: SceneDocument, doc: Doc) -> None:
    if doc.stripped:
        raise _refuse(
            scene,
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
            scene,
            doc,
            "belongs to a prefab instance (its m_CorrespondingSourceObject "
            "is set); changes would become overrides",
            _PREFAB_HINT,
        )


def _require_editable(scene: SceneDocument, go: GameObject) -> None:
    doc = scene.document(go.file_id)
    if go.prefab_instance_id and doc is not None and doc.class_id == 1001:
        raise _refuse(
            scene,
            doc,
            f"'{go.path}' is a prefab instance; adding to it needs a "
            "prefab override, which is not supported",
            _PREFAB_HINT,
        )
    if doc is not None:
        _require_doc_editable(scene, doc)


def _exemplar(scene: SceneDocument, class_id: int) -> Doc | None:
    """An existing object of the class, not from a prefab, whose layout new ones copy."""
    for doc in scene.documents():
        if doc.class_id == class_id and not doc.stripped:
            source = F.ref_value(doc, "m_CorrespondingSourceObject") or F.ref_value(
                doc, "m_PrefabParentObject"
            )
            if not source:
                return doc
    return None


def _emit(scene: SceneDocument, name: str, value: FieldValue) -> list[str]:
    if not _FIELD_NAME_RE.fullmatch(name):
        raise UserError(f"'{name}' is not a serialized field name")
    if name in _STRUCTURAL:
        raise UserError(f"'{name}' is maintained by Unity's object structure and cannot be set")
    try:
        return emit_field(
            name, value, 2, quote_trailing_bracket=scene.generation.qualified_class_identifier
        )
    except (TypeError, ValueError) as exc:
        raise UserError(f"field '{name}': {exc}") from None


def _block_end(scene: SceneDocument, go_doc: Doc) -> int:
    """Index just after a GameObject's own document and its components' (prefab order)."""
    docs = scene.documents()
    wanted = {go_doc.file_id, *F.list_refs(go_doc, "m_Component")}
    return max(i for i, d in enumerate(docs) if d.file_id in wanted) + 1


def _prefab_go_slot(scene: SceneDocument, go_id: int) -> int:
    docs = scene.documents()
    gos = [i for i, d in enumerate(docs) if d.class_id == 1 and not d.stripped]
    later = [i for i in gos if docs[i].file_id > go_id]
    if later:
        return later[0]
    return _block_end(scene, docs[gos[-1]]) if gos else len(docs)


def ensure_gameobject(scene: SceneDocument, path: str, create: bool) -> GameObject:
    found, missing_at = scene._search(path)
    if missing_at is None:
        return scene._view(scene._unique(path, found))
    if not create:
        raise scene._missing_error(path, found, missing_at)
    names = path.strip("/").split("/")
    parent_id: int | None = None
    if missing_at > 0:
        parent_id = scene._unique("/".join(names[:missing_at]), found)
        _require_editable(scene, scene._view(parent_id))
    for level in range(missing_at, len(names)):
        parent_id = _create(scene, parent_id, "/".join(names[: level + 1]), names[level])
    assert parent_id is not None
    return scene._view(parent_id)


def _create(scene: SceneDocument, parent_id: int | None, path: str, name: str) -> int:
    gen = scene.generation
    go_id = stable_file_id(("GameObject", path), _Taken(scene._by_id))
    tr_id = stable_file_id(("Transform", path), _Taken(scene._by_id, go_id))
    roots = scene.hierarchy.roots
    parent_tr: Doc | None = None
    if parent_id is None:
        if not gen.is_scene and roots:
            raise UserError(
                f"{scene.path}: a prefab has a single root; '{path}' would be another",
                hint=f"create it under '{scene.hierarchy.paths[roots[0]]}'",
            )
        order = len(roots)
    else:
        transform_id = scene.hierarchy.nodes[parent_id].transform_id
        parent_tr = scene.document(transform_id) if transform_id is not None else None
        if parent_tr is None:
            raise UserError(f"{scene.path}: '{scene.hierarchy.paths[parent_id]}' has no Transform")
        order = len(F.list_refs(parent_tr, "m_Children"))
    father = parent_tr.file_id if parent_tr is not None else 0
    go_text = new_gameobject(gen, _exemplar(scene, 1), go_id, name, tr_id)
    tr_text = new_transform(
        gen, _exemplar(scene, 4), tr_id, go_id, father, order if gen.root_order else None
    )
    index = None if gen.is_scene else _prefab_go_slot(scene, go_id)
    scene._insert(Doc(1, go_id, False, go_text), index)
    scene._insert(Doc(4, tr_id, False, tr_text), None if index is None else index + 1)
    if parent_tr is not None:
        T.append_list_item(parent_tr, "m_Children", f"  - {{fileID: {tr_id}}}")
        scene._touch(parent_tr)
    elif gen.scene_roots:
        _append_scene_root(scene, tr_id)
    scene._invalidate()
    return go_id


def _append_scene_root(scene: SceneDocument, file_id: int) -> None:
    roots_doc = next(d for d in reversed(scene.documents()) if d.class_id == SCENE_ROOTS_CLASS)
    T.append_list_item(roots_doc, "m_Roots", f"  - {{fileID: {file_id}}}")
    scene._touch(roots_doc)


def ensure_component(
    scene: SceneDocument,
    go: GameObject | str,
    script: ScriptRef,
    fields: Sequence[tuple[str, FieldValue]],
) -> Component:
    target = scene._go(go)
    _require_editable(scene, target)
    existing = scene.find_component(target, script.guid, script.file_id)
    if existing is not None:
        set_fields(scene, scene._doc_of(existing), fields)
        return scene.component(existing.file_id)
    go_doc = scene._doc_of(target.file_id)
    lines = [line for name, value in fields for line in _emit(scene, name, value)]
    comp_id = stable_file_id(
        ("MonoBehaviour", target.path, script.guid, str(script.file_id)), _Taken(scene._by_id)
    )
    text = new_monobehaviour(
        scene.generation, _exemplar(scene, 114), comp_id, target.file_id, script, lines
    )
    index = None if scene.generation.is_scene else _block_end(scene, go_doc)
    scene._insert(Doc(114, comp_id, False, text), index)
    T.append_list_item(go_doc, "m_Component", component_item(scene.generation, 114, comp_id))
    scene._touch(go_doc)
    return scene.component(comp_id)


def set_fields(scene: SceneDocument, doc: Doc, fields: Sequence[tuple[str, FieldValue]]) -> bool:
    _require_doc_editable(scene, doc)
    order = [name for name, _ in fields]
    changed = False
    for position, (name, value) in enumerate(fields):
        lines = _emit(scene, name, value)
        if F.field_span(doc, name) is not None:
            if value_equals(F.parse_field(doc, name), value):
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
        scene._touch(doc)
    return changed


def remove_component(scene: SceneDocument, file_id: int) -> bool:
    doc = scene.document(file_id)
    if doc is None:
        return False
    if doc.class_id in TRANSFORM_CLASSES:
        raise UserError(f"{scene.path}: {doc.header} is a Transform; remove its GameObject instead")
    _require_doc_editable(scene, doc)
    owner = scene.document(F.ref_value(doc, "m_GameObject") or 0)
    if owner is not None and T.remove_list_item(owner, "m_Component", file_id):
        scene._touch(owner)
    scene._remove(doc)
    needle = f"{{fileID: {file_id}}}"
    for other in scene.documents():
        if needle in other.text:
            T.set_text(other, other.text.replace(needle, "{fileID: 0}"))
            scene._touch(other)
    return True
