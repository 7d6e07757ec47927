"""The ``.mat`` files of ROS#'s importer: the four Unity saved for r2d2, to the byte; a textured
material as ROS#'s ``UrdfMaterial.CreateMaterial`` makes it; and the file each material name
becomes, the same on every system."""

from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import escape

import pytest
import yaml

from unityscaffold.unity.material import MATERIAL_FILE_ID
from unityscaffold.unity.meta import native_format_meta, read_meta_guid
from unityscaffold.urdf import parse_urdf, read_urdf
from unityscaffold.urdf.materials import ImporterMaterial, importer_materials, material_stems
from unityscaffold.urdf.objects import MaterialRef, importer_tree

WHITE = (1.0, 1.0, 1.0, 1.0)  # a new Standard material's _Color (Unity's default)


def by_path(robot_xml: bytes) -> dict[str, ImporterMaterial]:
    return {m.path: m for m in importer_materials(parse_urdf(robot_xml, "r.urdf"))}


def test_r2d2s_materials_are_the_files_unity_saved(r2d2_urdf: Path) -> None:
    folder = r2d2_urdf.parent / "Urdf" / "file_server2" / "Materials"
    ours = importer_materials(read_urdf(r2d2_urdf))
    assert sorted(m.path for m in ours) == sorted(
        f"Materials/{p.name}" for p in folder.glob("*.mat")
    )
    for material in ours:
        saved = folder / f"{material.stem}.mat"
        assert material.text() == saved.read_text(encoding="utf-8"), material.stem
        guid = read_meta_guid(f"{saved}.meta")
        assert guid is not None
        assert native_format_meta(guid, MATERIAL_FILE_ID) == Path(f"{saved}.meta").read_text()


def test_the_first_definition_of_a_name_wins_and_unnamed_ones_are_named_by_colour() -> None:
    ours = by_path(
        b'<robot name="r"><material name="red"><color rgba="1 0 0 1"/></material>'
        b'<link name="a"><visual><geometry><sphere radius="1"/></geometry>'
        b'<material name="red"><color rgba="0 1 0 1"/></material></visual>'
        b'<visual><geometry><sphere radius="1"/></geometry>'
        b'<material name=""><color rgba="0.5 0 0.25 1"/></material></visual>'
        b'<visual><geometry><sphere radius="1"/></geometry><material name="plain"/></visual>'
        b"</link></robot>"
    )
    assert sorted(ours) == [
        "Materials/Default.mat",
        "Materials/plain.mat",
        "Materials/red.mat",
        "Materials/rgba-0.5-0-0.25-1.mat",
    ]
    assert "_Color: {r: 1, g: 0, b: 0, a: 1}" in ours["Materials/red.mat"].text()
    assert "_Color: {r: 1, g: 1, b: 1, a: 1}" in ours["Materials/plain.mat"].text()


TEXTURED = (
    b'<robot name="r"><material name="skin"><texture filename="package://d/t/skin.jpg"/>'
    b'</material><material name="both"><color rgba="0 0 1 1"/>'
    b'<texture filename="package://d/t/skin.jpg"/></material>'
    b'<link name="a"><visual><geometry><box size="1 1 1"/></geometry><material name="">'
    b'<texture filename="package://d/t/other.tga"/></material></visual></link></robot>'
)


def test_a_material_of_a_texture_alone_is_white_with_that_texture_as_its_albedo() -> None:
    """UrdfMaterial.CreateMaterial: ``if (color != null) material.color = …; else if (texture
    != null) material.mainTexture = LoadTexture(…)`` on a new Standard material, whose colour
    stays white. The reference is the one a Unity 2022.3.0-saved .mat holds in
    ``_MainTex`` (github.com/Unity-Technologies/com.unity.multiplayer.samples.coop, commit
    058dfa7b844f, Assets/Material/Characters/Character_Shadow.mat)."""
    skin = by_path(TEXTURED)["Materials/skin.mat"]
    assert skin.color == WHITE and skin.textured is not None
    assert skin.textured.texture == "package://d/t/skin.jpg"
    guid = "0123456789abcdef0123456789abcdef"
    empty = "    - _MainTex:\n        m_Texture: {fileID: 0}\n"
    albedo = f"    - _MainTex:\n        m_Texture: {{fileID: 2800000, guid: {guid}, type: 3}}\n"
    # the colour material's text (checked above against Unity's) with that one reference
    assert empty in skin.text()
    assert skin.text(guid) == skin.text().replace(empty, albedo)
    assert "_Color: {r: 1, g: 1, b: 1, a: 1}" in skin.text(guid)


def test_a_material_with_a_colour_ignores_its_texture_and_an_unnamed_one_is_named_by_it() -> None:
    """CreateMaterial's ``else if``: the colour wins; GenerateMaterialName names an unnamed
    material of a texture ``"texture-" + Path.GetFileName(filename)``."""
    ours = by_path(TEXTURED)
    both = ours["Materials/both.mat"]
    assert both.color == (0.0, 0.0, 1.0, 1.0) and both.textured is None
    unnamed = ours["Materials/texture-other.tga.mat"]
    assert unnamed.textured is not None and unnamed.textured.texture == "package://d/t/other.tga"
    tree = importer_tree(parse_urdf(TEXTURED))
    renderer = tree.children[1].children[0].children[0].children[0].components[1]
    assert renderer.field("m_Materials") == [MaterialRef("texture-other.tga")]


