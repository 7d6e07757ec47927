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

# Matched from the line break before the key rather than with ``^`` and re.M: a pattern that
# starts with literal text is found by a fast scan, ten times quicker than trying ``^`` at every
# position. A document starts with its header, so no field line is at offset 0.
_QUALIFIED_ID_RE = re.compile(r"\n  m_EditorClassIdentifier: \S+::")
_CLASSID_ITEM_RE = re.compile(r"\n  - \d+: \{fileID:")


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
    modern = legacy = False
    for doc in docs:  # the first document with either prefab field tells
        modern = "\n  m_CorrespondingSourceObject:" in doc.text
        legacy = "\n  m_PrefabParentObject:" in doc.text
        if modern or legacy:
            break
    root_order = plain_transform = scene_roots = False
    gameobjects: list[str] = []
    behaviours: list[str] = []
    for doc in docs:  # one class test per document in the usual case: this runs per document
        class_id = doc.class_id
        if class_id == 114:
            behaviours.append(doc.text)
        elif class_id == 1:
            gameobjects.append(doc.text)
        elif class_id == 4:
            if root_order or doc.stripped:
                continue  # one Transform with m_RootOrder settles it
            if "\n  m_RootOrder:" in doc.text:
                root_order = True
            else:
                plain_transform = True
        elif class_id == SCENE_ROOTS_CLASS:
            scene_roots = True
    # one search per document, iterated in C and stopping at the first hit: cheaper than
    # joining the documents into bigger pieces to search
    classid = any(map(_CLASSID_ITEM_RE.search, gameobjects))
    qualified = any(map(_QUALIFIED_ID_RE.search, behaviours))
    if not root_order and not plain_transform:
        root_order = not scene_roots  # an empty pre-2022 scene has neither marker
    return SerializationEra(
        modern_prefab_fields=modern or not legacy,
        classid_component_items=classid,
        root_order=root_order,
        scene_roots=scene_roots,
        qualified_class_identifier=qualified,
    )
