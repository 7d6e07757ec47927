"""unity stage: Unity scenes, prefabs and ``.meta`` files, edited surgically as text.

``SceneDocument`` loads a text scene or prefab byte-exactly, indexes its hierarchy, and attaches
or updates MonoBehaviours idempotently (see ``docs/unity-yaml.md``). ``meta`` writes and
reads ``.meta`` files, and ``project`` finds a project's root, salt and script GUIDs. Nothing
here writes a file itself: ``SceneDocument.write`` goes through ``unityscaffold.fileout``.
"""

from unityscaffold.unity._eras import SerializationEra
from unityscaffold.unity.index import GameObject, SceneComponent
from unityscaffold.unity.scene import GameObjectNotFound, SceneDocument
from unityscaffold.unity.textdiff import diff
from unityscaffold.unity.values import (
    AssetRef,
    Enum,
    FieldValue,
    InlineMap,
    ObjectRef,
    ScriptRef,
    script_file_id_for_dll_class,
)

__all__ = [
    "AssetRef",
    "Enum",
    "FieldValue",
    "GameObject",
    "GameObjectNotFound",
    "InlineMap",
    "ObjectRef",
    "SceneComponent",
    "SceneDocument",
    "ScriptRef",
    "SerializationEra",
    "diff",
    "script_file_id_for_dll_class",
]
