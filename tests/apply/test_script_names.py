"""Which script a `components:` entry's `script:` means: components only, looked for in every
place at once (generated, the project's own, ROS#'s catalog, uGUI), the same with and without
Unity's Library/, and two candidates are an error listing both; a script whose class is not
named like its file is read as Unity reads it."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from helpers import require, run_cli, snapshot

VENDOR = Path(__file__).resolve().parents[3] / "shared" / "vendor" / "ros-sharp" / "2.2.1"
UGUI_IMAGE = "fe87c0e1cc204ed48ad3b37840f39efc"
HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
connector: {gameobject: RosConnector}
"""
IMAGE_ENTRY = """\
components:
  - {script: Image, gameobject: Canvas/Logo, create: true}
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return tmp_path / "p"


def _apply(project: Path, body: str, *options: str):
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", *options, str(project / "robot.yaml"))


def _scene(project: Path) -> str:
    return (project / "Assets" / "Scenes" / "Main.unity").read_text()


def _refused(project: Path, body: str, *fragments: str) -> str:
    before = snapshot(project)
    run = _apply(project, body)
    assert run.code == 2, run.out + run.err
    for fragment in fragments:
        assert fragment in run.err, run.err
    assert snapshot(project) == {**before, "robot.yaml": snapshot(project)["robot.yaml"]}
    return run.err


def test_image_is_ugui_s_whether_or_not_unity_has_put_rossharp_in_its_cache(project, tmp_path):
    require((VENDOR / "com.siemens.ros-sharp" / "Runtime").is_dir(), f"ROS# 2.2.1 ({VENDOR})")
    bare = tmp_path / "bare"
    assert run_cli("init", str(bare), "--ros", "2").code == 0
    cache = project / "Library" / "PackageCache" / "com.siemens.ros-sharp@ea80541a4f"
    shutil.copytree(VENDOR / "com.siemens.ros-sharp", cache)
    run = _apply(project, IMAGE_ENTRY)  # ROS# 2.2.1 ships two message classes named Image
    assert run.code == 0, run.err
    assert f"guid: {UGUI_IMAGE}" in _scene(project)
    assert _apply(bare, IMAGE_ENTRY).code == 0
    assert _scene(project) == _scene(bare)


def test_an_embedded_rossharps_message_classes_are_no_candidates_its_components_are(project):
    require((VENDOR / "com.siemens.ros-sharp" / "Runtime").is_dir(), f"ROS# 2.2.1 ({VENDOR})")
    shutil.copytree(
        VENDOR / "com.siemens.ros-sharp", project / "Packages" / "com.siemens.ros-sharp"
    )
    run = _apply(
        project, IMAGE_ENTRY + "  - {script: TwistSubscriber, gameobject: Robot, create: true}\n"
    )
    assert run.code == 0, run.err
    assert f"guid: {UGUI_IMAGE}" in _scene(project)
    assert "guid: 81c5dfb51482c2e47b602e8096d45712" in _scene(project)  # 2.2.1's .meta


def test_a_generated_message_class_named_image_does_not_replace_ugui_s(project):
    body = (
        "namespace: MyRobot.Ros\n"
        "topics:\n"
        "  - {name: /camera, type: sensor_msgs/msg/Image, direction: subscribe}\n" + IMAGE_ENTRY
    )
    assert _apply(project, body).code == 0
    assert list(project.rglob("Image.cs")), "the manifest generates a message class Image"
    again = _apply(project, body)
    assert again.code == 0 and again.out.endswith("wrote 0 files, removed 0\n"), again.out
    assert f"guid: {UGUI_IMAGE}" in _scene(project)
    assert _apply(project, body, "--check").code == 0


def _write(project: Path, relative: str, text: str, guid: str) -> None:
    path = project / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    path.with_name(path.name + ".meta").write_text(f"fileFormatVersion: 2\nguid: {guid}\n")


OWN_IMAGE = "namespace MyGame.Ui {\n  public class Image : UnityEngine.MonoBehaviour { }\n}\n"


def test_two_components_of_one_name_are_refused_at_the_script_line_with_both_named(project):
    _write(project, "Assets/Ui/Image.cs", OWN_IMAGE, "a" * 32)
    err = _refused(
        project,
        IMAGE_ENTRY,
        "robot.yaml:7:14: error: Image could be any of 2 MonoBehaviours: ",
        "MyGame.Ui.Image (Assets/Ui/Image.cs)",
        "UnityEngine.UI.Image (uGUI (com.unity.ugui), UnityEngine.UI)",
    )
    assert "write the qualified name" in err and "path" in err


@pytest.mark.parametrize(
    ("written", "guid"),
    [
        ("UnityEngine.UI.Image", UGUI_IMAGE),
        ("MyGame.Ui.Image", "a" * 32),
        ("Assets/Ui/Image.cs", "a" * 32),
    ],
)
def test_a_qualified_name_or_a_path_chooses_among_them(project, written, guid):
    _write(project, "Assets/Ui/Image.cs", OWN_IMAGE, "a" * 32)
    run = _apply(project, IMAGE_ENTRY.replace("script: Image", f"script: {written}"))
    assert run.code == 0, run.err
    assert f"guid: {guid}" in _scene(project)


def test_a_project_class_that_is_no_component_is_not_a_candidate_and_the_miss_says_why(project):
    _write(project, "Assets/Msgs/Pose.cs", "public class Pose : Message { }\n", "b" * 32)
    _refused(
        project,
        "components:\n  - {script: Pose, gameobject: Robot, create: true}\n",
        "no MonoBehaviour named Pose",
        "Assets/Msgs/Pose.cs holds Pose, which is not a MonoBehaviour",
    )
    _refused(
        project,
        "components:\n  - {script: Assets/Msgs/Pose.cs, gameobject: Robot, create: true}\n",
        "Assets/Msgs/Pose.cs holds Pose, which is not a MonoBehaviour (it derives from Message)",
    )


# ROS#'s sample PubHeadTorque.cs holds a class named otherwise, as Unity allows.
HEAD_TORQUE = """\
using UnityEngine;
using UnityEngine.UI;
namespace RosSharp.RosBridgeClient
{
    public class Float64Publisher : MonoBehaviour
    {
        public string Topic;
        public Slider Slider;
    }
}
"""


def _torque(script: str, field: str) -> str:
    return (
        "components:\n"
        "  - {script: Slider, gameobject: Canvas/Torque, create: true}\n"
        f"  - script: {script}\n    gameobject: Head\n    create: true\n"
        f"    fields: {{Topic: /torque, {field}: '@Canvas/Torque'}}\n"
    )


@pytest.mark.parametrize("script", ["Assets/Samples/PubHeadTorque.cs", "Float64Publisher"])
def test_a_class_not_named_like_its_file_is_the_one_unity_uses_and_its_fields_are_checked(
    project, script
):
    _write(project, "Assets/Samples/PubHeadTorque.cs", HEAD_TORQUE, "c" * 32)
    _refused(project, _torque(script, "Slidr"), "Float64Publisher", "did you mean Slider")
    run = _apply(project, _torque(script, "Slider"))
    assert run.code == 0, run.err
    scene = _scene(project)
    slider = scene.split("guid: 67db9e8f0e2ae9c40bc1e2b64352a6b4")[0].rsplit("--- !u!114 &", 1)[1]
    ours = scene[scene.index(f"guid: {'c' * 32}") :].split("--- ")[0]
    assert f"Slider: {{fileID: {slider.split()[0]}}}" in ours, ours


def test_a_file_with_two_components_none_named_like_it_is_refused_with_why(project):
    two = (
        "using UnityEngine;\npublic class A : MonoBehaviour { }\n"
        "public class B : MonoBehaviour { }\n"
    )
    _write(project, "Assets/Both.cs", two, "d" * 32)
    _refused(
        project,
        "components:\n  - {script: Assets/Both.cs, gameobject: Robot, create: true}\n",
        "Assets/Both.cs is not a script Unity can attach: it declares 2 MonoBehaviours and none "
        "is named Both like the file (A, B)",
    )


def test_rossharps_scripts_answer_to_their_qualified_names_and_a_wrong_namespace_to_none(project):
    run = _apply(project, IMAGE_ENTRY.replace("Image", "RosSharp.RosBridgeClient.TwistSubscriber"))
    assert run.code == 0, run.err
    assert "guid: 81c5dfb51482c2e47b602e8096d45712" in _scene(project)
    _refused(
        project,
        IMAGE_ENTRY.replace("Image", "UnityEngine.Image"),
        "no MonoBehaviour named UnityEngine.Image",
    )
