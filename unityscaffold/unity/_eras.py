"""Which serialization era a file was written in (detected per file, never per project).

See ``docs/unity-yaml.md#eras``: prefab fields (``m_CorrespondingSourceObject`` from 2018.3,
``m_PrefabParentObject`` before), ``m_Component`` item style, ``m_RootOrder`` (≤ 2021) or a
``SceneRoots`` document (2022+), and the ``m_EditorClassIdentifier`` style (``Asm::Ns.Class`` in
newer 6.x).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from unityscaffold.unity._classids import SCENE_ROOTS_CLASS
from unityscaffold.unity._split import Doc

__all__ = ["SerializationEra", "detect_era"]

_QUALIFIED_ID_RE = re.compile(r"^  m_EditorClassIdentifier: \S+::", re.M)
_CLASSID_ITEM_RE = re.compile(r"^  - \d+: \{fileID:", re.M)


@dataclass(frozen=True, slots=True)
class SerializationEra:
    """The layout Unity versions of one era write, followed when new documents go into a file."""

    modern_prefab_fields: bool  # m_CorrespondingSourceObject/m_PrefabInstance/m_PrefabAsset
    classid_component_items: bool  # early 5.x ``- 4: {fileID: N}``
    root_order: bool  # Transforms carry m_RootOrder
    scene_roots: bool  # a SceneRoots document lists the roots
    qualified_class_identifier: bool  # m_EditorClassIdentifier: Asm::Ns.Class

    @property
    def label(self) -> str:
        if self.qualified_class_identifier:
            return "6000.x (qualified m_EditorClassIdentifier)"
        if self.scene_roots or (self.modern_prefab_fields and not self.root_order):
            return "2022.x+ (SceneRoots, no m_RootOrder)"
        if self.modern_prefab_fields:
            return "2018.3–2021 (m_RootOrder)"
        if self.classid_component_items:
            return "5.x (class-ID component items)"
        return "5.5–2018.2 (m_PrefabParentObject)"


def detect_era(docs: Sequence[Doc]) -> SerializationEra:
    """Read the era markers of a file from its documents."""
    modern = legacy = root_order = plain_transform = classid = qualified = scene_roots = False
    for doc in docs:
        text = doc.text
        if doc.class_id == SCENE_ROOTS_CLASS:
            scene_roots = True
        if not modern and not legacy:
            modern = "\n  m_CorrespondingSourceObject:" in text
            legacy = "\n  m_PrefabParentObject:" in text
        if doc.class_id == 4 and not doc.stripped:
            if "\n  m_RootOrder:" in text:
                root_order = True
            else:
                plain_transform = True
        if doc.class_id == 1 and not classid and _CLASSID_ITEM_RE.search(text):
            classid = True
        if doc.class_id == 114 and not qualified and _QUALIFIED_ID_RE.search(text):
            qualified = True
    if not root_order and not plain_transform:
        root_order = not scene_roots  # an empty pre-2022 scene has neither marker
    return SerializationEra(
        modern_prefab_fields=modern or not legacy,
        classid_component_items=classid,
        root_order=root_order,
        scene_roots=scene_roots,
        qualified_class_identifier=qualified,
    )
