"""The prefab ROS#'s STL post-processor saves for an STL file, with fileIDs of our own.

ROS# (``StlAssetPostProcessor``) makes a GameObject named after the file with one child per
Mesh asset (``<stem>_<i>``), each with a MeshFilter on that asset and a MeshRenderer with
Unity's Default-Diffuse material, and saves it as ``<stem>.prefab``. Unity gives the saved
objects random fileIDs; here they derive from the prefab's name, and are ordered so that
whatever order Unity keeps the changes of an instance in (by the target's fileID or by when
they were made) is the same: the root's Transform before its GameObject, and per child its
GameObject, Transform, MeshRenderer, then MeshFilter. The layout is Unity 2022.3's (the tests
compare it with the prefabs Unity wrote for the Niryo gripper's STL files).
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass

from unityscaffold.unity._scalars import format_string
from unityscaffold.unity.mesh import MESH_FILE_ID

__all__ = ["StlPart", "StlPrefab", "prefab_meta", "stl_prefab", "stl_prefab_text"]

_DEFAULT_DIFFUSE = "{fileID: 10302, guid: 0000000000000000f000000000000000, type: 0}"
_HEADER = (
    "  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n"
    "  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n"
)


@dataclass(frozen=True, slots=True)
class StlPart:
    """A child of the prefab: ``<stem>_<i>`` and its objects' fileIDs."""

    name: str
    gameobject: int
    transform: int
    renderer: int
    filter: int


@dataclass(frozen=True, slots=True)
class StlPrefab:
    """The prefab of ``<stem>.stl``: its root's fileIDs and one part per Mesh asset."""

    name: str
    transform: int
    gameobject: int
    parts: tuple[StlPart, ...]


def stl_prefab(stem: str, meshes: int) -> StlPrefab:
    """The prefab's objects for an STL file named ``stem`` cut into ``meshes`` Mesh assets."""
    count = 2 + 4 * meshes
    seed = f"stl-prefab\x1f{stem}\x1f{meshes}"
    ids = sorted(_file_ids(seed, count))
    parts = tuple(StlPart(f"{stem}_{i}", *ids[2 + 4 * i : 6 + 4 * i]) for i in range(meshes))
    return StlPrefab(stem, ids[0], ids[1], parts)


def _file_ids(seed: str, count: int) -> set[int]:
    """``count`` distinct positive 63-bit values derived from ``seed``."""
    found: set[int] = set()
    attempt = 0
    while len(found) < count:
        digest = hashlib.sha256(f"{seed}\x1f{attempt}".encode()).digest()
        value = int.from_bytes(digest[:8], "big") >> 1
        if value > 4:
            found.add(value)
        attempt += 1
    return found


def stl_prefab_text(prefab: StlPrefab, mesh_guids: list[str]) -> str:
    """The ``.prefab`` file; ``mesh_guids`` are the GUIDs of the parts' Mesh assets."""
    documents: list[tuple[int, str]] = [
        (
            prefab.gameobject,
            _gameobject(prefab.gameobject, prefab.name, [prefab.transform])
            + _transform(
                prefab.transform,
                prefab.gameobject,
                father=0,
                children=[p.transform for p in prefab.parts],
            ),
        )
    ]
    for part, guid in zip(prefab.parts, mesh_guids, strict=True):
        components = [part.transform, part.filter, part.renderer]
        text = (
            _gameobject(part.gameobject, part.name, components)
            + _transform(part.transform, part.gameobject, father=prefab.transform, children=[])
            + f"--- !u!33 &{part.filter}\nMeshFilter:\n{_HEADER}"
            f"  m_GameObject: {{fileID: {part.gameobject}}}\n"
            f"  m_Mesh: {{fileID: {MESH_FILE_ID}, guid: {guid}, type: 2}}\n"
            + _renderer(part.renderer, part.gameobject)
        )
        documents.append((part.gameobject, text))
    # Unity writes a prefab's GameObjects by fileID, each followed by its components
    body = "".join(text for _, text in sorted(documents))
    return "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n" + body


