"""Mesh geometries as model instances: the eight instances of the r2d2 sample scene Unity
saved, the prefabs Unity wrote for the Niryo gripper's STL files, the ``.meta`` files Unity
wrote for the sample's models and textures, and what is refused, at its place, and why."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from helpers import binary_stl

from unityscaffold.errors import LocatedError
from unityscaffold.unity.meta import read_meta_guid
from unityscaffold.unity.modelids import ROOT_PATH, model_file_id
from unityscaffold.unity.prefabinstance import AssetObject, ModelInstance, instance_documents
from unityscaffold.unity.stlprefab import stl_prefab, stl_prefab_text
from unityscaffold.urdf import RobotImport, import_robot
from unityscaffold.urdf.stl import FACETS_PER_MESH, stl_mesh_assets

DOC_RE = re.compile(r"^--- !u!(\d+) &(-?\d+)( stripped)?\n", re.M)


def documents(text: str) -> dict[int, str]:
    """Each document's text by its fileID."""
    starts = list(DOC_RE.finditer(text))
    ends = [m.start() for m in starts[1:]] + [len(text)]
    return {int(m.group(2)): text[m.start() : end] for m, end in zip(starts, ends, strict=True)}


def ref(text: str, key: str) -> int:
    match = re.search(rf"^  {key}: \{{fileID: (-?\d+)\}}", text, re.M)
    assert match, key
    return int(match.group(1))


def name_of(docs: dict[int, str], transform: int) -> str:
    go = docs[ref(docs[transform], "m_GameObject")]
    match = re.search(r"^  m_Name: (.*)$", go, re.M)
    assert match
    return match.group(1)


def r2d2_import(urdf: Path) -> RobotImport:
    sample = urdf.parent
    packages = {"urdf_tutorial": sample / "Urdf" / "file_server2" / "urdf_tutorial"}
    return import_robot(urdf, packages=packages, project=sample)


def test_each_instance_of_the_r2d2_scene_is_the_one_made_for_its_mesh(
    r2d2_urdf: Path, r2d2_scene: Path
) -> None:
    """The PrefabInstance, its stripped objects and its added MeshCollider, text for text
    (the tutorial's author pressed "Convex: Enable", which the writer's ``convex`` does)."""
    result = r2d2_import(r2d2_urdf)
    docs = documents(r2d2_scene.read_text(encoding="utf-8"))
    meshes = r2d2_urdf.parent / "Urdf" / "file_server2"
    links = {link.name: i for i, link in enumerate(result.robot.links)}
    instances = [i for i, text in docs.items() if text.startswith("--- !u!1001 ")]
    assert len(instances) == 8
    for instance_id in instances:
        parent = ref(docs[instance_id], "  m_TransformParent")
        part = ref(docs[parent], "m_Father")
        link = name_of(docs, ref(docs[part], "m_Father"))
        kind = "visual" if name_of(docs, part) == "Visuals" else "collision"
        key = f"link[{links[link]}]/{kind}[0]/shape"
        made = result.models[key].with_convex(True)
        owned = {
            file_id: text
            for file_id, text in docs.items()
            if f"m_PrefabInstance: {{fileID: {instance_id}}}" in text
        }
        colliders = [
            file_id
            for file_id, text in docs.items()
            if any(f"m_GameObject: {{fileID: {go}}}" in text for go in owned)
        ]
        roles = made.scene_roles()
        ids = dict(zip(roles, [instance_id, *sorted(owned), *colliders], strict=True))
        rendered = instance_documents(
            made,
            parent=parent,
            ids=ids,
            guid_of=lambda path: read_meta_guid(meshes / f"{path}.meta") or "",
        )
        assert dict(rendered) == {i: docs[i] for i in ids.values()}, key


NIRYO_STEMS = ["G1_ClampLeft", "G1_ClampRight", "G1_MainSupport", "G1_Rod", "G1_ServoHead"]


def as_unity_2022(prefab_2020: str) -> str:
    """A prefab Unity 2020.3 wrote, in 2022.3's layout (as the r2d2 scene shows it): a
    Transform gained ``serializedVersion: 2`` and ``m_ConstrainProportionsScale`` and lost
    ``m_RootOrder``; a MeshRenderer gained ``m_StaticShadowCaster``."""
    text = re.sub(
        r"(Transform:\n(?:  .*\n)*?  m_GameObject: .*\n)",
        r"\1  serializedVersion: 2\n",
        prefab_2020,
    )
    text = re.sub(r"(  m_LocalScale: .*\n)", r"\1  m_ConstrainProportionsScale: 0\n", text)
    text = re.sub(r"  m_RootOrder: \d+\n", "", text)
    return text.replace(
        "  m_DynamicOccludee: 1\n", "  m_DynamicOccludee: 1\n  m_StaticShadowCaster: 0\n"
    )


