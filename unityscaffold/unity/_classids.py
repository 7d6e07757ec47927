"""Unity class IDs (the number in a ``--- !u!<class> &<fileID>`` header) that need a name here."""

from __future__ import annotations

__all__ = ["SCENE_ROOTS_CLASS", "SETTINGS_CLASSES", "TRANSFORM_CLASSES"]

#: The ``SceneRoots`` document a 2022+ scene ends with, listing its root Transforms in order.
SCENE_ROOTS_CLASS = 1660057539
#: OcclusionCullingSettings, RenderSettings, LightmapSettings, NavMeshSettings (fileIDs 1–4):
#: only a scene has them, a prefab never does.
SETTINGS_CLASSES = frozenset({29, 104, 157, 196})
#: Transform and RectTransform: either one places a GameObject in the hierarchy.
TRANSFORM_CLASSES = frozenset({4, 224})
