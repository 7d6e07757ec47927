"""A Unity Mesh asset (``.asset``, class 43) as Unity 2022.3 writes one saved by
``AssetDatabase.CreateAsset``: positions and normals, 16-bit indices, one submesh.

The layout is the one Unity writes (checked against Unity's own Mesh assets in
``tests/urdf/test_stl.py``): vertex data is one interleaved stream of float32
position (offset 0) and normal (offset 12), stride 24, written as little-endian hex; the index
buffer is uint16 little-endian hex; the bounds are the float32 centre and half-size of the
positions, for the submesh and the whole mesh alike.
"""

from __future__ import annotations

import struct
from collections.abc import Sequence
from dataclasses import dataclass

from unityscaffold.unity._scalars import format_float, to_float32

__all__ = ["MESH_FILE_ID", "MeshData", "mesh_asset"]

#: The fileID of the Mesh in its own ``.asset`` (class 43 × 100000).
MESH_FILE_ID = 4300000
_STRIDE = 24  # float32 x 6: position, normal
_UNUSED_CHANNEL = "    - stream: 0\n      offset: 0\n      format: 0\n      dimension: 0\n"


@dataclass(frozen=True, slots=True)
class MeshData:
    """Vertices as packed little-endian float32 ``(px, py, pz, nx, ny, nz)`` records, and
    triangle indices into them."""

    vertices: bytes
    indices: Sequence[int]

    @property
    def vertex_count(self) -> int:
        return len(self.vertices) // _STRIDE


def mesh_asset(name: str, mesh: MeshData) -> str:
    """The text of ``<name>.asset`` holding ``mesh``."""
    if mesh.vertex_count > 0xFFFF:
        raise ValueError(f"{mesh.vertex_count} vertices do not fit 16-bit indices")
    count = mesh.vertex_count
    bounds = _bounds(mesh.vertices)
    index_hex = struct.pack(f"<{len(mesh.indices)}H", *mesh.indices).hex()
    return (
        "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n"
        f"--- !u!43 &{MESH_FILE_ID}\nMesh:\n"
        "  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n"
        "  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n"
        f"  m_Name: {name}\n  serializedVersion: 11\n"
        "  m_SubMeshes:\n  - serializedVersion: 2\n    firstByte: 0\n"
        f"    indexCount: {len(mesh.indices)}\n    topology: 0\n    baseVertex: 0\n"
        f"    firstVertex: 0\n    vertexCount: {count}\n    localAABB:\n"
        f"{_indent(bounds, 6)}"
        "  m_Shapes:\n    vertices: []\n    shapes: []\n    channels: []\n    fullWeights: []\n"
        "  m_BindPose: []\n  m_BoneNameHashes: \n  m_RootBoneNameHash: 0\n  m_BonesAABB: []\n"
        "  m_VariableBoneCountWeights:\n    m_Data: \n  m_MeshCompression: 0\n"
        "  m_IsReadable: 1\n  m_KeepVertices: 0\n  m_KeepIndices: 0\n  m_IndexFormat: 0\n"
        f"  m_IndexBuffer: {index_hex}\n"
        f"  m_VertexData:\n    serializedVersion: 3\n    m_VertexCount: {count}\n"
        "    m_Channels:\n"
        "    - stream: 0\n      offset: 0\n      format: 0\n      dimension: 3\n"
        "    - stream: 0\n      offset: 12\n      format: 0\n      dimension: 3\n"
        f"{_UNUSED_CHANNEL * 12}"
        f"    m_DataSize: {len(mesh.vertices)}\n    _typelessdata: {mesh.vertices.hex()}\n"
        f"  m_CompressedMesh:\n{_COMPRESSED_MESH}"
        f"  m_LocalAABB:\n{_indent(bounds, 4)}"
        "  m_MeshUsageFlags: 0\n  m_CookingOptions: 30\n"
        "  m_BakedConvexCollisionMesh: \n  m_BakedTriangleCollisionMesh: \n"
        "  m_MeshMetrics[0]: 1\n  m_MeshMetrics[1]: 1\n  m_MeshOptimizationFlags: 1\n"
        "  m_StreamData:\n    serializedVersion: 2\n    offset: 0\n    size: 0\n    path: \n"
    )


def _bounds(vertices: bytes) -> str:
    """``m_Center`` and ``m_Extent`` lines of the positions' box (zero for no vertices)."""
    floats = struct.unpack(f"<{len(vertices) // 4}f", vertices)
    centre, extent = [], []
    for axis in range(3):
        values = floats[axis::6]
        low, high = (min(values), max(values)) if values else (0.0, 0.0)
        centre.append(to_float32(to_float32(high + low) * 0.5))
        extent.append(to_float32(to_float32(high - low) * 0.5))
    return f"m_Center: {_vector(centre)}\nm_Extent: {_vector(extent)}\n"


def _vector(values: list[float]) -> str:
    x, y, z = (format_float(v) for v in values)
    return f"{{x: {x}, y: {y}, z: {z}}}"


def _indent(lines: str, width: int) -> str:
    return "".join(" " * width + line + "\n" for line in lines.splitlines())


def _compressed(name: str, *, ranged: bool) -> str:
    range_lines = "      m_Range: 0\n      m_Start: 0\n" if ranged else ""
    return f"    {name}:\n      m_NumItems: 0\n{range_lines}      m_Data: \n      m_BitSize: 0\n"


_COMPRESSED_MESH = (
    "".join(
        _compressed(name, ranged=ranged)
        for name, ranged in (
            ("m_Vertices", True),
            ("m_UV", True),
            ("m_Normals", True),
            ("m_Tangents", True),
            ("m_Weights", False),
            ("m_NormalSigns", False),
            ("m_TangentSigns", False),
            ("m_FloatColors", True),
            ("m_BoneIndices", False),
            ("m_Triangles", False),
        )
    )
    + "    m_UVInfo: 0\n"
)
