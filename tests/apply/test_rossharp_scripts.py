"""Every ROS# MonoBehaviour of the catalog on a fresh ``init`` project without ``Library/``: it
attaches with a value in each of its fields, the scene validates, ``apply --check`` is clean and
``scene ls`` names it. Field names and values are checked against the C# class first."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import run_cli, snapshot

from unityscaffold.unity.catalog import CatalogField, CatalogScript, rossharp_catalog
from unityscaffold.unity.scene import SceneDocument

CATALOG = rossharp_catalog()
ATTACHABLE = [s for s in CATALOG.scripts if s.attachable]
HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
connector: {gameobject: RosConnector}
"""
_STRUCTS = {
    "Vector2": "{x: 1, y: 2}",
    "Vector3": "{x: 1, y: 2.5, z: -3}",
    "Quaternion": "{x: 0, y: 0, z: 0.70710677, w: 0.70710677}",
    "Color": "{r: 1, g: 0.5, b: 0, a: 1}",
}
_SCALARS = {"int": "7", "float": "0.25", "bool": "true", "string": "/robot/topic"}
# Built-in components on the GameObjects that hold them: the init scene's, and a declared one.
_BUILT_IN = {"ref:Camera": "Main Camera", "ref:Light": "Directional Light", "ref:Rigidbody": "Body"}
_OBJECTS = "objects:\n  - {path: Body, components: [Rigidbody]}\n"


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    assert not (tmp_path / "p" / "Library").exists()
    return tmp_path / "p"


def _concrete(class_name: str) -> CatalogScript | None:
    """An attachable ROS# script that can stand in a field of this class."""
    for script in ATTACHABLE:
        if class_name in (script.class_name, *script.bases):
            return script
    return None


def _value(field: CatalogField, extra: list[str]) -> str | None:
    """A manifest value for the field (None for a built-in component the scene lacks)."""
    kind = field.unity.removesuffix("[]")
    if kind in _SCALARS:
        value = _SCALARS[kind]
    elif kind in _STRUCTS:
        value = _STRUCTS[kind]
    elif kind.startswith("enum:"):
        value = list(CATALOG.enums[kind[5:]])[-1]
    elif kind in ("ref:Transform", "ref:GameObject"):
        value = '"@Target"'
    elif kind in _BUILT_IN:
        value = f'"@{_BUILT_IN[kind]}"'
    elif kind.startswith("ref:"):
        target = _concrete(kind[4:].rsplit(".", 1)[-1])
        if target is None:
            return None  # a built-in component objects: cannot declare (MeshRenderer)
        extra.append(
            f"  - {{script: {target.class_name}, gameobject: Holder{len(extra)}, create: true}}"
        )
        value = f'"@Holder{len(extra) - 1}"'
    else:
        raise AssertionError(f"no sample value for {field.unity}")
    return f"[{value}]" if field.unity.endswith("[]") else value


@pytest.mark.parametrize("script", ATTACHABLE, ids=lambda s: s.class_name)
def test_every_stock_script_attaches_without_library(project: Path, script: CatalogScript) -> None:
    extra: list[str] = []
    values = {f.name: v for f in script.fields if (v := _value(f, extra)) is not None}
    fields = ", ".join(f"{name}: {value}" for name, value in values.items())
    body = (
        "components:\n"
        + f"  - script: {script.class_name}\n    gameobject: Thing\n    create: true\n"
        + f"    fields: {{{fields}}}\n"
        + "\n".join(extra)
        + "\n"
        + _OBJECTS
    )
    (project / "Assets" / "Scenes").mkdir(exist_ok=True)
    manifest = project / "robot.yaml"
    manifest.write_text(HEADER + _with_target(body))
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    assert f"add {script.class_name} to Thing" in run.out
    scene_path = project / "Assets" / "Scenes" / "Main.unity"
    doc = SceneDocument.load(scene_path)
    assert doc.validate() == []
    assert f"guid: {script.guid('2.2.1')}" in scene_path.read_text()
    assert run_cli("apply", "--check", str(manifest)).code == 0
    listing = run_cli("scene", "ls", str(scene_path))
    assert "Thing" in listing.out and script.class_name in listing.out


def _with_target(body: str) -> str:
    """A ``Target`` GameObject for Transform and GameObject fields, created by an entry."""
    return body.replace(
        "components:\n",
        "components:\n  - {script: RosConnector, gameobject: Target, create: true}\n",
        1,
    )