def _gameobject(file_id: int, name: str, components: list[int]) -> str:
    listed = "".join(f"  - component: {{fileID: {c}}}\n" for c in components)
    return (
        f"--- !u!1 &{file_id}\nGameObject:\n{_HEADER}  serializedVersion: 6\n"
        f"  m_Component:\n{listed}  m_Layer: 0\n"
        f"  m_Name: {format_string(name, column=10)}\n"
        "  m_TagString: Untagged\n  m_Icon: {fileID: 0}\n  m_NavMeshLayer: 0\n"
        "  m_StaticEditorFlags: 0\n  m_IsActive: 1\n"
    )


def _transform(file_id: int, gameobject: int, *, father: int, children: list[int]) -> str:
    listed = "".join(f"\n  - {{fileID: {c}}}" for c in children) if children else " []"
    return (
        f"--- !u!4 &{file_id}\nTransform:\n{_HEADER}"
        f"  m_GameObject: {{fileID: {gameobject}}}\n  serializedVersion: 2\n"
        "  m_LocalRotation: {x: 0, y: 0, z: 0, w: 1}\n  m_LocalPosition: {x: 0, y: 0, z: 0}\n"
        "  m_LocalScale: {x: 1, y: 1, z: 1}\n  m_ConstrainProportionsScale: 0\n"
        f"  m_Children:{listed}\n  m_Father: {{fileID: {father}}}\n"
        "  m_LocalEulerAnglesHint: {x: 0, y: 0, z: 0}\n"
    )


def _renderer(file_id: int, gameobject: int) -> str:
    """A MeshRenderer as ``AddComponent`` makes it, with Default-Diffuse (ROS#'s choice)."""
    return (
        f"--- !u!23 &{file_id}\nMeshRenderer:\n{_HEADER}"
        f"  m_GameObject: {{fileID: {gameobject}}}\n  m_Enabled: 1\n  m_CastShadows: 1\n"
        "  m_ReceiveShadows: 1\n  m_DynamicOccludee: 1\n  m_StaticShadowCaster: 0\n"
        "  m_MotionVectors: 1\n  m_LightProbeUsage: 1\n  m_ReflectionProbeUsage: 1\n"
        "  m_RayTracingMode: 2\n  m_RayTraceProcedural: 0\n  m_RenderingLayerMask: 1\n"
        f"  m_RendererPriority: 0\n  m_Materials:\n  - {_DEFAULT_DIFFUSE}\n"
        "  m_StaticBatchInfo:\n    firstSubMesh: 0\n    subMeshCount: 0\n"
        "  m_StaticBatchRoot: {fileID: 0}\n  m_ProbeAnchor: {fileID: 0}\n"
        "  m_LightProbeVolumeOverride: {fileID: 0}\n  m_ScaleInLightmap: 1\n"
        "  m_ReceiveGI: 1\n  m_PreserveUVs: 0\n  m_IgnoreNormalsForChartDetection: 0\n"
        "  m_ImportantGI: 0\n  m_StitchLightmapSeams: 1\n  m_SelectedEditorRenderState: 3\n"
        "  m_MinimumChartSize: 4\n  m_AutoUVMaxDistance: 0.5\n  m_AutoUVMaxAngle: 89\n"
        "  m_LightmapParameters: {fileID: 0}\n  m_SortingLayerID: 0\n  m_SortingLayer: 0\n"
        "  m_SortingOrder: 0\n  m_AdditionalVertexStreams: {fileID: 0}\n"
    )


def prefab_meta(guid: str) -> str:
    """A ``.prefab``'s ``.meta``."""
    return (
        f"fileFormatVersion: 2\nguid: {guid}\nPrefabImporter:\n  externalObjects: {{}}\n"
        "  userData: \n  assetBundleName: \n  assetBundleVariant: \n"
    )
