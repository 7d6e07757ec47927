"""References typed by the field's declared type, for the project's own scripts (read from their
``.cs``) and ROS#'s (from the catalog): ``GameObject`` gets the GameObject, ``Transform`` and
``RectTransform`` its transform, a built-in component or a MonoBehaviour class the one component
that fits (``@Path:Class`` chooses), arrays and ``List<>`` of any of these. A target that fits
none or several stops apply at the manifest line (exit 2) and nothing is written."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from helpers import build_tree, run_cli, snapshot

from unityscaffold.unity.catalog import rossharp_catalog
from unityscaffold.unity.scene import SceneDocument

HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
connector: {gameobject: RosConnector}
components:
  - {script: Helper, gameobject: Robot, create: true}
  - {script: Helper, gameobject: Multi, create: true}
  - {script: Derived, gameobject: Multi, create: true}
  - {script: Derived, gameobject: Arm, create: true}
  - {script: JointStateReader, gameobject: Joint, create: true}
"""
RIG = """\
using System.Collections.Generic;
using UnityEngine;
using RosSharp.RosBridgeClient;

namespace Demo
{
    public enum Mode { Idle, Drive = 5 }

    public class Rig : MonoBehaviour
    {
        public GameObject Go;
        public Transform Tr;
        public RectTransform Rect;
        public Camera Cam;
        public Light Sun;
        public JointStateReader Reader;
        public Helper Other;
        public MonoBehaviour AnyScript;
        public Transform[] Chain;
        public List<GameObject> Things;
        public List<Helper> Helpers;
        [SerializeField] private float speed = 1f;
        public Mode mode;
        private int hidden;
        public static int Shared;
    }
}
"""
SCRIPTS = {
    "Assets/Scripts/Rig.cs": RIG,
    "Assets/Scripts/Helper.cs": "using UnityEngine;\npublic class Helper : MonoBehaviour\n"
    "{\n    public int N;\n}\n",
    "Assets/Scripts/Derived.cs": "public class Derived : Helper\n{\n    public string Label;\n}\n",
}
# A UI object as Unity 2022.3 saves it: a GameObject whose transform is a RectTransform.
PANEL = """\
--- !u!1 &100
GameObject:
  m_ObjectHideFlags: 0
  m_CorrespondingSourceObject: {fileID: 0}
  m_PrefabInstance: {fileID: 0}
  m_PrefabAsset: {fileID: 0}
  serializedVersion: 6
  m_Component:
  - component: {fileID: 101}
  m_Layer: 5
  m_Name: Panel
  m_TagString: Untagged
  m_Icon: {fileID: 0}
  m_NavMeshLayer: 0
  m_StaticEditorFlags: 0
  m_IsActive: 1
--- !u!224 &101
RectTransform:
  m_ObjectHideFlags: 0
  m_CorrespondingSourceObject: {fileID: 0}
  m_PrefabInstance: {fileID: 0}
  m_PrefabAsset: {fileID: 0}
  m_GameObject: {fileID: 100}
  m_LocalRotation: {x: 0, y: 0, z: 0, w: 1}
  m_LocalPosition: {x: 0, y: 0, z: 0}
  m_LocalScale: {x: 1, y: 1, z: 1}
  m_ConstrainProportionsScale: 0
  m_Children: []
  m_Father: {fileID: 0}
  m_LocalEulerAnglesHint: {x: 0, y: 0, z: 0}
  m_AnchorMin: {x: 0, y: 0}
  m_AnchorMax: {x: 1, y: 1}
  m_AnchoredPosition: {x: 0, y: 0}
  m_SizeDelta: {x: 0, y: 0}
  m_Pivot: {x: 0.5, y: 0.5}
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    root = build_tree(tmp_path / "p", SCRIPTS)
    scene = root / "Assets" / "Scenes" / "Main.unity"
    text = scene.read_text()
    roots = text.index("--- !u!1660057539 ")
    text = text[:roots] + PANEL + text[roots:] + "  - {fileID: 101}\n"
    scene.write_text(text)
    assert SceneDocument.load(scene).validate() == []
    return root


def _rig(project: Path, fields: str) -> Path:
    manifest = project / "robot.yaml"
    manifest.write_text(
        HEADER + f"  - script: Rig\n    gameobject: Rig\n    create: true\n    fields: {fields}\n"
    )
    return manifest


def _field(doc: SceneDocument, name: str) -> str:
    found = re.search(rf"(?m)^  {name}:(.*(?:\n  - .*)*)", doc.text())
    assert found is not None, name
    return found.group(1).strip()


def _component(doc: SceneDocument, path: str, label: str) -> int:
    """The fileID of the component ``label`` (a built-in's type or a script's class) on
    ``path``."""
    meta = Path(doc.path).parents[1] / "Scripts" / f"{label}.cs.meta"
    if meta.is_file():
        found = re.search(r"guid: (\w+)", meta.read_text())
        assert found is not None
        guid = found.group(1)
    else:
        script = rossharp_catalog().named(label)
        guid = (script.guid("2.2.1") if script else None) or ""
    return next(
        c.file_id
        for c in doc.components_of(doc.find_gameobject(path))
        if (c.script is None and c.type_name == label)
        or (c.script is not None and c.script.guid == guid)
    )


def test_each_field_gets_what_its_declared_type_holds(project: Path) -> None:
    manifest = _rig(
        project,
        '{Go: "@Robot", Tr: "@Robot", Rect: "@Panel", Cam: "@Main Camera", '
        'Sun: "@Directional Light", Reader: "@Joint", Other: "@Arm", '
        'AnyScript: "@Multi:Derived", Chain: ["@Robot", "@Panel"], Things: ["@Robot", "@Arm"], '
        'Helpers: ["@Robot", "@Arm", "@Multi:Helper"], speed: 2.5, mode: Drive}',
    )
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    doc = SceneDocument.load(project / "Assets" / "Scenes" / "Main.unity")
    robot, arm = doc.find_gameobject("Robot"), doc.find_gameobject("Arm")
    assert _field(doc, "Go") == f"{{fileID: {robot.file_id}}}"
    assert _field(doc, "Tr") == f"{{fileID: {robot.transform_id}}}"
    assert _field(doc, "Rect") == "{fileID: 101}"
    assert _field(doc, "Cam") == f"{{fileID: {_component(doc, 'Main Camera', 'Camera')}}}"
    assert _field(doc, "Sun") == f"{{fileID: {_component(doc, 'Directional Light', 'Light')}}}"
    assert _field(doc, "Reader") == f"{{fileID: {_component(doc, 'Joint', 'JointStateReader')}}}"
    assert _field(doc, "Other") == f"{{fileID: {_component(doc, 'Arm', 'Derived')}}}"
    assert _field(doc, "AnyScript") == f"{{fileID: {_component(doc, 'Multi', 'Derived')}}}"
    assert _field(doc, "Chain") == (f"- {{fileID: {robot.transform_id}}}\n  - {{fileID: 101}}")
    assert _field(doc, "Things") == (
        f"- {{fileID: {robot.file_id}}}\n  - {{fileID: {arm.file_id}}}"
    )
    helpers = [
        _component(doc, "Robot", "Helper"),
        _component(doc, "Arm", "Derived"),
        _component(doc, "Multi", "Helper"),
    ]
    assert _field(doc, "Helpers") == "\n  ".join(f"- {{fileID: {h}}}" for h in helpers)
    assert _field(doc, "speed") == "2.5"
    assert _field(doc, "mode") == "5"
    assert run_cli("apply", "--check", str(manifest)).code == 0


@pytest.mark.parametrize(
    ("fields", "message", "hint"),
    [
        (
            '{Cam: "@Robot"}',
            "Robot has no Camera for this field (a Camera field)",
            "components there: Transform, Helper",
        ),
        (
            '{Rect: "@Robot"}',
            "Robot has no RectTransform for this field",
            "components there: Transform, Helper",
        ),
        (
            '{AnyScript: "@Multi"}',
            "Multi has 2 components that fit this MonoBehaviour field: Helper, Derived",
            "choose one with @Multi:<Class>",
        ),
        (
            '{Other: "@Multi"}',
            "Multi has 2 components that fit this Helper field: Helper, Derived",
            "choose one with @Multi:<Class>",
        ),
        (
            '{Other: "@Multi:Camera"}',
            "Multi has no Helper named Camera for this field",
            "components there: Transform, Helper, Derived",
        ),
        (
            '{Helpers: ["@Robot", "@Joint"]}',
            "Joint has no Helper for this field",
            "components there: Transform, JointStateReader",
        ),
        (
            '{Reader: "@Nowhere"}',
            "no GameObject named 'Nowhere' at the root",
            "declare it under `objects:`",
        ),
        (
            '{Tr: "Robot"}',
            "Tr expects a reference to a Transform (@Path or @Path:Class, or null), not 'Robot'",
            'a reference starts with @: "@Robot"',
        ),
        ("{Chain: 3}", "Chain expects a list of a reference to a Transform", None),
        ("{speed: fast}", "speed expects a number, not 'fast'", None),
        ("{mode: Park}", "mode expects a member of the enum Mode, not 'Park'", "Idle, Drive"),
        ("{Sped: 1}", "Rig has no field Sped", "did you mean speed?"),
        ("{hidden: 1}", "Rig has no field hidden", None),
        ("{Shared: 1}", "Rig has no field Shared", None),
    ],
)
def test_a_wrong_or_ambiguous_target_stops_at_the_manifest_line_and_writes_nothing(
    project: Path, fields: str, message: str, hint: str | None
) -> None:
    manifest = _rig(project, fields)
    before = snapshot(project)
    run = run_cli("apply", str(manifest))
    assert run.code == 2, run.out
    assert "robot.yaml:15:" in run.err and message in run.err, run.err
    if hint is not None:
        assert hint in run.err, run.err
    assert "Traceback" not in run.err
    assert snapshot(project) == before


def test_a_rosharp_list_of_scripts_refers_to_each_by_class(project: Path) -> None:
    manifest = project / "robot.yaml"
    manifest.write_text(
        HEADER
        + "  - script: JointStatePublisher\n    gameobject: Joint\n"
        + '    fields: {Topic: /joint_states, JointStateReaders: ["@Joint", "@Joint"]}\n'
    )
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    doc = SceneDocument.load(project / "Assets" / "Scenes" / "Main.unity")
    reader = _component(doc, "Joint", "JointStateReader")
    assert _field(doc, "JointStateReaders") == f"- {{fileID: {reader}}}\n  - {{fileID: {reader}}}"
    assert run_cli("apply", "--check", str(manifest)).code == 0


def test_a_field_typed_as_a_generated_script_settles_on_the_first_run(project: Path) -> None:
    build_tree(
        project,
        {
            "Assets/Scripts/Dash.cs": "using UnityEngine;\npublic class Dash : MonoBehaviour\n"
            "{\n    public RosGenerated.OdomSubscriber Odom;\n}\n"
        },
    )
    manifest = project / "robot.yaml"
    manifest.write_text(
        HEADER.split("components:")[0]
        + "topics:\n  - {name: /odom, type: nav_msgs/msg/Odometry, direction: subscribe, "
        + "gameobject: Robot}\ncomponents:\n"
        + '  - {script: Dash, gameobject: Robot, fields: {Odom: "@Robot"}}\n'
    )
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    doc = SceneDocument.load(project / "Assets" / "Scenes" / "Main.unity")
    robot = doc.find_gameobject("Robot")
    odom = [c.file_id for c in doc.components_of(robot) if c.script is not None]
    assert _field(doc, "Odom") == f"{{fileID: {odom[0]}}}"
    assert run_cli("apply", "--check", str(manifest)).code == 0
