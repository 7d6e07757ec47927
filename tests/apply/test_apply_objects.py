"""The manifest's `objects`: declared GameObjects, UI objects and built-in components, written
as Unity 2022.3 writes them (compared with documents Unity saved), idempotent, and listed by
`scene ls`; and several instances of one script told apart by `id`."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from helpers import run_cli

from unityscaffold.unity.scene import SceneDocument

DATA = Path(__file__).resolve().parents[1] / "data" / "unity" / "ros-sharp"
JOY = "c8e7046e9f110da4a81262f9658c8514"  # ROS# 2.2.1's JoyAxisReader
HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return tmp_path / "p"


def _apply(project: Path, body: str, *extra: str):
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", str(project / "robot.yaml"), *extra)


def _scene(project: Path) -> SceneDocument:
    return SceneDocument.load(project / "Assets" / "Scenes" / "Main.unity")


def split_documents(text: str) -> list[str]:
    """The ``--- !u!`` documents of a Unity file, each with its header line."""
    return ["--- " + part for part in re.split(r"^--- ", text, flags=re.M)[1:]]


def _real(name: str, file: str = "ROS2_3_With_UI.documents.txt") -> str:
    """The first document of class ``name`` in a real 2022.3 file."""
    for text in split_documents((DATA / file).read_text(encoding="utf-8")):
        if text.split("\n", 2)[1] == f"{name}:":
            return text
    raise AssertionError(f"no {name} in {file}")


def _body(text: str) -> str:
    """A document without its header, its own fileID and the fileIDs of its place."""
    lines = text.split("\n")[2:]
    return "\n".join(line for line in lines if not line.startswith("  m_GameObject:"))


def _declared_doc(project: Path, path: str, class_name: str) -> str:
    scene = _scene(project)
    go = scene.find_gameobject(path)
    comp = next(c for c in scene.components_of(go) if c.type_name == class_name)
    doc = scene.document(comp.file_id)
    assert doc is not None
    return doc.text


# class, the fields to give it the real document's values, the real file it comes from
CASES = [
    ("Rigidbody", "{m_Mass: 0.5, m_InertiaTensor: [0.001, 0.001, 0.001], "
     "m_InertiaRotation: {x: 0, y: -0.0, z: -0.0, w: 1}, m_ImplicitCom: false, "
     "m_ImplicitTensor: false, m_UseGravity: false, m_IsKinematic: true}", None),
    ("BoxCollider", "{}", None),
    ("SphereCollider", "{}", None),
    ("Canvas", "{}", None),
    ("CanvasRenderer", "{}", None),
    ("Camera", "{m_Depth: -1}", "ROSVersionSwitch.unity"),
    ("AudioListener", "{}", "ROSVersionSwitch.unity"),
    ("Light", "{m_Type: 1, m_Color: {r: 1, g: 0.95686275, b: 0.8392157, a: 1}, "
     "m_Lightmapping: 1}", "ROSVersionSwitch.unity"),
]  # fmt: skip


@pytest.mark.parametrize(("name", "fields", "file"), CASES, ids=[c[0] for c in CASES])
def test_a_built_in_component_is_written_as_unity_2022_3_writes_it(project, name, fields, file):
    run = _apply(project, f"objects:\n  - {{path: Thing, components: [{{type: {name}, "
                 f"fields: {fields}}}]}}\n")  # fmt: skip
    assert run.code == 0, run.err
    ours = _body(_declared_doc(project, "Thing", name))
    real = _body(_real(name, file or "ROS2_3_With_UI.documents.txt"))
    if name == "Light":  # the scene's Directional Light casts soft shadows; a new Light none
        real = real.replace("  m_Shadows:\n    m_Type: 2\n", "  m_Shadows:\n    m_Type: 0\n")
    assert ours == real


def test_a_ui_object_gets_the_rect_transform_unity_writes(project):
    run = _apply(
        project,
        "objects:\n  - {path: Canvas, ui: true}\n"
        "  - path: Canvas/JoystickBackground\n"
        "    ui: {anchor_min: [0, 0], anchor_max: [0, 0], position: [150, 150],\n"
        "         size: [100, 100]}\n",
    )
    assert run.code == 0, run.err
    scene = _scene(project)
    go = scene.find_gameobject("Canvas/JoystickBackground")
    assert go.transform_id is not None
    doc = scene.document(go.transform_id)
    assert doc is not None and doc.class_id == 224

    def shape(text: str) -> str:  # children and father are the file's own
        body = re.sub(r"  m_Children:\n(  - .*\n)*|  m_Children: \[\]\n", "", _body(text) + "\n")
        return re.sub(r"  m_Father: \{fileID: \d+\}\n", "", body)

    assert shape(doc.text) == shape(_real("RectTransform"))
    assert "m_Layer: 5\n" in (scene.document(go.file_id) or doc).text


def test_a_rotation_unity_wrote_for_the_same_angles_is_left_alone(project):
    # Unity's Inspector rounds Quaternion.Euler(90, 180, 0) in single precision
    # ({x: -0, y: 0.7071068, ...}); apply takes it as the same rotation and writes nothing.
    real = _real("Transform")
    run = _apply(
        project,
        "objects:\n  - {path: Plane, rotation: [90, 180, 0], position: [0, 0.59999996, 2.26],\n"
        "     scale: [0.37296024, 1, 0.30000004]}\n",
    )
    assert run.code == 0, run.err
    scene_path = project / "Assets" / "Scenes" / "Main.unity"
    scene = _scene(project)
    ours = scene.document(scene.find_gameobject("Plane").transform_id or 0)
    assert ours is not None
    pose = re.compile(r"  m_Local(Rotation|Position|Scale|EulerAnglesHint): .*\n")
    unity_pose = "".join(m.group(0) for m in pose.finditer(real))
    text = scene_path.read_text()
    ours_pose = "".join(m.group(0) for m in pose.finditer(ours.text))
    assert "m_LocalRotation: {x: 0, y: 0.70710677, z: -0.70710677, w: 0}" in ours_pose
    scene_path.write_text(text.replace(ours_pose, unity_pose))
    again = run_cli("apply", str(project / "robot.yaml"))
    assert again.code == 0 and again.out.endswith("wrote 0 files, removed 0\n"), again.out


def test_declared_objects_are_a_fixed_point_and_scene_ls_reads_them(project):
    body = """\