def by_role(prefab: str) -> dict[str, str]:
    """The prefab's documents keyed by class and GameObject name, fileIDs replaced by those
    keys (Unity's are random, ours derived): what is left is what Unity decides."""
    docs = documents(prefab)
    names: dict[int, str] = {}
    for file_id, text in docs.items():
        match = re.search(r"^  m_Name: (.*)$", text, re.M)
        if text.startswith("--- !u!1 ") and match:
            names[file_id] = match.group(1)
    roles = {}
    for file_id, text in docs.items():
        cls = text.split("\n", 2)[1].rstrip(":")
        owner = file_id if cls == "GameObject" else ref(text, "m_GameObject")
        roles[file_id] = f"{cls}@{names[owner]}"
    keyed = {}
    for file_id, text in docs.items():
        text = re.sub(r"-?\d{6,}", lambda m: roles.get(int(m.group()), m.group()), text)
        keyed[roles[file_id]] = text
    return keyed


@pytest.mark.parametrize("stem", NIRYO_STEMS)
def test_an_stl_prefab_is_the_one_unity_wrote_but_for_its_file_ids(niryo: Path, stem: str) -> None:
    guid = read_meta_guid(niryo / f"{stem}_0.asset.meta")
    assert guid is not None
    (count,) = {len(stl_mesh_assets(niryo / f"{stem}.STL"))}
    ours = stl_prefab_text(stl_prefab(stem, count), [guid])
    theirs = as_unity_2022((niryo / f"{stem}.prefab").read_text(encoding="utf-8"))
    assert by_role(ours) == by_role(theirs)
    # and in Unity's order: GameObjects by fileID, each followed by its components
    for text in (ours, theirs):
        gameobjects = [int(m.group(2)) for m in DOC_RE.finditer(text) if m.group(1) == "1"]
        assert gameobjects == sorted(gameobjects)
        assert text.startswith("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!1 ")


def test_the_r2d2_models_and_textures_get_the_meta_unity_wrote_but_for_the_guid(
    r2d2_urdf: Path,
) -> None:
    result = r2d2_import(r2d2_urdf)
    folder = r2d2_urdf.parent / "Urdf" / "file_server2"
    assert [a.path for a in result.model_assets] == [
        "urdf_tutorial/meshes/l_finger.dae",
        "urdf_tutorial/meshes/l_finger_color.png",
        "urdf_tutorial/meshes/l_finger_tip.dae",
        "urdf_tutorial/meshes/l_finger_tip_color.png",
    ]
    for asset in result.model_assets:
        unity = (folder / f"{asset.path}.meta").read_text(encoding="utf-8")
        guid = read_meta_guid(folder / f"{asset.path}.meta")
        assert guid is not None
        assert asset.meta(guid) == unity, asset.path
        assert asset.content(lambda _: "") == (folder / asset.path).read_bytes()


def stl_robot(tmp_path: Path, niryo: Path, body: str, stems: tuple[str, ...] = ("G1_Rod",)) -> Path:
    package = tmp_path / "desc" / "meshes"
    package.mkdir(parents=True)
    for stem in stems:
        shutil.copy(niryo / f"{stem}.STL", package / f"{stem}.STL")
    urdf = tmp_path / "r.urdf"
    urdf.write_text(f'<robot name="r">\n<link name="a">\n{body}</link>\n</robot>\n', "utf-8")
    return urdf


