"""The asset files a robot's import writes, seen from the rest of the manifest and from the
project's folders: an `objects:` entry may name them on the very apply that first writes them."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import build_tree, run_cli, snapshot

from unityscaffold.unity.scene import SceneDocument

HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
robots:
  - urdf: ros/bot.urdf
"""
URDF = """<robot name="bot">
  <material name="blue"><color rgba="0 0 0.8 1"/></material>
  <link name="base">
    <visual><geometry><box size="1 2 3"/></geometry><material name="blue"/></visual>
  </link>
</robot>
"""
SCENE = "Assets/Scenes/Main.unity"
PLANE = (
    "objects:\n  - {path: bot/base/Screen, primitive: plane, components: [{type: MeshRenderer, "
    "fields: {m_Materials: [Assets/Urdf/bot/Materials/blue.mat]}}]}\n"
)


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return build_tree(tmp_path / "p", {"ros/bot.urdf": URDF})


def _apply(project: Path, body: str = "", *extra: str):  # type: ignore[no-untyped-def]
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", str(project / "robot.yaml"), *extra)


def _materials(project: Path, path: str) -> object:
    scene = SceneDocument.load(project / SCENE)
    renderer = next(
        c for c in scene.components_of(scene.find_gameobject(path)) if c.type_name == "MeshRenderer"
    )
    return scene.field(renderer, "m_Materials")


def test_an_object_names_a_robots_material_on_the_apply_that_first_writes_it(
    project: Path,
) -> None:
    run = _apply(project, PLANE)
    assert run.code == 0, run.err
    meta = (project / "Assets/Urdf/bot/Materials/blue.mat.meta").read_text()
    guid = meta.split("guid: ")[1].split()[0]
    wanted = [{"fileID": "2100000", "guid": guid, "type": "2"}]
    assert _materials(project, "bot/base/Screen") == wanted
    # the robot's own renderer names the same file
    assert _materials(project, "bot/base/Visuals/unnamed/Cube") == wanted
    before = snapshot(project)
    again = _apply(project, PLANE)
    assert again.code == 0 and "the project matches the manifest" in again.out, again.out
    assert snapshot(project) == before
