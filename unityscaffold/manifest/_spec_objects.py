"""The key table's sections for the scene's declared objects: ``objects:`` entries, their UI
layout and their built-in components."""

from __future__ import annotations

from unityscaffold.manifest._keys import (
    BOOL,
    BUILTIN_LAYERS,
    BUILTIN_TYPES,
    FLOAT32_MAX,
    GAMEOBJECT_VALUE,
    KEY,
    PRIMITIVE_NAMES,
    STR,
    Key,
    Section,
    list_of,
    ref,
    scene_key,
)

__all__ = ["BUILTIN", "OBJECT", "UI"]

_FLOAT = {"type": "number", "minimum": -FLOAT32_MAX, "maximum": FLOAT32_MAX}
_VEC3 = {"type": "array", "items": _FLOAT, "minItems": 3, "maxItems": 3}
_VEC2 = {"type": "array", "items": _FLOAT, "minItems": 2, "maxItems": 2}

UI = Section(
    "ui",
    "ui",
    "A UI object's RectTransform; keys left out keep the scene's values (new: Unity's defaults).",
    (
        Key("anchor_min", "`m_AnchorMin`, e.g. `[0, 0]`.", _VEC2),
        Key("anchor_max", "`m_AnchorMax`, e.g. `[1, 1]`.", _VEC2),
        Key("position", "`m_AnchoredPosition` in pixels, e.g. `[150, 150]`.", _VEC2),
        Key("size", "`m_SizeDelta` in pixels, e.g. `[100, 100]`.", _VEC2),
        Key("pivot", "`m_Pivot`, e.g. `[0.5, 0.5]`.", _VEC2),
    ),
)

BUILTIN = Section(
    "built-in component",
    "builtinComponent",
    "A built-in Unity component of a declared object.",
    (
        Key(
            "type",
            "Class of the component: " + ", ".join(f"`{name}`" for name in BUILTIN_TYPES) + ".",
            {"enum": list(BUILTIN_TYPES)},
            required=True,
        ),
        Key(
            "id",
            "Tells apart several components of one class on the object.",
            {"type": "string", "pattern": KEY},
        ),
        Key(
            "fields",
            "Values by Unity's serialized name (`m_Mass`, `m_IsTrigger`, `m_Size`); the rest "
            "keep Unity's defaults.",
            {"type": ["object", "null"], "additionalProperties": ref("fieldValue")},
        ),
    ),
)

OBJECT = Section(
    "object",
    "object",
    "A GameObject created if missing and kept as declared; keys left out keep the scene's values.",
    (
        Key(
            "path",
            "Hierarchy path (`Parent/Child`); missing parents are created as empty objects.",
            GAMEOBJECT_VALUE,
            required=True,
        ),
        scene_key("object"),
        Key("position", "Local position `[x, y, z]`.", _VEC3),
        Key(
            "rotation",
            "Local rotation as Euler angles in degrees `[x, y, z]`, as the Inspector shows it.",
            _VEC3,
        ),
        Key("scale", "Local scale `[x, y, z]`.", _VEC3),
        Key("active", "Whether the GameObject is active.", BOOL),
        Key(
            "tag",
            "Tag: a built-in one (`MainCamera`, `Player`, …) or one in "
            "ProjectSettings/TagManager.asset.",
            STR,
        ),
        Key(
            "layer",
            "Layer number 0–31, or a built-in layer's name (" + ", ".join(BUILTIN_LAYERS) + ").",
            {"anyOf": [{"type": "integer", "minimum": 0, "maximum": 31}, {"enum": BUILTIN_LAYERS}]},
        ),
        Key(
            "ui",
            "`true` (or a mapping of its layout) for a UI object with a RectTransform.",
            {"anyOf": [{"type": "boolean"}, ref("ui")]},
        ),
        Key(
            "sibling_index",
            "Place among its parent's children (or the scene's root objects), as the "
            "Hierarchy window lists them: 0 is the first. Others keep their order around it.",
            {"type": "integer", "minimum": 0},
        ),
        Key(
            "primitive",
            "Make it the shape Unity's GameObject > 3D Object menu makes: "
            + ", ".join(f"`{name}`" for name in PRIMITIVE_NAMES[:-1])
            + f" or `{PRIMITIVE_NAMES[-1]}`"
            + " (a MeshFilter with the built-in mesh, a MeshRenderer with Default-Material, "
            "and the collider). `components` may set their fields.",
            {"enum": list(PRIMITIVE_NAMES)},
        ),
        Key(
            "components",
            "Built-in components: a class name (`Camera`) or `{type, id, fields}`.",
            list_of({"anyOf": [{"enum": list(BUILTIN_TYPES)}, ref("builtinComponent")]}),
        ),
    ),
)
