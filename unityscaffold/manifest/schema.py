"""The manifest's JSON Schema: built from the key table, shipped as ``robot.schema.json``.

``build_schema()`` derives the schema from ``_spec.SECTIONS``, the table the validator reads,
so editors and ``scaffold`` accept the same keys. The shipped file is that output; regenerate
it after changing the table with::

    python -m unityscaffold.manifest.schema > unityscaffold/schema/robot.schema.json

(a test fails while the two differ). Rules the schema cannot express (scenes inside the project,
duplicate names, a scene for every entry) are only checked by ``scaffold``.
"""

from __future__ import annotations

import json
import sys
from typing import Any

from unityscaffold.manifest import _spec as spec
from unityscaffold.resources import schema_text

__all__ = ["build_schema", "load_schema", "render_schema"]

_FIELD_VALUE = {
    "description": "A serialized field value: number, text, boolean, list or mapping "
    "(a struct). Text starting with '@' refers to a GameObject or component in the scene; "
    "null is an empty reference (written null or ~: a key with no value is an error).",
    "anyOf": [
        {"type": ["string", "number", "boolean", "null"]},
        {"type": "array", "items": {"$ref": "#/$defs/fieldValue"}},
        {"type": "object", "additionalProperties": {"$ref": "#/$defs/fieldValue"}},
    ],
}


def _section(section: spec.Section) -> dict[str, Any]:
    properties: dict[str, Any] = {}
    for key in section.keys:
        prop: dict[str, Any] = {"description": key.doc, **key.schema}
        if key.default is not spec.NO_DEFAULT:
            prop["default"] = key.default
        properties[key.name] = prop
    result: dict[str, Any] = {
        "type": "object",
        "description": section.doc,
        "properties": properties,
        "additionalProperties": False,
    }
    if section.required:
        result["required"] = list(section.required)
    if section.rules:
        result["allOf"] = [dict(rule) for rule in section.rules]
    return result


def build_schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of manifest version 1."""
    top, *nested = spec.SECTIONS
    defs = {section.ref: _section(section) for section in nested}
    defs["fieldValue"] = _FIELD_VALUE
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "unityscaffold robot.yaml",
        **_section(top),
        "$defs": defs,
    }


def render_schema() -> str:
    """``build_schema()`` as the exact text of the shipped file."""
    return json.dumps(build_schema(), indent=2, ensure_ascii=False) + "\n"


def load_schema() -> dict[str, Any]:
    """The shipped schema, as the installed package holds it."""
    result: dict[str, Any] = json.loads(schema_text())
    return result


if __name__ == "__main__":
    sys.stdout.write(render_schema())
