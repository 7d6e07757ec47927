"""The image files an import copies: a COLLADA model's textures and a URDF material's texture,
in every format Unity's TextureImporter reads, each with the ``.meta`` Unity 2022.3 wrote for
the r2d2 sample's PNG textures; what Unity would import with another importer is refused at
its place, every such problem of a robot at once."""

from __future__ import annotations

from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError
from unityscaffold.unity.meta import read_meta_guid
from unityscaffold.urdf import RobotImport, import_robot
from unityscaffold.urdf.materials import TexturedMaterialAsset
from unityscaffold.urdf.textures import TEXTURE_SUFFIXES, TextureAsset

# a finger texture of ROS#'s r2d2 sample, and the .meta Unity 2022.3 wrote for it
FINGER_PNG = Path("Urdf/file_server2/urdf_tutorial/meshes/l_finger_color.png")


def test_the_texture_formats_are_those_of_unity_s_texture_importer() -> None:
    """Unity 2022.3 manual, Built-in Importers: "TextureImporter: jpg, jpeg, tif, tiff, tga,
    gif, png, psd, bmp, iff, pict, pic, pct, exr, hdr"
    (https://docs.unity3d.com/2022.3/Documentation/Manual/BuiltInImporters.html)."""
    assert sorted(s.lstrip(".") for s in TEXTURE_SUFFIXES) == sorted(
        "jpg jpeg tif tiff tga gif png psd bmp iff pict pic pct exr hdr".split()
    )


@pytest.mark.parametrize("suffix", sorted(TEXTURE_SUFFIXES))
def test_a_texture_of_any_format_gets_the_meta_unity_wrote_for_a_png_but_for_the_guid(
    r2d2_urdf: Path, suffix: str
) -> None:
    """One TextureImporter reads every format, with one set of settings: Unity 2022.3 wrote the
    same fields, in the same order, for a .png, a .tga and an .exr (Boss Room at its 2022.3
    commits, github.com/Unity-Technologies/com.unity.multiplayer.samples.coop 058dfa7b844f
    and 59d1080050ff); only values a user set differ there. docs/unity-yaml.md has the rest."""
    meta = r2d2_urdf.parent / f"{FINGER_PNG}.meta"
    guid = read_meta_guid(meta)
    assert guid is not None
    copy = TextureAsset(f"p/t{suffix}", r2d2_urdf.parent / FINGER_PNG)
    assert copy.meta(guid) == meta.read_text(encoding="utf-8")
    assert copy.content(lambda _: "") == (r2d2_urdf.parent / FINGER_PNG).read_bytes()


def collada(*images: str) -> str:
    """A Y_UP model of one node drawn in one part, naming ``images``."""
    library = "".join(
        f'<image id="i{n}"><init_from>{image}</init_from></image>' for n, image in enumerate(images)
    )
    return (
        '<?xml version="1.0"?>\n<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema"'
        ' version="1.4.1"><asset><up_axis>Y_UP</up_axis></asset>\n'
        f"<library_images>{library}</library_images>\n"
        '<library_geometries><geometry id="g"><mesh><triangles count="0"/></mesh></geometry>'
        '</library_geometries><library_visual_scenes><visual_scene id="s"><node id="n" name="n">'
        '<instance_geometry url="#g"/></node></visual_scene></library_visual_scenes>'
        '<scene><instance_visual_scene url="#s"/></scene></COLLADA>\n'
    )


def robot(tmp_path: Path, visuals: str, files: dict[str, str]) -> Path:
    """``r.urdf`` with one link of ``visuals``, beside package ``desc`` holding ``files``."""
    for name, text in files.items():
        (tmp_path / "desc" / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / "desc" / name).write_text(text, encoding="utf-8")
    urdf = tmp_path / "r.urdf"
    urdf.write_text(f'<robot name="r"><link name="a">\n{visuals}\n</link></robot>\n')
    return urdf


def imported(urdf: Path) -> RobotImport:
    return import_robot(urdf, packages={}, project=urdf.parent)


def refusal(urdf: Path) -> str:
    with pytest.raises(LocatedError) as caught:
        imported(urdf)
    return caught.value.render()


MODEL = '<visual><geometry><mesh filename="package://desc/m.dae"/></geometry></visual>'


def test_a_model_s_textures_of_every_importer_format_are_copied_beside_it(
    tmp_path: Path,
) -> None:
    """Where ROS#'s transfer puts a model's files: ``<package>/<path>``, the image's path
    taken from the model's folder. A missing image, or one Unity imports as no texture
    (``.webp``), Unity's model import leaves out: so is it here."""
    images = ("tex/a.jpg", "tex/b.TGA", "tex/../c.psd", "d.exr", "missing.png", "e.webp")
    files = {"m.dae": collada(*images), "tex/a.jpg": "J", "tex/b.TGA": "T", "c.psd": "P"}
    urdf = robot(tmp_path, MODEL, {**files, "d.exr": "E", "e.webp": "W"})
    copied = {a.path: a for a in imported(urdf).model_assets if isinstance(a, TextureAsset)}
    assert sorted(copied) == ["desc/c.psd", "desc/d.exr", "desc/tex/a.jpg", "desc/tex/b.TGA"]
    assert copied["desc/tex/a.jpg"].content(str) == b"J"


