"""ROS#'s cylinder collider mesh: text-identical to the six Meshes its importer saved in the
r2d2 scene."""

from __future__ import annotations

from pathlib import Path

from unityscaffold.unity import SceneDocument
from unityscaffold.unity.mesh import mesh_document
from unityscaffold.urdf.cylinder import cylinder_collider_mesh


def test_the_cylinder_collider_mesh_is_the_one_in_the_scene_to_the_byte(r2d2_scene: Path) -> None:
    scene = SceneDocument.load(r2d2_scene)
    meshes = [doc for doc in scene.documents() if doc.class_id == 43]
    assert len(meshes) == 6
    ours = cylinder_collider_mesh()
    for doc in meshes:
        assert mesh_document(doc.file_id, "", ours, keep=True) == doc.text


def test_the_cylinder_mesh_has_rossharps_counts() -> None:
    mesh = cylinder_collider_mesh()
    assert (mesh.vertex_count, len(mesh.indices), max(mesh.indices)) == (1864, 363, 123)
