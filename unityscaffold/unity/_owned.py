"""Edits for owned objects (see ``owned``): created when missing, owned fields enforced, the
rest kept."""

from __future__ import annotations

from collections.abc import Collection, Sequence

from unityscaffold.errors import UserError
from unityscaffold.unity import _fields as F
from unityscaffold.unity import _textops as T
from unityscaffold.unity._builders import (
    component_item,
    new_builtin,
    new_gameobject,
    new_monobehaviour,
    new_transform,
)
from unityscaffold.unity._documents import Documents
from unityscaffold.unity._edits import (
    _emit,
    _exemplar,
    remove_component,
    remove_empty_gameobject,
    set_fields,
)
from unityscaffold.unity._split import Doc
from unityscaffold.unity.owned import OwnedComponent, OwnedDocument, OwnedObject
from unityscaffold.unity.values import FieldValue, Verbatim

__all__ = ["remove_owned", "sync_owned"]


def sync_owned(
    docs: Documents, objects: Sequence[OwnedObject], documents: Sequence[OwnedDocument]
) -> list[str]:
    """Make ``objects`` (parents before children) and ``documents`` as declared; one line per
    object that was created or changed."""
    era = docs.era
    if era.root_order or not era.modern_prefab_fields or not era.scene_roots:
        raise UserError(
            f"{docs.path} was saved by a Unity older than 2022.2; robots are written in "
            "Unity 2022.3's layout",
            hint="open the scene in Unity 2022.3 or later and save it once",
        )
    said: list[str] = []
    for item in documents:
        _document(docs, item, said)
    for obj in objects:
        revision = docs.revision
        created = docs.get(obj.file_id) is None
        if created:
            _create(docs, obj)
        _enforce(docs, obj, created)
        for component in obj.components:
            _component(docs, obj, component)
        if created:
            said.append(f"create {obj.path}")
        elif docs.revision != revision:
            said.append(f"update {obj.path}")
    docs.invalidate()
    return said


def _document(docs: Documents, item: OwnedDocument, said: list[str]) -> None:
    doc = docs.get(item.file_id)
    if doc is None:
        stripped = item.text[: item.text.index("\n")].endswith(" stripped")
        docs.insert(Doc(item.class_id, item.file_id, stripped, item.text))
        said.append(f"create {_label(item)}")
    elif doc.text != item.text:
        T.set_text(doc, item.text)
        docs.touch(doc)
        said.append(f"update {_label(item)}")


def _label(item: OwnedDocument) -> str:
    return f"--- !u!{item.class_id} &{item.file_id}"


def _create(docs: Documents, obj: OwnedObject) -> None:
    era = docs.era
    go = new_gameobject(era, _exemplar(docs, 1), obj.file_id, obj.name, obj.transform_id)
    tr = new_transform(era, _exemplar(docs, 4), obj.transform_id, obj.file_id, obj.parent, None)
    docs.insert(Doc(1, obj.file_id, False, go))
    docs.insert(Doc(4, obj.transform_id, False, tr))


def _enforce(docs: Documents, obj: OwnedObject, created: bool) -> None:
    go, tr = docs.require(obj.file_id), docs.require(obj.transform_id)
    if go.class_id != 1 or tr.class_id != 4:
        raise UserError(
            f"{docs.path}: &{obj.file_id} or &{obj.transform_id} is not the GameObject and "
            f"Transform apply made for {obj.path}",
            hint="the scene was edited outside Unity; restore it from version control",
        )
    put = _fill if created else set_fields
    put(docs, go, [("m_ObjectHideFlags", obj.hide_flags), ("m_Name", obj.name)])
    put(docs, tr, [("m_ObjectHideFlags", obj.hide_flags), *obj.transform])
    wanted = [obj.transform_id, *(c.file_id for c in obj.components)]
    classes = [4, *(c.class_id for c in obj.components)]
    items = [component_item(docs.era, c, i) for i, c in zip(wanted, classes, strict=True)]
    _list(docs, go, "m_Component", wanted, items)
    _list(
        docs, tr, "m_Children", list(obj.children), [f"  - {{fileID: {i}}}" for i in obj.children]
    )
    _father(docs, obj, tr)


def _list(docs: Documents, doc: Doc, key: str, wanted: list[int], items: list[str]) -> None:
    """``key``'s list: the owned ``wanted`` first, in order, then the others it held."""
    held = F.list_refs(doc, key)
    kept = [i for i in held if i not in set(wanted)]
    order = wanted + kept
    if held == order:
        return
    lines = items + [line for i in kept for line in _held_line(doc, key, i)]
    T.replace_field(doc, key, [f"  {key}:", *lines] if lines else [f"  {key}: []"])
    docs.touch(doc)


def _held_line(doc: Doc, key: str, file_id: int) -> list[str]:
    text = F.field_text(doc, key) or ""
    return [line for line in text.split("\n") if f"{{fileID: {file_id}}}" in line][:1]


