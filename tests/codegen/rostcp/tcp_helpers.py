"""Helpers of the ROS-TCP-Connector generator's tests: the vendored connector package, its
message runtime compiled with mcs, and generated classes compiled against it."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from csharp import Compiled, compile_cs
from helpers import require

from tests.runtime.bridge import vendor_folder
from unityscaffold.codegen import GeneratedCode

HERE = Path(__file__).resolve().parent
UNITY_STUB = HERE / "stubs" / "UnityEngine.cs"
PACKAGE_VARIABLE = "UNITYSCAFFOLD_ROSTCP"
PACKAGE_NAME = "ros-tcp-connector/0.7.0/com.unity.robotics.ros-tcp-connector"
# The connector's own sources, compiled as they are: under ROS 1 they have unused private
# fields (CS0414), which is theirs to fix, not a warning of our classes.
_THEIRS_NOWARN = ("-nowarn:414",)


def connector_package() -> Path:
    folder = vendor_folder(PACKAGE_VARIABLE, PACKAGE_NAME)
    require(folder, f"ROS-TCP-Connector 0.7.0's package folder ({PACKAGE_VARIABLE})")
    assert folder
    return folder


def runtime_sources(package: Path) -> list[Path]:
    """``Runtime/MessageGeneration`` and ``Runtime/Messages`` (shipped classes included)."""
    runtime = package / "Runtime"
    folders = (runtime / "MessageGeneration", runtime / "Messages")
    return sorted(p for folder in folders for p in folder.rglob("*.cs"))


def write_files(code: GeneratedCode, out: Path) -> list[Path]:
    paths = []
    for file in code.files:
        path = out / file.path
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(file.text, encoding="utf-8", newline="\n")
        paths.append(path)
    return paths


def compile_runtime(mcs: str, package: Path, out: Path, *, ros2: bool) -> tuple[Path, Path]:
    """UnityEngine.dll (the stand-in) and the connector's message runtime, built in ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    engine = compile_cs(mcs, [UNITY_STUB], out / "UnityEngine.dll", ros2=False)
    engine.assert_clean()
    runtime = compile_cs(
        mcs,
        runtime_sources(package),
        out / "RosTcpMessages.dll",
        ros2=ros2,
        references=(engine.assembly,),
        extra=_THEIRS_NOWARN,
    )
    runtime.assert_clean()
    return engine.assembly, runtime.assembly


def compile_generated(
    mcs: str, sources: Iterable[Path], references: tuple[Path, ...], out: Path, *, ros2: bool
) -> Compiled:
    """Generated classes (and any test program) against the runtime, warnings as errors."""
    return compile_cs(mcs, list(sources), out, ros2=ros2, references=references)


def ros2_python() -> Path:
    """The Python of the ROS 2 Jazzy stack's venv (rclpy and every interface package it
    carries), built by ``scripts/ros2_stack.py`` when this machine has none."""
    from tests.runtime.ros2 import stack_module

    module = stack_module()
    try:
        root = module.ensure()
    except module.StackError as error:
        require(False, f"ROS 2 Jazzy ({error})")
    python: Path = module.venv_python(root)
    return python
