"""The scene half of a plan: the RosConnector, the generated scripts and the manifest's
components, attached to their GameObjects through the surgical scene patcher.

Components are recognised by GameObject + script, so a second run finds everything in place.
Components an earlier apply attached (per the lock) that the manifest no longer asks for are
removed. GameObjects apply made or adopted are known by fileID (see ``_identity``): one renamed
or moved in Unity is never created a second time. Scenes are only read and edited in memory
here; writing happens in ``apply.run``.
"""

from __future__ import annotations

from unityscaffold.apply._attach import (
    attach_connector,
    attach_entries,
    attach_generated,
    set_references,
)
from unityscaffold.apply._code import CodePlan
from unityscaffold.apply._context import SceneContext, component_script
from unityscaffold.apply._editor import SceneEditor, ScenePlan
from unityscaffold.apply._facts import ScriptFacts
from unityscaffold.apply._identity import moved_objects, now_at, recorded_now
from unityscaffold.apply._lock import LockFile
from unityscaffold.apply._objects import declare_scene_objects, set_builtin_references
from unityscaffold.apply._order import order_objects
from unityscaffold.apply._renames import follow
from unityscaffold.apply._rossharp import RosSharp
from unityscaffold.apply._target import target_for
from unityscaffold.apply.robots import PlannedRobot, place_robots, remove_kept
from unityscaffold.errors import (
    InternalError,
    LocatedError,
    Severity,
    SourceLocation,
    located_at,
)
from unityscaffold.manifest.model import (
    Action,
    Component,
    Connector,
    Manifest,
    SceneObject,
    Service,
    Topic,
)
from unityscaffold.manifest.robot_entry import RobotEntry
from unityscaffold.unity import (
    SceneDocument,
)
from unityscaffold.unity.project import ScriptInfo

__all__ = ["ScenePlan", "plan_scenes"]


def _edit_scene(
    ctx: SceneContext,
    plan: ScenePlan,
    doc: SceneDocument,
    lock: LockFile,
    robots: tuple[PlannedRobot, ...],
) -> None:
    m = ctx.manifest
    now = follow(ctx, plan, doc, lock)
    moves = moved_objects(doc, lock.gameobjects_in(plan.relative))
    doc.prefer(recorded_now(doc, lock.gameobjects_in(plan.relative)))
    recorded = [c for c in lock.components if c.scene == plan.relative]
    owned = {(now_at(c.gameobject, moves) or c.gameobject, c.script) for c in recorded}
    editor = SceneEditor(plan, doc, owned, now)
    # Components apply attached that are gone from the scene: attaching them again is news.
    editor.deleted = {
        (now_at(c.gameobject, moves) or c.gameobject, c.entry)
        for c in recorded
        if not c.file_id or doc.document(c.file_id) is None
    }
    entries = [c for c in m.components if c.scene == plan.relative]
    scripts = {id(c): component_script(ctx, c) for c in entries}
    for c in entries:
        if c.key is not None:
            ref = scripts[id(c)]
            slot = (editor.path(c.gameobject), ref.guid, ref.file_id)
            editor.keys.setdefault(slot, []).append(c.key)
    place_robots(ctx, editor, robots, lock)
    objects = declare_scene_objects(ctx, editor, lock)
    target = target_for(m)
    needs_connector = [
        c
        for c in entries
        if (facts := ctx.facts(scripts[id(c)])) is not None
        and target.connection_class in facts.requires
    ]
    connector_script = None
    if m.connector.scene == plan.relative or needs_connector:
        connector_script = target.connection_script(ctx.rossharp, m.project_root)
    connector_id = attach_connector(ctx, editor, connector_script)
    # connectors apply attached itself may be pruned; one that is not came from the user
    owned_ids = {c.file_id for c in lock.components if c.scene == plan.relative}
    attach_generated(ctx, editor, connector_script, connector_id, owned_ids)
    pending = attach_entries(ctx, editor, entries, scripts, needs_connector, connector_script)
    # References last, once every component of every kind is in the scene: a field may name
    # one that a later entry or object adds.
    if objects is not None:
        set_builtin_references(editor.doc, objects)
    set_references(ctx, editor, pending)
    editor.prune(lock.components, editor.wanted)
    remove_kept(editor)
    _prune_gameobjects(plan, doc, lock)
    objects_here = [o for o in m.objects if o.scene == plan.relative]
    order_objects(doc, objects_here, editor.path, plan.edits)