objects:
  - path: Robot
    position: [0, 0.1, 0]
    rotation: [0, 90, 0]
    scale: [1, 1, 1]
    components:
      - Rigidbody
      - {type: BoxCollider, id: bumper, fields: {m_Size: [0.5, 0.2, 0.8], m_IsTrigger: true}}
      - {type: BoxCollider, id: body, fields: {m_Center: {x: 0, y: 0.25, z: 0}}}
      - {type: CapsuleCollider, fields: {m_Radius: 0.25}}
      - SphereCollider
  - path: Robot/Camera
    tag: MainCamera
    active: false
    layer: 3
    components: [Camera, AudioListener, Light]
  - path: Canvas
    ui: true
    components: [{type: Canvas, fields: {m_RenderMode: 1, m_Camera: "@Robot/Camera"}}]
  - path: Canvas/Speed
    ui: {anchor_min: [0, 1], anchor_max: [0, 1], position: [90, -20], size: [160, 30]}
    components: [CanvasRenderer]
components:
  - {script: CanvasScaler, gameobject: Canvas, fields: {m_UiScaleMode: 1}}
  - {script: GraphicRaycaster, gameobject: Canvas}
  - {script: Text, gameobject: Canvas/Speed}
  - {script: EventSystem, gameobject: EventSystem}
  - {script: StandaloneInputModule, gameobject: EventSystem}
