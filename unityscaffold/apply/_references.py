"""``@Path`` values of a manifest's fields, resolved in a scene.

A field whose declared type is known (ROS#'s scripts from the catalog, the project's from their
``.cs``) gets what that type holds: the GameObject, its transform, or the one component on it
that fits (``@Path:Class`` chooses). A field of a script apply cannot read gets the GameObject,
or its Transform when the field's name ends in ``Transform``.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Protocol

from unityscaffold.errors import LocatedError, SourceLocation
from unityscaffold.manifest.model import EmptyReference, ObjectPath, StructValue
from unityscaffold.unity import GameObject, ObjectRef, SceneComponent, SceneDocument, ScriptRef
from unityscaffold.unity.catalog import CatalogScript
from unityscaffold.unity.values import FieldValue

__all__ = ["Classes", "Finder", "fits", "label", "paths_in", "typed_reference", "untyped_value"]

_TRANSFORM_CLASS_ID = 4
_RECT_TRANSFORM_CLASS_ID = 224


class Classes(Protocol):
    """What is known about the scripts in a scene: their class names and declarations."""

    def class_of(self, guid: str) -> str | None: ...

    def facts(self, script: ScriptRef) -> CatalogScript | None: ...


class Finder(Protocol):
    """The scene being edited, and how a manifest path finds its GameObject there."""

    doc: SceneDocument

    def find(self, path: str, where: SourceLocation) -> GameObject: ...


def _by_name(
    ctx: Classes, editor: Finder, name: str, value: ObjectPath, where: SourceLocation
) -> ObjectRef:
    """``@Path`` for a field whose type is unknown: guessed from the field's name."""
    doc = editor.doc
    go = editor.find(value.path, where)
    wanted = value.component or ("Transform" if name.lower().endswith("transform") else None)
    if wanted is None:
        return ObjectRef(go.file_id)
    for comp in doc.components_of(go):
        script_name = ctx.class_of(comp.script.guid) if comp.script else None
        if wanted in (comp.type_name, script_name) or (
            wanted == "Transform" and comp.class_id == _TRANSFORM_CLASS_ID
        ):
            return ObjectRef(comp.file_id)
    raise LocatedError.at(
        where,
        f"{value.path} has no {wanted} component",
        hint="components there: " + ", ".join(c.type_name for c in doc.components_of(go)),
    )


def untyped_value(
    ctx: Classes, editor: Finder, name: str, value: object, where: SourceLocation
) -> FieldValue:
    """A field value of a script apply cannot read, written as given (references resolved,
    ``null`` an empty one)."""
    if isinstance(value, ObjectPath):
        return _by_name(ctx, editor, name, value, where)
    if isinstance(value, EmptyReference):
        return ObjectRef(0)
    if isinstance(value, StructValue):
        return {k: untyped_value(ctx, editor, k, v, where) for k, v in value.items}
    if isinstance(value, tuple):
        return [untyped_value(ctx, editor, name, v, where) for v in value]
    return value  # type: ignore[return-value]


# Unity's abstract component classes and the built-in classes a field of that type accepts.
_UNITY_BASES: dict[str, frozenset[str]] = {
    "Collider": frozenset({"BoxCollider", "SphereCollider", "CapsuleCollider", "MeshCollider"}),
    "Joint": frozenset(
        {"HingeJoint", "FixedJoint", "SpringJoint", "CharacterJoint", "ConfigurableJoint"}
    ),
    "Renderer": frozenset({"MeshRenderer", "SkinnedMeshRenderer", "LineRenderer"}),
}


def fits(ctx: Classes, comp: SceneComponent, wanted: str) -> bool:
    """Whether a component can stand in a field declared as class ``wanted``."""
    if wanted in ("Transform", "Component"):
        return comp.class_id in (_TRANSFORM_CLASS_ID, _RECT_TRANSFORM_CLASS_ID) or (
            wanted == "Component"
        )
    if wanted == "RectTransform":
        return comp.class_id == _RECT_TRANSFORM_CLASS_ID
    if comp.script is None:
        return comp.type_name == wanted or comp.type_name in _UNITY_BASES.get(wanted, ())
    if wanted in ("MonoBehaviour", "Behaviour"):
        return True
    name = ctx.class_of(comp.script.guid)
    if name == wanted:
        return True
    facts = ctx.facts(comp.script)
    return facts is not None and wanted in facts.bases


def typed_reference(
    ctx: Classes, editor: Finder, value: ObjectPath, declared: str, where: SourceLocation
) -> ObjectRef:
    """``@Path`` (or ``@Path:Class``) for a field declared as ``declared``: the GameObject, its
    transform, or the one component on it that fits."""
    wanted = declared.rsplit(".", 1)[-1]
    doc = editor.doc
    go = editor.find(value.path, where)
    if wanted == "GameObject" and value.component is None:
        return ObjectRef(go.file_id)
    comps = doc.components_of(go)
    fitting = [c for c in comps if fits(ctx, c, wanted)]
    if value.component is not None:
        fitting = [c for c in fitting if value.component in (c.type_name, label(ctx, c))]
    if len(fitting) == 1:
        return ObjectRef(fitting[0].file_id)
    there = ", ".join(label(ctx, c) for c in comps) or "nothing"
    if not fitting:
        chosen = f" named {value.component}" if value.component else ""
        raise LocatedError.at(
            where,
            f"{value.path} has no {wanted}{chosen} for this field (a {wanted} field)",
            hint=f"components there: {there}",
        )
    raise LocatedError.at(
        where,
        f"{value.path} has {len(fitting)} components that fit this {wanted} field: "
        + ", ".join(label(ctx, c) for c in fitting),
        hint=f"choose one with @{value.path}:<Class>",
    )


def label(ctx: Classes, comp: SceneComponent) -> str:
    return (ctx.class_of(comp.script.guid) if comp.script else None) or comp.type_name


def paths_in(value: object) -> Iterable[str]:
    if isinstance(value, ObjectPath):
        yield value.path
    elif isinstance(value, StructValue):
        for _, item in value.items:
            yield from paths_in(item)
    elif isinstance(value, tuple):
        for item in value:
            yield from paths_in(item)
