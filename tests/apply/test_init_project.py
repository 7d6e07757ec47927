"""``scaffold init`` writes a Unity project that opens clean: its scene and scene folder have
``.meta`` files (with GUIDs derived from the project, not random ones Unity would make on first
open), the build settings list the scene, the ``.gitignore`` covers what Unity, IDEs and crashes
leave behind, and for ROS 2 every build target group gets the ``ROS2`` define."""

from __future__ import annotations

import json
import re
from pathlib import Path

import yaml
from helpers import run_cli

from unityscaffold.unity.meta import guid_for, read_meta_guid
from unityscaffold.unity.project import project_salt


def _init(tmp_path: Path, ros: str = "2", name: str = "robot") -> Path:
    project = tmp_path / name
    run = run_cli("init", str(project), "--ros", ros)
    assert run.code == 0, run.err
    return project


def _unity_yaml(path: Path) -> dict[str, object]:
    """One-document Unity YAML without its ``%TAG``/``--- !u!`` header lines."""
    body = [line for line in path.read_text().splitlines() if not line.startswith(("%", "---"))]
    return yaml.safe_load("\n".join(body))


def test_the_scene_and_its_folder_have_metas_with_project_derived_guids(tmp_path):
    project = _init(tmp_path)
    salt = project_salt(project)
    scene_meta = project / "Assets/Scenes/Main.unity.meta"
    folder_meta = project / "Assets/Scenes.meta"
    assert read_meta_guid(scene_meta) == guid_for(salt, "Assets/Scenes/Main.unity")
    assert read_meta_guid(folder_meta) == guid_for(salt, "Assets/Scenes")
    assert "DefaultImporter:" in scene_meta.read_text()
    assert "folderAsset: yes" in folder_meta.read_text()
    other = _init(tmp_path, name="rover")  # another project name: other GUIDs
    assert read_meta_guid(other / "Assets/Scenes/Main.unity.meta") != read_meta_guid(scene_meta)


def test_the_build_settings_list_the_scene_by_path_and_guid(tmp_path):
    project = _init(tmp_path)
    settings = _unity_yaml(project / "ProjectSettings/EditorBuildSettings.asset")
    [scene] = settings["EditorBuildSettings"]["m_Scenes"]
    assert scene == {
        "enabled": 1,
        "path": "Assets/Scenes/Main.unity",
        "guid": read_meta_guid(project / "Assets/Scenes/Main.unity.meta"),
    }


def test_the_gitignore_covers_unity_ide_and_crash_files(tmp_path):
    lines = set((_init(tmp_path) / ".gitignore").read_text().splitlines())
    for pattern in (
        "/[Ll]ibrary/", "/[Tt]emp/", "/[Ll]ogs/", "/[Uu]ser[Ss]ettings/", "/[Bb]uild/",
        "/[Bb]uilds/", "/[Mm]emoryCaptures/", "/[Rr]ecordings/", ".utmp/", ".vs/", ".idea/",
        "*.user", "*.suo", "*.csproj", "*.sln", "*.log", "mono_crash.*",
    ):  # fmt: skip
        assert pattern in lines, pattern


def test_a_ros2_project_gets_the_define_in_every_build_target_group(tmp_path):
    project = _init(tmp_path, "2")
    applied = run_cli("apply", str(project / "robot.yaml"))
    assert applied.code == 0, applied.out + applied.err
    text = (project / "ProjectSettings/ProjectSettings.asset").read_text()
    for group in ("Standalone", "Android", "iPhone", "WebGL", "Windows Store Apps", "Server"):
        assert re.search(rf"^    {group}: ROS2$", text, re.M), group
    again = run_cli("apply", "--check", str(project / "robot.yaml"))
    assert again.code == 0, again.out


def test_init_force_refuses_to_write_through_a_linked_assets_folder(tmp_path):
    # apply refuses writes that resolve outside the project; init --force follows the same rule
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    project = tmp_path / "proj"
    project.mkdir()
    (project / "Assets").symlink_to(outside, target_is_directory=True)
    run = run_cli("init", str(project), "--force")
    assert run.code == 2, run.out + run.err
    assert "it resolves to" in run.err and f"outside the Unity project {project}" in run.err
    assert "Traceback" not in run.err
    assert list(outside.iterdir()) == []
    assert sorted(p.name for p in project.iterdir()) == ["Assets"]


def test_init_force_into_a_project_pins_rossharp_and_adds_no_scene(tmp_path):
    project = tmp_path / "existing"
    (project / "Assets" / "Levels").mkdir(parents=True)
    (project / "Assets" / "Levels" / "Lab.unity").write_text("%YAML 1.1\n")
    (project / "Packages").mkdir()
    packages = project / "Packages" / "manifest.json"
    packages.write_text('{\n  "dependencies": {\n    "com.unity.ugui": "1.0.0"\n  }\n}\n')
    run = run_cli("init", str(project), "--force")
    assert run.code == 0, run.err
    deps = json.loads(packages.read_text())["dependencies"]
    assert list(deps) == ["com.siemens.ros-sharp", "com.unity.ugui"]
    assert deps["com.siemens.ros-sharp"].endswith(".git?path=/com.siemens.ros-sharp#2.2.1")
    assert [p.name for p in project.rglob("*.unity")] == ["Lab.unity"]
    assert "scene: Assets/Levels/Lab.unity" in (project / "robot.yaml").read_text()
    # a project that already names ROS# keeps its choice
    deps["com.siemens.ros-sharp"] = "file:../ros-sharp"
    packages.write_text(json.dumps({"dependencies": deps}, indent=2) + "\n")
    before = packages.read_text()
    assert run_cli("init", str(project), "--force").code == 0
    assert packages.read_text() == before
