"""Real robot descriptions, imported as a user would write them: Franka's Panda (with its hand)
and Universal Robots' UR5e, from their ``.xacro`` files, as vendored from their repositories
(``robots/franka_description``, Apache-2.0; ``robots/ur_description``, BSD-3-Clause). Both have
``Z_UP`` COLLADA visuals of several nodes (Panda's ``link1.dae`` one moved node, UR5e's
materials on every node) and STL collisions.

What must hold: the import applies, a second apply writes nothing, ``--check`` is clean; the
scene holds ROS#'s structure (the robot, ``Plugins``, per link the link with ``Visuals`` and
``Collisions``, per visual and collision an ``unnamed`` object and its geometry, here a model's
instance); and every object of a model an instance names exists in that model: for a ``.dae``
by the node-tree rule of ``unity.modelids`` (read here from the file with the standard
library), for an STL prefab among the prefab's own documents.
"""

from __future__ import annotations

import re
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from helpers import require
from robot_helpers import ROBOTS, SCENE, VENDOR, apply, apply_writes_nothing, init_project

from unityscaffold.unity import SceneDocument
from unityscaffold.unity.modelids import ROOT_PATH, model_file_id
from unityscaffold.urdf import read_urdf
from unityscaffold.urdf.model import Mesh

ROBOT_FOLDER = VENDOR / "robots"
PANDA = (
    "  - urdf: ros/franka_description/robots/panda/panda.urdf.xacro\n"
    "    packages: {franka_description: ros/franka_description}\n"
    "    args: {hand: 'true'}\n"
)
UR5E = (
    "  - urdf: ros/ur_description/urdf/ur5e.xacro\n"
    "    packages: {ur_description: ros/ur_description}\n"
)
NS = "{http://www.collada.org/2005/11/COLLADASchema}"
REFERENCE = re.compile(r"\{fileID: (-?\d+), guid: (\w+), type: 3\}")


@pytest.fixture(scope="module")
def project(tmp_path_factory: pytest.TempPathFactory) -> Path:
    require(ROBOT_FOLDER.is_dir(), f"the vendored robot descriptions ({ROBOT_FOLDER})")
    root = init_project(tmp_path_factory.mktemp("real"), {"robot.yaml": ROBOTS + PANDA + UR5E})
    for name in ("franka_description", "ur_description"):
        shutil.copytree(ROBOT_FOLDER / name, root / "ros" / name)
    run = apply(root)
    assert run.code == 0, run.err
    return root


def test_both_robots_apply_once_and_then_are_a_no_op(project: Path) -> None:
    apply_writes_nothing(project)
    assert apply(project, "--check").code == 0


@pytest.mark.parametrize(
    ("robot", "xacro", "package", "args"),
    [
        ("panda", "robots/panda/panda.urdf.xacro", "franka_description", {"hand": "true"}),
        ("ur5e_robot", "urdf/ur5e.xacro", "ur_description", {}),
    ],
)
def test_each_robot_has_ros_sharp_s_structure(
    project: Path, robot: str, xacro: str, package: str, args: dict[str, str]
) -> None:
    """Counted against the expanded URDF (its own reader's tests check it): Panda's
    ``_sc`` links hold primitive collisions, the meshes are models' instances."""
    folder = project / "ros" / package
    urdf = read_urdf(folder / xacro, packages={package: folder}, xacro_args=args)
    links = len(urdf.links)
    visuals = sum(len(link.visuals) for link in urdf.links)
    collisions = sum(len(link.collisions) for link in urdf.links)
    meshes = sum(
        isinstance(part.geometry, Mesh)
        for link in urdf.links
        for part in (*link.visuals, *link.collisions)
    )
    scene = SceneDocument.load(project / SCENE)
    top = scene.find_gameobject(robot)
    found, instances, stack = 0, 0, [top]
    while stack:
        go = stack.pop()
        found += 1
        instances += go.is_prefab_instance
        stack += scene.children(go)
    assert found == 2 + 3 * links + 2 * visuals + 2 * collisions
    assert instances == meshes > 0


def test_every_model_object_an_instance_names_exists_in_its_model(project: Path) -> None:
    assets = project / "Assets" / "Urdf"
    models = {meta_guid(meta): meta.with_suffix("") for meta in assets.rglob("*.meta")}
    text = (project / SCENE).read_text(encoding="utf-8")
    named: dict[str, set[int]] = {}
    for file_id, guid in REFERENCE.findall(text):
        if guid in models and int(file_id) != 100100000:
            named.setdefault(guid, set()).add(int(file_id))
    assert {models[guid].suffix for guid in named} == {".dae", ".prefab"}
    for guid, ids in named.items():
        model = models[guid]
        known = dae_file_ids(model) if model.suffix == ".dae" else prefab_file_ids(model)
        assert ids <= known, (model, ids - known)


def meta_guid(meta: Path) -> str:
    found = re.search(r"^guid: (\w+)", meta.read_text(encoding="utf-8"), re.M)
    return found.group(1) if found else ""


def dae_file_ids(model: Path) -> set[int]:
    """The fileIDs of every GameObject, Transform, MeshFilter, MeshRenderer and Mesh Unity
    makes of the file: one top node folded into the root, else each below it."""
    scene = ET.parse(model).getroot().find(f"{NS}library_visual_scenes/{NS}visual_scene")
    assert scene is not None
    top = scene.findall(f"{NS}node")
    places = (
        [(top[0], ROOT_PATH)] if len(top) == 1 else [(n, f"{ROOT_PATH}/{name(n)}") for n in top]
    )
    ids = {model_file_id(cls, ROOT_PATH) for cls in ("GameObject", "Transform")}
    while places:
        node, path = places.pop()
        ids |= {model_file_id(cls, path) for cls in ("GameObject", "Transform")}
        if node.find(f"{NS}instance_geometry") is not None:
            ids |= {model_file_id(cls, path) for cls in ("MeshFilter", "MeshRenderer")}
            ids.add(model_file_id("Mesh", name(node)))
        places += [(child, f"{path}/{name(child)}") for child in node.findall(f"{NS}node")]
    return ids


def name(node: ET.Element) -> str:
    return node.get("name") or node.get("id") or ""


def prefab_file_ids(prefab: Path) -> set[int]:
    text = prefab.read_text(encoding="utf-8")
    return {int(i) for i in re.findall(r"^--- !u!\d+ &(-?\d+)", text, re.M)}
