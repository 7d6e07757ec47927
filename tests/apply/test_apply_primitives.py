"""An object's `primitive` and the mesh components (MeshFilter, MeshRenderer, MeshCollider):
written as Unity 2022.3 writes them, compared with objects Unity 2022.3's 3D Object menu made —
the Plane of ROS#'s Gazebo tutorial scene (tests/data, and the hand-made CameraPlane of its
COMPLETED scene, read from ../shared/vendor), a Cube of ROS#'s Unity simulation scene, and the
Sphere, Capsule, Cylinder and Quad of a public 2022.3 project (MENU_MADE) — and their asset
fields naming Unity's built-in resources or the project's assets."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from helpers import require, run_cli, snapshot
from robot_helpers import R2D2

from unityscaffold.manifest import _keys
from unityscaffold.unity import builtins
from unityscaffold.unity.scene import SceneDocument

DATA = Path(__file__).resolve().parents[1] / "data" / "unity" / "ros-sharp"
COMPLETED = R2D2 / "Scenes" / "Completed" / "gazebo_simulation_scene_ROS2_1_Camera_COMPLETED.unity"
HEADER = "version: 1\nros: 2\nproject: .\nscene: Assets/Scenes/Main.unity\n"
# The GUID of the Cube's material in ROS#'s Unity simulation scene.
CUBE_MATERIAL = "fb5af7f4f42afbf4bb4880e8f14a8d9d"


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return tmp_path / "p"


def _apply(project: Path, body: str, *extra: str):
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", str(project / "robot.yaml"), *extra)


def _scene_path(project: Path) -> Path:
    return project / "Assets" / "Scenes" / "Main.unity"


def _documents(text: str) -> list[str]:
    return ["--- " + part for part in re.split(r"^--- ", text, flags=re.M)[1:]]


def _body(text: str) -> str:
    """A document without its header line and its m_GameObject (fileIDs differ)."""
    lines = text.rstrip("\n").split("\n")[1:]
    return "\n".join(line for line in lines if not line.startswith("  m_GameObject:"))


def _real_object(text: str, name: str) -> dict[str, str]:
    """The components of the GameObject called ``name`` in Unity-written ``text``, by class."""
    docs = _documents(text)
    go = next(d for d in docs if d.split("\n")[1] == "GameObject:" and f"  m_Name: {name}\n" in d)
    go_id = re.match(r"--- !u!1 &(\d+)", go).group(1)  # type: ignore[union-attr]
    return {
        d.split("\n")[1].rstrip(":"): d
        for d in docs
        if f"  m_GameObject: {{fileID: {go_id}}}\n" in d
    }


def _our_object(project: Path, path: str) -> list[tuple[str, str]]:
    """(class, document text) of each component of ``path``, in m_Component order."""
    scene = SceneDocument.load(_scene_path(project))
    go = scene.find_gameobject(path)
    found = []
    for comp in scene.components_of(go):
        doc = scene.document(comp.file_id)
        assert doc is not None
        found.append((comp.type_name, doc.text))
    return found


def test_a_plane_is_the_plane_unity_2022_3_made_with_create_primitive(project):
    # gazebo_simulation_scene_ROS2_1_Camera.unity's "Plane": GameObject > 3D Object > Plane.
    real = _real_object((DATA / "gazebo_simulation_scene_ROS2_1_Camera.unity").read_text(), "Plane")
    run = _apply(project, "objects:\n  - {path: Floor, primitive: plane}\n")
    assert run.code == 0, run.err
    ours = _our_object(project, "Floor")
    assert [c for c, _ in ours] == ["Transform", "MeshFilter", "MeshRenderer", "MeshCollider"]
    for class_name, text in ours[1:]:
        assert _body(text) == _body(real[class_name]), class_name


# What Unity 2022.3's GameObject > 3D Object menu put on a Sphere, a Capsule, a Cylinder and a
# Quad, read off the prefabs a Unity 2022.3 project saved them as (its Packages/manifest.json
# has URP 14.0.12, a 2022.3-only package; the objects are untouched but for their position):
# https://github.com/Alex144xD/Tesis/blob/ec6bf96cdac34ab2d8201c77216547bbcb92bbd8/Assets/Prefabs/
# (Sphere.prefab, "Capsule (1).prefab", Cylinder.prefab, Quad.prefab). Each has the Transform,
# then the MeshFilter (this mesh), the MeshRenderer (Default-Material, the same document as the
# Plane's below) and this collider, whose body (after m_GameObject) is copied here. The Capsule's
# and the Cylinder's agree with those of another 2022.3 project's prefabs,
# https://github.com/AFabulousWhale/EditorTools/blob/fc308952021becd38beb4d695232c45565a3da09/Assets/Prefabs/
_COLLIDER_HEAD = (
    "  m_Material: {fileID: 0}\n  m_IncludeLayers:\n    serializedVersion: 2\n    m_Bits: 0\n"
    "  m_ExcludeLayers:\n    serializedVersion: 2\n    m_Bits: 0\n  m_LayerOverridePriority: 0\n"
    "  m_IsTrigger: 0\n  m_ProvidesContacts: 0\n  m_Enabled: 1\n"
)
MENU_MADE = {
    "sphere": (
        "m_Mesh: {fileID: 10207, guid: 0000000000000000e000000000000000, type: 0}",
        "SphereCollider",
        "  serializedVersion: 3\n  m_Radius: 0.5\n  m_Center: {x: 0, y: 0, z: 0}\n",
    ),
    "capsule": (
        "m_Mesh: {fileID: 10208, guid: 0000000000000000e000000000000000, type: 0}",
        "CapsuleCollider",
        "  serializedVersion: 2\n  m_Radius: 0.5\n  m_Height: 2\n  m_Direction: 1\n"
        "  m_Center: {x: 0, y: 0, z: 0}\n",
    ),
    "cylinder": (
        "m_Mesh: {fileID: 10206, guid: 0000000000000000e000000000000000, type: 0}",
        "CapsuleCollider",
        "  serializedVersion: 2\n  m_Radius: 0.5000001\n  m_Height: 2\n  m_Direction: 1\n"
        "  m_Center: {x: 0.000000059604645, y: 0, z: -0.00000008940697}\n",
    ),
    "quad": (
        "m_Mesh: {fileID: 10210, guid: 0000000000000000e000000000000000, type: 0}",
        "MeshCollider",
        "  serializedVersion: 5\n  m_Convex: 0\n  m_CookingOptions: 30\n"
        "  m_Mesh: {fileID: 10210, guid: 0000000000000000e000000000000000, type: 0}\n",
    ),
}


@pytest.mark.parametrize("shape", list(MENU_MADE))
def test_each_other_primitive_is_the_one_unity_2022_3s_menu_made(project, shape):
    mesh, collider, shape_fields = MENU_MADE[shape]
    plane = _real_object(
        (DATA / "gazebo_simulation_scene_ROS2_1_Camera.unity").read_text(), "Plane"
    )
    run = _apply(project, f"objects:\n  - {{path: Thing, primitive: {shape}}}\n")
    assert run.code == 0, run.err
    ours = _our_object(project, "Thing")
    assert [c for c, _ in ours] == ["Transform", "MeshFilter", "MeshRenderer", collider]
    assert _body(ours[1][1]).endswith(f"\n  {mesh}")
    assert _body(ours[2][1]) == _body(plane["MeshRenderer"])
    assert ours[3][1].split("\n", 1)[1] == (
        f"{collider}:\n  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {{fileID: 0}}\n"
        "  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n"
        + re.search(r"  m_GameObject: .*\n", ours[3][1]).group(0)  # type: ignore[union-attr]
        + _COLLIDER_HEAD
        + shape_fields
    )
    check = _apply(project, (project / "robot.yaml").read_text()[len(HEADER) :], "--check")
    assert check.code == 0, check.out


def test_a_primitives_collider_keeps_the_values_set_on_it_after_unity_fitted_them(project):
    body = "objects:\n  - {path: Pipe, primitive: cylinder}\n"
    assert _apply(project, body).code == 0
    scene = _scene_path(project)
    # Set in Unity's Inspector: the fitted values are where it starts, not what apply keeps.
    scene.write_text(scene.read_text().replace("m_Radius: 0.5000001", "m_Radius: 0.25"))
    check = _apply(project, body, "--check")
    assert check.code == 0, check.out
    assert "m_Radius: 0.25\n" in scene.read_text()


def test_a_cube_is_the_cube_unity_2022_3_made_its_material_named_by_path(project):
    # UnitySimulationScene.unity's "Cube", whose renderer holds the project's material.
    real = _real_object((DATA / "UnitySimulationScene.cube.documents.txt").read_text(), "Cube")
    mat = project / "Assets" / "Materials" / "Blue.mat"
    mat.parent.mkdir(parents=True)
    mat.write_text("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!21 &2100000\nMaterial:\n")
    Path(f"{mat}.meta").write_text(f"fileFormatVersion: 2\nguid: {CUBE_MATERIAL}\n")
    run = _apply(
        project,
        "objects:\n  - path: Cube\n    primitive: cube\n    components:\n"
        "      - {type: MeshRenderer, fields: {m_Materials: [Assets/Materials/Blue.mat]}}\n",
    )
    assert run.code == 0, run.err
    ours = _our_object(project, "Cube")
    assert [c for c, _ in ours] == ["Transform", "MeshFilter", "MeshRenderer", "BoxCollider"]
    for class_name, text in ours[1:]:
        assert _body(text) == _body(real[class_name]), class_name
    check = run_cli("apply", "--check", str(project / "robot.yaml"))
    assert check.code == 0, check.out


def test_the_tutorials_camera_plane_is_its_completed_scenes(project):
    # The CameraPlane a person added under r2d2's box in ROS#'s step-1 COMPLETED scene.
    require(COMPLETED.is_file(), f"ROS#'s r2d2 sample scene ({COMPLETED})")
    real = _real_object(COMPLETED.read_text(encoding="utf-8"), "CameraPlane")
    run = _apply(
        project,
        "objects:\n  - path: r2d2/base_link/box/CameraPlane\n    primitive: plane\n"
        "    position: [0, 0.6, 2.26]\n    rotation: [90, 180, 0]\n"
        "    scale: [0.37296, 1, 0.3]\n    components:\n"
        "      - {type: MeshRenderer, fields: {m_CastShadows: 0}}\n"
        "      - {type: MeshCollider, fields: {m_Convex: true}}\n",
    )
    assert run.code == 0, run.err
    ours = dict(_our_object(project, "r2d2/base_link/box/CameraPlane"))
    for class_name in ("MeshFilter", "MeshRenderer", "MeshCollider"):
        assert _body(ours[class_name]) == _body(real[class_name]), class_name
    again = _apply(project, (project / "robot.yaml").read_text()[len(HEADER) :], "--check")
    assert again.code == 0, again.out


def test_a_primitive_is_a_fixed_point_and_a_changed_mesh_is_drift(project):
    body = "objects:\n  - {path: Floor, primitive: plane}\n"
    assert _apply(project, body).code == 0
    scene = _scene_path(project)
    first = scene.read_bytes()
    assert _apply(project, body).code == 0
    assert scene.read_bytes() == first
    scene.write_bytes(first.replace(b"fileID: 10209,", b"fileID: 10202,", 1))
    check = _apply(project, body, "--check")
    assert check.code == 1, check.out
    assert _apply(project, body).code == 0
    assert scene.read_bytes() == first


def test_mesh_components_declared_alone_take_built_in_and_project_assets(project):
    mesh = project / "Assets" / "Meshes" / "Part_0.asset"
    mesh.parent.mkdir(parents=True)
    mesh.write_text("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!43 &4300000\nMesh:\n")
    Path(f"{mesh}.meta").write_text(
        "fileFormatVersion: 2\nguid: 0123456789abcdef0123456789abcdef\n"
    )
    run = _apply(
        project,
        "objects:\n  - path: Part\n    components:\n"
        "      - {type: MeshFilter, fields: {m_Mesh: Assets/Meshes/Part_0.asset}}\n"
        "      - {type: MeshRenderer, fields: {m_Materials: [Default-Material, null]}}\n"
        "      - {type: MeshCollider, fields: {m_Mesh: Sphere, m_Convex: true}}\n",
    )
    assert run.code == 0, run.err
    ours = dict(_our_object(project, "Part"))
    assert (
        "  m_Mesh: {fileID: 4300000, guid: 0123456789abcdef0123456789abcdef, type: 2}\n"
        in ours["MeshFilter"]
    )
    assert (
        "  m_Materials:\n  - {fileID: 10303, guid: 0000000000000000f000000000000000, type: 0}\n"
        "  - {fileID: 0}\n" in ours["MeshRenderer"]
    )
    assert (
        "  m_Mesh: {fileID: 10207, guid: 0000000000000000e000000000000000, type: 0}\n"
        in ours["MeshCollider"]
    )


BAD = [
    ("objects:\n  - {path: Ball, primitive: cone}\n", "robot.yaml:6:",
     "expected one of: capsule, cube, cylinder, plane, quad, sphere"),
    ("objects:\n  - {path: Ball, primitive: Plane}\n", "robot.yaml:6:", "did you mean 'plane'?"),
    ("objects:\n  - path: Ball\n    primitive: cube\n    components:\n"
     "      - {type: MeshFilter, fields: {m_Mesh: Sphere}}\n", "robot.yaml:9:", "m_Mesh of a cube"),
    ("objects:\n  - path: P\n    components:\n"
     "      - {type: MeshFilter, fields: {m_Mesh: Cone}}\n",
     "robot.yaml:8:", "m_Mesh expects Mesh assets, not 'Cone'"),
    ("objects:\n  - path: P\n    components:\n"
     "      - {type: MeshFilter, fields: {m_Mesh: Assets/None.asset}}\n",
     "robot.yaml:8:", "no file Assets/None.asset in the project"),
    ("objects:\n  - path: P\n    components:\n"
     "      - {type: MeshRenderer, fields: {m_Materials: [Assets/../x.mat]}}\n",
     "robot.yaml:8:", "is not a .mat file inside the project"),
    ("objects:\n  - path: P\n    components:\n"
     "      - {type: MeshRenderer, fields: {m_Materials: Default-Material}}\n",
     "robot.yaml:8:", "expects a list of Material assets"),
]  # fmt: skip


@pytest.mark.parametrize(("body", "where", "message"), BAD, ids=[b[2] for b in BAD])
def test_a_bad_primitive_or_asset_stops_at_its_line_and_writes_nothing(
    project, body, where, message
):
    before = snapshot(project)
    run = _apply(project, body)
    assert run.code == 2, run.out + run.err
    assert where in run.err and message in run.err, run.err
    assert snapshot(project) == {**before, "robot.yaml": (HEADER + body).encode()}


def test_an_asset_without_a_meta_or_of_another_class_is_refused(project):
    mat = project / "Assets" / "Red.mat"
    mat.write_text("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!21 &2100000\nMaterial:\n")
    body = (
        "objects:\n  - path: P\n    components:\n      - {type: MeshFilter, fields: {m_Mesh: X}}\n"
    )
    run = _apply(project, body.replace("X", "Assets/Red.mat"))
    assert run.code == 2 and "is not a .asset file" in run.err, run.err
    run = _apply(
        project,
        body.replace("MeshFilter", "MeshRenderer").replace(
            "m_Mesh: X", "m_Materials: [Assets/Red.mat]"
        ),
    )
    assert run.code == 2 and "Assets/Red.mat has no .meta file" in run.err, run.err
    Path(f"{mat}.meta").write_text("fileFormatVersion: 2\nguid: 0123456789abcdef0123456789abcdef\n")
    mat.write_text("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!43 &4300000\nMesh:\n")
    run = _apply(
        project,
        body.replace("MeshFilter", "MeshRenderer").replace(
            "m_Mesh: X", "m_Materials: [Assets/Red.mat]"
        ),
    )
    assert run.code == 2 and "Assets/Red.mat holds no Material" in run.err, run.err


def test_the_manifest_offers_exactly_the_primitives_the_unity_stage_makes():
    assert set(_keys.PRIMITIVE_NAMES) == set(builtins.PRIMITIVES)
    assert {p.mesh for p in builtins.PRIMITIVES.values()} == set(builtins.BUILTIN_MESHES)


def test_a_new_mesh_collider_takes_the_mesh_filters_mesh_as_the_editor_gives_it(project):
    # Unity's editor sets a MeshCollider added to an object to its MeshFilter's mesh: from the
    # entry's MeshFilter (declared after it, even), or from the one the scene already has.
    run = _apply(
        project,
        "objects:\n  - path: Part\n    components:\n      - MeshCollider\n"
        "      - {type: MeshFilter, fields: {m_Mesh: Cylinder}}\n  - path: Ball\n"
        "    components: [{type: MeshFilter, fields: {m_Mesh: Sphere}}]\n",
    )
    assert run.code == 0, run.err
    cylinder = "  m_Mesh: {fileID: 10206, guid: 0000000000000000e000000000000000, type: 0}\n"
    assert cylinder in dict(_our_object(project, "Part"))["MeshCollider"]
    # Ball's MeshFilter, no longer declared, stays in the scene with its mesh.
    body = (project / "robot.yaml").read_text()[len(HEADER) :]
    run = _apply(
        project, body.replace("[{type: MeshFilter, fields: {m_Mesh: Sphere}}]", "[MeshCollider]")
    )
    assert run.code == 0, run.err
    sphere = "  m_Mesh: {fileID: 10207, guid: 0000000000000000e000000000000000, type: 0}\n"
    assert sphere in dict(_our_object(project, "Ball"))["MeshCollider"]


def test_an_existing_mesh_collider_keeps_its_mesh_and_a_declared_one_wins(project):
    body = (
        "objects:\n  - path: Part\n    components:\n"
        "      - {type: MeshFilter, fields: {m_Mesh: Cube}}\n"
        "      - {type: MeshCollider, fields: {m_Mesh: Sphere}}\n"
    )
    assert _apply(project, body).code == 0
    sphere = "  m_Mesh: {fileID: 10207, guid: 0000000000000000e000000000000000, type: 0}\n"
    assert sphere in dict(_our_object(project, "Part"))["MeshCollider"]
    scene = _scene_path(project)
    # Emptied in Unity: the mesh is given once, to a new collider, and not forced after.
    scene.write_text(scene.read_text().replace(sphere, "  m_Mesh: {fileID: 0}\n"))
    unset = body.replace("{type: MeshCollider, fields: {m_Mesh: Sphere}}", "MeshCollider")
    check = _apply(project, unset, "--check")
    assert check.code == 0, check.out
