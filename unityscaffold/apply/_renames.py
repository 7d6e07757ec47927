"""The manifest's GameObject paths checked against the lock's fileIDs before a scene is edited:
each one Unity renamed or moved stops apply at the lines that name it, or, with
``--follow-renames``, is used where it is now (see ``_identity`` for why)."""

from __future__ import annotations

from unityscaffold.apply._context import SceneContext
from unityscaffold.apply._editor import ScenePlan
from unityscaffold.apply._identity import (
    Implied,
    Moved,
    Named,
    moved_objects,
    now_at,
    report_moves,
)
from unityscaffold.apply._lock import LockFile
from unityscaffold.apply._references import paths_in
from unityscaffold.unity import SceneDocument

__all__ = ["follow"]


def _named_paths(ctx: SceneContext, scene: str) -> list[Named]:
    """Every GameObject path the manifest names in ``scene``, where it names it."""
    m = ctx.manifest
    found = []
    connector = m.connector
    if connector.scene == scene:
        written = connector.locations.has("gameobject")
        implied: Implied = "connector" if m.locations.has("connector") else "section"
        where = connector.locations.of("gameobject")
        found.append(Named(connector.gameobject, where, implied="" if written else implied))
    for script in ctx.code.scripts:
        made = script.item
        if made.scene != scene:
            continue
        if made.locations.has("gameobject"):
            found.append(Named(made.gameobject, made.locations.of("gameobject")))
        elif connector.scene != scene or connector.gameobject != made.gameobject:
            found.append(Named(made.gameobject, made.locations.item, implied="entry"))
        # else it is the RosConnector's GameObject, which its own entry names
    for entry in m.components:
        if entry.scene != scene:
            continue
        found.append(Named(entry.gameobject, entry.locations.of("gameobject")))
        for item in entry.fields:
            found += [Named(p, item.location, True) for p in paths_in(item.value)]
    for obj in m.objects:
        if obj.scene != scene:
            continue
        found.append(Named(obj.path, obj.locations.of("path")))
        for comp in obj.components:
            for item in comp.fields:
                found += [Named(p, item.location, True) for p in paths_in(item.value)]
    return found


def follow(
    ctx: SceneContext, plan: ScenePlan, doc: SceneDocument, lock: LockFile
) -> dict[str, str]:
    """Manifest path -> where its GameObject is now, for the ones Unity renamed or moved.

    Without ``--follow-renames`` any such path stops apply with the lines to change.
    """
    moves = moved_objects(doc, lock.gameobjects_in(plan.relative))
    if not moves:
        return {}
    taken = set(doc.hierarchy.paths.values())
    moved = [
        Moved(named, now, replaced=named.path in taken)
        for named in _named_paths(ctx, plan.relative)
        if (now := now_at(named.path, moves)) is not None
    ]
    if moved and not ctx.follow_renames:
        raise report_moves(plan.relative, moved)
    plan.followed += moved
    return {m.named.path: m.now for m in moved}
