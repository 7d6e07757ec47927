"""Reading the ``objects`` entries: declared GameObjects and their built-in components."""

from __future__ import annotations

import math

from unityscaffold.manifest import _spec as spec
from unityscaffold.manifest._entries import Context, locations, read_scene
from unityscaffold.manifest._fields import read_fields
from unityscaffold.manifest._keys import PRIMITIVE_NAMES
from unityscaffold.manifest._read import Reader, one_of, suggest
from unityscaffold.manifest._yaml import YMap, YNode, YScalar, YSeq
from unityscaffold.manifest.model import BuiltinComponent, RectLayout, SceneObject

__all__ = ["read_object", "read_vector"]

EXPECT_PATH = "a hierarchy path such as Robot/base_link"


def read_object(r: Reader, node: YNode, ctx: Context) -> SceneObject | None:
    m = r.mapping(node, spec.OBJECT)
    if m is None:
        return None
    path = r.text(m, "path", EXPECT_PATH, spec.GAMEOBJECT)
    components = tuple(
        c for c in (_builtin(r, n) for n in r.items(m, "components")) if c is not None
    )
    item = SceneObject(
        path=path or "",
        scene=read_scene(r, m, ctx, "object") or "",
        position=read_vector(r, m, "position", 3),  # type: ignore[arg-type]
        rotation=read_vector(r, m, "rotation", 3),  # type: ignore[arg-type]
        scale=read_vector(r, m, "scale", 3),  # type: ignore[arg-type]
        active=r.boolean(m, "active"),
        tag=r.text(m, "tag", "a tag such as MainCamera"),
        layer=_layer(r, m),
        ui=_ui(r, m),
        components=components,
        locations=locations(m),
        sibling_index=_sibling_index(r, m),
        primitive=_primitive(r, m, components),
    )
    return item if path else None


def _primitive(r: Reader, m: YMap, components: tuple[BuiltinComponent, ...]) -> str | None:
    entry = m.get("primitive")
    if entry is None:
        return None
    value = entry.value.value if isinstance(entry.value, YScalar) else None
    if value in PRIMITIVE_NAMES:
        for comp in components:  # the primitive's mesh is the primitive's to set
            mesh = next((f for f in comp.fields if f.name == "m_Mesh"), None)
            if comp.type == "MeshFilter" and comp.key is None and mesh is not None:
                r.error(
                    mesh.location,
                    f"m_Mesh of a {value} is its built-in mesh",
                    hint="leave out `primitive` to give the MeshFilter a mesh of your own",
                )
        return str(value)
    word = value if isinstance(value, str) else ""
    r.invalid(
        entry,
        one_of(PRIMITIVE_NAMES),
        hint=suggest(word.lower(), PRIMITIVE_NAMES) if word else None,
    )
    return None


def _sibling_index(r: Reader, m: YMap) -> int | None:
    entry = m.get("sibling_index")
    if entry is None:
        return None
    value = entry.value.value if isinstance(entry.value, YScalar) else None
    if isinstance(value, int) and not isinstance(value, bool) and 0 <= value <= spec.INT32_MAX:
        return value
    r.invalid(
        entry,
        "a whole number from 0 (the first child)",
        hint="count as the Hierarchy window lists the siblings, from the top",
    )
    return None


def read_vector(r: Reader, m: YMap, key: str, size: int) -> tuple[float, ...] | None:
    entry = m.get(key)
    if entry is None:
        return None
    node = entry.value
    numbers = (
        [i.value for i in node.items if isinstance(i, YScalar)] if isinstance(node, YSeq) else []
    )
    ok = (
        isinstance(node, YSeq)
        and len(numbers) == len(node.items) == size
        and all(isinstance(n, (int, float)) and not isinstance(n, bool) for n in numbers)
        and all(math.isfinite(n) and abs(n) <= spec.FLOAT32_MAX for n in numbers)  # type: ignore[arg-type]
    )
    if not ok:
        example = ", ".join(["0"] * size)
        r.invalid(entry, f"a list of {size} numbers such as [{example}]", hint=_hint(numbers))
        return None
    return tuple(float(n) for n in numbers)  # type: ignore[arg-type]


def _hint(numbers: list[object]) -> str | None:
    if any(isinstance(n, float) and not math.isfinite(n) for n in numbers):
        return "a scene stores finite 32-bit floats"
    return None


def _layer(r: Reader, m: YMap) -> int | None:
    entry = m.get("layer")
    if entry is None:
        return None
    value = entry.value.value if isinstance(entry.value, YScalar) else None
    if isinstance(value, int) and not isinstance(value, bool) and 0 <= value <= 31:
        return value
    if isinstance(value, str) and value in spec.LAYER_NUMBERS:
        return spec.LAYER_NUMBERS[value]
    hint = suggest(value, spec.BUILTIN_LAYERS) if isinstance(value, str) else None
    r.invalid(
        entry,
        "a layer number 0–31 or " + one_of(spec.BUILTIN_LAYERS),
        hint=hint or "a layer you added in Unity goes by its number (Tags and Layers)",
    )
    return None


def _ui(r: Reader, m: YMap) -> RectLayout | None:
    entry = m.get("ui")
    if entry is None:
        return None
    if isinstance(entry.value, YScalar) and isinstance(entry.value.value, bool):
        return RectLayout() if entry.value.value else None
    if not isinstance(entry.value, YMap):
        r.invalid(entry, "true, or a mapping of anchor_min, anchor_max, position, size, pivot")
        return None
    u = r.mapping(entry.value, spec.UI)
    if u is None:
        return None
    keys = ("anchor_min", "anchor_max", "position", "size", "pivot")
    return RectLayout(*(read_vector(r, u, key, 2) for key in keys))  # type: ignore[arg-type]


def _builtin(r: Reader, node: YNode) -> BuiltinComponent | None:
    if isinstance(node, YScalar):
        if _type_ok(r, node, node.value):
            return BuiltinComponent(str(node.value), (), None, node.location)
        return None
    m = r.mapping(node, spec.BUILTIN)
    if m is None:
        return None
    entry = m.get("type")
    ok = entry is not None and _type_ok(r, entry.value, getattr(entry.value, "value", None))
    key = r.text(m, "id", "a short name of letters, digits, '_', '-' or '.'", spec.KEY)
    fields = read_fields(r, m)
    if not ok or entry is None:
        return None
    return BuiltinComponent(str(getattr(entry.value, "value", "")), fields, key, m.location)


def _type_ok(r: Reader, node: YNode, value: object) -> bool:
    if isinstance(value, str) and value in spec.BUILTIN_TYPES:
        return True
    word = value if isinstance(value, str) else ""
    hint = suggest(word, spec.BUILTIN_TYPES) or (
        "scripts (uGUI's Image, CanvasScaler, …; ROS#'s; yours) go under 'components:'"
    )
    r.error(
        node.location,
        f"unsupported built-in component {word or value!r}",
        expected=one_of(spec.BUILTIN_TYPES),
        hint=hint,
    )
    return False
