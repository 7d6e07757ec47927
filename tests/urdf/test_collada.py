"""What the stage reads of a COLLADA file: the r2d2 sample's finger as Unity imported it."""

from __future__ import annotations

from pathlib import Path, PurePosixPath

from unityscaffold.urdf.collada import read_collada


def test_the_r2d2_finger_is_one_still_y_up_node_with_one_geometry(r2d2_urdf: Path) -> None:
    meshes = r2d2_urdf.parent / "Urdf" / "file_server2" / "urdf_tutorial" / "meshes"
    facts = read_collada(meshes / "l_finger.dae")
    assert (facts.up_axis, facts.meter) == ("Y_UP", 1.0)
    (node,) = facts.nodes
    # its <scale> does not move it: Unity folds the node into the root with that scale only
    assert (node.name, node.id, node.geometries, node.has_children, node.moved) == (
        "finger_M2K_mod",
        "finger_M2K_mod",
        1,
        False,
        False,
    )
    assert (node.location.line, node.location.col) == (170, 7)
    # its geometry is one <triangles>: one submesh, one material slot on the root's renderer
    assert node.parts == 1
    # the normal map is named but not shipped: only what exists is copied
    assert facts.images == (
        PurePosixPath("l_finger_color.png"),
        PurePosixPath("l_finger_normals.png"),
    )


def test_a_file_without_up_axis_or_unit_reads_as_collada_s_defaults(tmp_path: Path) -> None:
    path = tmp_path / "m.dae"
    path.write_text('<COLLADA><asset><unit meter="cm"/></asset></COLLADA>', encoding="utf-8")
    facts = read_collada(path)
    assert (facts.up_axis, facts.meter, facts.nodes, facts.images) == ("Y_UP", 1.0, (), ())


def test_a_node_s_parts_are_the_primitives_of_the_geometries_it_draws(tmp_path: Path) -> None:
    path = tmp_path / "m.dae"
    path.write_text(
        "<COLLADA><library_geometries>"
        '<geometry id="g"><mesh><source id="s"/><triangles/><polylist/></mesh></geometry>'
        '<geometry id="h"><mesh><lines/></mesh></geometry>'
        "</library_geometries><library_visual_scenes><visual_scene>"
        '<node name="a"><instance_geometry url="#g"/><instance_geometry url="#h"/></node>'
        '<node name="b"><instance_geometry url="#missing"/></node>'
        "</visual_scene></library_visual_scenes></COLLADA>",
        encoding="utf-8",
    )
    assert [(n.name, n.geometries, n.parts) for n in read_collada(path).nodes] == [
        ("a", 2, 3),
        ("b", 1, 0),
    ]
