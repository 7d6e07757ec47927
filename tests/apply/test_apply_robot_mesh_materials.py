"""A URDF ``<material>`` on a mesh visual, as ROS#'s importer leaves it: each renderer of the
instance gets the robot's ``.mat`` in its first material slot, recorded among the instance's
changes. The instances' text is golden (``golden/robot_materials``; regenerate with
``UNITYSCAFFOLD_UPDATE=1`` and review the diff); a changed material changes the change, a
removed one removes it, and a second apply writes nothing."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from helpers import binary_stl, text_diff, updating
from robot_helpers import (
    HEADER,
    apply,
    apply_writes_nothing,
    copy_meshes,
    inertial,
    init_project,
    meta_guid,
    prefab_instances,
)

from unityscaffold.urdf.stl import FACETS_PER_MESH

GOLDEN = Path(__file__).parent / "golden" / "robot_materials"
MANIFEST = HEADER + "    packages: {desc: ros/desc}\n"
STL = '<mesh filename="package://desc/meshes/{}.STL"/>'
DAE = '<mesh filename="package://desc/meshes/l_finger.dae"/>'
# the three ways a visual names its material: a top-level definition, one of its own, unnamed
MATERIALS = {
    "top": '<material name="grey"/>',
    "inline": '<material name="red"><color rgba="1 0 0 1"/></material>',
    "rgba": '<material name=""><color rgba="0 0.5 1 1"/></material>',
}


def visual(mesh: str, material: str) -> str:
    return f"<visual><geometry>{mesh}</geometry>{material}</visual>"


def urdf(materials: dict[str, str]) -> str:
    """A robot whose links each hold an STL visual and a COLLADA visual with one material:
    ``big`` is an STL cut into two Mesh assets (two renderers)."""
    links, joints = [], []
    for i, (name, material) in enumerate(materials.items()):
        stl = STL.format("big" if name == "rgba" else "G1_Rod")
        links.append(
            f'<link name="{name}">{inertial()}\n  {visual(stl, material)}\n'
            f"  {visual(DAE, material)}\n</link>"
        )
        if i:
            joints.append(
                f'<joint name="j{i}" type="fixed"><parent link="top"/>'
                f'<child link="{name}"/></joint>'
            )
    return (
        '<robot name="bot">\n<material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>\n'
        + "\n".join(links + joints)
        + "\n</robot>\n"
    )


@pytest.fixture
def project(tmp_path: Path) -> Path:
    root = init_project(tmp_path, {"ros/bot.urdf": urdf(MATERIALS), "robot.yaml": MANIFEST})
    meshes = copy_meshes(root, ("G1_Rod.STL", "l_finger.dae"))
    # one facet past what one Mesh asset takes: ROS# cuts it in two
    binary_stl(meshes / "big.STL", FACETS_PER_MESH + 1)
    return root


def instances(project: Path) -> str:
    """The scene's PrefabInstance documents, each headed by the path of its visual."""
    return "".join(f"# {path}\n{text}" for path, text in sorted(prefab_instances(project)))


def material_guids(project: Path) -> dict[str, str]:
    folder = project / "Assets/Urdf/bot/Materials"
    return {
        meta.name.removesuffix(".mat.meta"): meta_guid(meta) for meta in folder.glob("*.mat.meta")
    }


def test_mesh_visuals_with_a_material_are_the_golden_instances(project: Path) -> None:
    run = apply(project)
    assert run.code == 0, run.err
    text = instances(project)
    golden = GOLDEN / "instances.txt"
    if updating():
        golden.parent.mkdir(parents=True, exist_ok=True)
        golden.write_text(text, encoding="utf-8")
    assert text == golden.read_text(encoding="utf-8"), text_diff(
        golden.read_text(), text, golden.name
    )
    # the .mat each refers to: the top-level one, the visual's own, the one named by colour
    guids = material_guids(project)
    assert sorted(guids) == ["Default", "grey", "red", "rgba-0-0.5-1-1"]
    for name, renderers in (("grey", 2), ("red", 2), ("rgba-0-0.5-1-1", 3)):
        assert text.count(f"{{fileID: 2100000, guid: {guids[name]}, type: 2}}") == renderers
    apply_writes_nothing(project)
    assert apply(project, "--check").code == 0


def test_a_changed_material_changes_the_renderers_and_a_removed_one_leaves_the_model_s(
    project: Path,
) -> None:
    assert apply(project).code == 0
    changed = {**MATERIALS, "inline": '<material name="red"><color rgba="1 0 0 0.5"/></material>'}
    changed["rgba"] = '<material name=""><color rgba="0 1 0 1"/></material>'
    (project / "ros/bot.urdf").write_text(urdf(changed))
    assert apply(project).code == 0
    guids = material_guids(project)
    assert sorted(guids) == ["Default", "grey", "red", "rgba-0-1-0-1"]
    assert (
        "_Color: {r: 1, g: 0, b: 0, a: 0.5}"
        in (project / "Assets/Urdf/bot/Materials/red.mat").read_text()
    )
    text = instances(project)
    assert text.count(f"guid: {guids['rgba-0-1-0-1']}, type: 2}}") == 3
    assert apply(project, "--check").code == 0
    # no material: the instances are the ones a visual without one gets, nothing else
    (project / "ros/bot.urdf").write_text(urdf(dict.fromkeys(MATERIALS, "")))
    run = apply(project)
    assert run.code == 0, run.err
    text = instances(project)
    assert "m_Materials" not in text and text.count("--- !u!1001 ") == 6
    assert sorted(material_guids(project)) == ["Default", "grey"]
    apply_writes_nothing(project)
    assert apply(project, "--check").code == 0


def test_a_material_on_a_model_of_several_parts_fills_its_renderer_s_first_slot(
    project: Path,
) -> None:
    """``Renderer.sharedMaterial`` is a renderer's first material (Unity's scripting
    reference): setting it changes slot 0, the finger's second part keeps the model's own."""
    dae = (project / "ros/desc/meshes/l_finger.dae").read_text()
    # the finger drawn in two parts: two submeshes, two material slots on its renderer
    triangles = re.search(r"<triangles .*?</triangles>", dae, re.S)
    assert triangles
    dae = dae.replace(triangles.group(), triangles.group() * 2)
    (project / "ros/desc/meshes/l_finger.dae").write_text(dae)
    run = apply(project)
    assert run.code == 0, run.err
    text = instances(project)
    assert "m_Materials.Array.data[0]" in text and "m_Materials.Array.data[1]" not in text
    apply_writes_nothing(project)
