"""Text of new GameObject, Transform and MonoBehaviour documents in a file's own layout.

The field order (and any field we have no opinion about) is copied from an existing object of
the same class in the same file when there is one; built-in layouts per serialization era are
the fallback. Values we set ourselves are the defaults Unity gives a fresh object.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from unityscaffold.unity import _fields as F
from unityscaffold.unity._emit import emit_field
from unityscaffold.unity._eras import SerializationEra
from unityscaffold.unity._split import Doc
from unityscaffold.unity.builtins import BuiltinClass
from unityscaffold.unity.values import ScriptRef

__all__ = [
    "component_item",
    "new_builtin",
    "new_gameobject",
    "new_monobehaviour",
    "new_rect_transform",
    "new_transform",
]

_NULL = "{fileID: 0}"
_MODERN = ["m_ObjectHideFlags", "m_CorrespondingSourceObject", "m_PrefabInstance", "m_PrefabAsset"]
_LEGACY = ["m_ObjectHideFlags", "m_PrefabParentObject", "m_PrefabInternal"]
_GO_TAIL = [
    "m_Component",
    "m_Layer",
    "m_Name",
    "m_TagString",
    "m_Icon",
    "m_NavMeshLayer",
    "m_StaticEditorFlags",
    "m_IsActive",
]
_TRANSFORM_POSE = ["m_LocalRotation", "m_LocalPosition", "m_LocalScale"]
_RECT = ["m_AnchorMin", "m_AnchorMax", "m_AnchoredPosition", "m_SizeDelta", "m_Pivot"]
_MB_TAIL = [
    "m_GameObject",
    "m_Enabled",
    "m_EditorHideFlags",
    "m_Script",
    "m_Name",
    "m_EditorClassIdentifier",
]
_COMMON = {
    "m_ObjectHideFlags": "0",
    "m_CorrespondingSourceObject": _NULL,
    "m_PrefabInstance": _NULL,
    "m_PrefabAsset": _NULL,
    "m_PrefabParentObject": _NULL,
}


def _builtin_layout(kind: str, era: SerializationEra) -> list[str]:
    head = _MODERN if era.modern_prefab_fields else _LEGACY
    if kind == "GameObject":
        return [*head, "serializedVersion", *_GO_TAIL]
    if kind == "MonoBehaviour":
        return [*head, *_MB_TAIL]
    if kind == "RectTransform":  # no serializedVersion, the rect after the Transform's fields
        if era.root_order:
            pose = [*_TRANSFORM_POSE, "m_Children", "m_Father", "m_RootOrder"]
        else:
            pose = [*_TRANSFORM_POSE, "m_ConstrainProportionsScale", "m_Children", "m_Father"]
        return [*head, "m_GameObject", *pose, "m_LocalEulerAnglesHint", *_RECT]
    if era.root_order:
        return [
            *head,
            "m_GameObject",
            *_TRANSFORM_POSE,
            "m_Children",
            "m_Father",
            "m_RootOrder",
            "m_LocalEulerAnglesHint",
        ]
    return [
        *head,
        "m_GameObject",
        "serializedVersion",
        *_TRANSFORM_POSE,
        "m_ConstrainProportionsScale",
        "m_Children",
        "m_Father",
        "m_LocalEulerAnglesHint",
    ]


def _render(
    header: str,
    kind: str,
    era: SerializationEra,
    exemplar: Doc | None,
    values: Mapping[str, str | list[str]],
    stop_after: str | None = None,
) -> str:
    layout = F.field_names(exemplar) if exemplar is not None else _builtin_layout(kind, era)
    if stop_after is not None and stop_after in layout:
        layout = layout[: layout.index(stop_after) + 1]
    lines = [header, f"{kind}:"]
    for key in layout:
        value = values.get(key)
        if isinstance(value, list):
            lines += value
        elif value is not None:
            lines.append(f"  {key}: {value}")
        elif exemplar is not None:
            lines.append((F.field_text(exemplar, key) or "").rstrip("\n"))
    return "\n".join(lines) + "\n"


def _prefab_internal(exemplar: Doc | None) -> str:
    # In an old-format prefab asset every object points at the asset's Prefab object.
    copied = F.field_value(exemplar, "m_PrefabInternal") if exemplar is not None else None
    return copied or _NULL


def component_item(era: SerializationEra, class_id: int, file_id: int) -> str:
    """One ``m_Component`` entry in the file's style."""
    key = str(class_id) if era.classid_component_items else "component"
    return f"  - {key}: {{fileID: {file_id}}}"