def _apply(project: Path, body: str):
    manifest = project / "robot.yaml"
    manifest.write_text(HEADER + body)
    return run_cli("apply", str(manifest))


def _refused(project: Path, body: str):
    """Apply a manifest that must be refused; check that nothing but it was written."""
    manifest = project / "robot.yaml"
    manifest.write_text(HEADER + body)
    before = snapshot(project)
    run = run_cli("apply", str(manifest))
    assert run.code == 2, run.out
    assert snapshot(project) == before
    return run


def test_a_misspelled_field_gets_did_you_mean_and_nothing_is_written(project: Path) -> None:
    run = _refused(
        project,
        "components:\n  - script: StringPublisher\n    gameobject: Chat\n    create: true\n"
        "    fields: {Topik: /chatter}\n",
    )
    assert "robot.yaml:10:21: error: StringPublisher has no field Topik" in run.err
    assert "hint: did you mean Topic?" in run.err


@pytest.mark.parametrize(
    ("fields", "message"),
    [
        ("{Topic: 5}", "Topic expects a string, not 5"),
        ("{TimeStep: fast}", "TimeStep expects a number, not 'fast'"),
        ("{EnsureThreadSafety: 1}", "EnsureThreadSafety expects true or false, not 1"),
        ("{SubscribedTransform: Robot}", "SubscribedTransform expects a reference to a Transform"),
    ],
)
def test_a_value_of_the_wrong_type_is_refused(project: Path, fields: str, message: str) -> None:
    run = _refused(
        project,
        "components:\n  - script: TwistSubscriber\n    gameobject: Robot\n    create: true\n"
        f"    fields: {fields}\n",
    )
    assert "robot.yaml:10:" in run.err and message in run.err


def test_an_enum_is_set_by_member_name_and_a_wrong_one_lists_the_members(project: Path) -> None:
    ok = _apply(
        project,
        "components:\n  - script: UrdfVisual\n    gameobject: Link\n    create: true\n"
        "    fields: {GeometryType: Sphere}\n",
    )
    assert ok.code == 0, ok.err
    scene = (project / "Assets" / "Scenes" / "Main.unity").read_text()
    assert "  GeometryType: 2\n" in scene
    bad = _apply(
        project,
        "components:\n  - script: UrdfVisual\n    gameobject: Link\n    create: true\n"
        "    fields: {GeometryType: Cube}\n",
    )
    assert bad.code == 2
    assert "GeometryType expects a member of the enum GeometryTypes, not 'Cube'" in bad.err
    assert "hint: its members: Box, Cylinder, Sphere, Mesh" in bad.err


def test_a_transform_field_gets_the_transform_not_the_gameobject(project: Path) -> None:
    run = _apply(
        project,
        "components:\n  - script: TwistSubscriber\n    gameobject: Robot\n    create: true\n"
        '    fields: {Topic: /cmd_vel, SubscribedTransform: "@Robot"}\n',
    )
    assert run.code == 0, run.err
    doc = SceneDocument.load(project / "Assets" / "Scenes" / "Main.unity")
    robot = doc.find_gameobject("Robot")
    assert f"  SubscribedTransform: {{fileID: {robot.transform_id}}}\n" in doc.text()


def test_vectors_are_written_inline_as_unity_writes_them(project: Path) -> None:
    run = _apply(
        project,
        "components:\n  - script: UrdfInertial\n    gameobject: Link\n    create: true\n"
        "    fields: {CenterOfMass: {x: 0, y: 0.5, z: 1}, Mass: 2}\n",
    )
    assert run.code == 0, run.err
    scene = (project / "Assets" / "Scenes" / "Main.unity").read_text()
    assert "  CenterOfMass: {x: 0, y: 0.5, z: 1}\n" in scene
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_a_stock_script_on_the_connectors_gameobject_is_a_fixed_point(project: Path) -> None:
    run = _apply(
        project,
        "components:\n  - script: TwistSubscriber\n    gameobject: RosConnector\n"
        "    fields: {Topic: /cmd_vel_unity}\n",
    )
    assert run.code == 0, run.err
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0
    again = run_cli("apply", str(project / "robot.yaml"))
    assert again.out.endswith("wrote 0 files, removed 0\n")


def test_scene_ls_names_the_rosconnector_without_library(project: Path) -> None:
    assert _apply(project, "").code == 0
    listing = run_cli("scene", "ls", str(project / "Assets" / "Scenes" / "Main.unity"))
    assert "RosConnector" in listing.out
    assert "ff98778ae051cfd40a6e4effdf851ebd" not in listing.out
