"""``null`` as a field value: an empty reference (None in the Inspector, ``{fileID: 0}`` in the
scene) for a reference field, an item of a list of references, a built-in component's reference
and a field of a script apply cannot read; anything else refused at the value in the
manifest's own words (never the tool's internal objects), and nothing written."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import init_with_unreadable_script, run_cli, snapshot

from unityscaffold.unity.scene import SceneDocument

HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
"""
BODY = """\
components:
  - {script: JointStateReader, gameobject: Robot, create: true}
  - {script: TwistPublisher, gameobject: Robot, fields: {PublishedTransform: %s}}
  - {script: JointStatePublisher, gameobject: Robot, fields: {JointStateReaders: %s}}
  - {script: Image, gameobject: Canvas}
  - {script: Button, gameobject: Canvas, fields: {m_TargetGraphic: %s}}
  - {script: Assets/Scripts/Blind.cs, gameobject: Robot, fields: {Shown: %s}}
objects:
  - {path: Canvas, ui: true, components: [{type: Canvas, fields: {m_Camera: %s}}]}
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    return init_with_unreadable_script(tmp_path / "p")


def _apply(project: Path, *values: str, check: bool = False):
    (project / "robot.yaml").write_text(HEADER + BODY % values)
    extra = ("--check",) if check else ()
    return run_cli("apply", *extra, str(project / "robot.yaml"))


def _fields(project: Path) -> dict[str, object]:
    scene = SceneDocument.load(project / "Assets" / "Scenes" / "Main.unity")
    found: dict[str, object] = {}
    for path in ("Robot", "Canvas"):
        for comp in scene.components_of(scene.find_gameobject(path)):
            for name in (
                "PublishedTransform",
                "JointStateReaders",
                "m_TargetGraphic",
                "m_Camera",
                "Shown",
            ):
                value = scene.field(comp, name)
                if value is not None:
                    found[name] = value
    return found


def test_null_empties_a_reference_a_list_item_a_ugui_a_built_ins_and_an_untyped_field(
    project: Path,
) -> None:
    set_ = _apply(
        project, '"@Main Camera"', '["@Robot"]', '"@Canvas:Image"', '"@Robot"', '"@Main Camera"'
    )
    assert set_.code == 0, set_.err
    assert all(v != {"fileID": "0"} for v in _fields(project).values())
    run = _apply(project, "null", '[null, "@Robot", ~]', "~", "null", "null")
    assert run.code == 0, run.err
    empty = {"fileID": "0"}
    fields = _fields(project)
    for name in ("PublishedTransform", "m_TargetGraphic", "m_Camera", "Shown"):
        assert fields[name] == empty, name
    readers = fields["JointStateReaders"]
    assert isinstance(readers, list) and readers[0] == readers[2] == empty != readers[1]
    assert "update TwistPublisher on Robot" in run.out and "update Canvas on Canvas" in run.out
    assert _apply(project, "null", '[null, "@Robot", ~]', "~", "null", "null", check=True).code == 0


@pytest.mark.parametrize(
    ("values", "message", "hint"),
    [
        (
            ("{fileID: 0}", "[]", "null", "null", "null"),
            "PublishedTransform expects a reference to a Transform (@Path or @Path:Class, or "
            "null), not {fileID: 0}",
            "write null for an empty reference",
        ),
        (
            ("null", "[{fileID: 0, x: [1, true]}]", "null", "null", "null"),
            "JointStateReaders expects a reference to a JointStateReader (@Path or "
            "@Path:Class, or null), not {fileID: 0, x: [1, true]}",
            "write null for an empty reference",
        ),
        (
            ("null", "null", "null", "null", "null"),
            "JointStateReaders expects a list of a reference to a JointStateReader (@Path or "
            "@Path:Class, or null), not null",
            "null is an empty reference, only for fields that hold an object or component",
        ),
    ],
)
def test_a_value_that_is_not_a_reference_is_refused_in_the_manifests_words(
    project: Path, values: tuple[str, ...], message: str, hint: str
) -> None:
    before = snapshot(project)
    run = _apply(project, *values)
    assert run.code == 2, run.out + run.err
    assert message in run.err and hint in run.err, run.err
    assert "StructValue" not in run.err and "EmptyReference" not in run.err
    assert snapshot(project) == {**before, "robot.yaml": (project / "robot.yaml").read_bytes()}
