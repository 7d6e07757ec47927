"""apply on real scenes Unity saved (the corpus): a 2022.3 scene with SceneRoots and an existing
RosConnector, and a 2020.3 scene with m_RootOrder. Untouched documents keep their bytes."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from helpers import run_cli

REPO = Path(__file__).resolve().parents[2]
CORPUS = REPO / "tests" / "data" / "unity"

MANIFEST = """\
version: 1
ros: {ros}
project: .
scene: Assets/Scenes/{scene}
connector: {{gameobject: {connector}, url: "ws://localhost:9090"}}
topics:
  - {{name: /cmd_vel, type: geometry_msgs/Twist, direction: publish, rate: 10,
     gameobject: {connector}}}
  - {{name: /odom, type: nav_msgs/Odometry, direction: subscribe, gameobject: Robot/base_link}}
"""


def _project(tmp_path: Path, corpus_file: Path, ros: int, connector: str) -> Path:
    project = tmp_path / "project"
    assert run_cli("init", str(project), "--ros", str(ros)).code == 0
    shutil.copy(corpus_file, project / "Assets" / "Scenes" / corpus_file.name)
    (project / "robot.yaml").write_text(
        MANIFEST.format(ros=ros, scene=corpus_file.name, connector=connector)
    )
    return project


def _documents(text: str) -> set[str]:
    """Each document with its header line and its own final newline."""
    return {chunk for chunk in re.split(r"(?m)^(?=--- )", text) if chunk.startswith("--- ")}


@pytest.mark.parametrize(
    ("corpus_file", "ros", "connector"),
    [
        (CORPUS / "ros-sharp" / "ROSVersionSwitch.unity", 2, "RosSocket"),
        (CORPUS / "unity-robotics-hub" / "DemoScene.unity", 1, "RosConnector"),
    ],
)
def test_apply_on_a_real_scene_keeps_every_untouched_document(
    tmp_path, corpus_file, ros, connector
):
    project = _project(tmp_path, corpus_file, ros, connector)
    original = corpus_file.read_text()
    first = run_cli("apply", str(project / "robot.yaml"))
    assert first.code == 0, first.err
    scene = (project / "Assets" / "Scenes" / corpus_file.name).read_text()
    kept = _documents(original) - _documents(scene)
    # Only documents apply meant to change differ: the connector's GameObject (new component),
    # and the hierarchy bookkeeping (SceneRoots / nothing in m_RootOrder files).
    changed_kinds = {doc.split("\n", 2)[1] for doc in kept}
    assert changed_kinds <= {"GameObject:", "MonoBehaviour:", "SceneRoots:"}, kept
    assert run_cli("apply", str(project / "robot.yaml")).out.endswith("wrote 0 files, removed 0\n")
    assert run_cli("apply", "--check", str(project / "robot.yaml")).code == 0


def test_an_existing_ros_connector_is_updated_in_place_not_duplicated(tmp_path):
    corpus_file = CORPUS / "ros-sharp" / "ROSVersionSwitch.unity"
    project = _project(tmp_path, corpus_file, 2, "RosSocket")
    run = run_cli("apply", str(project / "robot.yaml"))
    assert run.code == 0, run.err
    assert "add RosConnector" not in run.out
    scene = (project / "Assets" / "Scenes" / corpus_file.name).read_text()
    assert scene.count("guid: ff98778ae051cfd40a6e4effdf851ebd") == 1
