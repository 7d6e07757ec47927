"""Sibling order: where a GameObject is among its parent's children or the scene's roots.

Unity keeps the order in the parent Transform's ``m_Children``; for roots in the ``SceneRoots``
document's ``m_Roots`` (2022+), or in each root Transform's ``m_RootOrder`` before, where every
child's ``m_RootOrder`` is its sibling index too. The lists are permuted in place, item lines
kept as written, so that only the order changes.
"""

from __future__ import annotations

from collections.abc import Mapping

from unityscaffold.errors import UserError
from unityscaffold.unity import _fields as F
from unityscaffold.unity import _textops as T
from unityscaffold.unity._documents import Documents
from unityscaffold.unity._split import Doc

__all__ = ["place_siblings", "sibling_order"]


def sibling_order(current: list[int], wanted: Mapping[int, int]) -> list[int]:
    """``current`` with each of ``wanted``'s nodes at its index, the others in their order
    around them. An index past the last sibling is a ``UserError``."""
    others = [n for n in current if n not in wanted]
    order = list(others)
    # Ascending, so that each goes where asked: those placed before it are all in front of it.
    for node, index in sorted(wanted.items(), key=lambda item: item[1]):
        if index > len(order):
            there = (
                "the only one there is 0"
                if len(current) == 1
                else f"those there are numbered 0 to {len(current) - 1}"
            )
            raise UserError(
                f"sibling_index {index} is past the last sibling ({there})",
                hint="count the siblings as the Hierarchy window lists them, from 0",
            )
        order.insert(index, node)
    return order


def place_siblings(docs: Documents, parent: int | None, wanted: Mapping[int, int]) -> bool:
    """Put ``wanted``'s nodes (GameObject fileID -> index) at their places among ``parent``'s
    children (the roots when None); whether the file changed."""
    hierarchy = docs.hierarchy
    current = list(hierarchy.roots if parent is None else hierarchy.nodes[parent].children)
    order = sibling_order(current, wanted)
    if order == current and not docs.era.root_order:
        return False
    changed = False
    if parent is not None:
        transform_id = hierarchy.nodes[parent].transform_id
        changed = _permute(docs, docs.require(transform_id or 0), "m_Children", current, order)
    elif docs.era.scene_roots:
        roots = docs.scene_roots()
        assert roots is not None  # the era has one
        changed = _permute(docs, roots, "m_Roots", current, order)
    if docs.era.root_order:
        changed = _number(docs, order) or changed
    if changed:
        docs.invalidate()
    return changed


def _permute(docs: Documents, doc: Doc, key: str, current: list[int], order: list[int]) -> bool:
    """Reorder the list ``key`` of ``doc`` (one item per node of ``current``) as ``order``."""
    listed = F.list_refs(doc, key)
    if len(listed) != len(current):
        raise UserError(
            f"{docs.path}: {key} of {doc.header} does not list each sibling once; sibling "
            "order cannot be set",
            hint="open the scene in Unity and save it, which rewrites the list",
        )
    if order == current:
        return False
    item = dict(zip(current, listed, strict=True))
    T.replace_field(doc, key, [f"  {key}:", *(f"  - {{fileID: {item[n]}}}" for n in order)])
    docs.touch(doc)
    return True


def _number(docs: Documents, order: list[int]) -> bool:
    """``m_RootOrder`` of each sibling set to its index (files before 2022)."""
    changed = False
    for index, node_id in enumerate(order):
        node = docs.hierarchy.nodes[node_id]
        transform = docs.get(node.transform_id) if node.transform_id is not None else None
        if transform is None or transform.stripped:
            raise UserError(
                f"{docs.path}: a prefab instance is among the siblings; in a scene of a Unity "
                "before 2022 its place is one of the prefab's overrides, which apply does not set",
                hint="order these objects in Unity, or drop sibling_index here",
            )
        line = f"  m_RootOrder: {index}"
        if F.field_span(transform, "m_RootOrder") is None:
            T.insert_field(transform, [line], after="m_Father")
        elif F.field_value(transform, "m_RootOrder") != str(index):
            T.replace_field(transform, "m_RootOrder", [line])
        else:
            continue
        docs.touch(transform)
        changed = True
    return changed