"""
    run = _apply(project, body)
    assert run.code == 0, run.err
    assert "create object Robot" in run.out and "add Camera to Robot/Camera" in run.out
    check = run_cli("apply", "--check", str(project / "robot.yaml"))
    assert check.code == 0, check.out + check.err
    again = run_cli("apply", str(project / "robot.yaml"))
    assert again.out.endswith("wrote 0 files, removed 0\n"), again.out
    listed = run_cli("scene", "ls", str(project / "Assets" / "Scenes" / "Main.unity"))
    assert listed.code == 0, listed.err
    assert (
        "Robot  [Transform, Rigidbody, BoxCollider, BoxCollider, CapsuleCollider, SphereCollider]"
        in listed.out
    )
    assert "Canvas  [RectTransform, Canvas, CanvasScaler, GraphicRaycaster]" in listed.out
    assert "Speed  [RectTransform, CanvasRenderer, Text]" in listed.out
    assert "EventSystem  [Transform, EventSystem, StandaloneInputModule]" in listed.out
    scene = _scene(project)
    camera = scene.find_gameobject("Robot/Camera")
    canvas = _declared_doc(project, "Canvas", "Canvas")
    camera_id = next(c.file_id for c in scene.components_of(camera) if c.type_name == "Camera")
    assert f"  m_Camera: {{fileID: {camera_id}}}\n" in canvas
    go_text = (scene.document(camera.file_id) or canvas).text
    assert "m_TagString: MainCamera\n" in go_text and "m_IsActive: 0\n" in go_text
    assert "m_Layer: 3\n" in go_text


def test_a_ugui_guid_in_the_table_is_the_one_real_scenes_use(project):
    # each GUID is followed, in a scene Unity saved, by the fields that tell its class
    from unityscaffold.unity.ugui import UGUI_SCRIPTS

    telling = {
        "Image": "m_Sprite",
        "Slider": "m_FillRect",
        "CanvasScaler": "m_UiScaleMode",
        "GraphicRaycaster": "m_BlockingMask",
        "EventSystem": "m_FirstSelected",
        "StandaloneInputModule": "m_HorizontalAxis",
    }
    docs = split_documents((DATA / "ROS2_3_With_UI.documents.txt").read_text(encoding="utf-8"))
    for name, field in telling.items():
        guid = UGUI_SCRIPTS[name][1]
        found = [d for d in docs if f"guid: {guid}," in d]
        assert found and all(f"\n  {field}:" in d for d in found), name


def test_a_field_reference_to_a_declared_object_resolves_on_a_fresh_project(project):
    run = _apply(
        project,
        """\
components:
  - script: TwistSubscriber
    gameobject: RosConnector
    fields: {Topic: /cmd_vel_unity, SubscribedTransform: "@Robot/base_link"}
objects:
  - {path: Robot/base_link, position: [0, 0.1, 0]}
""",
    )
    assert run.code == 0, run.err
    check = run_cli("apply", "--check", str(project / "robot.yaml"))
    assert check.code == 0, check.out


def test_two_instances_of_one_script_keep_their_ids_across_runs(project):
    body = """\
components:
  - {script: JoyAxisReader, gameobject: Joystick, id: horizontal, fields: {name: Horizontal}}
  - {script: JoyAxisReader, gameobject: Joystick, id: vertical, fields: {name: Vertical}}
"""
    run = _apply(project, body)
    assert run.code == 0, run.err
    assert "add JoyAxisReader#horizontal to Joystick" in run.out
    scene = _scene(project)
    readers = [c for c in scene.components_of("Joystick") if c.script and c.script.guid == JOY]
    names = {c.file_id: scene.field(c, "name") for c in readers}
    assert sorted(names.values()) == ["Horizontal", "Vertical"]  # type: ignore[type-var]
    # swapped in the manifest: each id keeps its component, only nothing changes
    swapped = "components:\n" + "\n".join(reversed(body.splitlines()[1:])) + "\n"
    again = _apply(project, swapped)
    assert again.out.endswith("wrote 0 files, removed 0\n"), again.out
    scene = _scene(project)
    assert {c.file_id: scene.field(c, "name") for c in readers} == names


def test_instances_made_in_unity_are_adopted_not_doubled(project):
    first = _apply(project, "components:\n  - {script: JoyAxisReader, gameobject: Pad}\n")
    assert first.code == 0, first.err
    body = """\
components:
  - {script: JoyAxisReader, gameobject: Pad, id: x, fields: {name: Horizontal}}
  - {script: JoyAxisReader, gameobject: Pad, id: y, fields: {name: Vertical}}