def new_gameobject(
    era: SerializationEra, exemplar: Doc | None, file_id: int, name: str, transform_id: int
) -> str:
    version = "6" if era.modern_prefab_fields else "4" if era.classid_component_items else "5"
    values: dict[str, str | list[str]] = {
        **_COMMON,
        "m_PrefabInternal": _prefab_internal(exemplar),
        "m_Component": ["  m_Component:", component_item(era, 4, transform_id)],
        "m_Layer": "0",
        "m_Name": emit_field("m_Name", name),
        "m_TagString": "Untagged",
        "m_Icon": _NULL,
        "m_NavMeshLayer": "0",
        "m_StaticEditorFlags": "0",
        "m_IsActive": "1",
    }
    if exemplar is None:
        values["serializedVersion"] = version
    return _render(f"--- !u!1 &{file_id}", "GameObject", era, exemplar, values)


def _transform_values(
    exemplar: Doc | None, gameobject_id: int, father_id: int
) -> dict[str, str | list[str]]:
    """The fields a new Transform and a new RectTransform share, at Unity's identity values."""
    return {
        **_COMMON,
        "m_PrefabInternal": _prefab_internal(exemplar),
        "m_GameObject": f"{{fileID: {gameobject_id}}}",
        "m_LocalRotation": "{x: 0, y: 0, z: 0, w: 1}",
        "m_LocalPosition": "{x: 0, y: 0, z: 0}",
        "m_LocalScale": "{x: 1, y: 1, z: 1}",
        "m_ConstrainProportionsScale": "0",
        "m_Children": "[]",
        "m_Father": f"{{fileID: {father_id}}}",
        "m_LocalEulerAnglesHint": "{x: 0, y: 0, z: 0}",
    }


def new_transform(
    era: SerializationEra,
    exemplar: Doc | None,
    file_id: int,
    gameobject_id: int,
    father_id: int,
    root_order: int | None,
) -> str:
    values = _transform_values(exemplar, gameobject_id, father_id)
    if root_order is not None:
        values["m_RootOrder"] = str(root_order)
    if exemplar is None:
        values["serializedVersion"] = "2"
    return _render(f"--- !u!4 &{file_id}", "Transform", era, exemplar, values)


def new_rect_transform(
    era: SerializationEra,
    exemplar: Doc | None,
    file_id: int,
    gameobject_id: int,
    father_id: int,
    root_order: int | None,
) -> str:
    """A UI object's RectTransform, with the values Unity gives a new one."""
    values = {
        **_transform_values(exemplar, gameobject_id, father_id),
        "m_AnchorMin": "{x: 0.5, y: 0.5}",
        "m_AnchorMax": "{x: 0.5, y: 0.5}",
        "m_AnchoredPosition": "{x: 0, y: 0}",
        "m_SizeDelta": "{x: 100, y: 100}",
        "m_Pivot": "{x: 0.5, y: 0.5}",
    }
    if root_order is not None:
        values["m_RootOrder"] = str(root_order)
    return _render(f"--- !u!224 &{file_id}", "RectTransform", era, exemplar, values)


def new_builtin(file_id: int, gameobject_id: int, builtin: BuiltinClass) -> str:
    """A built-in component as Unity 2022.3 writes a new one (see ``unity/builtins.py``)."""
    head = "".join(f"  {key}: {_COMMON[key]}\n" for key in _MODERN)
    return (
        f"--- !u!{builtin.class_id} &{file_id}\n{builtin.name}:\n{head}"
        f"  m_GameObject: {{fileID: {gameobject_id}}}\n{builtin.body}"
    )


def class_identifier(era: SerializationEra, script: ScriptRef) -> str:
    """``m_EditorClassIdentifier``: empty, or ``Asm::Ns.Class`` in files that use that form."""
    if not era.qualified_class_identifier or not script.class_name:
        return ""
    qualified = f"{script.namespace}.{script.class_name}" if script.namespace else script.class_name
    return f"{script.assembly or 'Assembly-CSharp'}::{qualified}"


def new_monobehaviour(
    era: SerializationEra,
    exemplar: Doc | None,
    file_id: int,
    gameobject_id: int,
    script: ScriptRef,
    field_lines: Sequence[str],
) -> str:
    values: dict[str, str | list[str]] = {
        **_COMMON,
        "m_PrefabInternal": _prefab_internal(exemplar),
        "m_GameObject": f"{{fileID: {gameobject_id}}}",
        "m_Enabled": "1",
        "m_EditorHideFlags": "0",
        "m_Script": f"{{fileID: {script.file_id}, guid: {script.guid}, type: {script.type}}}",
        "m_Name": ["  m_Name: "],
        "m_EditorClassIdentifier": [f"  m_EditorClassIdentifier: {class_identifier(era, script)}"],
    }
    stop = "m_EditorClassIdentifier"
    if exemplar is not None and stop not in F.spans(exemplar):
        stop = "m_Name"
    text = _render(f"--- !u!114 &{file_id}", "MonoBehaviour", era, exemplar, values, stop)
    return text + "".join(line + "\n" for line in field_lines)
