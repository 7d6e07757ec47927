"""Field values a scene plan writes: a connection the user set by hand on a generated script
(kept), an entry's values checked against its script's class, and notes for the
``[RequireComponent]``s Unity would have added."""

from __future__ import annotations

from unityscaffold.apply._context import SceneContext
from unityscaffold.apply._editor import SceneEditor
from unityscaffold.apply._references import fits, paths_in, typed_reference, untyped_value
from unityscaffold.apply._typed import typed_value
from unityscaffold.errors import SourceLocation, UserError
from unityscaffold.manifest.model import Component, ObjectPath
from unityscaffold.unity import SceneDocument, ScriptRef
from unityscaffold.unity.catalog import CatalogScript
from unityscaffold.unity.values import FieldValue

__all__ = ["catalog_values", "hand_set_connector", "requirements"]


def hand_set_connector(
    doc: SceneDocument,
    path: str,
    script_field: tuple[ScriptRef, str],
    connector: ScriptRef | None,
    recorded: set[int],
) -> int:
    """The connection (RosConnector, ROSConnection) a generated script's connection field was
    pointed at in Unity, to keep: a scene with two connectors (two robots, say) chooses per
    script. 0 when there is no such choice (no component yet, an empty field, a field that is
    not such a connection, or one apply attached itself, which follows the manifest's
    ``connector``)."""
    if connector is None:
        return 0
    script, field = script_field  # the generated script and its connection field
    try:
        go = doc.find_gameobject(path)
    except UserError:
        return 0
    component = doc.find_component(go, script.guid, script.file_id)
    value = doc.field(component, field) if component is not None else None
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


def catalog_values(
    ctx: SceneContext, editor: SceneEditor, facts: CatalogScript, entry: Component, references: bool
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


def requirements(
    editor: SceneEditor, ctx: SceneContext, facts: CatalogScript, entry: Component
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
