"""STL → Mesh assets: the bytes Unity wrote for the Niryo gripper's STL files, and ROS#'s
splitting, ordering and file detection."""

from __future__ import annotations

import struct
from pathlib import Path

import pytest
import yaml

from unityscaffold.errors import LocatedError
from unityscaffold.urdf.stl import FACETS_PER_MESH, read_stl, stl_mesh_assets, stl_meshes

NIRYO_STLS = ["G1_ClampLeft", "G1_ClampRight", "G1_MainSupport", "G1_Rod", "G1_ServoHead"]


def as_unity_2022(text_2020: str) -> str:
    """A Mesh asset Unity 2020.3 wrote, in 2022.3's layout: the Mesh's serializedVersion went
    from 10 to 11 and ``m_CookingOptions`` (default 30) joined after ``m_MeshUsageFlags``."""
    return text_2020.replace("  serializedVersion: 10\n", "  serializedVersion: 11\n", 1).replace(
        "  m_MeshUsageFlags: 0\n", "  m_MeshUsageFlags: 0\n  m_CookingOptions: 30\n", 1
    )


@pytest.mark.parametrize("stem", NIRYO_STLS)
def test_an_stl_becomes_the_mesh_asset_unity_wrote_for_it(niryo: Path, stem: str) -> None:
    """Vertex and index bytes, bounds, counts and every other line, as in Unity's file."""
    (name, text), *rest = stl_mesh_assets(niryo / f"{stem}.STL")
    expected = as_unity_2022((niryo / f"{stem}_0.asset").read_text(encoding="utf-8"))
    assert rest == [] and name == f"{stem}_0.asset"
    assert text == expected


def binary_stl(path: Path, facets: list[tuple[float, ...]]) -> Path:
    body = b"".join(struct.pack("<12fH", *facet, 0) for facet in facets)
    path.write_bytes(
        b"solid looks like ascii".ljust(80, b" ") + struct.pack("<I", len(facets)) + body
    )
    return path


def ascii_stl(path: Path, facets: list[tuple[float, ...]]) -> Path:
    lines = ["solid thing"]
    for f in facets:
        lines += [f"  facet normal {f[0]:.9g}  {f[1]:.9g} {f[2]:.9g}", "    outer loop"]
        lines += [f"      vertex\t{f[i]:.9g} {f[i + 1]:.9g}   {f[i + 2]:.9g}" for i in (3, 6, 9)]
        lines += ["    endloop", "  endfacet"]
    path.write_text("\n".join([*lines, "endsolid thing", ""]), encoding="ascii")
    return path


def test_an_ascii_stl_gives_the_same_mesh_as_the_binary_one(niryo: Path, tmp_path: Path) -> None:
    facets = read_stl(niryo / "G1_Rod.STL")
    converted = ascii_stl(tmp_path / "G1_Rod.stl", facets)
    assert stl_meshes(converted) == stl_meshes(niryo / "G1_Rod.STL")


def test_each_facet_gets_three_vertices_in_unity_axes_with_its_normal(tmp_path: Path) -> None:
    facet = (0.0, 0.0, 1.0, 1, 2, 3, 4, 5, 6, 7, 8, 9)
    (mesh,) = stl_meshes(binary_stl(tmp_path / "one.stl", [facet]))
    records = struct.unpack("<18f", mesh.vertices)
    # ROS (x, y, z) → Unity (-y, z, x); corners 0, 2, 1
    assert records == (-2, 3, 1, -0.0, 1, 0, -8, 9, 7, -0.0, 1, 0, -5, 6, 4, -0.0, 1, 0)
    assert list(mesh.indices) == [0, 1, 2]


@pytest.mark.parametrize(
    ("count", "sizes"),
    [
        (1, [1]),
        (FACETS_PER_MESH - 1, [FACETS_PER_MESH - 1]),
        (FACETS_PER_MESH, [FACETS_PER_MESH, 0]),
        (FACETS_PER_MESH + 1, [FACETS_PER_MESH, 1]),
    ],
)
def test_facets_are_cut_into_meshes_of_at_most_65535_vertices_as_rossharp_does(
    tmp_path: Path, count: int, sizes: list[int]
) -> None:
    facet = (0.0, 0.0, 1.0, 0, 0, 0, 1, 0, 0, 0, 1, 0)
    meshes = stl_meshes(binary_stl(tmp_path / "many.stl", [facet] * count))
    assert [m.vertex_count // 3 for m in meshes] == sizes
    assert all(list(m.indices) == list(range(m.vertex_count)) for m in meshes)


def test_assets_are_named_after_the_file_and_numbered(tmp_path: Path) -> None:
    facet = (0.0, 0.0, 1.0, 0, 0, 0, 1, 0, 0, 0, 1, 0)
    path = binary_stl(tmp_path / "arm_link.STL", [facet] * FACETS_PER_MESH)
    assets = stl_mesh_assets(path)
    assert [name for name, _ in assets] == ["arm_link_0.asset", "arm_link_1.asset"]
    assert "  m_Name: arm_link_1\n" in assets[1][1] and "  m_VertexCount: 0\n" in assets[1][1]


def test_the_same_stl_gives_byte_identical_assets(niryo: Path) -> None:
    assert stl_mesh_assets(niryo / "G1_ClampLeft.STL") == stl_mesh_assets(
        niryo / "G1_ClampLeft.STL"
    )


def test_a_truncated_binary_stl_is_refused(tmp_path: Path) -> None:
    path = binary_stl(tmp_path / "cut.stl", [(0.0,) * 12] * 3)
    path.write_bytes(path.read_bytes()[:-60])
    with pytest.raises(LocatedError, match="announces 3 facets but holds 1"):
        read_stl(path)


def test_a_bad_number_in_an_ascii_stl_is_located_at_its_line(tmp_path: Path) -> None:
    path = tmp_path / "bad.stl"
    path.write_text("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zero\n", encoding="ascii")
    with pytest.raises(LocatedError) as caught:
        read_stl(path)
    assert caught.value.render().startswith(f"{path}:4:1: error: expected three numbers")


def test_a_number_beyond_float32_in_an_ascii_stl_is_located_at_its_line(tmp_path: Path) -> None:
    path = tmp_path / "huge.stl"
    path.write_text(
        "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1e40 0 0\n", encoding="ascii"
    )
    with pytest.raises(LocatedError) as caught:
        read_stl(path)
    rendered = caught.value.render()
    assert rendered.startswith(f"{path}:5:1: error: a number in this ASCII STL line is beyond")
    assert "hint: check the mesh's units" in rendered


def test_a_mesh_named_with_yaml_indicators_keeps_its_name(tmp_path: Path) -> None:
    # the name is the file's: written plain, '#' began a comment and ': ' a mapping
    path = binary_stl(tmp_path / "arm #2: left.stl", [(0.0,) * 12])
    [(name, text)] = stl_mesh_assets(path)
    assert name == "arm #2: left_0.asset"
    body = text.split("\n--- !u!43 &4300000\n", 1)[1]
    assert yaml.safe_load(body)["Mesh"]["m_Name"] == "arm #2: left_0"
