"""The manifest's ``objects`` in one scene: created if missing, then kept as declared.

Objects go first (parents before children), so that every other entry, and every ``@Path`` a
field refers to, finds them. Only what an entry writes is enforced; the rest stays as the scene
has it. Built-in components' reference fields are set in a pass of their own, once every
component of the scene exists (``set_builtin_references``). A ``primitive``'s components come
first (``_primitives``), and the lock's record of what it made lets a new shape replace them.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.apply._assets import asset_value
from unityscaffold.apply._context import SceneContext
from unityscaffold.apply._editor import SceneEditor
from unityscaffold.apply._lock import LockFile, LockPrimitive
from unityscaffold.apply._primitives import (
    declared_components,
    filter_mesh,
    primitive_components,
    remove_replaced,
    restarted_ids,
    start_component,
)
from unityscaffold.apply._references import typed_reference
from unityscaffold.apply._typed import Resolver, check_names, typed_value
from unityscaffold.apply.robots import refuse_reshaped_robot_objects
from unityscaffold.errors import LocatedError, SourceLocation, UserError, located_at
from unityscaffold.manifest.model import BuiltinComponent, ObjectPath, RectLayout, SceneObject
from unityscaffold.unity import AssetRef, FieldValue, GameObject, InlineMap, SceneDocument
from unityscaffold.unity.builtins import BUILTIN_TAGS, builtin_class
from unityscaffold.unity.rotation import euler_to_quaternion

__all__ = [
    "DeclaredObjects",
    "Hooks",
    "declare_objects",
    "declare_scene_objects",
    "project_tags",
    "set_builtin_references",
]

_RECT_TRANSFORM = 224
_TAGS_RE = re.compile(r"^  tags:\n((?:  - .*\n)*)", re.M)


def _vector(keys: str, values: tuple[float, ...]) -> InlineMap:
    return InlineMap(tuple(zip(keys, values, strict=True)))


def _same_rotation(stored: object, wanted: tuple[float, ...]) -> bool:
    """Whether the scene's quaternion is ``wanted`` up to float32 rounding (and the sign of a
    zero): Unity's Inspector computes it in single precision, so the last digit may differ."""
    if not isinstance(stored, dict) or list(stored) != ["x", "y", "z", "w"]:
        return False
    try:
        values = [float(stored[k]) for k in "xyzw"]
    except (TypeError, ValueError):
        return False
    return all(abs(a - b) <= 1e-6 for a, b in zip(values, wanted, strict=True))


def _transform_fields(item: SceneObject, stored_rotation: object) -> list[tuple[str, FieldValue]]:
    fields: list[tuple[str, FieldValue]] = []
    if item.rotation is not None:
        quaternion = euler_to_quaternion(*item.rotation)
        if not _same_rotation(stored_rotation, quaternion):
            fields.append(("m_LocalRotation", _vector("xyzw", quaternion)))
    if item.position is not None:
        fields.append(("m_LocalPosition", _vector("xyz", item.position)))
    if item.scale is not None:
        fields.append(("m_LocalScale", _vector("xyz", item.scale)))
    if item.rotation is not None:  # what the Inspector shows, as Unity keeps it
        fields.append(("m_LocalEulerAnglesHint", _vector("xyz", item.rotation)))
    if item.ui is not None:
        fields += _rect_fields(item.ui)
    return fields


def _rect_fields(ui: RectLayout) -> list[tuple[str, FieldValue]]:
    named = (
        ("m_AnchorMin", ui.anchor_min),
        ("m_AnchorMax", ui.anchor_max),
        ("m_AnchoredPosition", ui.position),
        ("m_SizeDelta", ui.size),
        ("m_Pivot", ui.pivot),
    )
    return [(name, _vector("xy", value)) for name, value in named if value is not None]


def _gameobject_fields(item: SceneObject) -> list[tuple[str, FieldValue]]:
    fields: list[tuple[str, FieldValue]] = []
    if item.layer is not None:
        fields.append(("m_Layer", item.layer))
    if item.tag is not None:
        fields.append(("m_TagString", item.tag))
    if item.active is not None:
        fields.append(("m_IsActive", item.active))
    return fields


def project_tags(project_root: Path) -> tuple[str, ...]:
    """The built-in tags and the ones ``ProjectSettings/TagManager.asset`` adds."""
    path = project_root / "ProjectSettings" / "TagManager.asset"
    try:
        text = path.read_text(encoding="utf-8")
    except OSError:
        return BUILTIN_TAGS
    match = _TAGS_RE.search(text)
    added = [line[4:].strip() for line in match.group(1).splitlines()] if match else []
    return (*BUILTIN_TAGS, *added)