def _prune_gameobjects(plan: ScenePlan, doc: SceneDocument, lock: LockFile) -> None:
    """GameObjects apply made for entries the manifest no longer has, once nothing is on
    them: deepest first, so that a parent it made emptied by this goes too. Anything a user
    added (a component, a child, a reference) keeps it, and so does one Unity made."""
    kept = set(plan.gameobjects.values())
    recorded = lock.gameobjects_in(plan.relative)
    for path in sorted(recorded, key=lambda p: (-p.count("/"), p)):
        file_id = recorded[path]
        if path in plan.gameobjects or file_id in kept or doc.document(file_id) is None:
            continue
        if doc.remove_made_gameobject(file_id, path):
            plan.edits.append(f"remove GameObject {path} (apply made it; nothing else is on it)")


def _load(manifest: Manifest, relative: str, where: SourceLocation) -> SceneDocument:
    path = manifest.project_root / relative
    if not path.is_file():
        raise LocatedError.at(
            where,
            f"scene {relative} not found in the Unity project {manifest.project_root}",
            hint="scene paths are relative to the project, e.g. Assets/Scenes/Main.unity",
        )
    with located_at(where):
        return SceneDocument.load(path)


def _scene_locations(manifest: Manifest) -> dict[str, SourceLocation]:
    """Where each scene is named: the item's own ``scene`` key, else the top-level one."""
    found: dict[str, SourceLocation] = {}
    items: tuple[Connector | Topic | Service | Action | Component | SceneObject | RobotEntry, ...]
    items = (
        manifest.connector,
        *manifest.topics,
        *manifest.services,
        *manifest.actions,
        *manifest.components,
        *manifest.objects,
        *manifest.robots,
    )
    for item in items:
        own = item.locations.has("scene")
        where = item.locations.of("scene") if own else manifest.locations.of("scene")
        if own or item.scene not in found:
            found.setdefault(item.scene, where)
    return found


def plan_scenes(
    manifest: Manifest,
    code: CodePlan,
    rossharp: RosSharp,
    scripts: dict[str, ScriptInfo],
    lock: LockFile,
    *,
    follow_renames: bool = False,
    robots: tuple[PlannedRobot, ...] = (),
) -> list[ScenePlan]:
    """Every scene the manifest or the lock mentions, edited in memory."""
    names = rossharp.class_names()
    generated = frozenset(s.view.class_name for s in code.scripts)
    known = ScriptFacts(manifest.project_root, rossharp, scripts, names, generated)
    assets = {path: ref for robot in robots for path, ref in robot.asset_refs().items()}
    ctx = SceneContext(manifest, code, rossharp, scripts, names, known, follow_renames, assets)
    named = _scene_locations(manifest)
    locations = dict(named)
    for scene in [c.scene for c in lock.components] + [r.scene for r in lock.robots]:
        locations.setdefault(scene, SourceLocation(str(manifest.path)))
    plans = []
    for relative in sorted(locations):
        if relative not in named and not (manifest.project_root / relative).is_file():
            continue  # a scene only the lock knows, since deleted: nothing to prune
        doc = _load(manifest, relative, locations[relative])
        before = doc.text()
        plan = ScenePlan(manifest.project_root / relative, relative, before, before)
        # Checked before the first walk of the hierarchy (a corrupt one may not end), and again
        # after editing only if something was edited: an unchanged file gives the same answer.
        _refuse_problems(doc)
        with located_at(locations[relative]):
            _edit_scene(ctx, plan, doc, lock, robots)
        if doc.revision:
            _check_own_edits(doc, relative)
        plan.after = doc.text()
        plans.append(plan)
    return plans


def _refuse_problems(doc: SceneDocument) -> None:
    problems = [d for d in doc.validate() if d.severity is Severity.ERROR]
    if problems:
        raise LocatedError(problems)


def _check_own_edits(doc: SceneDocument, relative: str) -> None:
    """The scene was whole before apply edited it, so a problem now is apply's own doing: a
    bug to report, said by object, since the lines are those of a text never written."""
    problems = [d for d in doc.validate() if d.severity is Severity.ERROR]
    if problems:
        raise InternalError(
            f"internal error: apply's edits would leave {relative} inconsistent, which is a bug "
            "in unityscaffold; nothing was written. Please report it with the manifest, the "
            "files it names and this output:\n" + "\n".join(f"  {d.message}" for d in problems)
        )
