"""A robot with textures, applied: a COLLADA model whose texture is a JPG, a URDF material of a
texture alone, and materials whose names are no file names. The texture files are copied where
ROS#'s importer finds them, each with the ``.meta`` Unity 2022.3 wrote for the r2d2 sample's
PNG texture (but for the GUID); the textured ``.mat`` is golden (``golden/robot_textures``;
regenerate with ``UNITYSCAFFOLD_UPDATE=1`` and review the diff); a second apply writes nothing
and ``--check`` is clean."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from helpers import text_diff, updating
from robot_helpers import (
    FINGER,
    HEADER,
    apply,
    apply_manifest,
    apply_refused,
    apply_writes_nothing,
    copy_meshes,
    field,
    inertial,
    init_project,
    meta_guid,
)

GOLDEN = Path(__file__).parent / "golden" / "robot_textures"
MANIFEST = HEADER + "    packages: {desc: ros/desc}\n"
ROBOT = "Assets/Urdf/bot"
SKIN = '<material name="pal/Skin"><texture filename="package://desc/textures/skin.tga"/></material>'
URDF = f"""<robot name="bot">
  {SKIN}
  <link name="base">{inertial()}
    <visual name="finger"><geometry><mesh filename="package://desc/meshes/l_finger.dae"/></geometry></visual>
    <visual name="box"><geometry><box size="1 1 1"/></geometry><material name="pal/Skin"/></visual>
    <visual name="red"><geometry><sphere radius="1"/></geometry>
      <material name="Red"><color rgba="1 0 0 1"/></material></visual>
    <visual name="other"><geometry><sphere radius="1"/></geometry>
      <material name="red"><color rgba="0.5 0 0 1"/></material></visual>
  </link>
</robot>
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    root = init_project(tmp_path, {"ros/bot.urdf": URDF, "robot.yaml": MANIFEST})
    meshes = copy_meshes(root, ("l_finger.dae",))
    # the finger's texture as a JPG: the model names it so, the bytes are copied as they are
    dae = meshes / "l_finger.dae"
    dae.write_text(dae.read_text().replace("l_finger_color.png", "l_finger_color.jpg"))
    shutil.copy(FINGER / "l_finger_color.png", meshes / "l_finger_color.jpg")
    (root / "ros/desc/textures").mkdir()
    (root / "ros/desc/textures/skin.tga").write_bytes(b"TGA bytes")
    return root


def unity_texture_meta(guid: str) -> str:
    """The .meta Unity 2022.3 wrote for the r2d2 finger's texture, with ``guid``."""
    meta = FINGER / "l_finger_color.png.meta"
    return meta.read_text().replace(meta_guid(meta), guid)


def renderer_material(project: Path, visual: str, shape: str) -> str:
    (material,) = field(
        project, f"bot/base/Visuals/{visual}/{shape}", "MeshRenderer", "m_Materials"
    )
    assert isinstance(material, dict) and material["fileID"] == "2100000"
    return str(material["guid"])


def test_textures_are_copied_with_unity_s_meta_and_the_textured_mat_names_its_texture(
    project: Path,
) -> None:
    run = apply(project)
    assert run.code == 0, run.err
    for texture, source in (
        ("desc/meshes/l_finger_color.jpg", FINGER / "l_finger_color.png"),
        ("desc/textures/skin.tga", project / "ros/desc/textures/skin.tga"),
    ):
        copy = project / ROBOT / texture
        assert copy.read_bytes() == source.read_bytes()
        meta = Path(f"{copy}.meta")
        assert meta.read_text() == unity_texture_meta(meta_guid(meta)), texture
    # pal/Skin is Skin.mat (ROS#'s Path.GetFileName); Red and red would be one file on a
    # case-insensitive disk, so the second is numbered
    materials = sorted(p.name for p in (project / ROBOT / "Materials").glob("*.mat"))
    assert materials == ["Default.mat", "Red.mat", "Skin.mat", "red 1.mat"]
    skin = (project / ROBOT / "Materials/Skin.mat").read_text()
    tga = meta_guid(project / ROBOT / "desc/textures/skin.tga.meta")
    assert f"m_Texture: {{fileID: 2800000, guid: {tga}, type: 3}}" in skin
    golden = GOLDEN / "Skin.mat"
    if updating():
        golden.parent.mkdir(parents=True, exist_ok=True)
        golden.write_text(skin, encoding="utf-8")
    assert skin == golden.read_text(encoding="utf-8"), text_diff(golden.read_text(), skin, "Skin")
    # each renderer names the .mat its material's name became
    guids = {
        name: meta_guid(project / ROBOT / f"Materials/{name}.mat.meta")
        for name in ("Skin", "Red", "red 1")
    }
    assert renderer_material(project, "box", "Cube") == guids["Skin"]
    assert renderer_material(project, "red", "Sphere") == guids["Red"]
    assert renderer_material(project, "other", "Sphere") == guids["red 1"]
    apply_writes_nothing(project)
    assert apply(project, "--check").code == 0


def test_every_texture_problem_is_reported_in_one_refused_apply(project: Path) -> None:
    """A missing texture and a model's DDS texture (Unity's IHVImageFormatImporter, whose
    .meta is not checked here): both in one run, at their elements, nothing written."""
    (project / "ros/desc/textures/skin.tga").unlink()
    (project / "ros/desc/meshes/n.dds").write_bytes(b"DDS")
    dae = project / "ros/desc/meshes/l_finger.dae"
    dae.write_text(dae.read_text().replace("l_finger_color.jpg", "n.dds"))
    run = apply_refused(project)
    assert "bot.urdf:2:3: error: texture 'package://desc/textures/skin.tga' names a file" in (
        run.err
    ), run.err
    assert "bot.urdf:4:37: error: model 'package://desc/meshes/l_finger.dae' uses the" in run.err


def test_an_object_names_the_textured_mat_on_the_apply_that_first_writes_it(
    project: Path,
) -> None:
    """The textured .mat is written with its texture's GUID, apart from the colour ones, yet
    an ``objects`` entry may name it as it names those (``PlannedRobot.asset_refs``)."""
    screen = (
        "objects:\n  - {path: bot/base/Screen, primitive: plane, components: [{type: "
        "MeshRenderer, fields: {m_Materials: [Assets/Urdf/bot/Materials/Skin.mat]}}]}\n"
    )
    run = apply_manifest(project, MANIFEST + screen)
    assert run.code == 0, run.err
    guid = meta_guid(project / ROBOT / "Materials/Skin.mat.meta")
    (material,) = field(project, "bot/base/Screen", "MeshRenderer", "m_Materials")
    assert material == {"fileID": "2100000", "guid": guid, "type": "2"}
    apply_writes_nothing(project)
