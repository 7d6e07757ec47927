"""A Unity Mesh (class 43) as Unity 2022.3 writes one: positions, normals and optionally one
UV set, 16-bit indices, one submesh; as an ``.asset`` file or as a document inside a scene.

The layout is the one Unity writes (checked against Unity's own Mesh assets and against the
Meshes ROS# makes in a scene, ``tests/urdf``): vertex data is one interleaved stream of float32
position (offset 0), normal (offset 12) and UV (offset 24), written as little-endian hex; the
index buffer is uint16 little-endian hex; bounds are the float32 centre and half-size of the
positions: of the vertices the indices span for the submesh, of all of them for the mesh.
"""

from __future__ import annotations

import struct
from collections.abc import Sequence
from dataclasses import dataclass

from unityscaffold.unity._scalars import format_float, format_string, to_float32

__all__ = ["MESH_FILE_ID", "MeshData", "mesh_asset", "mesh_document"]

#: The fileID of the Mesh in its own ``.asset`` (class 43 × 100000).
MESH_FILE_ID = 4300000
_CHANNEL = "    - stream: 0\n      offset: {}\n      format: 0\n      dimension: {}\n"
_CHANNELS = 14  # position, normal, tangent, colour, 8 UV sets, blend weights and indices


@dataclass(frozen=True, slots=True)
class MeshData:
    """Vertices as packed little-endian float32 records ``(px, py, pz, nx, ny, nz)``, followed
    by ``(u, v)`` when ``uv``; and triangle indices into them."""

    vertices: bytes
    indices: Sequence[int]
    uv: bool = False

    @property
    def stride(self) -> int:
        return 32 if self.uv else 24

    @property
    def vertex_count(self) -> int:
        return len(self.vertices) // self.stride


def mesh_asset(name: str, mesh: MeshData) -> str:
    """The text of ``<name>.asset`` holding ``mesh``, as ``AssetDatabase.CreateAsset`` saves it."""
    header = "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n"
    return header + mesh_document(MESH_FILE_ID, name, mesh, keep=False)


def mesh_document(file_id: int, name: str, mesh: MeshData, *, keep: bool) -> str:
    """The ``--- !u!43`` document of ``mesh``. ``keep`` is Unity's ``m_KeepVertices`` and
    ``m_KeepIndices``: set on a Mesh made in code and saved with a scene, not on an asset."""
    if mesh.vertex_count > 0xFFFF:
        raise ValueError(f"{mesh.vertex_count} vertices do not fit 16-bit indices")
    first = min(mesh.indices, default=0)
    used = max(mesh.indices) - first + 1 if mesh.indices else 0
    span = mesh.vertices[first * mesh.stride : (first + used) * mesh.stride]
    index_hex = struct.pack(f"<{len(mesh.indices)}H", *mesh.indices).hex()
    channels = _CHANNEL.format(0, 3) + _CHANNEL.format(12, 3) + _CHANNEL.format(0, 0) * 2
    channels += _CHANNEL.format(24, 2) if mesh.uv else _CHANNEL.format(0, 0)
    channels += _CHANNEL.format(0, 0) * (_CHANNELS - 5)
    keep_flag = int(keep)
    return (
        f"--- !u!43 &{file_id}\nMesh:\n"
        "  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n"
        "  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n"
        f"  m_Name: {format_string(name, column=10)}\n  serializedVersion: 11\n"
        "  m_SubMeshes:\n  - serializedVersion: 2\n    firstByte: 0\n"
        f"    indexCount: {len(mesh.indices)}\n    topology: 0\n    baseVertex: 0\n"
        f"    firstVertex: {first}\n    vertexCount: {used}\n    localAABB:\n"
        f"{_bounds(span, mesh.stride, 6)}"
        "  m_Shapes:\n    vertices: []\n    shapes: []\n    channels: []\n    fullWeights: []\n"
        "  m_BindPose: []\n  m_BoneNameHashes: \n  m_RootBoneNameHash: 0\n  m_BonesAABB: []\n"
        "  m_VariableBoneCountWeights:\n    m_Data: \n  m_MeshCompression: 0\n"
        f"  m_IsReadable: 1\n  m_KeepVertices: {keep_flag}\n  m_KeepIndices: {keep_flag}\n"
        f"  m_IndexFormat: 0\n  m_IndexBuffer: {index_hex}\n"
        f"  m_VertexData:\n    serializedVersion: 3\n    m_VertexCount: {mesh.vertex_count}\n"
        f"    m_Channels:\n{channels}"
        f"    m_DataSize: {len(mesh.vertices)}\n    _typelessdata: {mesh.vertices.hex()}\n"
        f"  m_CompressedMesh:\n{_COMPRESSED_MESH}"
        f"  m_LocalAABB:\n{_bounds(mesh.vertices, mesh.stride, 4)}"
        "  m_MeshUsageFlags: 0\n  m_CookingOptions: 30\n"
        "  m_BakedConvexCollisionMesh: \n  m_BakedTriangleCollisionMesh: \n"
        "  m_MeshMetrics[0]: 1\n  m_MeshMetrics[1]: 1\n  m_MeshOptimizationFlags: 1\n"
        "  m_StreamData:\n    serializedVersion: 2\n    offset: 0\n    size: 0\n    path: \n"
    )


def _bounds(vertices: bytes, stride: int, indent: int) -> str:
    """``m_Center`` and ``m_Extent`` lines of the positions' box (zero for no vertices)."""
    floats = struct.unpack(f"<{len(vertices) // 4}f", vertices)
    step = stride // 4
    centre, extent = [], []
    for axis in range(3):
        values = floats[axis::step]
        low, high = (min(values), max(values)) if values else (0.0, 0.0)
        centre.append(to_float32(to_float32(high + low) * 0.5))
        extent.append(to_float32(to_float32(high - low) * 0.5))
    pad = " " * indent
    return f"{pad}m_Center: {_vector(centre)}\n{pad}m_Extent: {_vector(extent)}\n"


def _vector(values: list[float]) -> str:
    x, y, z = (format_float(v) for v in values)
    return f"{{x: {x}, y: {y}, z: {z}}}"


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
