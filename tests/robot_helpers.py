"""Helpers for the tests of the manifest's `robots`: a project holding a URDF, the manifest that
imports it, applying it, and reading the scene and the assets back.

A named module rather than ``conftest.py`` (as ``codegen_helpers``), so the tests under
``tests/apply`` and ``tests/urdf`` import what they use explicitly. What a test checks stays in
the test: these only set up and read back.
"""

from __future__ import annotations

import os
import re
import shutil
from pathlib import Path

from helpers import Run, build_tree, require, run_cli, snapshot

from unityscaffold.unity import SceneComponent, SceneDocument

REPO = Path(__file__).resolve().parent.parent
#: The vendored third-party files (as CI puts them beside the repository), or
#: ``$UNITYSCAFFOLD_VENDOR``: the real meshes and scenes the robot tests import and compare with.
VENDOR = Path(os.environ.get("UNITYSCAFFOLD_VENDOR", REPO.parent / "shared" / "vendor"))
#: Unity-Robotics-Hub's Niryo gripper: its STL files and the Mesh assets Unity wrote from them.
NIRYO = VENDOR / "unity-robotics-hub" / "niryo-gripper1"
#: ROS#'s r2d2 sample (step 1 of its "Gazebo Simulation Scenes ROS2" tutorial).
R2D2 = VENDOR / "ros-sharp" / "samples" / "gazebo-ros2-step1"
#: The r2d2 sample's COLLADA meshes (``l_finger.dae`` and its texture).
FINGER = R2D2 / "Urdf" / "file_server2" / "urdf_tutorial" / "meshes"

SCENE = "Assets/Scenes/Main.unity"
#: A manifest of the scene and nothing in it: a robot dropped from the manifest, or a start for
#: other sections.
NO_ROBOTS = f"version: 1\nros: 2\nproject: .\nscene: {SCENE}\n"
#: A manifest up to its `robots:` key, for a test to add the entries it needs.
ROBOTS = NO_ROBOTS + "robots:\n"
#: The manifest of one robot from ``ros/bot.urdf``; a test appends the entry's keys (indented
#: four spaces) or further sections.
HEADER = ROBOTS + "  - urdf: ros/bot.urdf\n"


def inertial(mass: int = 1, moments: tuple[int, int, int] = (1, 1, 1)) -> str:
    """A link's ``<inertial>`` on one line, with a diagonal inertia: a link without one gets no
    Rigidbody from ROS#'s importer, and most tests want the link's full set of components."""
    ixx, iyy, izz = moments
    return (
        f'<inertial><mass value="{mass}"/>'
        f'<inertia ixx="{ixx}" ixy="0" ixz="0" iyy="{iyy}" iyz="0" izz="{izz}"/></inertial>'
    )


#: A two-link robot with one material, a plugin and a revolute joint: a primitive of each kind
#: the import writes (box, cylinder, sphere), in visuals and collisions.
BOT_URDF = f"""<robot name="bot">
  <material name="blue"><color rgba="0 0 0.8 1"/></material>
  <gazebo>
    <plugin name="p"/>
  </gazebo>
  <link name="base">
    {inertial(2, (1, 2, 3))}
    <visual><geometry><box size="1 2 3"/></geometry><material name="blue"/></visual>
    <collision><geometry><cylinder radius="0.5" length="2"/></geometry></collision>
  </link>
  <link name="arm">
    {inertial(1, (1, 2, 3))}
    <visual><origin xyz="0 0 0.5"/><geometry><sphere radius="0.1"/></geometry></visual>
    <collision><geometry><sphere radius="0.1"/></geometry></collision>
  </link>
  <joint name="j" type="revolute"><origin xyz="0 0 1"/><parent link="base"/><child link="arm"/>
    <axis xyz="0 1 0"/><limit effort="1" velocity="1" lower="-1" upper="1"/></joint>
</robot>
"""

#: A robot of mesh geometries from package ``desc``: an STL (our prefab) and a COLLADA model,
#: each a visual and a collision, with the manifest that imports it (convex colliders).
MESH_URDF = f"""<robot name="bot">
  <link name="base">{inertial()}
    <visual><geometry><mesh filename="package://desc/meshes/G1_Rod.STL"/></geometry></visual>
    <collision><geometry><mesh filename="package://desc/meshes/G1_Rod.STL"/></geometry></collision>
  </link>
  <link name="finger">{inertial()}
    <visual><geometry><mesh filename="package://desc/meshes/l_finger.dae"/></geometry></visual>
    <collision><geometry><mesh filename="package://desc/meshes/l_finger.dae"/></geometry></collision>
  </link>
  <joint name="j" type="fixed"><parent link="base"/><child link="finger"/></joint>
</robot>
"""
MESH_MANIFEST = HEADER + "    packages: {desc: ros/desc}\n    convex: true\n"