def test_an_stl_collision_replaces_each_part_s_renderer_and_filter_by_a_collider(
    tmp_path: Path, niryo: Path
) -> None:
    urdf = stl_robot(
        tmp_path,
        niryo,
        '<visual><geometry><mesh filename="package://desc/meshes/G1_Rod.STL"/></geometry>'
        "</visual>\n"
        '<collision><geometry><mesh filename="package://desc/meshes/G1_Rod.STL"/></geometry>'
        "</collision>\n",
    )
    result = import_robot(urdf, packages={}, project=tmp_path)
    visual = result.models["link[0]/visual[0]/shape"]
    collision = result.models["link[0]/collision[0]/shape"]
    prefab = stl_prefab("G1_Rod", 1)
    (part,) = prefab.parts
    assert visual.source == collision.source == "desc/meshes/G1_Rod.prefab"
    assert (visual.removed, visual.added) == ((), ())
    assert collision.removed == (part.renderer, part.filter)
    ((added),) = collision.added
    assert added.target == part.gameobject and not added.convex
    assert added.mesh.path == "desc/meshes/G1_Rod_0.asset" and added.mesh.file_id == 4300000
    # the root's place and name, as for a model: with ROS#'s negative zeros of alignment
    changes = [(c.target, c.property_path, c.value) for c in visual.modifications]
    assert changes[3:7] == [
        (prefab.transform, "m_LocalRotation.w", "1"),
        (prefab.transform, "m_LocalRotation.x", "-0"),
        (prefab.transform, "m_LocalRotation.y", "-0"),
        (prefab.transform, "m_LocalRotation.z", "-0"),
    ]
    assert changes[-1] == (prefab.gameobject, "m_Name", "G1_Rod")
    (asset,) = result.model_assets
    text = asset.content(lambda path: "0123456789abcdef0123456789abcdef").decode()
    assert asset.path == "desc/meshes/G1_Rod.prefab" and "  m_Name: G1_Rod_0\n" in text


def test_the_order_of_an_stl_instance_s_changes_is_both_by_target_and_by_time() -> None:
    """Unity keeps an instance's changes in one of these orders; the prefab's fileIDs make
    them the same, so a scene Unity saves again does not move them."""
    prefab = stl_prefab("arm", 3)
    in_time = [prefab.transform, prefab.gameobject]
    for part in prefab.parts:
        in_time += [part.gameobject, part.transform, part.renderer, part.filter]
    assert in_time == sorted(in_time) and len(set(in_time)) == len(in_time)


def refusal(urdf: Path, project: Path) -> str:
    with pytest.raises(LocatedError) as caught:
        import_robot(urdf, packages={}, project=project)
    return caught.value.render()


MATERIAL_CHANGE = "m_Materials.Array.data[0]"


def material_changes(instance: ModelInstance) -> list[tuple[int, str | None]]:
    """The instance's material changes: each renderer and the asset it gets."""
    return [
        (c.target, c.reference.path if c.reference else None)
        for c in instance.modifications
        if c.property_path == MATERIAL_CHANGE
    ]


def test_a_material_on_an_stl_visual_goes_on_every_part_s_renderer_after_the_root_s_changes(
    tmp_path: Path, niryo: Path
) -> None:
    """ROS# sets ``sharedMaterial`` on each renderer under the visual: one per Mesh asset."""
    urdf = stl_robot(
        tmp_path,
        niryo,
        '<visual><geometry><mesh filename="package://desc/meshes/big.STL"/></geometry>\n'
        '  <material name="red"><color rgba="1 0 0 1"/></material></visual>\n'
        '<visual><geometry><mesh filename="package://desc/meshes/big.STL"/></geometry>'
        "</visual>\n",
    )
    binary_stl(tmp_path / "desc" / "meshes" / "big.STL", FACETS_PER_MESH + 1)
    result = import_robot(urdf, packages={}, project=tmp_path)
    painted = result.models["link[0]/visual[0]/shape"]
    plain = result.models["link[0]/visual[1]/shape"]
    prefab = stl_prefab("big", 2)
    assert material_changes(painted) == [
        (part.renderer, "Materials/red.mat") for part in prefab.parts
    ]
    # the rest is the instance a visual without a material gets, its changes first
    assert painted.modifications[: len(plain.modifications)] == plain.modifications
    assert material_changes(plain) == [] and len(painted.modifications) == 13
    (change, _) = painted.modifications[-2:]
    assert (change.value, change.reference) == ("", AssetObject("Materials/red.mat", 2100000, 2))
    assert "Materials/red.mat" in result.files


