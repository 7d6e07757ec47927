"""STL files into the Mesh assets ROS#'s STL post-processor makes in the editor.

ROS# (``StlImporter``, ``StlAssetPostProcessor``) reads a binary STL when a NUL is among its
first 100 characters, else an ASCII one; converts each point and facet normal to Unity's axes;
gives every facet three vertices of its own (in the order 0, 2, 1: Unity winds the other way)
with the facet's normal, no welding; and cuts the facets into meshes of at most 21,845 facets
(65,535 vertices), named ``<stem>_<i>``. When the facet count is a multiple of 21,845 the last
mesh is empty: ROS# makes one mesh more than it fills, kept here so the assets are the ones ROS#
would name.

Two things ROS# does are not reproduced, because they only turn a readable file into wrong
geometry: in ASCII files it reads the numbers of a line separated by single spaces only (a
second space makes it read 0), and it reads a number it cannot parse as 0. Here any whitespace
separates numbers, and a bad number or a truncated file is a located error.
"""

from __future__ import annotations

import struct
from pathlib import Path

from unityscaffold.errors import LocatedError, SourceLocation, UserError
from unityscaffold.unity.mesh import MeshData, mesh_asset

__all__ = ["FACETS_PER_MESH", "read_stl", "stl_mesh_assets", "stl_meshes"]

FACETS_PER_MESH = 65535 // 3
_FACET = struct.Struct("<12f2x")
Facet = tuple[float, ...]  # normal xyz, then the three vertices' xyz, in ROS's axes


def stl_mesh_assets(path: Path, stem: str | None = None) -> list[tuple[str, str]]:
    """``(file name, text)`` of each ``<stem>_<i>.asset`` ROS# makes from the STL at ``path``
    (``stem``: the name the URDF gives the file, by default its name on disk)."""
    stem = path.stem if stem is None else stem
    return [
        (f"{stem}_{i}.asset", mesh_asset(f"{stem}_{i}", m)) for i, m in enumerate(stl_meshes(path))
    ]


def stl_meshes(path: Path) -> list[MeshData]:
    """The meshes of the STL at ``path``, as ROS#'s importer cuts and orders them."""
    facets = read_stl(path)
    meshes = []
    for start in range(0, len(facets) // FACETS_PER_MESH * FACETS_PER_MESH + 1, FACETS_PER_MESH):
        chunk = facets[start : start + FACETS_PER_MESH]
        meshes.append(MeshData(_unity_vertices(chunk), range(3 * len(chunk))))
    return meshes


def _unity_vertices(facets: list[Facet]) -> bytes:
    """Position and normal records: ROS (x, y, z) is Unity (-y, z, x); corners 0, 2, 1."""
    values: list[float] = []
    for f in facets:
        normal = (-f[1], f[2], f[0])
        for start in (3, 9, 6):
            values += (-f[start + 1], f[start + 2], f[start], *normal)
    return struct.pack(f"<{len(values)}f", *values)


def read_stl(path: Path) -> list[Facet]:
    """Every facet of a binary or ASCII STL file."""
    try:
        raw = path.read_bytes()
    except OSError as error:
        raise UserError(
            f"cannot read the mesh {str(path)!r}: {error.strerror or error}",
            hint="check that the file exists and can be read",
        ) from None
    if "\0" in raw[:400].decode("utf-8", "replace")[:100]:
        return _binary(raw, str(path))
    return _ascii(raw, str(path))


def _binary(raw: bytes, path: str) -> list[Facet]:
    if len(raw) < 84:
        raise LocatedError.at(
            SourceLocation(path), "binary STL shorter than its 84-byte header", hint=_STL_HINT
        )
    (count,) = struct.unpack_from("<I", raw, 80)
    if len(raw) < 84 + count * _FACET.size:
        held = (len(raw) - 84) // _FACET.size
        raise LocatedError.at(
            SourceLocation(path),
            f"binary STL announces {count} facets but holds {held}",
            hint=_STL_HINT,
        )
    return [_FACET.unpack_from(raw, 84 + i * _FACET.size) for i in range(count)]


_STL_HINT = "export the mesh again as a binary or ASCII STL"
_FLOAT32_MAX = 3.4028234663852886e38


def _ascii(raw: bytes, path: str) -> list[Facet]:
    facets: list[Facet] = []
    current: list[float] = []
    for number, line in enumerate(raw.decode("utf-8", "replace").splitlines(), start=1):
        words = line.split()
        if words[:2] == ["facet", "normal"]:
            current = _floats(words[2:], path, number, line)
        elif words[:1] == ["vertex"] and current:
            current += _floats(words[1:], path, number, line)
            if len(current) == 12:
                facets.append(_float32(current))
                current = []
    return facets


def _floats(words: list[str], path: str, line_number: int, line: str) -> list[float]:
    try:
        if len(words) != 3:
            raise ValueError
        values = [float(word) for word in words]
    except ValueError:
        raise LocatedError.at(
            SourceLocation(path, line_number, 1, line),
            "expected three numbers in this ASCII STL line",
            hint=_STL_HINT,
        ) from None
    # a Mesh holds float32: a larger number has no value there (packing it raised OverflowError)
    if any(abs(value) > _FLOAT32_MAX for value in values if value == value):
        raise LocatedError.at(
            SourceLocation(path, line_number, 1, line),
            "a number in this ASCII STL line is beyond float32's range (±3.4e38)",
            hint="check the mesh's units and export it again",
        )
    return values


def _float32(values: list[float]) -> Facet:
    return struct.unpack("<12f", struct.pack("<12f", *values))