def test_an_empty_texture_filename_is_no_texture() -> None:
    """UrdfMaterial.LoadTexture: ``filename == "" ? null : …``: a white material."""
    ours = by_path(
        b'<robot name="r"><material name="m"><texture filename=""/></material>'
        b'<link name="a"/></robot>'
    )
    assert ours["Materials/m.mat"] == ImporterMaterial("m", WHITE)


# XML normalises a raw tab in an attribute to a space: the character reference keeps it
ATTRIBUTE = {'"': "&quot;", "\t": "&#9;"}


def stems(*names: str) -> dict[str, str]:
    """The ``.mat`` name of each top-level material ``names`` (in that order)."""
    materials = "".join(
        f'<material name="{escape(name, ATTRIBUTE)}"><color rgba="1 0 0 1"/></material>'
        for name in names
    )
    robot = parse_urdf(f'<robot name="r">{materials}<link name="a"/></robot>'.encode())
    found = material_stems(robot)
    return {name: found[name] for name in names}


@pytest.mark.parametrize(
    ("name", "stem", "why"),
    [
        # ROS#'s GetMaterialAssetPath: Path.GetFileName(name) + ".mat", on every system
        ("pal/Orange", "Orange", "after the last '/'"),
        ("a/b/c d", "c d", "after the last '/'; spaces are kept"),
        # Windows' Mono splits at these, Linux' keeps them: one file name for both
        ("a\\b", "a_b", "'\\' is replaced"),
        ("C:drive", "C_drive", "':' is replaced"),
        # Windows refuses these in file names (and Mono's GetFileName throws on '"<>|' there)
        ('a*b?"<>|', "a_b_____", "each is replaced"),
        ("tab\there", "tab_here", "a control character is replaced"),
        # Unity's asset database ignores a file starting with '.'
        ("..", "_.", "the leading '.' is replaced"),
        (".hidden", "_hidden", "the leading '.' is replaced"),
        ("pal/", "_", "no name at all is '_'"),
        # a Windows device name, even with an extension, is no file name there
        ("con", "_con", "a device name gets a leading '_'"),
        ("LPT1.x", "_LPT1.x", "a device name gets a leading '_'"),
        ("console", "console", "only a whole device name is one"),
    ],
)
def test_a_material_name_becomes_a_file_name_the_same_on_every_system(
    name: str, stem: str, why: str
) -> None:
    assert stems(name) == {name: stem}, why


def test_names_one_file_on_a_case_insensitive_disk_are_numbered_in_ross_order() -> None:
    """ROS# on Linux makes ``Red.mat`` and ``red.mat``; on Windows and macOS the second
    would load the first (CreateMaterial reuses the .mat at its path). They are kept apart as
    Unity numbers a copy; ``Default`` is ROS#'s own, made first."""
    assert stems("Red", "red", "RED", "default", "a*b", "a?b") == {
        "Red": "Red",
        "red": "red 1",
        "RED": "RED 2",
        "default": "default 1",
        "a*b": "a_b",
        "a?b": "a_b 1",
    }


def test_names_ending_alike_after_a_slash_share_the_first_one_s_file_as_in_ross() -> None:
    """``pal/Orange`` and ``other/Orange`` are both ``Orange.mat`` for ROS# on every system:
    the second finds the first's .mat and reuses it, colour and all."""
    robot = parse_urdf(
        b'<robot name="r"><material name="pal/Orange"><color rgba="1 0.5 0 1"/></material>'
        b'<material name="other/Orange"><color rgba="0 0 1 1"/></material>'
        b'<link name="a"><visual><geometry><box size="1 1 1"/></geometry>'
        b'<material name="other/Orange"/></visual></link></robot>'
    )
    assert material_stems(robot)["other/Orange"] == "Orange"
    ours = {m.path: m for m in importer_materials(robot)}
    assert sorted(ours) == ["Materials/Default.mat", "Materials/Orange.mat"]
    assert ours["Materials/Orange.mat"].color == (1.0, 0.5, 0.0, 1.0)
    # the material takes its file's name, as a native asset's main object does
    body = ours["Materials/Orange.mat"].text().split("\n--- !u!21 &2100000\n", 1)[1]
    assert yaml.safe_load(body)["Material"]["m_Name"] == "Orange"
    renderer = importer_tree(robot).children[1].children[0].children[0].children[0]
    assert renderer.components[1].field("m_Materials") == [MaterialRef("Orange")]


def test_a_material_named_with_yaml_indicators_keeps_its_name() -> None:
    ours = by_path(
        b'<robot name="r"><material name="red #2 - &amp;shiny"><color rgba="1 0 0 1"/>'
        b'</material><link name="a"/></robot>'
    )
    text = ours["Materials/red #2 - &shiny.mat"].text()
    body = text.split("\n--- !u!21 &2100000\n", 1)[1]
    assert yaml.safe_load(body)["Material"]["m_Name"] == "red #2 - &shiny"
