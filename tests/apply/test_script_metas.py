"""A project script the manifest names before Unity has imported it gets a ``.meta`` with a
deterministic GUID, so the scene can refer to it at once."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import run_cli

from unityscaffold.unity.meta import guid_for, monoscript_meta
from unityscaffold.unity.project import project_salt

HEADER = """\
version: 1
ros: 2
project: .
scene: Assets/Scenes/Main.unity
connector: {gameobject: RosConnector}
"""
SCRIPT = """\
using UnityEngine;

public class Blinker : MonoBehaviour
{
    public float Period = 1f;
}
"""


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    root = tmp_path / "p"
    (root / "Assets" / "Scripts").mkdir(parents=True, exist_ok=True)
    (root / "Assets" / "Scripts" / "Blinker.cs").write_text(SCRIPT)
    return root


@pytest.mark.parametrize("script", ["Blinker", "Assets/Scripts/Blinker.cs"])
def test_a_script_without_meta_gets_one_and_is_attached(project: Path, script: str) -> None:
    manifest = project / "robot.yaml"
    manifest.write_text(
        HEADER + f"components:\n  - {{script: {script}, gameobject: Lamp, create: true}}\n"
    )
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    guid = guid_for(project_salt(project), "Assets/Scripts/Blinker.cs")
    meta = project / "Assets" / "Scripts" / "Blinker.cs.meta"
    assert meta.read_text() == monoscript_meta(guid)
    scene = (project / "Assets" / "Scenes" / "Main.unity").read_text()
    assert f"m_Script: {{fileID: 11500000, guid: {guid}, type: 3}}" in scene
    assert run_cli("apply", "--check", str(manifest)).code == 0
    again = run_cli("apply", str(manifest))
    assert again.out.endswith("wrote 0 files, removed 0\n")


def test_an_existing_meta_is_kept(project: Path) -> None:
    meta = project / "Assets" / "Scripts" / "Blinker.cs.meta"
    meta.write_text("fileFormatVersion: 2\nguid: 0123456789abcdef0123456789abcdef\n")
    manifest = project / "robot.yaml"
    manifest.write_text(
        HEADER + "components:\n  - {script: Blinker, gameobject: Lamp, create: true}\n"
    )
    assert run_cli("apply", str(manifest)).code == 0
    assert meta.read_text() == "fileFormatVersion: 2\nguid: 0123456789abcdef0123456789abcdef\n"
    scene = (project / "Assets" / "Scenes" / "Main.unity").read_text()
    assert "guid: 0123456789abcdef0123456789abcdef, type: 3" in scene
