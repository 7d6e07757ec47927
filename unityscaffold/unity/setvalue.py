"""Field values written as text (``scaffold scene attach --set NAME=VALUE``).

VALUE is a YAML scalar or flow value: ``10`` (int), ``0.1`` (float), ``true`` (bool), ``text``
or ``'quoted text'`` (string), ``[1, 2]`` (list), ``{x: 0, y: 1}`` (vector-like flow mapping),
``{fileID: N}`` (object in this file), ``{fileID: F, guid: G, type: T}`` (asset). References to
objects of the same scene read ``@Path/To/GameObject`` or ``@Path/To/GameObject:Component``,
where Component is a class name (``Transform``, ``Camera``) or a script's class name; inside a
list, quote them (``['@A', '@B']``). ``@@`` starts a string that begins with a literal ``@``.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

import yaml

from unityscaffold.errors import UserError
from unityscaffold.unity.index import SceneComponent
from unityscaffold.unity.scene import SceneDocument
from unityscaffold.unity.values import AssetRef, FieldValue, InlineMap, ObjectRef

__all__ = ["component_label", "parse_assignment", "parse_value"]

_INT_RE = re.compile(r"[-+]?\d+")
_FLOAT_RE = re.compile(r"[-+]?(\d+\.\d*|\.\d+|\d+)([eE][-+]?\d+)?|[-+]?Infinity|NaN")


def parse_assignment(text: str) -> tuple[str, str]:
    """Split ``NAME=VALUE``."""
    name, sep, value = text.partition("=")
    if not sep or not name.strip():
        raise UserError(f"--set expects NAME=VALUE, got '{text}'")
    return name.strip(), value


def component_label(comp: SceneComponent, script_names: Mapping[str, str]) -> str:
    """A component's readable name: its class, or its script's class name, or the GUID."""
    if comp.script is None:
        return comp.type_name if comp.class_id != 114 else "MonoBehaviour (missing script)"
    name = script_names.get(comp.script.guid)
    if name and comp.script.file_id == 11500000:
        return name
    if comp.script.file_id != 11500000:
        return f"{comp.script.guid}:{comp.script.file_id}"
    return comp.script.guid


def parse_value(
    text: str, scene: SceneDocument, script_names: Mapping[str, str] | None = None
) -> FieldValue:
    """Turn VALUE text into a typed field value, resolving ``@`` references in ``scene``."""
    names = script_names or {}
    if text.startswith("@"):
        return _reference(text, scene, names)
    try:
        node = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.YAMLError as exc:
        first = str(exc).strip().split("\n")[0]
        raise UserError(
            f"cannot read value '{text}': {first}",
            hint="quote strings that contain YAML syntax: 'a: b'",
        ) from None
    return "" if node is None else _node(node, scene, names)


def _node(node: yaml.Node, scene: SceneDocument, names: Mapping[str, str]) -> FieldValue:
    if isinstance(node, yaml.ScalarNode):
        return _scalar(node.value, node.style, scene, names)
    if isinstance(node, yaml.SequenceNode):
        return [_node(item, scene, names) for item in node.value]
    assert isinstance(node, yaml.MappingNode)
    items = {str(k.value): _node(v, scene, names) for k, v in node.value}
    if set(items) == {"fileID"}:
        return ObjectRef(_int(items["fileID"]))
    if set(items) == {"fileID", "guid", "type"}:
        try:
            return AssetRef(_int(items["fileID"]), str(items["guid"]), _int(items["type"]))
        except ValueError as exc:
            raise UserError(str(exc)) from None
    if all(isinstance(v, (bool, int, float)) for v in items.values()):
        return InlineMap(tuple(items.items()))  # type: ignore[arg-type]
    return items


def _int(value: object) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise UserError(f"expected an integer, got '{value}'")
    return value


def _scalar(
    text: str, style: str | None, scene: SceneDocument, names: Mapping[str, str]
) -> FieldValue:
    if style is not None:  # quoted: always a string, or an @reference
        return _reference(text, scene, names) if text.startswith("@") else text
    if _INT_RE.fullmatch(text):
        return int(text)
    if _FLOAT_RE.fullmatch(text):
        return float(text.replace("Infinity", "inf"))
    if text.lower() in {"true", "false"}:
        return text.lower() == "true"
    return text


def _reference(text: str, scene: SceneDocument, names: Mapping[str, str]) -> FieldValue:
    if text.startswith("@@"):
        return text[1:]
    path, _, wanted = text[1:].partition(":")
    go = scene.find_gameobject(path)
    if not wanted:
        return ObjectRef(go.file_id)
    comps = scene.components_of(go)
    matches = [c for c in comps if wanted in (c.type_name, component_label(c, names))]
    if len(matches) == 1:
        return ObjectRef(matches[0].file_id)
    present = ", ".join(sorted({component_label(c, names) for c in comps})) or "none"
    if not matches:
        raise UserError(f"'{go.path}' has no component '{wanted}'; it has: {present}")
    raise UserError(
        f"'{go.path}' has {len(matches)} components '{wanted}'",
        hint="refer to one by {fileID: N}: " + ", ".join(str(c.file_id) for c in matches),
    )
