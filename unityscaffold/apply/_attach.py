"""A scene's MonoBehaviours attached in two passes, so that entry order never matters.

The first pass makes every component of every kind (the RosConnector, the generated scripts,
the ``components:`` entries and their connectors) with the values that name nothing; the second
sets the fields that refer to GameObjects or components, once everything they may name is in
the scene. The editor says one line per component however many passes touch it.
"""

from __future__ import annotations

from dataclasses import dataclass

from unityscaffold.apply._context import SceneContext
from unityscaffold.apply._editor import SceneEditor
from unityscaffold.apply._facts import NewFields
from unityscaffold.apply._references import paths_in, untyped_value
from unityscaffold.apply._target import target_for
from unityscaffold.apply._typed import check_names
from unityscaffold.apply._wiring import catalog_values, hand_set_connector, requirements
from unityscaffold.apply.robots import refuse_owned_fields
from unityscaffold.errors import SourceLocation
from unityscaffold.manifest.model import Component
from unityscaffold.unity import ObjectRef, ScriptRef
from unityscaffold.unity.catalog import CatalogScript
from unityscaffold.unity.values import FieldValue

__all__ = ["Pending", "attach_connector", "attach_entries", "attach_generated", "set_references"]


@dataclass(frozen=True, slots=True)
class Pending:
    """An entry attached without its references, to finish once the scene is complete."""

    entry: Component
    script: ScriptRef
    facts: CatalogScript | None
    where: SourceLocation


def attach_connector(
    ctx: SceneContext, editor: SceneEditor, connector_script: ScriptRef | None
) -> int:
    """The manifest's connection component (ROS#'s RosConnector, ROS-TCP-Connector's
    ROSConnection), if it lives in this scene: its fileID, else 0."""
    m = ctx.manifest
    if m.connector.scene != editor.plan.relative:
        return 0
    assert connector_script is not None
    where = m.connector.locations.of("gameobject")
    fields = target_for(m).connection_fields(m)
    return editor.attach(
        m.connector.gameobject, True, connector_script, fields, where, "connector"
    ).file_id


def attach_generated(
    ctx: SceneContext,
    editor: SceneEditor,
    connector_script: ScriptRef | None,
    connector_id: int,
    owned_ids: set[int],
) -> None:
    """The generated topic, service and action scripts of this scene."""
    target = target_for(ctx.manifest)
    for script in ctx.code.scripts:
        item = script.item
        if item.scene != editor.plan.relative:
            continue
        if connector_id == 0:
            editor.plan.edits.append(
                f"note: {script.view.class_name}'s {target.connection_field} stays empty "
                f"(the {target.connection_class} is in another scene); it finds one at runtime"
            )
        ref = ScriptRef(
            script.guid, class_name=script.view.class_name, namespace=script.view.namespace
        )
        field = target.connection_field
        chosen = hand_set_connector(
            editor.doc, item.gameobject, (ref, field), connector_script, owned_ids
        )
        fields: list[tuple[str, FieldValue]] = [
            (field, ObjectRef(chosen or connector_id)),
            *script.view.serialized_fields(),
        ]
        where = item.locations.of("gameobject")
        # a new component also gets the fields the manifest leaves alone (a client's timeout)
        new = NewFields((*fields, *script.view.unowned_fields()))
        editor.attach(item.gameobject, item.create, ref, fields, where, script.entry, new=new)


def attach_entries(
    ctx: SceneContext,
    editor: SceneEditor,
    entries: list[Component],
    scripts: dict[int, ScriptRef],
    needs_connector: list[Component],
    connector_script: ScriptRef | None,
) -> list[Pending]:
    """The first pass over ``components:``: each entry's GameObject, the RosConnector ROS#'s
    stock scripts require, and the component with the values that refer to nothing."""
    pending = []
    for entry in entries:
        ref = scripts[id(entry)]
        facts = ctx.facts(ref)
        where = entry.locations.of("gameobject")
        refuse_owned_fields(editor, entry.gameobject, ref, entry.fields)
        editor.gameobject(entry.gameobject, entry.create, where)
        if facts is not None:
            check_names(facts.class_name, facts.fields, entry.fields)
        if entry in needs_connector and connector_script is not None:
            # ROS#'s stock components [RequireComponent(typeof(RosConnector))].
            fields = target_for(ctx.manifest).connection_fields(ctx.manifest)
            label = f"connector for {entry.script}"
            editor.attach(entry.gameobject, entry.create, connector_script, fields, where, label)
        item = Pending(entry, ref, facts, where)
        # a new component gets every field its script serializes; the second pass finds it
        _attach(editor, item, _values(ctx, editor, item, references=False), ctx.defaults(ref))
        pending.append(item)
    return pending


def set_references(ctx: SceneContext, editor: SceneEditor, pending: list[Pending]) -> None:
    """The second pass: every entry with all its values, references included."""
    for item in pending:
        _attach(editor, item, _values(ctx, editor, item, references=True))
        if item.facts is not None:
            requirements(editor, ctx, item.facts, item.entry)


def _values(
    ctx: SceneContext, editor: SceneEditor, item: Pending, references: bool
) -> list[tuple[str, FieldValue]]:
    """The entry's values; without the ones that name something unless ``references``."""
    if item.facts is not None:
        return catalog_values(ctx, editor, item.facts, item.entry, references)
    return [
        (f.name, untyped_value(ctx, editor, f.name, f.value, f.location))
        for f in item.entry.fields
        if references or not any(True for _ in paths_in(f.value))
    ]


def _attach(
    editor: SceneEditor,
    item: Pending,
    values: list[tuple[str, FieldValue]],
    new: NewFields | None = None,
) -> None:
    entry = item.entry
    editor.attach(
        entry.gameobject,
        entry.create,
        item.script,
        values,
        item.where,
        f"component {entry.label}",
        entry.key,
        new,
    )
