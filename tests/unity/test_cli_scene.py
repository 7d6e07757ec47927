"""``scaffold scene ls|attach`` through the real entry point: output, exit codes, no tracebacks."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from unityscaffold.cli import main
from unityscaffold.unity.meta import monoscript_meta
from unityscaffold.unity.scene import SceneDocument

DATA = Path(__file__).resolve().parents[1] / "data" / "unity"
CONNECTOR_GUID = "ff98778ae051cfd40a6e4effdf851ebd"


@pytest.fixture
def project(tmp_path: Path) -> Path:
    root = tmp_path / "Proj"
    (root / "Assets" / "Scenes").mkdir(parents=True)
    (root / "ProjectSettings").mkdir()
    shutil.copy(
        DATA / "ros-sharp" / "ROSVersionSwitch.unity", root / "Assets" / "Scenes" / "Main.unity"
    )
    scripts = root / "Assets" / "Scripts"
    scripts.mkdir()
    for name, guid in [
        ("RosConnector", CONNECTOR_GUID),
        ("JoyPublisher", "92dedf3f173285b4d9a806dec2334596"),
    ]:
        (scripts / f"{name}.cs").write_text(f"public class {name} {{}}\n")
        (scripts / f"{name}.cs.meta").write_text(monoscript_meta(guid))
    return root


def _run(capsys: pytest.CaptureFixture[str], *args: object) -> tuple[int, str, str]:
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    return code, out, err


def test_ls_shows_the_tree_with_script_names(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, _ = _run(capsys, "scene", "ls", project / "Assets" / "Scenes" / "Main.unity")
    assert code == 0
    assert out.splitlines() == [
        "Main Camera  [Transform, Camera, AudioListener]",
        "Directional Light  [Transform, Light]",
        "RosSocket  [Transform, RosConnector, c1d9e9b7745777745968fa0757b4318d]",
    ]


def test_ls_json_lists_components_with_their_scripts(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, _ = _run(
        capsys, "scene", "ls", project / "Assets" / "Scenes" / "Main.unity", "--json"
    )
    data = json.loads(out)
    assert code == 0 and data["generation"].startswith("2022")
    socket = next(g for g in data["gameobjects"] if g["path"] == "RosSocket")
    assert socket["components"][1]["script"] == {
        "guid": CONNECTOR_GUID,
        "fileID": 11500000,
        "name": "RosConnector",
    }


def test_ls_marks_prefab_instances(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = _run(
        capsys, "scene", "ls", DATA / "ros-tcp-connector" / "EmptyVisualizationSuite.prefab"
    )
    assert code == 0
    assert "  BasicDrawingManager  (prefab instance &1914626938635344595)" in out.splitlines()


def test_attach_writes_once_then_reports_unchanged(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    scene = project / "Assets" / "Scenes" / "Main.unity"
    args = [
        "scene",
        "attach",
        scene,
        "--gameobject",
        "Robot/base_link",
        "--create",
        "--script",
        project / "Assets" / "Scripts" / "JoyPublisher.cs",
        "--set",
        "Topic=/joy",
        "--set",
        "CycleTime=0.1",
        "--set",
        "Flag=true",
        "--set",
        "Connector=@RosSocket:RosConnector",
        "--set",
        "Base=@Robot/base_link:Transform",
        "--set",
        "Names=[a, '@Robot', '@@at']",
        "--set",
        "Material={fileID: 2100000, guid: e84c5fd102288448a8e2305335f05d28, type: 2}",
    ]
    code, out, _ = _run(capsys, *args)
    assert code == 0 and out.startswith(f"updated {scene}: JoyPublisher on Robot/base_link")
    doc = SceneDocument.load(scene)
    comp = doc.find_component("Robot/base_link", "92dedf3f173285b4d9a806dec2334596")
    assert comp is not None
    base = doc.find_gameobject("Robot/base_link")
    robot = doc.find_gameobject("Robot")
    assert doc.field(comp, "Connector") == {"fileID": "1259760939"}
    assert doc.field(comp, "Base") == {"fileID": str(base.transform_id)}
    assert doc.field(comp, "Names") == ["a", {"fileID": str(robot.file_id)}, "@at"]
    assert doc.field(comp, "Flag") == "1" and doc.field(comp, "CycleTime") == "0.1"
    before = scene.stat().st_mtime_ns
    code, out, _ = _run(capsys, *args)
    assert code == 0 and out.startswith("unchanged") and scene.stat().st_mtime_ns == before


def test_dry_run_prints_the_diff_and_writes_nothing(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    scene = project / "Assets" / "Scenes" / "Main.unity"
    before = scene.read_bytes()
    code, out, _ = _run(
        capsys,
        "scene",
        "attach",
        scene,
        "-g",
        "RosSocket",
        "--guid",
        CONNECTOR_GUID,
        "--set",
        "SecondsTimeout=30",
        "--dry-run",
    )
    assert code == 0 and scene.read_bytes() == before
    assert "-  SecondsTimeout: 10\n+  SecondsTimeout: 30\n" in out
    code, out, _ = _run(
        capsys, "scene", "attach", scene, "-g", "RosSocket", "--guid", CONNECTOR_GUID, "--dry-run"
    )
    assert code == 0 and out.startswith("no changes")


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["-g", "Nope", "--guid", CONNECTOR_GUID], "names there: 'Directional Light'"),
        (["-g", "RosSocket"], "exactly one of --script"),
        (["-g", "RosSocket", "--guid", "XYZ"], "not a Unity GUID"),
        (["-g", "RosSocket", "--guid", CONNECTOR_GUID, "--set", "novalue"], "NAME=VALUE"),
        (
            ["-g", "RosSocket", "--guid", CONNECTOR_GUID, "--set", "X=@Nope"],
            "no GameObject named 'Nope'",
        ),
        (
            ["-g", "RosSocket", "--guid", CONNECTOR_GUID, "--set", "X=@RosSocket:Camera"],
            "has no component 'Camera'",
        ),
        (
            ["-g", "RosSocket", "--guid", CONNECTOR_GUID, "--set", "X=[unclosed"],
            "cannot read value",
        ),
        (["-g", "RosSocket", "--guid", CONNECTOR_GUID, "--set", "m_Script=1"], "cannot be set"),
        (["-g", "RosSocket", "--script", "Missing.cs"], "no .meta file"),
        # the manifest refuses these paths, so the CLI does too
        (["-g", "/RosSocket", "--guid", CONNECTOR_GUID], "invalid GameObject path '/RosSocket'"),
        (["-g", "RosSocket/", "--guid", CONNECTOR_GUID], "invalid GameObject path 'RosSocket/'"),
    ],
)
def test_user_mistakes_exit_2_with_a_message_and_write_nothing(
    project: Path, capsys: pytest.CaptureFixture[str], args: list[str], message: str
) -> None:
    scene = project / "Assets" / "Scenes" / "Main.unity"
    before = scene.read_bytes()
    code, _out, err = _run(capsys, "scene", "attach", scene, *args)
    assert code == 2 and message in err
    assert scene.read_bytes() == before


def test_a_missing_gameobject_hint_names_the_create_flag(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    scene = project / "Assets" / "Scenes" / "Main.unity"
    code, _, err = _run(
        capsys, "scene", "attach", scene, "-g", "Robot/arm", "--guid", CONNECTOR_GUID
    )
    assert code == 2 and "no GameObject named 'Robot' at the root" in err
    hint = err.split("hint: ", 1)[1]
    assert "--create" in hint and "create: true" not in hint


@pytest.mark.parametrize(
    ("content", "message"),
    [
        (b"\x00\x01binary", "binary-serialized"),
        (None, "refers to fileID 42"),
        (b"%YAML 1.1\n--- !u!1 &1\nGameObject:\n  m_Name: {a", "does not end with a line break"),
    ],
    ids=["binary", "dangling", "truncated"],
)
def test_corrupt_scenes_are_refused_by_the_cli(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], content: bytes | None, message: str
) -> None:
    scene = tmp_path / "Bad.unity"
    if content is None:
        text = (DATA / "ros-sharp" / "ROSVersionSwitch.unity").read_text()
        content = text.replace("m_Father: {fileID: 0}", "m_Father: {fileID: 42}", 1).encode()
    scene.write_bytes(content)
    code, _, err = _run(
        capsys, "scene", "attach", scene, "-g", "RosSocket", "--guid", CONNECTOR_GUID
    )
    assert code == 2 and message in err
    assert scene.read_bytes() == content
    assert [p.name for p in tmp_path.iterdir()] == ["Bad.unity"]


def test_attach_refuses_a_scene_whose_document_a_new_object_would_copy_is_not_yaml(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # The first Transform is the layout new ones copy; a tab hides its m_Children from a
    # line-based reader, so the new Robot's Transform would have none.
    scene = tmp_path / "Bad.unity"
    text = (DATA / "ros-sharp" / "ROSVersionSwitch.unity").read_text()
    lines = text.splitlines(keepends=True)
    assert lines[216] == "  m_Children: []\n"
    lines[216] = "\tm_Children: []\n"
    scene.write_text("".join(lines))
    before = scene.read_bytes()
    for flags in ([], ["--dry-run"]):
        code, out, err = _run(
            capsys,
            "scene",
            "attach",
            scene,
            "-g",
            "Robot",
            "--create",
            "--guid",
            CONNECTOR_GUID,
            *flags,
        )
        assert code == 2, out
        assert err.startswith(
            f"{scene}:217:1: error: --- !u!4 &705507995: is not valid YAML (found a tab character "
            "that violates indentation); new Transforms copy its layout\n"
        )
        assert scene.read_bytes() == before


def test_attach_help_documents_the_reference_syntax(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = _run(capsys, "scene", "attach", "--help")
    assert code == 0
    flat = " ".join(out.split())
    assert "@Path/To/Object:Transform" in flat and "{fileID: N}" in flat
