"""Every field Unity serializes for uGUI's components, as the catalog describes ROS#'s scripts.

``ugui_fields.json`` beside this module is written by ``scripts/update_ugui_fields.py`` from
documents Unity 2022.3 saved (defaults from uGUI's C# initializers where a saved document holds
the user's value). apply writes a new uGUI component with all of them, so that Unity's next save
changes nothing, and checks a manifest's values against each field's kind.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache

from unityscaffold.resources import ugui_fields_text
from unityscaffold.unity.catalog import CatalogField, CatalogScript
from unityscaffold.unity.values import Verbatim

__all__ = ["UguiClass", "ugui_enums", "ugui_fields"]


@dataclass(frozen=True, slots=True)
class UguiClass:
    """One uGUI script: its declaration, and each field as Unity writes a new component's."""

    script: CatalogScript
    defaults: tuple[tuple[str, Verbatim], ...]


@cache
def _data() -> dict[str, UguiClass]:
    classes = json.loads(ugui_fields_text())["classes"]
    found = {}
    for name, c in classes.items():
        fields = tuple(CatalogField(f["name"], f["type"], f["unity"]) for f in c["fields"])
        script = CatalogScript(
            class_name=name,
            namespace=c["namespace"],
            path="",
            bases=tuple(c["bases"]),
            attachable=True,
            requires=tuple(c["requires"]),
            fields=fields,
            guids=(),
        )
        found[name] = UguiClass(
            script, tuple((f["name"], Verbatim(f["text"])) for f in c["fields"])
        )
    return found


def ugui_fields(class_name: str) -> UguiClass | None:
    """The uGUI class ``class_name`` (``Image``), or None when the table has no such class."""
    return _data().get(class_name)


@cache
def ugui_enums() -> dict[str, dict[str, int]]:
    """Full C# name -> member -> value of the enums uGUI's fields use."""
    enums: dict[str, dict[str, int]] = json.loads(ugui_fields_text())["enums"]
    return enums