@pytest.mark.parametrize(
    ("first", "second", "written"),
    [
        ("meshes/G1_Rod.STL", "meshes/G1_Rod.stl", "desc/meshes/G1_Rod.prefab"),
        ("meshes/G1_Rod.STL", "meshes/g1_rod.STL", "desc/meshes/g1_rod.prefab"),
        ("meshes/G1_Rod.STL", "Meshes/G1_Rod.STL", "desc/Meshes/G1_Rod.prefab"),
    ],
)
def test_two_mesh_files_whose_names_differ_only_by_case_are_refused_at_the_second(
    tmp_path: Path, niryo: Path, first: str, second: str, written: str
) -> None:
    """Windows and macOS, where Unity opens the project, would make one file of their assets
    (and ``arm.STL`` and ``arm.stl`` would even share one prefab path on Linux)."""
    urdf = stl_robot(
        tmp_path,
        niryo,
        f'<visual><geometry><mesh filename="package://desc/{first}"/></geometry></visual>\n'
        f'<collision><geometry><mesh filename="package://desc/{second}"/></geometry>'
        "</collision>\n",
    )
    copy = tmp_path / "desc" / second
    copy.parent.mkdir(exist_ok=True)
    shutil.copy(niryo / "G1_Rod.STL", copy)
    message = refusal(urdf, tmp_path)
    assert message.startswith(
        f"{urdf}:4:22: error: mesh 'package://desc/{second}' would be written as "
        f"{written}, which on a case-insensitive file system (Windows, macOS) is the file of "
        f"mesh 'package://desc/{first}' (line 3)"
    ), message
    assert "hint: rename one of the two mesh files" in message


@pytest.mark.parametrize(
    ("suffix", "reason"),
    [
        # ROS# instantiates Unity's import, whose root pose no Unity-written scene here shows
        (".fbx", "ROS# instantiates the model Unity imports from a .fbx file, whose root pose"),
        (".FBX", "ROS# instantiates the model Unity imports from a .fbx file, whose root pose"),
        # Unity imports neither without a package: ROS#'s FindUrdfAsset finds nothing
        (".gltf", "Unity 2022.3 imports .gltf files only with a package (glTFast, UnityGLTF)"),
        (".glb", "Unity 2022.3 imports .glb files only with a package (glTFast, UnityGLTF)"),
        (".ply", "Unity 2022.3 imports no model from a .ply file by itself"),
        ("", "Unity 2022.3 imports no model from a file without extension by itself"),
    ],
)
def test_model_formats_ros_sharp_cannot_import_as_checked_are_refused_at_the_mesh(
    tmp_path: Path, suffix: str, reason: str
) -> None:
    (tmp_path / "desc").mkdir()
    (tmp_path / "desc" / f"arm{suffix}").write_text("arm\n", encoding="utf-8")
    urdf = tmp_path / "r.urdf"
    urdf.write_text(
        f'<robot name="r"><link name="a"><visual><geometry>\n  <mesh filename='
        f'"package://desc/arm{suffix}"/></geometry></visual></link></robot>',
        encoding="utf-8",
    )
    message = refusal(urdf, tmp_path)
    assert message.startswith(f"{urdf}:2:3: error: mesh 'package://desc/arm{suffix}': {reason}")
    assert "hint: convert the mesh to STL or COLLADA (.dae)" in message


def test_every_refused_mesh_of_a_robot_is_reported_in_one_run(tmp_path: Path) -> None:
    (tmp_path / "desc").mkdir()
    for name in ("a.fbx", "b.glb"):
        (tmp_path / "desc" / name).write_text("x\n", encoding="utf-8")
    urdf = tmp_path / "r.urdf"
    urdf.write_text(
        '<robot name="r"><link name="a">\n'
        '<visual><geometry><mesh filename="package://desc/a.fbx"/></geometry></visual>\n'
        '<visual><geometry><mesh filename="package://desc/b.glb"/></geometry></visual>\n'
        "</link></robot>",
        encoding="utf-8",
    )
    message = refusal(urdf, tmp_path)
    assert f"{urdf}:2:19: error: mesh 'package://desc/a.fbx'" in message
    assert f"{urdf}:3:19: error: mesh 'package://desc/b.glb'" in message


def collada(nodes: str, *, up: str = "Y_UP", images: str = "", geometries: str = "") -> str:
    return (
        '<?xml version="1.0"?>\n<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema"'
        ' version="1.4.1">\n'
        f'<asset><unit name="meter" meter="1"/><up_axis>{up}</up_axis></asset>\n'
        f"<library_images>{images}</library_images>\n"
        f"<library_geometries>{geometries}</library_geometries>\n"
        '<library_visual_scenes><visual_scene id="s">\n'
        f"{nodes}</visual_scene></library_visual_scenes>\n"
        '<scene><instance_visual_scene url="#s"/></scene>\n</COLLADA>\n'
    )


