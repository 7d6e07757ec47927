"""Generated C# compiles with Mono's mcs against the ROS# API stub, without warnings."""

from __future__ import annotations

from pathlib import Path

from codegen_helpers import generate_data, write_tree
from csharp import Compiled, compile_cs

from unityscaffold.codegen import GeneratedCode
from unityscaffold.interfaces.model import Dialect


def test_all_debian_ros1_types_compile_without_ros2_define(
    compiled_all_ros1: tuple[GeneratedCode, Compiled],
) -> None:
    code, compiled = compiled_all_ros1
    compiled.assert_clean()
    assert len(code.files) > 200
    assert {s.ros_type for s in code.skipped} == {"std_msgs/Time", "std_msgs/Duration"}


def test_all_jazzy_interfaces_compile_with_ros2_define(
    compiled_all_ros2: tuple[GeneratedCode, Compiled],
) -> None:
    code, compiled = compiled_all_ros2
    compiled.assert_clean()
    paths = {f.path for f in code.files}
    assert {
        "Test/msg/Arrays.cs",
        "Test/action/FibonacciActionGoal.cs",
        "BuiltinInterfaces/msg/Time.cs",
        "Std/srv/SetBoolRequest.cs",
    } <= paths
    assert not code.skipped


def _custom(
    mcs: str, tmp: Path, dialect: Dialect, runtime: Compiled, **options: object
) -> Compiled:
    names = ["scaffold_test_msgs/Kitchen", "scaffold_test_msgs/Cook", "scaffold_test_msgs/Lookup"]
    code = generate_data(dialect, names, **options)
    assert all(f.path.startswith("ScaffoldTest/") for f in code.files)
    sources = write_tree(code, tmp / "src")
    return compile_cs(
        mcs,
        sources,
        tmp / "Custom.dll",
        ros2=dialect is Dialect.ROS2,
        references=(runtime.assembly,),
    )


def test_custom_ros1_package_compiles_against_shipped_classes_in_another_assembly(
    mcs: str, tmp_path: Path, runtime_ros1: Compiled
) -> None:
    _custom(mcs, tmp_path, Dialect.ROS1, runtime_ros1).assert_clean()


def test_custom_ros2_package_compiles_against_shipped_classes_in_another_assembly(
    mcs: str, tmp_path: Path, runtime_ros2: Compiled
) -> None:
    _custom(mcs, tmp_path, Dialect.ROS2, runtime_ros2).assert_clean()


def test_another_root_namespace_generates_everything_and_compiles_beside_rossharp(
    mcs: str, tmp_path: Path, runtime_ros1: Compiled
) -> None:
    names = ["scaffold_test_msgs/Kitchen", "scaffold_test_msgs/Cook"]
    code = generate_data(Dialect.ROS1, names, namespace="MyRobot.Messages")
    assert "Geometry/msg/Pose.cs" in {f.path for f in code.files}
    assert not code.skipped
    sources = write_tree(code, tmp_path / "src")
    compile_cs(
        mcs, sources, tmp_path / "Ns.dll", ros2=False, references=(runtime_ros1.assembly,)
    ).assert_clean()


def test_the_compiler_check_can_fail(mcs: str, tmp_path: Path) -> None:
    broken = tmp_path / "Broken.cs"
    broken.write_text("namespace X { public class Y : Message { } }\n")
    compiled = compile_cs(mcs, [broken], tmp_path / "Broken.dll", ros2=False)
    assert compiled.returncode != 0
    assert "CS0246" in compiled.output
