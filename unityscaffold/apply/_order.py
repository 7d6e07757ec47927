"""Sibling order of the manifest's ``objects:``: each with a ``sibling_index`` is put at that
place among its parent's children (or the scene's roots), the others keeping their order.

Done last in a scene, after every GameObject apply makes or removes, so that the places hold
when the run ends and a second run finds nothing to move.
"""

from __future__ import annotations

from collections.abc import Callable

from unityscaffold.errors import located_at
from unityscaffold.manifest.model import SceneObject
from unityscaffold.unity import GameObject, SceneDocument

__all__ = ["order_objects"]


def order_objects(
    doc: SceneDocument, objects: list[SceneObject], now: Callable[[str], str], edits: list[str]
) -> None:
    """Set the sibling order the objects ask for, saying what moved in ``edits``."""
    groups: dict[str, list[SceneObject]] = {}
    for item in objects:
        if item.sibling_index is not None:
            groups.setdefault(now(item.path).rpartition("/")[0], []).append(item)
    for parent_path, items in sorted(groups.items()):
        parent = doc.find_gameobject(parent_path) if parent_path else None
        gos = [doc.find_gameobject(now(item.path)) for item in items]
        before = _siblings(doc, parent)
        wanted = {go.file_id: item.sibling_index or 0 for go, item in zip(gos, items, strict=True)}
        with located_at(items[0].locations.of("sibling_index")):
            changed = doc.place_siblings(parent, wanted)
        if not changed:
            continue
        among = f"among the children of {parent_path}" if parent_path else "among the scene's roots"
        moved = [
            f"move {item.path} to sibling index {item.sibling_index} {among}"
            for go, item in zip(gos, items, strict=True)
            if before.index(go.file_id) != item.sibling_index
        ]
        edits.extend(moved or [f"renumber the order {among} (m_RootOrder)"])


def _siblings(doc: SceneDocument, parent: GameObject | None) -> list[int]:
    listed = doc.children(parent) if parent is not None else doc.roots()
    return [go.file_id for go in listed]
