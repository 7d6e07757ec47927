"""The manifest's JSON Schema: built from the key table, shipped as ``robot.schema.json``.

``build_schema()`` derives the schema from ``_spec.SECTIONS``, the table the validator reads,
so editors and ``scaffold`` accept the same keys. The shipped file is that output; regenerate
it after changing the table with::

    python -m unityscaffold.manifest.schema > schema/robot.schema.json

(a test fails while the two differ). Rules the schema cannot express (scenes inside the project,
duplicate names, a scene for every entry) are only checked by ``scaffold``.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

import unityscaffold
from unityscaffold.errors import InternalError
from unityscaffold.manifest import _spec as spec

__all__ = ["build_schema", "load_schema", "render_schema", "schema_path"]

_FILE = "robot.schema.json"

_FIELD_VALUE = {
    "description": "A serialized field value: number, text, boolean, list or mapping "
    "(a struct). Text starting with '@' refers to a GameObject or component in the scene.",
    "anyOf": [
        {"type": ["string", "number", "boolean"]},
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


def schema_path() -> Path:
    """The shipped schema: inside the installed package (wheel), else the source checkout's."""
    package = Path(unityscaffold.__file__).parent
    for candidate in (package / "schema" / _FILE, package.parent / "schema" / _FILE):
        if candidate.is_file():
            return candidate
    raise InternalError(
        f"{_FILE} is missing from the installation (looked in "
        f"{package / 'schema'} and {package.parent / 'schema'})"
    )


def load_schema() -> dict[str, Any]:
    result: dict[str, Any] = json.loads(schema_path().read_text(encoding="utf-8"))
    return result


if __name__ == "__main__":
    sys.stdout.write(render_schema())