def test_a_model_s_image_outside_its_package_or_of_another_importer_is_refused_at_once(
    tmp_path: Path,
) -> None:
    """Unity imports ``.dds`` with its IHVImageFormatImporter (same manual page), whose
    ``.meta`` no Unity-written file here shows; an image outside the package would be copied
    outside the robot's folder. Both problems of the model are reported in one run."""
    dae = collada("../../a.png", "n.dds")
    urdf = robot(tmp_path, MODEL, {"m.dae": dae, "n.dds": "D"})
    message = refusal(urdf)
    assert message.count(f"{urdf}:2:19: error: model 'package://desc/m.dae'") == 2, message
    assert "names the image '../../a.png' outside its package folder" in message
    assert "uses the texture 'n.dds', which Unity imports with its IHVImageFormatImporter" in (
        message
    )


TEXTURED = (
    '<visual><geometry><box size="1 1 1"/></geometry>'
    '<material name="skin"><texture filename="package://desc/t/skin.jpg"/></material></visual>'
)


def test_a_material_s_texture_is_copied_and_its_mat_refers_to_it(tmp_path: Path) -> None:
    """ROS#'s UrdfMaterial.LoadTexture finds ``package://desc/t/skin.jpg`` at
    ``<robot folder>/desc/t/skin.jpg`` (LocateAssetHandler.FindUrdfAsset): the texture goes
    there, and ``Materials/skin.mat`` names its GUID in ``_MainTex``. A model naming the same
    image shares the one copy."""
    visuals = TEXTURED + "\n" + MODEL.replace("desc/m.dae", "desc/t/m.dae")
    urdf = robot(tmp_path, visuals, {"t/skin.jpg": "S", "t/m.dae": collada("skin.jpg")})
    result = imported(urdf)
    assert "Materials/skin.mat" not in result.files  # written with its texture's GUID
    copied = {a.path: a for a in result.model_assets}
    assert sorted(copied) == ["Materials/skin.mat", "desc/t/m.dae", "desc/t/skin.jpg"]
    texture, material = copied["desc/t/skin.jpg"], copied["Materials/skin.mat"]
    assert isinstance(texture, TextureAsset) and isinstance(material, TexturedMaterialAsset)
    guids = {"desc/t/skin.jpg": "0123456789abcdef0123456789abcdef"}
    text = material.content(guids.__getitem__).decode()
    assert "_MainTex:\n        m_Texture: {fileID: 2800000, guid: 0123456789abcdef" in text
    assert material.meta("fedcba9876543210fedcba9876543210").startswith(
        "fileFormatVersion: 2\nguid: fedcba9876543210fedcba9876543210\nNativeFormatImporter:"
    )


def test_every_texture_problem_and_model_problem_of_a_robot_is_reported_in_one_run(
    tmp_path: Path,
) -> None:
    """A texture is found as a mesh is (``_packages.resolve_file``), its errors worded for a
    texture;
    a texture Unity imports as no Texture leaves ROS#'s LoadTexture with none."""
    visuals = "\n".join(
        f'<visual><geometry><sphere radius="1"/></geometry><material name="m{n}">'
        f'<texture filename="{filename}"/></material></visual>'
        for n, filename in enumerate(
            (
                "package://desc/missing.png",
                "package://nowhere/t.png",
                "package://desc/t.dds",
                "package://desc/notes.txt",
            )
        )
    )
    dae = collada("../../a.png")
    urdf = robot(tmp_path, visuals + "\n" + MODEL, {"t.dds": "D", "notes.txt": "N", "m.dae": dae})
    message = refusal(urdf)
    assert f"{urdf}:2:50: error: texture 'package://desc/missing.png' names a file that " in message
    assert (
        f"{urdf}:3:50: error: texture 'package://nowhere/t.png' names package 'nowhere', "
        in message
    )
    assert f"{urdf}:4:50: error: material 'm2': its texture 'package://desc/t.dds' is a " in (
        message
    )
    assert "imports with its IHVImageFormatImporter" in message
    assert f"{urdf}:5:50: error: material 'm3': its texture 'package://desc/notes.txt'" in (message)
    assert "imports as no texture" in message
    assert f"{urdf}:6:19: error: model 'package://desc/m.dae' names the image" in message


def test_a_missing_mesh_and_a_missing_texture_are_reported_in_one_run(tmp_path: Path) -> None:
    visuals = (
        '<visual><geometry><mesh filename="package://desc/gone.stl"/></geometry></visual>\n'
        + TEXTURED
    )
    urdf = robot(tmp_path, visuals, {"t/other.png": "O"})
    message = refusal(urdf)
    assert f"{urdf}:2:19: error: mesh 'package://desc/gone.stl' names a file that" in message
    assert f"{urdf}:3:49: error: texture 'package://desc/t/skin.jpg' names a file that" in message
