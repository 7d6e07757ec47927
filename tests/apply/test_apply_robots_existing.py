"""A `robots` entry whose GameObject the scene already has, not made by apply: a robot imported
by hand in Unity's editor, or an object that is no robot at all."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from helpers import run_cli, snapshot
from robot_helpers import (
    BOT_URDF,
    HEADER,
    MESH_MANIFEST,
    MESH_URDF,
    SCENE,
    apply,
    apply_manifest,
    apply_refused,
    apply_writes_nothing,
    copy_meshes,
    inertial,
    init_project,
)

from unityscaffold.unity.catalog import rossharp_catalog
from unityscaffold.unity.scene import SceneDocument


@pytest.fixture
def project(tmp_path: Path) -> Path:
    return init_project(tmp_path, {"ros/bot.urdf": BOT_URDF})


def _by_hand(project: Path, path: str, class_name: str) -> None:
    """``class_name`` of ROS# attached to ``path`` as a user would in the Inspector."""
    guid = next(g for g, name in rossharp_catalog().all_class_names().items() if name == class_name)
    run = run_cli("scene", "attach", str(project / SCENE), "-g", path, "--guid", guid, "--create")
    assert run.code == 0, run.err


def _hand_import(project: Path, body: str | None = "") -> None:
    """The robot apply imports, as if imported by hand: every fileID apply gave it (and its
    references) renumbered, as Unity's own are random, and no lock (``body``: what follows
    the manifest's header; None: the manifest is there)."""
    run = apply(project) if body is None else apply_manifest(project, HEADER + body)
    assert run.code == 0, run.err
    lock = json.loads((project / "robot.lock.json").read_text())
    ids = lock["robots"][SCENE]["bot"]
    _renumber(project / SCENE, {old: 1000 + 7 * n for n, old in enumerate(ids)})
    (project / "robot.lock.json").unlink()


def _renumber(path: Path, renumbered: dict[int, int]) -> None:
    text = re.sub(
        r"(&|fileID: )(\d+)\b",
        lambda m: m[1] + str(renumbered.get(int(m[2]), m[2])),
        path.read_text(),
    )
    path.write_text(text)


def test_a_robot_imported_by_hand_is_adopted_with_its_fileids_and_nothing_changes(
    project: Path,
) -> None:
    _hand_import(project)
    scene = (project / SCENE).read_bytes()
    run = apply(project)
    assert run.code == 0, run.err
    assert "adopt robot bot, imported by hand (16 objects)" in run.out
    assert [line for line in run.out.splitlines() if "(robot bot)" in line] == []
    assert (project / SCENE).read_bytes() == scene
    again = apply_writes_nothing(project)
    assert "wrote 0 files" in again.out, again.out
    assert apply(project, "--check").code == 0


def test_an_adopted_robot_follows_its_urdf_in_place_as_one_apply_imported(
    project: Path,
) -> None:
    _hand_import(project)
    assert apply(project).code == 0
    ids = {go.path: go.file_id for _, go in SceneDocument.load(project / SCENE).tree()}
    (project / "ros/bot.urdf").write_text(
        BOT_URDF.replace('<mass value="1"/>', '<mass value="3"/>').replace(
            "</robot>",
            f'<link name="tool">{inertial(1, (1, 2, 3))}</link>'
            '<joint name="t" type="fixed"><parent link="arm"/><child link="tool"/></joint>'
            "</robot>",
        )
    )
    run = apply(project)
    assert run.code == 0, run.err
    assert "update bot/base/arm (robot bot)" in run.out
    assert "import robot bot (3 new objects)" in run.out  # the tool link
    now = {go.path: go.file_id for _, go in SceneDocument.load(project / SCENE).tree()}
    assert {path: now[path] for path in ids} == ids
    apply_writes_nothing(project)


@pytest.mark.parametrize(
    ("edit", "difference"),
    [
        (
            ("  m_Name: arm\n", "  m_Name: forearm\n"),
            "'bot/base' has no child 'arm' (the URDF's link[1]) in its place",
        ),
        (
            ("  m_Name: Sphere\n", "  m_Name: Ball\n"),
            "'bot/base/arm/Collisions/unnamed' has no child 'Sphere'",
        ),
    ],
)
def test_a_robot_imported_by_hand_that_is_not_the_urdfs_is_refused_at_its_first_difference(
    project: Path, edit: tuple[str, str], difference: str
) -> None:
    _hand_import(project)
    text = (project / SCENE).read_text()
    assert edit[0] in text
    (project / SCENE).write_text(text.replace(*edit, 1))
    run = apply_refused(project)
    assert (
        "robot.yaml:6:5: error: the robot imported by hand at 'bot' in Assets/Scenes/Main.unity "
        f"is not the import of bot.urdf: {difference}" in run.err
    )
    assert "hint: apply takes over a robot imported in Unity's editor only when" in run.err


