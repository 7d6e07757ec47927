"""Which serialization generation a file was written in (detected per file, never per project).

See ``reference/unity-yaml.md`` §1.2: prefab fields (``m_CorrespondingSourceObject`` from 2018.3,
``m_PrefabParentObject`` before), ``m_Component`` item style, ``m_RootOrder`` (≤ 2021) or a
``SceneRoots`` document (2022+), and the ``m_EditorClassIdentifier`` style (``Asm::Ns.Class`` in
newer 6.x).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from unityscaffold.unity._split import Doc

__all__ = ["SCENE_ROOTS_CLASS", "SCENE_ROOTS_FILE_ID", "SETTINGS_CLASSES", "Generation", "detect"]

SCENE_ROOTS_CLASS = 1660057539
SCENE_ROOTS_FILE_ID = 9223372036854775807
#: OcclusionCullingSettings, RenderSettings, LightmapSettings, NavMeshSettings (fileIDs 1–4).
SETTINGS_CLASSES = frozenset({29, 104, 157, 196})
TRANSFORM_CLASSES = frozenset({4, 224})

_QUALIFIED_ID_RE = re.compile(r"^  m_EditorClassIdentifier: \S+::", re.M)
_CLASSID_ITEM_RE = re.compile(r"^  - \d+: \{fileID:", re.M)


@dataclass(frozen=True, slots=True)
class Generation:
    """Layout choices of one file, used when emitting new documents into it."""

    modern_prefab_fields: bool  # m_CorrespondingSourceObject/m_PrefabInstance/m_PrefabAsset
    classid_component_items: bool  # early 5.x ``- 4: {fileID: N}``
    root_order: bool  # Transforms carry m_RootOrder
    scene_roots: bool  # a SceneRoots document lists the roots
    qualified_class_identifier: bool  # m_EditorClassIdentifier: Asm::Ns.Class
    is_scene: bool  # a .unity scene (settings objects) rather than a prefab

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


def detect(docs: Sequence[Doc], path: str = "") -> Generation:
    """Read the generation markers of a file from its documents."""
    modern = legacy = root_order = plain_transform = classid = qualified = False
    scene_roots = is_scene = False
    for doc in docs:
        text = doc.text
        if doc.class_id == SCENE_ROOTS_CLASS:
            scene_roots = True
        if doc.class_id in SETTINGS_CLASSES or doc.class_id == SCENE_ROOTS_CLASS:
            is_scene = True
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
    return Generation(
        modern_prefab_fields=modern or not legacy,
        classid_component_items=classid,
        root_order=root_order,
        scene_roots=scene_roots,
        qualified_class_identifier=qualified,
        is_scene=is_scene or path.endswith(".unity"),
    )
