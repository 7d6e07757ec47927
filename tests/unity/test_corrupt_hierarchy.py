"""A hierarchy that loops is refused before anything walks it; odd but valid layouts are accepted.

Every command that reads a scene (``scene ls``, ``scene attach``, ``apply`` with and without
``--check``/``--dry-run``) stops with exit 2 at the file, line and column of the object that is
its own ancestor, and writes nothing. Each run has a deadline: the bug being guarded against is
a walk that never ends.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from helpers import deadline, run_cli, snapshot

from unityscaffold.unity.scene import SceneDocument

REPO = Path(__file__).resolve().parents[2]
DATA = Path(__file__).resolve().parents[1] / "data" / "unity"
SCENE = "unity/Assets/Scenes/Main.unity"
ROBOT_TR = 9157773041844316076  # the sample's Robot, father of Lidar
LIDAR_TR = 5885231972161086862

LIDAR_CHILDLESS = "  m_Children: []\n  m_Father: {fileID: 9157773041844316076}\n"
ROBOT_ROOT = "  - {fileID: 5885231972161086862}\n  m_Father: {fileID: 0}\n"
# Robot and Lidar each the other's father, consistently on both sides, Robot no longer a root.
TWO_CYCLE = [
    (
        LIDAR_CHILDLESS,
        "  m_Children:\n  - {fileID: 9157773041844316076}\n"
        "  m_Father: {fileID: 9157773041844316076}\n",
    ),
    (ROBOT_ROOT, "  - {fileID: 5885231972161086862}\n  m_Father: {fileID: 5885231972161086862}\n"),
    ("  - {fileID: 5894855532091546194}\n  - {fileID: 9157773041844316076}\n", ""),
]
CYCLES = {
    "two-transforms": (
        TWO_CYCLE,
        f"m_Father: is its own ancestor: &{LIDAR_TR} → &{ROBOT_TR} → &{LIDAR_TR}",
    ),
    "own-father": (
        [
            (
                LIDAR_CHILDLESS,
                "  m_Children:\n  - {fileID: 5885231972161086862}\n"
                "  m_Father: {fileID: 5885231972161086862}\n",
            ),
            (
                "  m_Children:\n  - {fileID: 5885231972161086862}\n  m_Father: {fileID: 0}\n",
                "  m_Children: []\n  m_Father: {fileID: 0}\n",
            ),
        ],
        "m_Father: is its own parent",
    ),
    "own-child": (
        [
            (
                LIDAR_CHILDLESS,
                "  m_Children:\n  - {fileID: 5885231972161086862}\n"
                "  m_Father: {fileID: 9157773041844316076}\n",
            )
        ],
        "m_Children: lists this Transform itself",
    ),
}


@pytest.fixture
def sample(tmp_path: Path) -> Path:
    copy = tmp_path / "sample_project"
    shutil.copytree(REPO / "sample_project", copy)
    return copy


def _corrupt(sample: Path, replacements: list[tuple[str, str]]) -> None:
    path = sample / SCENE
    text = path.read_text()
    for old, new in replacements:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    path.write_text(text)


@pytest.mark.parametrize("case", sorted(CYCLES))
@pytest.mark.parametrize(
    "command",
    [
        ["scene", "ls", "{scene}"],
        ["apply", "{manifest}"],
        ["apply", "--check", "{manifest}"],
        ["apply", "--dry-run", "{manifest}"],
        ["plan", "{manifest}"],
        ["scene", "attach", "{scene}", "-g", "Robot/New", "--create", "--guid", "a" * 32],
    ],
    ids=["scene-ls", "apply", "check", "dry-run", "plan", "attach"],
)
def test_a_hierarchy_cycle_is_refused_at_its_line_by_every_command(
    sample: Path, case: str, command: list[str]
) -> None:
    replacements, message = CYCLES[case]
    _corrupt(sample, replacements)
    scene = sample / SCENE
    args = [a.format(scene=scene, manifest=sample / "robot.yaml") for a in command]
    before = snapshot(sample)
    with deadline(60, "a hierarchy walk does not end"):
        run = run_cli(*args)
    assert run.code == 2, run.out + run.err
    first = run.err.splitlines()[0]
    assert first.startswith(f"{scene}:") and message in first, run.err
    line, col = first[len(str(scene)) + 1 :].split(":")[:2]
    source = scene.read_text().splitlines()[int(line) - 1]
    assert col == "3" and source == run.err.splitlines()[1].strip().rjust(len(source)), run.err
    assert "Traceback" not in run.err
    assert snapshot(sample) == before


def test_a_prefab_instance_parented_inside_itself_is_refused() -> None:
    source = DATA / "ros-tcp-connector" / "EmptyVisualizationSuite.prefab"
    text = source.read_text().replace(
        "m_TransformParent: {fileID: 3885009520023495739}",
        "m_TransformParent: {fileID: 2742884835330475003}",
    )
    scene = SceneDocument.parse(text, "loop.prefab")
    with deadline(60, "a hierarchy walk does not end"):
        problems = scene.validate()
        walked = [go.path for go in scene.gameobjects()]
    assert [(p.location.line, p.location.col, p.message) for p in problems] == [
        (
            68,
            5,
            "--- !u!1001 &1914626938635344595: m_TransformParent: is its own ancestor: "
            "&1914626938635344595 → &2742884835330475003 → &1914626938635344595",
        )
    ]
    assert (
        problems[0].location.source_line == "    m_TransformParent: {fileID: 2742884835330475003}"
    )
    assert walked[0] == "BlankVisualizationSuite"


def test_attach_create_under_a_transform_without_m_children(sample: Path) -> None:
    # Older Unity versions and some prefabs write no m_Children key on a childless Transform.
    _corrupt(sample, [(LIDAR_CHILDLESS, "  m_Father: {fileID: 9157773041844316076}\n")])
    scene = sample / SCENE
    script = sample / "unity/Assets/RosGenerated/Scripts/ResetClient.cs"
    args = ["scene", "attach", str(scene), "-g", "Robot/Lidar/Sensor", "--create"]
    run = run_cli(*args, "--script", str(script))
    assert run.code == 0, run.err
    edited = SceneDocument.load(scene)
    assert edited.validate() == []
    lidar = edited.document(LIDAR_TR)
    assert lidar is not None
    sensor = edited.find_gameobject("Robot/Lidar/Sensor")
    assert f"  m_Children:\n  - {{fileID: {sensor.transform_id}}}\n  m_Father:" in lidar.text
    assert run_cli(*args, "--script", str(script)).out.startswith("unchanged")
