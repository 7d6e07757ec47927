"""The scene half of a plan: the RosConnector, the generated scripts and the manifest's
components, attached to their GameObjects through the surgical scene patcher.

Components are recognised by GameObject + script, so a second run finds everything in place.
Components an earlier apply attached (per the lock) that the manifest no longer asks for are
removed. GameObjects apply made or adopted are known by fileID (see ``_identity``): one renamed
or moved in Unity is never created a second time. Scenes are only read and edited in memory
here; writing happens in ``apply.run``.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.apply._code import CodePlan
from unityscaffold.apply._facts import ScriptFacts
from unityscaffold.apply._identity import Moved, Named, moved_objects, now_at, report_moves
from unityscaffold.apply._lock import LockComponent, LockFile
from unityscaffold.apply._objects import Hooks, declare_objects
from unityscaffold.apply._references import fits, paths_in, typed_reference, untyped_value
from unityscaffold.apply._rossharp import RosSharp
from unityscaffold.apply._typed import check_names, typed_value
from unityscaffold.errors import LocatedError, Severity, SourceLocation, UserError, located_at
from unityscaffold.manifest.model import (
    Action,
    Component,
    Connector,
    Manifest,
    ObjectPath,
    SceneObject,
    Service,
    Topic,
)
from unityscaffold.unity import (
    Enum,
    GameObject,
    GameObjectNotFound,
    ObjectRef,
    SceneComponent,
    SceneDocument,
    ScriptRef,
)
from unityscaffold.unity.catalog import CatalogScript, rossharp_catalog
from unityscaffold.unity.project import ScriptInfo, find_script, script_ref_for_file
from unityscaffold.unity.ugui import UGUI_SCRIPTS, ugui_class, ugui_script
from unityscaffold.unity.values import FieldValue

__all__ = ["ScenePlan", "plan_scenes"]


@dataclass(slots=True)
class ScenePlan:
    """One scene: its text before and after, and what changed in words."""

    path: Path
    relative: str
    before: str
    after: str
    edits: list[str] = field(default_factory=list)  # one line per change, for the summary
    components: list[LockComponent] = field(default_factory=list)
    gameobjects: dict[str, int] = field(default_factory=dict)  # path -> fileID, for the lock
    followed: list[Moved] = field(default_factory=list)  # manifest paths to rewrite

    @property
    def changed(self) -> bool:
        return self.before != self.after


_CREATE_HINT = (
    "add it in Unity, or set `create: true` on this entry (`create_gameobjects: true` for "
    "every entry) and apply creates it"
)


_REFERENCE_HINT = (
    "add it in Unity, or declare it under `objects:` (`- {path: ...}`) and apply creates it "
    "before it sets references"
)


class _SceneEditor:
    """Applies the desired components to one loaded scene, recording what it did."""

    def __init__(
        self,
        plan: ScenePlan,
        doc: SceneDocument,
        owned: set[tuple[str, str]],
        now: dict[str, str],
    ) -> None:
        self.plan = plan
        self.doc = doc
        self.owned = owned  # (GameObject path, script GUID) of components an earlier apply added
        self.now = now  # manifest path -> where that GameObject is now (--follow-renames)
        self.wanted: set[tuple[str, str]] = set()
        self.attached: set[int] = set()  # fileIDs of the components the manifest asks for
        self.keys: dict[tuple[str, str, int], list[str]] = {}  # (path, GUID, fileID) -> ids
        self.adopted: dict[tuple[str, str, int, str], int] = {}  # ... + id -> instance taken
        # (path, lock entry) of components an earlier apply made that are gone from the scene
        self.deleted: set[tuple[str, str]] = set()

    def path(self, named: str) -> str:
        """Where the GameObject the manifest calls ``named`` is (renames followed)."""
        return self.now.get(named, named)

    def _adoptable(self, go: GameObject, script: ScriptRef) -> SceneComponent | None:
        """An instance of ``script`` on ``go`` that no entry claims (made in Unity, or before
        the manifest gave ids), taken in m_Component order; None if there is none."""
        ids = self.keys.get((go.path, script.guid, script.file_id), [])
        keyed = {c.file_id for k in ids if (c := self.doc.keyed_component(go, script, k))}
        for comp in self.doc.instances(go, script):
            if comp.file_id not in self.attached and comp.file_id not in keyed:
                return comp
        return None

    def gameobject(self, path: str, create: bool, where: SourceLocation) -> GameObject:
        path = self.path(path)
        with located_at(where):
            try:
                go = self.doc.ensure_gameobject(path, create=create)
            except GameObjectNotFound as error:
                raise UserError(error.message, hint=_CREATE_HINT) from None
        self.record(go)
        return go

    def find(self, path: str, where: SourceLocation) -> GameObject:
        """A GameObject a field refers to; recorded too, so that a rename of it is caught."""
        with located_at(where):
            try:
                go = self.doc.find_gameobject(self.path(path))
            except GameObjectNotFound as error:
                raise UserError(error.message, hint=_REFERENCE_HINT) from None
        self.record(go)
        return go

    def record(self, go: GameObject) -> None:
        """Remember the fileIDs of ``go`` and of every GameObject on its path."""
        if go.path in self.plan.gameobjects:
            return
        names = go.path.split("/")
        for level in range(1, len(names) + 1):
            prefix = "/".join(names[:level])
            if prefix not in self.plan.gameobjects:
                found = go if level == len(names) else self.doc.find_gameobject(prefix)
                self.plan.gameobjects[prefix] = found.file_id

    def attach(
        self,
        path: str,
        create: bool,
        script: ScriptRef,
        fields: list[tuple[str, FieldValue]],
        where: SourceLocation,
        entry: str,
        key: str | None = None,
    ) -> SceneComponent:
        go = self.gameobject(path, create, where)
        path = go.path
        self.wanted.add((path, script.guid))
        adopt = None
        if key is None:
            existed = self.doc.find_component(go, script.guid, script.file_id) is not None
        else:
            existed = self.doc.keyed_component(go, script, key) is not None
            slot = (path, script.guid, script.file_id, key)
            if not existed and slot in self.adopted:
                adopt = self.doc.component(self.adopted[slot])
            elif not existed:
                adopt = self._adoptable(go, script)
            existed = existed or adopt is not None
        revision = self.doc.revision
        with located_at(where):
            component = self.doc.ensure_component(go, script, fields, key, adopt)
        self.attached.add(component.file_id)
        if adopt is not None and key is not None:
            self.adopted[(path, script.guid, script.file_id, key)] = adopt.file_id
        name = (script.class_name or script.guid) + (f"#{key}" if key else "")
        added = f"add {name} to {path}"
        # A lock entry (an instance with an id: that very entry) whose component is gone.
        if not existed and (path, entry) in self.deleted:
            readded = f"re-add {name} to {path} (removed in Unity since the last apply)"
            if readded not in self.plan.edits:
                self.plan.edits.append(readded)
        elif not existed:
            self.plan.edits.append(added)
        elif self.doc.revision != revision and not _added_here(self.plan.edits, name, path):
            self.plan.edits.append(f"update {name} on {path}")
        # Only what apply added is apply's to prune later; a component the user attached before
        # the manifest named it stays theirs.
        if not existed:
            self.owned.add((path, script.guid))
        if (path, script.guid) in self.owned:
            self.plan.components.append(
                LockComponent(self.plan.relative, path, script.guid, entry, component.file_id)
            )
        return component

    def prune(self, previous: Iterable[LockComponent], keep: set[tuple[str, str]]) -> None:
        for old in previous:
            if old.scene != self.plan.relative:
                continue
            component = self._recorded(old)
            if component is None or component.file_id in self.attached:
                continue
            keyed = "#" in old.entry  # one of several instances: its fileID alone tells
            if (
                not keyed
                and (self.doc.hierarchy.paths.get(component.gameobject_id), old.script) in keep
            ):
                continue
            if self.doc.remove_component(component):
                self.plan.edits.append(f"remove {old.entry or old.script} from {old.gameobject}")

    def _recorded(self, old: LockComponent) -> SceneComponent | None:
        """The component a lock entry names: by fileID, or by path for a lock without them."""
        if old.file_id:
            if self.doc.document(old.file_id) is None:
                return None  # removed in Unity already: nothing to remove
            found = self.doc.component(old.file_id)
            return found if found.script and found.script.guid == old.script else None
        try:
            go = self.doc.find_gameobject(self.path(old.gameobject))
        except UserError:
            return None  # the GameObject is gone already: nothing to remove
        return self.doc.find_component(go, old.script)


def _added_here(edits: list[str], name: str, path: str) -> bool:
    return f"add {name} to {path}" in edits or any(
        e.startswith(f"re-add {name} to {path} ") for e in edits
    )


def _hand_set_connector(
    doc: SceneDocument,
    path: str,
    script: ScriptRef,
    connector: ScriptRef | None,
    recorded: set[int],
) -> int:
    """The RosConnector a generated script's ``Connector`` was pointed at in Unity, to keep:
    a scene with two connectors (two robots, say) chooses per script. 0 when there is no such
    choice (no component yet, an empty field, a field that is not a RosConnector, or one apply
    attached itself, which follows the manifest's ``connector``)."""
    if connector is None:
        return 0
    try:
        go = doc.find_gameobject(path)
    except UserError:
        return 0
    component = doc.find_component(go, script.guid, script.file_id)
    value = doc.field(component, "Connector") if component is not None else None
    target = value.get("fileID") if isinstance(value, dict) else None
    if not isinstance(target, str) or not target.lstrip("-").isdigit() or target == "0":
        return 0
    other = doc.document(int(target))
    if other is None or other.class_id != 114:
        return 0
    found = doc.component(int(target)).script
    if found is None or found.guid != connector.guid or int(target) in recorded:
        return 0
    return int(target)


def _connector_fields(manifest: Manifest) -> list[tuple[str, FieldValue]]:
    c = manifest.connector
    return [
        ("selectedRosVersion", Enum(int(manifest.ros) - 1)),
        ("SecondsTimeout", int(c.timeout)),
        ("Serializer", Enum(int(c.serializer))),
        ("protocol", Enum(int(c.protocol))),
        ("RosBridgeServerUrl", c.url),
    ]


@dataclass(frozen=True, slots=True)
class _Context:
    manifest: Manifest
    code: CodePlan
    rossharp: RosSharp
    scripts: dict[str, ScriptInfo]
    rossharp_names: dict[str, str]  # GUID -> class of ROS#'s scripts
    known: ScriptFacts
    follow_renames: bool = False

    def planned(self, class_name: str) -> ScriptRef | None:
        """A script this plan generates: known by name before its file exists on disk."""
        for script in self.code.scripts:
            if script.view.class_name == class_name:
                return ScriptRef(
                    script.guid, class_name=class_name, namespace=script.view.namespace
                )
        return None

    def class_of(self, guid: str) -> str | None:
        for script in self.code.scripts:
            if script.guid == guid:
                return script.view.class_name
        info = self.scripts.get(guid)
        return info.class_name if info else self.rossharp_names.get(guid) or ugui_class(guid)

    def facts(self, script: ScriptRef) -> CatalogScript | None:
        """What a ROS# or project script declares (None for a generated or unreadable one)."""
        if any(s.guid == script.guid for s in self.code.scripts):
            return None  # apply writes a generated script's fields itself
        return self.known.of(script.guid)


def _component_script(ctx: _Context, item: Component) -> ScriptRef:
    if item.guid is not None:
        if item.dll_class is None:
            return ScriptRef(item.guid, class_name=ctx.class_of(item.guid))
        namespace, _, name = item.dll_class.rpartition(".")
        return ScriptRef.for_dll_class(item.guid, namespace, name)
    where = item.locations.of("script")
    with located_at(where):
        if item.script.endswith(".cs"):
            listed = next((i for i in ctx.scripts.values() if i.path == item.script), None)
            if listed is not None:
                return ScriptRef(listed.guid, class_name=listed.class_name)
            return script_ref_for_file(ctx.manifest.project_root / item.script)
        found = ctx.planned(item.script) or find_script(
            ctx.manifest.project_root, item.script, index=ctx.scripts
        )
        if found is None and ctx.rossharp.knows(item.script):
            found = ctx.rossharp.script(item.script)
        if found is None:
            found = ugui_script(item.script)
    if found is None:
        names = sorted(
            {info.class_name for info in ctx.scripts.values()}
            | {s.class_name for s in rossharp_catalog().scripts if s.attachable}
            | set(UGUI_SCRIPTS)
        )
        close = difflib.get_close_matches(item.script, names, n=3)
        hint = (
            f"did you mean {' or '.join(close)}?"
            if close
            else ("give the script's class name (its file name) or its path, such as Assets/Foo.cs")
        )
        raise LocatedError.at(where, f"no script named {item.script} in the project", hint=hint)
    return found


def _catalog_values(
    ctx: _Context, editor: _SceneEditor, facts: CatalogScript, entry: Component, references: bool
) -> list[tuple[str, FieldValue]]:
    """The entry's field values checked against the script's class; references only if asked.

    A field of a type the reader could not place (``raw:``) is written as given, as for a
    script without facts.
    """
    enums = ctx.known.enums
    kinds = {f.name: f.unity for f in facts.fields}
    values = []
    for item in entry.fields:
        kind = kinds[item.name]
        if kind.startswith("raw:"):
            if references or not any(True for _ in paths_in(item.value)):
                values.append(
                    (item.name, untyped_value(ctx, editor, item.name, item.value, item.location))
                )
            continue
        if "ref:" in kind and not references:
            continue

        def resolve(path: ObjectPath, declared: str, where: SourceLocation) -> FieldValue:
            return typed_reference(ctx, editor, path, declared, where)

        values.append(
            (item.name, typed_value(kind, item.value, item.location, item.name, enums, resolve))
        )
    return values


def _requirements(
    editor: _SceneEditor, ctx: _Context, facts: CatalogScript, entry: Component
) -> None:
    """Notes for [RequireComponent]s other than RosConnector that are not on the GameObject."""
    go = editor.doc.find_gameobject(editor.path(entry.gameobject))
    comps = editor.doc.components_of(go)
    for required in facts.requires:
        if required == "RosConnector" or any(fits(ctx, c, required) for c in comps):
            continue
        editor.plan.edits.append(
            f"note: {facts.class_name} on {entry.gameobject} requires a {required} there "
            "([RequireComponent]); Unity adds it only when the component is added in the editor"
        )


def _named(ctx: _Context, scene: str) -> list[Named]:
    """Every GameObject path the manifest names in ``scene``, where it names it."""
    m = ctx.manifest
    found = []
    if m.connector.scene == scene:
        found.append(Named(m.connector.gameobject, m.connector.locations.of("gameobject")))
    for script in ctx.code.scripts:
        if script.item.scene == scene:
            found.append(Named(script.item.gameobject, script.item.locations.of("gameobject")))
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


def _follow(ctx: _Context, plan: ScenePlan, doc: SceneDocument, lock: LockFile) -> dict[str, str]:
    """Manifest path -> where its GameObject is now, for the ones Unity renamed or moved.

    Without ``--follow-renames`` any such path stops apply with the lines to change.
    """
    moves = moved_objects(doc, lock.gameobjects_in(plan.relative))
    if not moves:
        return {}
    moved = [
        Moved(named, now)
        for named in _named(ctx, plan.relative)
        if (now := now_at(named.path, moves)) is not None
    ]
    if moved and not ctx.follow_renames:
        raise report_moves(plan.relative, moved)
    plan.followed += moved
    return {m.named.path: m.now for m in moved}


def _edit_scene(ctx: _Context, plan: ScenePlan, doc: SceneDocument, lock: LockFile) -> None:
    m = ctx.manifest
    now = _follow(ctx, plan, doc, lock)
    moves = moved_objects(doc, lock.gameobjects_in(plan.relative))
    recorded = [c for c in lock.components if c.scene == plan.relative]
    owned = {(now_at(c.gameobject, moves) or c.gameobject, c.script) for c in recorded}
    editor = _SceneEditor(plan, doc, owned, now)
    # Components apply attached that are gone from the scene: attaching them again is news.
    editor.deleted = {
        (now_at(c.gameobject, moves) or c.gameobject, c.entry)
        for c in recorded
        if not c.file_id or doc.document(c.file_id) is None
    }
    connector_id = 0
    connector_script = None
    scripts = {id(c): _component_script(ctx, c) for c in m.components if c.scene == plan.relative}
    for c in m.components:
        if c.scene == plan.relative and c.key is not None:
            ref = scripts[id(c)]
            slot = (editor.path(c.gameobject), ref.guid, ref.file_id)
            editor.keys.setdefault(slot, []).append(c.key)
    objects = [o for o in m.objects if o.scene == plan.relative]
    if objects:

        def resolve(path: ObjectPath, declared: str, where: SourceLocation) -> FieldValue:
            return typed_reference(ctx, editor, path, declared, where)

        hooks = Hooks(editor.path, editor.record, resolve)
        declare_objects(doc, objects, m.project_root, plan.edits, hooks)
    needs_connector = [
        c
        for c in m.components
        if c.scene == plan.relative
        and (facts := ctx.facts(scripts[id(c)])) is not None
        and "RosConnector" in facts.requires
    ]
    if m.connector.scene == plan.relative or needs_connector:
        connector_script = ctx.rossharp.script("RosConnector")
    if m.connector.scene == plan.relative:
        assert connector_script is not None
        where = m.connector.locations.of("gameobject")
        connector_id = editor.attach(
            m.connector.gameobject, True, connector_script, _connector_fields(m), where, "connector"
        ).file_id
    # connectors apply attached itself may be pruned; one that is not came from the user
    owned_ids = {c.file_id for c in lock.components if c.scene == plan.relative}
    for script in ctx.code.scripts:
        item = script.item
        if item.scene != plan.relative:
            continue
        if connector_id == 0:
            plan.edits.append(
                f"note: {script.view.class_name}'s Connector stays empty (the "
                "RosConnector is in another scene); it finds one at runtime"
            )
        ref = ScriptRef(
            script.guid, class_name=script.view.class_name, namespace=script.view.namespace
        )
        chosen = _hand_set_connector(doc, item.gameobject, ref, connector_script, owned_ids)
        fields: list[tuple[str, FieldValue]] = [
            ("Connector", ObjectRef(chosen or connector_id)),
            *script.view.serialized_fields(),
        ]
        editor.attach(
            item.gameobject,
            item.create,
            ref,
            fields,
            item.locations.of("gameobject"),
            script.entry,
        )
    deferred = []
    for entry in m.components:
        if entry.scene != plan.relative:
            continue
        ref = scripts[id(entry)]
        facts = ctx.facts(ref)
        where = entry.locations.of("gameobject")
        # Created before the fields are read, so they may refer to it.
        editor.gameobject(entry.gameobject, entry.create, where)
        if facts is not None:
            check_names(facts.class_name, facts.fields, entry.fields)
        if entry in needs_connector and connector_script is not None:
            # ROS#'s stock components [RequireComponent(typeof(RosConnector))].
            editor.attach(
                entry.gameobject,
                entry.create,
                connector_script,
                _connector_fields(m),
                where,
                f"connector for {entry.script}",
            )
        if facts is None:
            values = [
                (f.name, untyped_value(ctx, editor, f.name, f.value, f.location))
                for f in entry.fields
            ]
        else:
            # References are set once every component is there: a field may name one that a
            # later entry attaches.
            values = _catalog_values(ctx, editor, facts, entry, references=False)
            deferred.append((entry, ref, facts, where))
        _attach_component(editor, entry, ref, values, where)
    for entry, ref, facts, where in deferred:
        values = _catalog_values(ctx, editor, facts, entry, references=True)
        _attach_component(editor, entry, ref, values, where)
        _requirements(editor, ctx, facts, entry)
    editor.prune(lock.components, editor.wanted)
    _prune_gameobjects(plan, doc, lock)


def _attach_component(
    editor: _SceneEditor,
    entry: Component,
    ref: ScriptRef,
    values: list[tuple[str, FieldValue]],
    where: SourceLocation,
) -> None:
    editor.attach(
        entry.gameobject, entry.create, ref, values, where, f"component {entry.label}", entry.key
    )


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
    items: tuple[Connector | Topic | Service | Action | Component | SceneObject, ...] = (
        manifest.connector,
        *manifest.topics,
        *manifest.services,
        *manifest.actions,
        *manifest.components,
        *manifest.objects,
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
) -> list[ScenePlan]:
    """Every scene the manifest or the lock mentions, edited in memory."""
    names = rossharp.class_names()
    generated = frozenset(s.view.class_name for s in code.scripts)
    known = ScriptFacts(manifest.project_root, rossharp, scripts, names, generated)
    ctx = _Context(manifest, code, rossharp, scripts, names, known, follow_renames)
    named = _scene_locations(manifest)
    locations = dict(named)
    for old in lock.components:
        locations.setdefault(old.scene, SourceLocation(str(manifest.path)))
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
            _edit_scene(ctx, plan, doc, lock)
        if doc.revision:
            _refuse_problems(doc)
        plan.after = doc.text()
        plans.append(plan)
    return plans


def _refuse_problems(doc: SceneDocument) -> None:
    problems = [d for d in doc.validate() if d.severity is Severity.ERROR]
    if problems:
        raise LocatedError(problems)
