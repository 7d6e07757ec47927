"""The fields a robot's import owns on its components, and the entries refused for setting one.

``place_robots`` enforces what the URDF decides on every run (``unity.owned``). A
``components:`` entry, or a built-in component of an ``objects:`` entry, that reaches one of
those components and sets one of those fields would put its own value back after the import
on every apply: each run would report the same update while ``--check`` passed. Such an entry
is refused at the field; the fields the import leaves alone (a Rigidbody's drag, a
HingeJoint's connected anchor, which Unity recomputes) and the components a user adds stay
theirs to set.
"""

from __future__ import annotations

from collections.abc import Sequence

from unityscaffold.apply._editor import RobotFields, SceneEditor
from unityscaffold.errors import LocatedError, UserError
from unityscaffold.manifest.model import ComponentField, SceneObject
from unityscaffold.unity import GameObject, ScriptRef
from unityscaffold.unity.builtins import builtin_class

__all__ = ["refuse_owned_builtin_fields", "refuse_owned_fields"]


# Fields a robot's manifest entry decides rather than its URDF
_ENTRY_KEYS = {"m_IsKinematic": "kinematic", "m_UseGravity": "gravity", "m_Convex": "convex"}


def refuse_owned_fields(
    editor: SceneEditor, gameobject: str, script: ScriptRef, fields: Sequence[ComponentField]
) -> None:
    """A ``components:`` entry for ``script`` on ``gameobject`` that sets a field a robot's
    import owns on that script's component there (whichever instance the entry takes)."""
    go = _found(editor, gameobject)
    if go is None:
        return
    for component in editor.doc.instances(go, script):
        _refuse(go, editor.robot_fields.get(component.file_id), fields)


def refuse_owned_builtin_fields(editor: SceneEditor, objects: Sequence[SceneObject]) -> None:
    """An ``objects:`` entry's built-in component without an ``id`` is the first of its class
    on the object: on a robot's object, the import's one (a link's Rigidbody)."""
    for item in objects:
        go = _found(editor, item.path)
        if go is None:
            continue
        for comp in item.components:
            builtin = builtin_class(comp.type)
            if comp.key is not None or builtin is None:
                continue
            found = editor.doc.find_builtin(go, builtin)
            if found is not None:
                _refuse(go, editor.robot_fields.get(found.file_id), comp.fields)


def _found(editor: SceneEditor, path: str) -> GameObject | None:
    try:
        return editor.doc.find_gameobject(editor.path(path))
    except UserError:
        return None  # not in the scene yet: the entry makes it, no robot did


def _refuse(go: GameObject, owned: RobotFields | None, fields: Sequence[ComponentField]) -> None:
    if owned is None:
        return
    for field in fields:
        if field.name not in owned.names:
            continue
        key = _ENTRY_KEYS.get(field.name)
        change = (
            f"set `{key}` on the robot's `robots` entry"
            if key is not None
            else "change the value in the URDF"
        )
        taken = ", ".join(sorted(owned.names))
        raise LocatedError.at(
            field.location,
            f"{owned.label}'s {field.name} on '{go.path}' is set by robot {owned.robot}'s "
            "import (its URDF and `robots` entry own it), which puts it back on every apply",
            hint=f"{change}, or set a field the import does not own (it owns {taken})",
        )