NODE = '<node id="{0}" name="{0}"><instance_geometry url="#g"/></node>\n'
# the geometry NODE draws, in one part
GEOMETRY = '<geometry id="g"><mesh><triangles count="0"/></mesh></geometry>'
RED = '<material name="red"><color rgba="1 0 0 1"/></material>'
ROOT_TRANSFORM = model_file_id("Transform", ROOT_PATH)
ROOT_RENDERER = model_file_id("MeshRenderer", ROOT_PATH)
ROOT_GAMEOBJECT = model_file_id("GameObject", ROOT_PATH)


def dae_robot(tmp_path: Path, dae: str, part: str = "collision", material: str = "") -> Path:
    (tmp_path / "desc").mkdir(exist_ok=True)
    (tmp_path / "desc" / "m.dae").write_text(dae, encoding="utf-8")
    urdf = tmp_path / "r.urdf"
    urdf.write_text(
        f'<robot name="r"><link name="a"><{part}><geometry>\n'
        f'   <mesh filename="package://desc/m.dae"/></geometry>{material}</{part}></link></robot>',
        encoding="utf-8",
    )
    return urdf


@pytest.mark.parametrize(
    ("dae", "part", "reason"),
    [
        (
            collada(NODE.format("n").replace("/>", "/><instance_geometry url='#g'/>")),
            "collision",
            "its node 'n' (line 7) holds 2 geometries, cameras or lights",
        ),
        (
            collada(NODE.format("n").replace("/>", "/><instance_camera url='#c'/>")),
            "collision",
            "its node 'n' (line 7) holds 2 geometries, cameras or lights",
        ),
        (
            collada("<node>" + NODE.format("a") + "</node><node>" + NODE.format("b") + "</node>"),
            "collision",
            "a node without name or id leads to its node 'a' (line 7)",
        ),
    ],
)
def test_a_collada_model_whose_objects_are_not_checked_is_refused_at_the_mesh(
    tmp_path: Path, dae: str, part: str, reason: str
) -> None:
    urdf = dae_robot(tmp_path, dae, part)
    message = refusal(urdf, tmp_path)
    assert message.startswith(f"{urdf}:2:4: error: ") and reason in message, message
    assert "\n  hint: " in message


@pytest.mark.parametrize(
    "dae",
    [
        collada(NODE.format("n"), up="Z_UP"),
        collada(NODE.format("a") + NODE.format("b"), up="X_UP"),
        collada('<node id="n" name="n"><translate>0 1 0</translate></node>'),
        collada(""),
    ],
)
def test_models_of_any_up_axis_node_count_or_pose_are_visuals(tmp_path: Path, dae: str) -> None:
    urdf = dae_robot(tmp_path, dae, "visual")
    (instance,) = import_robot(urdf, packages={}, project=tmp_path).models.values()
    assert [c.value for c in instance.modifications][-1] == "m"
    assert (instance.removed, instance.added) == ((), ())


def test_a_collision_on_a_model_of_several_nodes_replaces_each_node_s_mesh_by_a_collider(
    tmp_path: Path,
) -> None:
    """ROS#'s ``ConvertMeshToColliders``: per object with a MeshFilter a MeshCollider on its
    mesh, its renderer and filter removed; the objects by ``urdf.colladamodel``'s paths."""
    nodes = NODE.format("a") + '<node id="b" name="b">' + NODE.format("c") + "</node>"
    urdf = dae_robot(tmp_path, collada(nodes, up="Z_UP", geometries=GEOMETRY))
    (instance,) = import_robot(urdf, packages={}, project=tmp_path).models.values()
    paths = ["//RootNode/root/a", "//RootNode/root/b/c"]
    assert instance.removed == tuple(
        model_file_id(cls, path) for path in paths for cls in ("MeshRenderer", "MeshFilter")
    )
    assert [(a.target, a.mesh.file_id, a.mesh.path) for a in instance.added] == [
        (model_file_id("GameObject", paths[0]), model_file_id("Mesh", "a"), "desc/m.dae"),
        (model_file_id("GameObject", paths[1]), model_file_id("Mesh", "c"), "desc/m.dae"),
    ]


def test_a_material_on_a_collada_visual_goes_on_every_node_s_renderer(tmp_path: Path) -> None:
    """As on the UR3 instances Unity saved (``tests/urdf/test_colladamodel.py``): one change
    of ``m_Materials.Array.data[0]`` per renderer, by the target's fileID."""
    dae = collada(NODE.format("node0") + NODE.format("node1"), up="Z_UP", geometries=GEOMETRY)
    urdf = dae_robot(tmp_path, dae, "visual", material=RED)
    (instance,) = import_robot(urdf, packages={}, project=tmp_path).models.values()
    assert material_changes(instance) == [
        (-7264643304161535556, "Materials/red.mat"),
        (55291342286754144, "Materials/red.mat"),
    ]