"""
    run = _apply(project, body)
    assert run.code == 0, run.err
    readers = [c for c in _scene(project).components_of("Pad") if c.script and c.script.guid == JOY]
    assert len(readers) == 2
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


@pytest.mark.parametrize(
    ("body", "message"),
    [
        (
            "objects:\n  - {path: Thing, components: [{type: Rigidbody, fields: {m_Mas: 2}}]}\n",
            "Rigidbody has no field m_Mas",
        ),
        (
            "objects:\n  - {path: Thing, components: [{type: Rigidbody, fields: {m_Mass: x}}]}\n",
            "m_Mass expects a number",
        ),
        ("objects:\n  - {path: Thing, tag: Robot}\n", "unknown tag 'Robot'"),
        (
            "objects:\n  - {path: Main Camera, ui: true}\n",
            "'Main Camera' exists with a Transform",
        ),
        (
            "objects:\n  - {path: C, components: [{type: Canvas, fields: {m_Camera: '@Nope'}}]}\n",
            "no GameObject named 'Nope'",
        ),
    ],
)
def test_a_bad_object_stops_at_its_line_and_writes_nothing(project, body, message):
    scene = project / "Assets" / "Scenes" / "Main.unity"
    before = scene.read_bytes()
    run = _apply(project, body)
    assert run.code == 2, run.out
    assert "robot.yaml:" in run.err and message in run.err, run.err
    assert "Traceback" not in run.err
    assert scene.read_bytes() == before
    assert not (project / "robot.lock.json").exists()


def test_a_tag_the_project_added_is_accepted(project):
    settings = project / "ProjectSettings" / "TagManager.asset"
    settings.write_text("%YAML 1.1\n--- !u!78 &1\nTagManager:\n  serializedVersion: 2\n"
                        "  tags:\n  - Robot\n  layers:\n  - Default\n")  # fmt: skip
    run = _apply(project, "objects:\n  - {path: Thing, tag: Robot}\n")
    assert run.code == 0, run.err


def test_an_instance_whose_id_leaves_the_manifest_is_removed_alone(project):
    both = """\
components:
  - {script: JoyAxisReader, gameobject: Pad, id: x, fields: {name: Horizontal}}
  - {script: JoyAxisReader, gameobject: Pad, id: y, fields: {name: Vertical}}
"""
    first = _apply(project, both)
    assert first.code == 0, first.err
    assert "re-add" not in first.out
    run = _apply(project, both.replace(both.splitlines()[2] + "\n", ""))
    assert run.code == 0, run.err
    assert "remove component JoyAxisReader#y from Pad" in run.out
    scene = _scene(project)
    readers = [c for c in scene.components_of("Pad") if c.script and c.script.guid == JOY]
    assert [scene.field(c, "name") for c in readers] == ["Horizontal"]
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_the_manifest_offers_exactly_the_built_in_classes_and_layers_the_unity_stage_knows():
    from unityscaffold.manifest import _spec as spec
    from unityscaffold.unity import builtins

    assert spec.BUILTIN_TYPES == builtins.BUILTIN_TYPES
    assert spec.BUILTIN_LAYERS == builtins.BUILTIN_LAYERS
    assert all(builtins.layer_number(n) == spec.LAYER_NUMBERS[n] for n in spec.BUILTIN_LAYERS)


@pytest.fixture
def project_2020(project: Path) -> Path:
    """The init project with a scene Unity 2020.3 saved (m_RootOrder, no SceneRoots)."""
    demo = DATA.parent / "unity-robotics-hub" / "DemoScene.unity"
    (project / "Assets" / "Scenes" / "Main.unity").write_bytes(demo.read_bytes())
    return project


def test_a_built_in_component_is_refused_in_a_scene_of_an_older_unity(project_2020):
    scene = project_2020 / "Assets" / "Scenes" / "Main.unity"
    before = scene.read_bytes()
    run = _apply(project_2020, "objects:\n  - {path: Thing, components: [Rigidbody]}\n")
    assert run.code == 2, run.out
    assert "robot.yaml:6:" in run.err and "written as Unity 2022.3 writes them" in run.err
    assert scene.read_bytes() == before


def test_a_ui_object_in_a_scene_of_an_older_unity_follows_its_layout(project_2020):
    run = _apply(project_2020, "objects:\n  - {path: Panel, ui: {size: [10, 20]}}\n")
    assert run.code == 0, run.err
    scene = _scene(project_2020)
    rect = scene.document(scene.find_gameobject("Panel").transform_id or 0)
    assert rect is not None and rect.class_id == 224
    assert "\n  m_RootOrder: " in rect.text and "m_ConstrainProportionsScale" not in rect.text
    assert "\n  m_SizeDelta: {x: 10, y: 20}\n" in rect.text
    assert run_cli("apply", "--check", str(project_2020 / "robot.yaml")).code == 0