def _check_tag(item: SceneObject, tags: tuple[str, ...]) -> None:
    if item.tag is None or item.tag in tags:
        return
    raise LocatedError.at(
        item.locations.of("tag"),
        f"unknown tag '{item.tag}'",
        expected=", ".join(tags),
        hint="add the tag in Unity (Edit > Project Settings > Tags and Layers), which writes "
        "ProjectSettings/TagManager.asset",
    )


def _place(doc: SceneDocument, item: SceneObject, path: str) -> tuple[GameObject, bool]:
    """The object's GameObject (at ``path``, where it is now), created if missing; whether it
    was."""
    existed = True
    try:
        doc.find_gameobject(path)
    except UserError:
        existed = False
    go = doc.ensure_gameobject(path, create=True, ui=item.ui is not None)
    transform = doc.document(go.transform_id or 0)
    if item.ui is not None and transform is not None and transform.class_id != _RECT_TRANSFORM:
        raise UserError(
            f"'{item.path}' exists with a Transform, and `ui` asks for a RectTransform",
            hint="add a UI component to it in Unity (which swaps the Transform), or drop `ui`",
        )
    return go, not existed


def _builtin_values(
    comp: BuiltinComponent, references: bool, hooks: Hooks, project_root: Path
) -> list[tuple[str, FieldValue]]:
    builtin = builtin_class(comp.type)
    assert builtin is not None  # the manifest accepts only supported classes
    check_names(builtin.name, builtin.fields, comp.fields)
    values: list[tuple[str, FieldValue]] = []
    for item in comp.fields:
        kind = builtin.kind(item.name) or ""
        if kind.startswith("ref:") != references:
            continue
        if kind.startswith("asset:"):
            value = asset_value(
                kind, item.value, item.location, item.name, project_root, hooks.assets
            )
        else:
            value = typed_value(kind, item.value, item.location, item.name, {}, hooks.resolve)
        values.append((item.name, value))
    return values


@dataclass(frozen=True, slots=True)
class Hooks:
    """What the scene editor lends: where a named object is now (renames followed), a record of
    the objects used (for the lock's identities), the reference resolver, the assets this
    apply writes by path (a robot's materials, whose ``.meta`` may not be on disk yet), and
    the primitives by object path as the lock has them."""

    now: Callable[[str], str]
    record: Callable[[GameObject], None]
    resolve: Resolver
    assets: Mapping[str, AssetRef]
    scene: str = ""
    primitives: Mapping[str, LockPrimitive] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class DeclaredObjects:
    """A scene's declared objects after the first pass, for the reference pass, and what
    their primitives made this run, for the lock."""

    ordered: tuple[SceneObject, ...]
    edits: list[str]
    hooks: Hooks
    project_root: Path
    made: tuple[LockPrimitive, ...]


def declare_scene_objects(
    ctx: SceneContext, editor: SceneEditor, lock: LockFile
) -> DeclaredObjects | None:
    """The manifest's ``objects:`` in this scene, created or kept as declared (their built-in
    components' references are left for ``set_builtin_references``); what their primitives
    made goes to the scene plan, for the lock."""
    scene = editor.plan.relative
    objects = [o for o in ctx.manifest.objects if o.scene == scene]
    if not objects:
        return None
    refuse_reshaped_robot_objects(editor, objects)

    def resolve(path: ObjectPath, declared: str, where: SourceLocation) -> FieldValue:
        return typed_reference(ctx, editor, path, declared, where)

    primitives = lock.primitives_in(scene)
    hooks = Hooks(editor.path, editor.record, resolve, ctx.robot_assets, scene, primitives)
    declared = declare_objects(
        editor.doc, objects, ctx.manifest.project_root, editor.plan.edits, hooks
    )
    editor.plan.primitives += declared.made
    return declared


