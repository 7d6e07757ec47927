"""A project's own MonoBehaviour attached by apply holds every field Unity serializes for it, at
its C# initializer (Unity's layout: base class first, references null, lists empty, events
with no calls); a field whose initializer is not a plain value is left to Unity with one note
per class; and a component already in the scene keeps the fields the manifest does not set."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import build_tree, run_cli

from unityscaffold.unity.scene import SceneDocument

BASE = """\
using UnityEngine;
public class Vehicle : MonoBehaviour
{
    public string Label = "car; {fast}";
}
"""
ROVER = """\
using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Events;

namespace Demo
{
    public enum Gear { Park, Drive = 3 }

    public class Rover : Vehicle
    {
        [Serializable]
        public class Limits
        {
            public float Max = 2f;
            public Vector2 Range;
            private int cache;
        }

        public float Speed = 2.5f;
        [SerializeField] private int wheels = 6;
        [HideInInspector] public bool Armed = true;
        public Gear Start = Gear.Drive;
        public Vector3 Offset = new Vector3(0, 1.5f, 0);
        public Color Tint = Color.white;
        public Quaternion Turn;
        public Transform Target;
        public float[] Ratios = new float[] { 1, 0.5f };
        public List<string> Names = new List<string>();
        public UnityEvent OnArrive;
        public Limits Bounds;
        public float Timeout = 60 * 5;
        public string Home = Application.productName;
        [NonSerialized] public int Skipped = 4;
        public const int Max = 9;
        public static int Count;
        private readonly int fixedOne = 1;
        protected int notSerialized = 2;
    }
}
"""
EXPECTED = """\
  Label: car; {fast}
  Speed: 2.5
  wheels: 6
  Armed: 1
  Start: 3
  Offset: {x: 0, y: 1.5, z: 0}
  Tint: {r: 1, g: 1, b: 1, a: 1}
  Turn: {x: 0, y: 0, z: 0, w: 0}
  Target: {fileID: 0}
  Ratios:
  - 1
  - 0.5
  Names: []
  OnArrive:
    m_PersistentCalls:
      m_Calls: []
  Bounds:
    Max: 2
    Range: {x: 0, y: 0}
"""
HEADER = "version: 1\nros: 2\nproject: .\nscene: Assets/Scenes/Main.unity\n"


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    scripts = {
        "Assets/Scripts/Vehicle.cs": BASE,
        "Assets/Scripts/Vehicle.cs.meta": "fileFormatVersion: 2\nguid: 1" + "0" * 31 + "\n",
        "Assets/Scripts/Rover.cs": ROVER,
        "Assets/Scripts/Rover.cs.meta": "fileFormatVersion: 2\nguid: 2" + "0" * 31 + "\n",
    }
    return build_tree(tmp_path / "p", scripts)


def _rover(project: Path, path: str) -> str:
    scene = SceneDocument.load(project / "Assets" / "Scenes" / "Main.unity")
    comp = next(c for c in scene.components_of(path) if c.type_name != "Transform")
    doc = scene.document(comp.file_id)
    assert doc is not None
    return doc.text.split("  m_EditorClassIdentifier: \n", 1)[1]


def test_a_new_component_holds_every_serialized_field_at_its_initializer(project):
    manifest = project / "robot.yaml"
    manifest.write_text(
        HEADER + "components:\n"
        "  - {script: Rover, gameobject: A, create: true, fields: {wheels: 4}}\n"
        "  - {script: Rover, gameobject: B, create: true}\n"
    )
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    assert _rover(project, "A") == EXPECTED.replace("wheels: 6", "wheels: 4")
    assert _rover(project, "B") == EXPECTED
    notes = [line for line in run.out.splitlines() if "Timeout, Home" in line]
    assert len(notes) == 1, run.out
    assert "Unity adds Rover's Timeout, Home when it next saves" in notes[0]
    again = run_cli("apply", str(manifest))
    assert again.out.endswith("wrote 0 files, removed 0\n"), again.out


def test_a_component_already_there_gets_only_the_fields_the_manifest_sets(project):
    manifest = project / "robot.yaml"
    manifest.write_text(HEADER + "components:\n  - {script: Rover, gameobject: A, create: true}\n")
    assert run_cli("apply", str(manifest)).code == 0
    scene = project / "Assets" / "Scenes" / "Main.unity"
    trimmed = scene.read_text().replace("  Tint: {r: 1, g: 1, b: 1, a: 1}\n", "")
    scene.write_text(trimmed)
    manifest.write_text(
        HEADER + "components:\n  - {script: Rover, gameobject: A, fields: {Speed: 3}}\n"
    )
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    assert scene.read_text() == trimmed.replace("  Speed: 2.5\n", "  Speed: 3\n")
    assert "Unity adds" not in run.out


EVERY_KIND = """\
version: 1
ros: ROS
project: .
scene: Assets/Scenes/Main.unity
topics:
  - {name: /chatter, type: std_msgs/String, direction: publish, rate: 5, gameobject: Talk}
  - {name: /heard, type: std_msgs/String, direction: subscribe, gameobject: Talk}
services:
  - {name: /ask, type: std_srvs/Trigger, role: client, gameobject: Ask}
  - {name: /answer, type: std_srvs/Trigger, role: server, gameobject: Ask}
actions:
  - {name: /count, type: ACTION, role: client, gameobject: Count}
  - {name: /counted, type: ACTION, role: server, gameobject: Count}
"""


@pytest.mark.parametrize("ros", ["1", "2"])
def test_a_generated_script_is_written_with_every_field_its_class_serializes(tmp_path, ros):
    # what the C# reader finds in the generated class is what the new component holds, at the
    # class's initializers where the manifest sets nothing (a client's ResponseTimeout)
    from unityscaffold.unity.scriptfacts import read_script_facts

    assert run_cli("init", str(tmp_path / "p"), "--ros", ros).code == 0
    project = tmp_path / "p"
    action = "nav_msgs/action/GetMap" if ros == "1" else "test_msgs/action/Fibonacci"
    manifest = project / "robot.yaml"
    manifest.write_text(EVERY_KIND.replace("ROS", ros).replace("ACTION", action))
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    scene = SceneDocument.load(project / "Assets" / "Scenes" / "Main.unity")
    checked = 0
    for source in sorted((project / "Assets").rglob("*.cs")):
        if source.name.endswith(".User.cs") or "Messages" in source.parts:
            continue
        facts = read_script_facts(source, source.stem, lambda name: None, lambda name: False)
        guid = _guid(source)
        comps = [c for go in scene.gameobjects() for c in scene.components_of(go)
                 if c.script and c.script.guid == guid]  # fmt: skip
        if facts is None or not comps:
            continue
        doc = scene.document(comps[0].file_id)
        assert doc is not None
        written = [line.split(":")[0].strip() for line in doc.text.split("\n")
                   if line.startswith("  ") and not line.startswith("   ")]  # fmt: skip
        names = [f.name for f in facts.script.fields]
        assert written[written.index("m_EditorClassIdentifier") + 1 :] == names, source.name
        for f in facts.script.fields:
            if f.name == "ResponseTimeout":
                assert f"\n  ResponseTimeout:{f.default}\n" in doc.text
        checked += 1
    assert checked == 6


def _guid(source: Path) -> str:
    meta = source.with_name(source.name + ".meta").read_text()
    return meta.split("guid: ", 1)[1].split()[0]