def test_a_material_on_a_model_whose_renderers_are_not_checked_is_refused_at_the_material(
    tmp_path: Path,
) -> None:
    nodes = NODE.format("n").replace("/>", "/><instance_geometry url='#g'/>")
    urdf = dae_robot(tmp_path, collada(nodes, geometries=GEOMETRY), "visual", material=RED)
    message = refusal(urdf, tmp_path)
    assert message.startswith(
        f"{urdf}:2:54: error: model 'package://desc/m.dae' cannot take a <material> as ROS# "
        "makes it: its node 'n' (line 7) holds 2 geometries, cameras or lights"
    ), message
    assert "hint: export the model with one geometry per node" in message


def test_a_moved_model_root_under_a_turned_link_is_placed_in_the_link_s_axes(
    tmp_path: Path,
) -> None:
    """ROS# parents the instance keeping its world position (``SetParentAndAlign``) while
    the link's parent ``b`` is already turned by its joint (yaw 90° → Unity ``Euler(0, -90,
    0)``) and the link ``c`` itself not yet (its own yaw is left out): the root's Y_UP position
    (-1, 0, 0) (node at x = 1, mirrored) turned back by +90° about y is (0, 0, 1)."""
    (tmp_path / "desc").mkdir()
    dae = collada(
        '<node id="n" name="n"><translate>1 0 0</translate><instance_geometry url="#g"/></node>',
        geometries=GEOMETRY,
    )
    (tmp_path / "desc" / "m.dae").write_text(dae, encoding="utf-8")
    urdf = tmp_path / "r.urdf"
    urdf.write_text(
        '<robot name="r"><link name="a"/><link name="b"/><link name="c"><visual><geometry>'
        '<mesh filename="package://desc/m.dae"/></geometry></visual></link>'
        '<joint name="j" type="fixed"><parent link="a"/><child link="b"/>'
        '<origin rpy="0 0 1.5707963267948966"/></joint>'
        '<joint name="k" type="fixed"><parent link="b"/><child link="c"/>'
        '<origin rpy="0 0 0.5"/></joint></robot>',
        encoding="utf-8",
    )
    (instance,) = import_robot(urdf, packages={}, project=tmp_path).models.values()
    position = [float(c.value) for c in instance.modifications[:3]]
    assert position == pytest.approx([0.0, 0.0, 1.0], abs=1e-6)


def test_a_malformed_collada_file_is_located_in_it(tmp_path: Path) -> None:
    urdf = dae_robot(tmp_path, "<COLLADA><asset></COLLADA>\n", "visual")
    message = refusal(urdf, tmp_path)
    assert message.startswith(f"{tmp_path / 'desc' / 'm.dae'}:1:")
    assert "malformed XML" in message and "hint: export the model again" in message


def test_a_top_node_whose_transform_is_no_numbers_is_refused_in_the_model(tmp_path: Path) -> None:
    """The one top node is the model's root, whose pose the scene records: an ``inf`` there
    (which once ended apply in a traceback) is a located error in the model file."""
    node = '<node id="n" name="n"><rotate>0 0 1 inf</rotate><instance_geometry url="#g"/></node>'
    urdf = dae_robot(tmp_path, collada(node, geometries=GEOMETRY), "visual")
    message = refusal(urdf, tmp_path)
    assert message.startswith(f"{tmp_path / 'desc' / 'm.dae'}:7:1: error: model "), message
    assert "its top node's transform is not numbers" in message


def test_a_node_far_past_float32_s_range_imports_at_infinity_as_csharp_casts(
    tmp_path: Path,
) -> None:
    """C#'s ``(float)`` of 1e39 is Infinity (once an OverflowError and a traceback here)."""
    node = (
        '<node id="n" name="n"><translate>1e39 0 0</translate><instance_geometry url="#g"/></node>'
    )
    urdf = dae_robot(tmp_path, collada(node, geometries=GEOMETRY), "visual")
    (instance,) = import_robot(urdf, packages={}, project=tmp_path).models.values()
    assert [c.value for c in instance.modifications[:3]] == ["-Infinity", "0", "0"]
