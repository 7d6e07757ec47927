"""``scaffold init``'s ``Packages/manifest.json`` lists what a Unity 2022.3 project made by
Unity Hub lists (uGUI and Unity's default module set), and so every Unity module whose API
ROS# 2.2.1's Runtime calls: ROS# declares no dependencies of its own, so a module left out
(``ImageConversion`` for ``Texture2D.EncodeToJPG``, say) makes ROS# fail to compile.

The Unity APIs are derived from ROS#'s sources: every identifier its Runtime uses is looked up
in ``UNITY_MODULE_APIS``, the public types (and extension methods) of Unity's optional modules
as Unity's scripting reference assigns them. Types of UnityEngine.CoreModule (GameObject,
Transform, Texture2D, ...) and of the always-present input and text modules need no package.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

from helpers import require, run_cli

REPO = Path(__file__).resolve().parents[2]
VENDORED = REPO.parent / "shared" / "vendor" / "ros-sharp" / "2.2.1" / "com.siemens.ros-sharp"

#: Unity 2022.3's default module set: the com.unity.modules.* a new project from Unity Hub lists.
DEFAULT_MODULES = {
    f"com.unity.modules.{name}"
    for name in (
        "ai androidjni animation assetbundle audio cloth director imageconversion imgui "
        "jsonserialize particlesystem physics physics2d screencapture terrain terrainphysics "
        "tilemap ui uielements umbra unityanalytics unitywebrequest unitywebrequestassetbundle "
        "unitywebrequestaudio unitywebrequesttexture unitywebrequestwww vehicles video vr wind xr"
    ).split()
}

#: Module package -> the names of its API (types, and the extension methods it adds to core
#: types, such as ImageConversion's on Texture2D).
UNITY_MODULE_APIS: dict[str, set[str]] = {
    "com.unity.modules.imageconversion": {
        "ImageConversion",
        "EncodeToJPG",
        "EncodeToPNG",
        "EncodeToEXR",
        "EncodeToTGA",
        "LoadImage",
    },
    "com.unity.modules.physics": {
        "Rigidbody",
        "Collider",
        "BoxCollider",
        "SphereCollider",
        "CapsuleCollider",
        "MeshCollider",
        "Physics",
        "RaycastHit",
        "Joint",
        "HingeJoint",
        "ConfigurableJoint",
        "FixedJoint",
        "CharacterJoint",
        "SpringJoint",
        "JointDrive",
        "JointLimits",
        "SoftJointLimit",
        "SoftJointLimitSpring",
        "JointSpring",
        "JointMotor",
        "ConfigurableJointMotion",
        "RigidbodyConstraints",
        "RigidbodyInterpolation",
        "CollisionDetectionMode",
        "ForceMode",
        "PhysicMaterial",
        "Collision",
        "ContactPoint",
        "ArticulationBody",
        "ArticulationDrive",
        "ArticulationJointType",
        "JointProjectionMode",
        "RotationDriveMode",
        "CharacterController",
        "QueryTriggerInteraction",
    },
    "com.unity.modules.physics2d": {"Rigidbody2D", "Collider2D", "Physics2D", "BoxCollider2D"},
    "com.unity.modules.jsonserialize": {"JsonUtility"},
    "com.unity.modules.unitywebrequest": {"UnityWebRequest", "DownloadHandler", "UploadHandler"},
    "com.unity.modules.unitywebrequesttexture": {
        "UnityWebRequestTexture",
        "DownloadHandlerTexture",
    },
    "com.unity.modules.audio": {"AudioSource", "AudioClip", "AudioListener", "Microphone"},
    "com.unity.modules.animation": {"Animator", "Animation", "AnimationClip", "Avatar"},
    "com.unity.modules.terrain": {"Terrain", "TerrainData"},
    "com.unity.modules.terrainphysics": {"TerrainCollider"},
    "com.unity.modules.imgui": {"GUI", "GUILayout", "GUIStyle", "GUIContent", "GUISkin", "Event"},
    "com.unity.modules.ui": {"Canvas", "CanvasGroup", "CanvasRenderer"},
    "com.unity.modules.particlesystem": {"ParticleSystem"},
    "com.unity.modules.vehicles": {"WheelCollider", "WheelHit"},
    "com.unity.modules.video": {"VideoPlayer", "VideoClip"},
    "com.unity.modules.screencapture": {"ScreenCapture"},
    "com.unity.modules.uielements": {"VisualElement", "UIDocument"},
    "com.unity.modules.tilemap": {"Tilemap"},
    "com.unity.modules.cloth": {"Cloth"},
    "com.unity.modules.ai": {"NavMesh", "NavMeshAgent"},
    "com.unity.modules.xr": {"XRSettings", "XRDevice", "InputTracking"},
    "com.unity.modules.director": {"PlayableDirector"},
    "com.unity.modules.wind": {"WindZone"},
    "com.unity.modules.assetbundle": {"AssetBundle"},
    "com.unity.modules.androidjni": {"AndroidJavaObject", "AndroidJavaClass", "AndroidJNI"},
}

_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
_IDENTIFIER = re.compile(r"\b[A-Za-z_][A-Za-z0-9_]*\b")


def _rossharp() -> Path:
    path = Path(os.environ.get("UNITYSCAFFOLD_ROSSHARP", VENDORED))
    require(
        (path / "Runtime").is_dir(),
        f"ROS# 2.2.1's com.siemens.ros-sharp (set UNITYSCAFFOLD_ROSSHARP; default {VENDORED})",
    )
    return path


def _modules_used(runtime: Path) -> dict[str, set[str]]:
    """Module package -> the names of its API that ROS#'s Runtime sources use."""
    names: set[str] = set()
    for source in runtime.rglob("*.cs"):
        text = _COMMENT.sub("", source.read_text(encoding="utf-8-sig", errors="replace"))
        if "UnityEngine" in text:
            names.update(_IDENTIFIER.findall(text))
    return {module: api & names for module, api in UNITY_MODULE_APIS.items() if api & names}