def _father(docs: Documents, obj: OwnedObject, tr: Doc) -> None:
    was = F.ref_value(tr, "m_Father")
    if was != obj.parent:
        T.replace_field(tr, "m_Father", [f"  m_Father: {{fileID: {obj.parent}}}"])
        docs.touch(tr)
        _leave(docs, was, obj.transform_id)
    if obj.parent:
        # an owned parent lists its owned children itself; another one (the robot's root
        # under the user's object) gets it appended
        father = docs.require(obj.parent)
        if obj.transform_id not in F.list_refs(father, "m_Children"):
            if F.field_span(father, "m_Children") is None:
                T.insert_field(father, ["  m_Children: []"], before="m_Father")
            T.append_list_item(father, "m_Children", f"  - {{fileID: {obj.transform_id}}}")
            docs.touch(father)
        return
    roots = docs.scene_roots()
    if roots is not None and obj.transform_id not in F.list_refs(roots, "m_Roots"):
        T.append_list_item(roots, "m_Roots", f"  - {{fileID: {obj.transform_id}}}")
        docs.touch(roots)


def _leave(docs: Documents, father: int | None, transform_id: int) -> None:
    """A Transform moved to another parent (a link whose joint now names another parent)
    leaves the list of the one it had: its old parent kept it among the children it did not
    own, and the scene's roots list a root."""
    if father:
        old = docs.get(father)
        if old is not None and T.remove_list_item(old, "m_Children", transform_id):
            docs.touch(old)
        return
    roots = docs.scene_roots()
    if roots is not None and T.remove_list_item(roots, "m_Roots", transform_id):
        docs.touch(roots)


def _component(docs: Documents, obj: OwnedObject, component: OwnedComponent) -> None:
    doc = docs.get(component.file_id)
    if doc is None:
        doc = Doc(component.class_id, component.file_id, False, _new(docs, obj, component))
        docs.insert(doc)
        _fill(docs, doc, list(component.fields))
    else:
        set_fields(docs, doc, list(component.fields))


def _fill(docs: Documents, doc: Doc, fields: Sequence[tuple[str, FieldValue]]) -> bool:
    """``set_fields`` for a document made in this run: its fields are replaced without first
    reading what they hold (a YAML parse per field, most of the time of a large import)."""
    spans = F.spans(doc)
    missing = [(name, value) for name, value in fields if name not in spans]
    present = [(name, value) for name, value in fields if name in spans]
    if len({name for name, _ in present}) < len(present):  # a field given twice: in order
        for name, value in present:
            T.replace_field(doc, name, _emit(docs, name, value))
    elif present:
        # one new text, not one per field: each replacement made the document's text again
        # and found its keys again, the most of a large import's scene edits
        emitted = {name: _emit(docs, name, value) for name, value in present}
        pieces, at = [], 0
        for name in sorted(emitted, key=lambda n: spans[n][0]):
            start, end = spans[name]
            pieces += [doc.text[at:start], *(line + "\n" for line in emitted[name])]
            at = end
        T.set_text(doc, "".join(pieces) + doc.text[at:])
    docs.touch(doc)
    return set_fields(docs, doc, missing) if missing else True


def _new(docs: Documents, obj: OwnedObject, component: OwnedComponent) -> str:
    if component.builtin is not None:
        return new_builtin(component.file_id, obj.file_id, component.builtin)
    assert component.script is not None
    given = dict(component.fields)
    lines: list[str] = []
    for name, default in component.defaults:
        if name in given:
            lines += _emit(docs, name, given[name])
        elif isinstance(default, Verbatim):
            lines += default.text.split("\n")
        else:
            lines += _emit(docs, name, default)
    exemplar = _exemplar(docs, 114)
    return new_monobehaviour(
        docs.era, exemplar, component.file_id, obj.file_id, component.script, lines
    )


_PREFAB_INSTANCE = 1001


def _remove_instance_part(docs: Documents, doc: Doc) -> None:
    """A model instance's document (the PrefabInstance or a stripped object of its source);
    a stripped Transform leaves its parent's children too."""
    if doc.class_id == 4:
        for father in docs.in_order:
            if father.class_id == 4 and T.remove_list_item(father, "m_Children", doc.file_id):
                docs.touch(father)
    docs.remove(doc)


def remove_owned(docs: Documents, ids: Collection[int]) -> tuple[list[str], dict[int, str]]:
    """Remove what an earlier run owned and this one no longer makes (``ids``): components and
    documents first, then GameObjects, deepest first, each only when nothing else is on it
    (another component, a child, a reference). Returns the paths of the GameObjects removed,
    and those kept by fileID (the ids of every object kept, GameObject or not, are its keys)."""
    hierarchy = docs.hierarchy
    paths = {i: hierarchy.paths.get(i, f"&{i}") for i in ids}
    for file_id in sorted(ids):
        doc = docs.get(file_id)
        if doc is not None and (doc.stripped or doc.class_id == _PREFAB_INSTANCE):
            _remove_instance_part(docs, doc)
        elif doc is not None and doc.class_id not in (1, 4):
            remove_component(docs, file_id)
    gameobjects = [i for i in ids if (doc := docs.get(i)) is not None and doc.class_id == 1]
    removed = []
    for file_id in sorted(gameobjects, key=lambda i: (-paths[i].count("/"), paths[i])):
        if remove_empty_gameobject(docs, file_id):
            removed.append(paths[file_id])
    docs.invalidate()
    return removed, {i: paths[i] for i in ids if i in docs}
