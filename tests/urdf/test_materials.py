"""The ``.mat`` files of ROS#'s importer: the four Unity saved for r2d2, to the byte."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from unityscaffold.errors import LocatedError
from unityscaffold.unity.material import MATERIAL_FILE_ID
from unityscaffold.unity.meta import native_format_meta, read_meta_guid
from unityscaffold.urdf import parse_urdf, read_urdf
from unityscaffold.urdf.materials import importer_materials


def test_r2d2s_materials_are_the_files_unity_saved(r2d2_urdf: Path) -> None:
    folder = r2d2_urdf.parent / "Urdf" / "file_server2" / "Materials"
    ours = importer_materials(read_urdf(r2d2_urdf))
    assert sorted(ours) == sorted(p.name for p in folder.glob("*.mat"))
    for name, text in ours.items():
        assert text == (folder / name).read_text(encoding="utf-8"), name
        meta = folder / f"{name}.meta"
        guid = read_meta_guid(meta)
        assert guid is not None
        assert native_format_meta(guid, MATERIAL_FILE_ID) == meta.read_text(encoding="utf-8")


def test_the_first_definition_of_a_name_wins_and_unnamed_ones_are_named_by_colour() -> None:
    robot = parse_urdf(
        b'<robot name="r"><material name="red"><color rgba="1 0 0 1"/></material>'
        b'<link name="a"><visual><geometry><sphere radius="1"/></geometry>'
        b'<material name="red"><color rgba="0 1 0 1"/></material></visual>'
        b'<visual><geometry><sphere radius="1"/></geometry>'
        b'<material name=""><color rgba="0.5 0 0.25 1"/></material></visual>'
        b'<visual><geometry><sphere radius="1"/></geometry><material name="plain"/></visual>'
        b"</link></robot>"
    )
    ours = importer_materials(robot)
    assert sorted(ours) == ["Default.mat", "plain.mat", "red.mat", "rgba-0.5-0-0.25-1.mat"]
    assert "_Color: {r: 1, g: 0, b: 0, a: 1}" in ours["red.mat"]
    assert "_Color: {r: 1, g: 1, b: 1, a: 1}" in ours["plain.mat"]


def test_a_textured_material_is_refused_for_now() -> None:
    robot = parse_urdf(
        b'<robot name="r"><material name="skin"><texture filename="package://p/t.png"/>'
        b'</material><link name="a"/></robot>',
        "r.urdf",
    )
    with pytest.raises(LocatedError) as caught:
        importer_materials(robot)
    assert caught.value.render().startswith("r.urdf:1:17: error: material 'skin' has a texture")


@pytest.mark.parametrize(
    ("name", "shown"),
    [("../../Evil", "'/'"), ("a\\b", repr("\\")), ("C:drive", "':'"), ("..", "no letters")],
)
def test_a_material_name_that_cannot_name_a_file_is_refused_at_the_material(
    name: str, shown: str
) -> None:
    # the name is the .mat file's: a separator or '..' put it outside the Materials folder
    robot = parse_urdf(
        f'<robot name="r">\n  <material name="{name}"><color rgba="1 0 0 1"/></material>'
        '<link name="a"/></robot>'.encode(),
        "r.urdf",
    )
    with pytest.raises(LocatedError) as caught:
        importer_materials(robot)
    rendered = caught.value.render()
    assert rendered.startswith(f"r.urdf:2:3: error: material {name!r} cannot name its .mat file")
    assert f"({shown})" in rendered and "hint: rename the material" in rendered


def test_a_material_named_with_yaml_indicators_keeps_its_name() -> None:
    robot = parse_urdf(
        b'<robot name="r"><material name="red #2 - &amp;shiny"><color rgba="1 0 0 1"/>'
        b'</material><link name="a"/></robot>'
    )
    text = importer_materials(robot)["red #2 - &shiny.mat"]
    body = text.split("\n--- !u!21 &2100000\n", 1)[1]
    assert yaml.safe_load(body)["Material"]["m_Name"] == "red #2 - &shiny"