def _init_dependencies(tmp_path: Path) -> dict[str, str]:
    run = run_cli("init", str(tmp_path / "robot"))
    assert run.code == 0, run.err
    manifest = json.loads((tmp_path / "robot" / "Packages" / "manifest.json").read_text())
    return manifest["dependencies"]


def test_init_lists_every_module_rossharp_runtime_uses(tmp_path):
    used = _modules_used(_rossharp() / "Runtime")
    # The two the issue found by reading ROS#, so the derivation is known to see them.
    assert "EncodeToJPG" in used["com.unity.modules.imageconversion"]
    assert "LoadImage" in used["com.unity.modules.imageconversion"]
    assert "ConfigurableJoint" in used["com.unity.modules.physics"]
    listed = _init_dependencies(tmp_path)
    missing = {module: sorted(api) for module, api in used.items() if module not in listed}
    assert not missing, f"ROS# 2.2.1's Runtime uses modules init does not list: {missing}"


def test_init_lists_unity_2022_3s_default_modules_ugui_and_rossharp(tmp_path):
    listed = _init_dependencies(tmp_path)
    assert {name for name in listed if name.startswith("com.unity.modules.")} == DEFAULT_MODULES
    assert listed["com.unity.ugui"] == "1.0.0"
    assert listed["com.siemens.ros-sharp"].endswith("#2.2.1")
    assert set(UNITY_MODULE_APIS) <= DEFAULT_MODULES  # the table names real modules


def test_the_sample_lists_the_same_packages_as_init(tmp_path):
    sample = REPO / "sample_project" / "unity" / "Packages" / "manifest.json"
    assert json.loads(sample.read_text())["dependencies"] == _init_dependencies(tmp_path)