def init_project(tmp_path: Path, files: dict[str, str]) -> Path:
    """A new ROS 2 project (``scaffold init``) at ``tmp_path/p`` holding ``files`` too: the
    real project layout apply expects, not a hand-made imitation of it."""
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return build_tree(tmp_path / "p", files)


def copy_meshes(project: Path, names: tuple[str, ...] = ("G1_Rod.STL",)) -> Path:
    """The vendored meshes ``names`` (the Niryo gripper's STL files, the r2d2 finger's COLLADA
    model and texture) copied into ``ros/desc/meshes``, package ``desc``'s folder: real files as
    a robot's description ships them. Skips locally, fails in CI, when they are missing."""
    sources = [NIRYO / name if name.endswith(".STL") else FINGER / name for name in names]
    require(all(source.is_file() for source in sources), f"the vendored meshes ({VENDOR})")
    meshes = project / "ros/desc/meshes"
    meshes.mkdir(parents=True, exist_ok=True)
    for source in sources:
        shutil.copy(source, meshes / source.name)
    return meshes


def apply(project: Path, *extra: str) -> Run:
    """``scaffold apply`` on the project's ``robot.yaml`` as it stands, in-process."""
    return run_cli("apply", str(project / "robot.yaml"), *extra)


def apply_manifest(project: Path, manifest: str, *extra: str) -> Run:
    """``robot.yaml`` written as ``manifest``, then applied: most tests change the manifest
    between applies, and the file is the manifest apply reads."""
    (project / "robot.yaml").write_text(manifest)
    return apply(project, *extra)


def apply_robot(project: Path, body: str = "", *extra: str) -> Run:
    """Apply the one-robot manifest ``HEADER`` followed by ``body`` (more keys of the entry,
    further entries or sections): what most robot tests vary between applies."""
    return apply_manifest(project, HEADER + body, *extra)


def apply_refused(project: Path, manifest: str | None = None, *extra: str) -> Run:
    """Apply (``robot.yaml`` written as ``manifest`` first, when given), which must refuse a
    user's mistake (exit 2) and leave every file as it was: a refused apply writes nothing.
    The run is returned for the test to check what the error says."""
    if manifest is not None:
        (project / "robot.yaml").write_text(manifest)
    before = snapshot(project)
    run = apply(project, *extra)
    assert run.code == 2, run.out + run.err
    assert snapshot(project) == before
    return run


def apply_writes_nothing(project: Path) -> Run:
    """Apply the ``robot.yaml`` an earlier apply of the test wrote, which must succeed and leave
    every file as it was: apply is idempotent, the promise that keeps scenes reviewable in git.
    The run is returned for the test to check what it says."""
    before = snapshot(project)
    run = apply(project)
    assert run.code == 0, run.out + run.err
    assert snapshot(project) == before
    return run


def drift_is_put_back(project: Path, old: str, new: str, count: int = 1) -> None:
    """The scene edited as Unity's Inspector would (``count`` of ``old`` made ``new``; -1: all)
    where the import decides: ``apply --check`` must report it and apply restore the scene to
    the byte, as the import is the truth for what it owns."""
    scene = project / SCENE
    text = scene.read_text()
    assert old in text, f"{old!r} is not in the scene"
    scene.write_text(text.replace(old, new, count))
    assert apply(project, "--check").code != 0
    assert apply(project).code == 0
    assert scene.read_text() == text


def component(scene: SceneDocument, path: str, class_name: str) -> SceneComponent:
    """The first ``class_name`` component of the GameObject at ``path`` (which must be the only
    one there), as Unity's ``GetComponent`` finds it."""
    return next(
        c for c in scene.components_of(scene.find_gameobject(path)) if c.type_name == class_name
    )


def field(project: Path, path: str, class_name: str, name: str) -> object:
    """Field ``name`` of ``class_name`` on ``path`` in the scene as apply left it on disk: read
    back from the file, so the test sees what Unity would load."""
    scene = SceneDocument.load(project / SCENE)
    return scene.field(component(scene, path, class_name), name)


def meta_guid(meta: Path) -> str:
    """The GUID a ``.meta`` file gives its asset: what a scene's references to it name."""
    found = re.search(r"guid: (\w+)", meta.read_text())
    assert found, f"{meta} has no guid"
    return found.group(1)


def prefab_instances(project: Path) -> list[tuple[str, str]]:
    """Each PrefabInstance of the scene (a mesh geometry's model) as the path of the object it
    sits under and its document's text, in the scene's order. Several visuals of one link share
    a path (each is ``unnamed``), hence pairs rather than a mapping."""
    scene = SceneDocument.load(project / SCENE)
    found = []
    for _, go in scene.tree():
        if go.is_prefab_instance:
            parent = scene.hierarchy.nodes[go.file_id].parent
            document = scene.document(go.file_id)
            assert document is not None
            found.append((scene.gameobject(parent).path if parent else "", document.text))
    return found
