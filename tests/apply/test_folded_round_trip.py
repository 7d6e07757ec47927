"""A user's scene whose long double-quoted strings Unity folded over lines goes through apply
untouched: in a list, a struct, a list of structs, a field the manifest does not set, whatever
column Unity folded them at. Unity keeps the spaces before each fold (a line ending in
``\\r\\n   `` is three spaces plus the fold's one), so a value the manifest sets to the same text
compares equal, and only what changed is written."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import run_cli

NOTES = """\
using System;
using UnityEngine;

[Serializable]
public struct Entry
{
    public string key;
    public string text;
}

public class Notes : MonoBehaviour
{
    public string[] Lines;
    public Entry Main;
    public Entry[] Entries;
    public string Other;
    public int Count;
}
"""
GUID = "5b1c2a9e7b3d48e6a05c9d21e7f36b81"
TEXT = (
    r"<gazebo>\r\n  <plugin filename=gz-sim-diff-drive-system name=DiffDrive>\r\n"
    r"    <left_joint>left_front_wheel_joint</left_joint>\r\n  </plugin>\r\n</gazebo>"
)
MANIFEST = f"""\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
components:
  - script: Notes
    gameobject: Holder
    fields:
      Lines: ["{TEXT}"]
      Main: {{key: a, text: "{TEXT}"}}
      Count: COUNT
"""
# The fields as a user's Unity may have saved them: folded at other columns than apply folds
# (spaces before a fold kept, shown as ·), with a field and a list the manifest does not own.
USERS = """\
  Lines:
  - "<gazebo>\\r\\n··<plugin filename=gz-sim-diff-drive-system
    name=DiffDrive>\\r\\n···
    <left_joint>left_front_wheel_joint</left_joint>\\r\\n·
    </plugin>\\r\\n</gazebo>"
  Main:
    key: a
    text: "<gazebo>\\r\\n··<plugin
      filename=gz-sim-diff-drive-system name=DiffDrive>\\r\\n···
      <left_joint>left_front_wheel_joint</left_joint>\\r\\n·
      </plugin>\\r\\n</gazebo>"
  Entries:
  - key: mine
    text: "<gazebo>\\r\\n··<plugin filename=gz-sim-user-commands-system
      name=UserCommands>\\r\\n···
      <x/>\\r\\n··</plugin>\\r\\n</gazebo>"
  Other: "<gazebo reference=box>\\r\\n··<sensor name=camera type=camera>\\r\\n···
    <camera>\\r\\n······<horizontal_fov>1.547</horizontal_fov>\\r\\n</gazebo>"
""".replace("·", " ")


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    root = tmp_path / "p"
    (root / "Assets" / "Scripts").mkdir()
    (root / "Assets" / "Scripts" / "Notes.cs").write_text(NOTES)
    (root / "Assets" / "Scripts" / "Notes.cs.meta").write_text(
        f"fileFormatVersion: 2\nguid: {GUID}\n"
    )
    return root


def _apply(project: Path, count: int, *extra: str):
    (project / "robot.yaml").write_text(MANIFEST.replace("COUNT", str(count)))
    return run_cli("apply", str(project / "robot.yaml"), *extra)


def _saved_by_users_unity(scene: Path) -> str:
    """The scene with the component's strings as the user's Unity folded them."""
    text = scene.read_text(encoding="utf-8")
    start = text.index("  Lines:\n", text.index(GUID))
    end = text.index("  Count: ", start)
    text = text[:start] + USERS + text[end:]
    scene.write_text(text, encoding="utf-8")
    return text


def test_strings_unity_folded_survive_apply_untouched(project):
    assert _apply(project, 1).code == 0
    scene = project / "Assets" / "Scenes" / "Main.unity"
    users = _saved_by_users_unity(scene)
    assert _apply(project, 1, "--check").code == 0  # the same values: no drift
    run = _apply(project, 2)
    assert run.code == 0, run.err
    assert scene.read_text(encoding="utf-8") == users.replace("  Count: 1\n", "  Count: 2\n")
    again = _apply(project, 2)
    assert "wrote 0 files" in again.out, again.out