def declare_objects(
    doc: SceneDocument,
    objects: list[SceneObject],
    project_root: Path,
    edits: list[str],
    hooks: Hooks,
) -> DeclaredObjects:
    """Create and update the scene's declared objects, saying what changed in ``edits``.

    Built-in components get their values that refer to nothing; ``set_builtin_references``
    sets the rest once every component of the scene exists.
    """
    tags = project_tags(project_root)
    ordered = sorted(objects, key=lambda o: o.path.count("/"))
    made: list[LockPrimitive] = []
    for item in ordered:
        _check_tag(item, tags)
        with located_at(item.locations.of("path")):
            go, created = _place(doc, item, hooks.now(item.path))
            hooks.record(go)
            if created:
                edits.append(f"create {'UI object' if item.ui else 'object'} {item.path}")
            revision = doc.revision
            doc.set_fields(go.file_id, _gameobject_fields(item))
            if go.transform_id is not None:
                stored = doc.field(go.transform_id, "m_LocalRotation")
                doc.set_fields(go.transform_id, _transform_fields(item, stored))
            if doc.revision != revision and not created:
                edits.append(f"update object {item.path}")
        if item.primitive is not None:
            made.append(_make_primitive(doc, item, item.primitive, go, hooks, edits, project_root))
        for comp in item.components:
            _ensure(doc, item, comp, hooks, edits, project_root, references=False)
    return DeclaredObjects(tuple(ordered), edits, hooks, project_root, tuple(made))


def _make_primitive(
    doc: SceneDocument,
    item: SceneObject,
    shape: str,
    go: GameObject,
    hooks: Hooks,
    edits: list[str],
    project_root: Path,
) -> LockPrimitive:
    """``item``'s primitive ``shape``: what an earlier shape made and this one does not
    removed, then this shape's components; the lock's record of the ones apply added (now or
    before)."""
    recorded = hooks.primitives.get(item.path)
    with located_at(item.locations.of("primitive")):
        edits += remove_replaced(doc, go, item, recorded)
    earlier = frozenset(recorded.file_ids) if recorded else frozenset()
    restart = restarted_ids(item, recorded)
    made = []
    for comp in primitive_components(item):
        file_id, added = _ensure(doc, item, comp, hooks, edits, project_root, False, restart)
        if added or file_id in earlier:
            made.append(file_id)
    return LockPrimitive(hooks.scene, item.path, shape, tuple(sorted(made)))


def set_builtin_references(doc: SceneDocument, declared: DeclaredObjects) -> None:
    """The declared built-in components' reference fields, in a pass of their own."""
    for item in declared.ordered:
        for comp in declared_components(item):
            _ensure(doc, item, comp, declared.hooks, declared.edits, declared.project_root, True)


def _ensure(
    doc: SceneDocument,
    item: SceneObject,
    comp: BuiltinComponent,
    hooks: Hooks,
    edits: list[str],
    project_root: Path,
    references: bool,
    restart: frozenset[int] = frozenset(),
) -> tuple[int, bool]:
    """One built-in component with its plain values (or only its references): one line for
    it, whichever pass adds or changes it. A new one (or one in ``restart``) starts from what
    Unity's editor would give it. Its fileID, and whether it was added."""
    builtin = builtin_class(comp.type)
    assert builtin is not None  # the manifest accepts only supported classes
    with located_at(comp.location):
        values = _builtin_values(comp, references, hooks, project_root)
        go = hooks.now(item.path)
        found = doc.find_builtin(go, builtin, comp.key)
        if references and not values:
            return (found.file_id if found else 0), False
        if not references and (found is None or found.file_id in restart):
            values = _start_values(doc, item, comp, hooks, project_root) + values
        revision = doc.revision
        file_id = doc.ensure_builtin(go, builtin, comp.key, values).file_id
    added, updated = f"add {comp.type} to {item.path}", f"update {comp.type} on {item.path}"
    if found is None:
        edits.append(added)
    elif doc.revision != revision and added not in edits and updated not in edits:
        edits.append(updated)
    return file_id, found is None


def _start_values(
    doc: SceneDocument, item: SceneObject, comp: BuiltinComponent, hooks: Hooks, root: Path
) -> list[tuple[str, FieldValue]]:
    """What Unity's editor gives a new ``comp``: a primitive's collider the values fitted to
    its mesh; a MeshCollider whose mesh the entry leaves out, the MeshFilter's mesh."""
    start = start_component(item, comp)
    if start is not None:
        return _builtin_values(start, False, hooks, root)
    if comp.type == "MeshCollider" and all(f.name != "m_Mesh" for f in comp.fields):
        go = doc.find_gameobject(hooks.now(item.path))
        mesh = filter_mesh(doc, go, item, root, hooks.assets)
        return [("m_Mesh", mesh)] if mesh is not None else []
    return []