def test_a_robot_imported_by_hand_missing_a_component_is_refused(project: Path) -> None:
    _hand_import(project)
    scene = SceneDocument.load(project / SCENE)
    arm = scene.find_gameobject("bot/base/arm")
    inertial = [c for c in scene.components_of(arm) if c.script is not None][1]
    text = (project / SCENE).read_text()
    text = text.replace(f"  - component: {{fileID: {inertial.file_id}}}\n", "")
    document = text.index(f"--- !u!114 &{inertial.file_id}\n")
    text = text[:document] + text[text.index("--- ", document + 4) :]
    (project / SCENE).write_text(text)
    run = apply(project)
    assert run.code == 2, run.out + run.err
    assert "'bot/base/arm' has no UrdfInertial after the Transform and UrdfLink, Rigidbody" in (
        run.err
    )


def test_a_bare_object_with_urdfrobot_is_refused_as_not_the_import(project: Path) -> None:
    _by_hand(project, "bot", "UrdfRobot")
    run = apply_refused(project, HEADER)
    assert "is not the import of bot.urdf: 'bot' has no child 'Plugins'" in run.err


def test_an_object_that_is_no_robot_where_the_robot_goes_is_refused(project: Path) -> None:
    run = apply_refused(project, HEADER + "    gameobject: Main Camera\n")
    assert (
        "robot.yaml:7:17: error: Assets/Scenes/Main.unity already has a GameObject "
        "'Main Camera' (Transform, Camera, AudioListener), which is not a robot" in run.err
    )
    assert "hint: rename or move that GameObject in Unity" in run.err


def test_a_robot_under_an_object_of_its_name_is_refused_only_there(project: Path) -> None:
    """Only the robot's own place counts: a same-named object elsewhere is another path."""
    _by_hand(project, "World/bot", "UrdfLink")
    run = apply_manifest(project, HEADER + "    gameobject: World/bot\n")
    assert run.code == 2 and "'World/bot' (Transform, UrdfLink), which is not a robot" in run.err
    run = apply_manifest(project, HEADER)
    assert run.code == 0, run.err


def test_a_robot_apply_made_is_its_own_even_without_the_lock(project: Path) -> None:
    assert apply_manifest(project, HEADER).code == 0
    (project / "robot.lock.json").unlink()
    scene = (project / SCENE).read_bytes()
    run = apply(project)
    assert run.code == 0, run.err
    assert (project / SCENE).read_bytes() == scene


def test_the_robots_root_takes_the_name_its_gameobject_path_gives(project: Path) -> None:
    body = (
        "    gameobject: World/Robot\n"
        "components:\n  - {script: JointStateWriter, gameobject: World/Robot/base/arm}\n"
    )
    run = apply_manifest(project, HEADER + body)
    assert run.code == 0, run.err
    scene = SceneDocument.load(project / SCENE)
    assert scene.find_gameobject("World/Robot").name == "Robot"
    assert [go.name for go in scene.children(scene.find_gameobject("World"))] == ["Robot"]
    apply_writes_nothing(project)


def test_a_robot_with_stl_meshes_imported_by_hand_is_refused_at_its_prefab(
    tmp_path: Path,
) -> None:
    """ROS#'s STL post-processor gives its prefab's objects random fileIDs, which the
    instances in the scene name; apply's own prefab has others, so such a robot is not
    taken over (the prefab, differing from apply's, is a file edited by hand first)."""
    project = init_project(tmp_path, {"ros/bot.urdf": MESH_URDF, "robot.yaml": MESH_MANIFEST})
    copy_meshes(project, ("G1_Rod.STL", "l_finger.dae", "l_finger_color.png"))
    _hand_import(project, None)
    prefab = project / "Assets/Urdf/bot/desc/meshes/G1_Rod.prefab"
    ids = [int(i) for i in re.findall(r"^--- !u!\d+ &(\d+)", prefab.read_text(), re.M)]
    renumbered = {old: 500 + n for n, old in enumerate(ids)}
    _renumber(prefab, renumbered)
    _renumber(project / SCENE, renumbered)
    before = snapshot(project)
    run = apply(project)
    assert run.code != 0 and "G1_Rod.prefab" in run.out + run.err
    run = apply_refused(project, None, "--force")
    assert (
        "'bot/base/Visuals/unnamed/G1_Rod' is an instance of ROS#'s STL prefab "
        "Assets/Urdf/bot/desc/meshes/G1_Rod.prefab, whose objects are not the ones of the "
        "prefab apply writes (robots with STL meshes are not adopted yet)" in run.err
    )
    assert snapshot(project) == before


def test_a_robot_imported_by_hand_beside_the_one_apply_imported_is_refused(project: Path) -> None:
    assert apply_manifest(project, HEADER).code == 0
    _by_hand(project, "Second", "UrdfRobot")
    scene = project / SCENE
    scene.write_text(scene.read_text().replace("  m_Name: Second\n", "  m_Name: bot\n"))
    run = apply_refused(project)
    assert "robot.yaml:6:5: error: Assets/Scenes/Main.unity has 2 GameObjects at 'bot'" in run.err
