"""Compiling C# with Mono's mcs in tests, the same flags everywhere.

mcs 6.8 accepts C# up to 7.2: generated code must stay within what Unity 2019+ compiles, and
compiles with warnings as errors (XML doc comments are checked too).
"""

from __future__ import annotations

import subprocess
from dataclasses import dataclass
from pathlib import Path

from unityscaffold.apply.run import load_registry
from unityscaffold.codegen import Options, generate
from unityscaffold.manifest import load_manifest

REPO = Path(__file__).resolve().parent.parent
ROSSHARP_STUB = REPO / "tests" / "codegen" / "stubs" / "RosSharpStub.cs"
UNITY_STUBS = (
    REPO / "tests" / "apply" / "stubs" / "UnityEngine.cs",
    REPO / "tests" / "apply" / "stubs" / "RosSharpRuntime.cs",
)
MCS_FLAGS = (
    "-langversion:7.2",
    "-target:library",
    "-warnaserror+",
    "-warn:4",
    "-nowarn:1591",
    "-nologo",
)


@dataclass(frozen=True)
class Compiled:
    returncode: int
    output: str
    assembly: Path

    def assert_clean(self) -> None:
        assert self.returncode == 0, self.output
        assert "warning" not in self.output, self.output


def compile_cs(
    mcs: str,
    sources: list[Path],
    out: Path,
    *,
    ros2: bool,
    references: tuple[Path, ...] = (),
    defines: tuple[str, ...] = (),
    extra: tuple[str, ...] = (),
    strict: bool = True,
) -> Compiled:
    """``extra`` flags come after the common ones (a ``-nowarn`` for third-party sources);
    ``strict=False`` drops warnings-as-errors, for third-party sources only."""
    flags = MCS_FLAGS if strict else tuple(f for f in MCS_FLAGS if f != "-warnaserror+")
    args = [mcs, *flags, *extra, f"-out:{out}", f"-doc:{out.with_suffix('.xml')}"]
    if ros2:
        args.append("-define:ROS2")
    args += [f"-define:{name}" for name in defines]
    args += [f"-r:{r}" for r in references]
    args += [str(s) for s in sources]
    done = subprocess.run(args, capture_output=True, text=True, check=False, timeout=300)
    return Compiled(done.returncode, done.stdout + done.stderr, out)


def _unity_engine(mcs: str, out: Path, defines: tuple[str, ...] = ()) -> Path:
    compiled = compile_cs(
        mcs, [UNITY_STUBS[0]], out / "UnityEngine.dll", ros2=False, defines=defines
    )
    compiled.assert_clean()
    return compiled.assembly


def _runtime_assembly(mcs: str, manifest_path: Path, out: Path, engine: Path) -> Path:
    """A stand-in for ROS#'s runtime assembly: the stubs plus the shipped classes the manifest's
    types use, generated with include_shipped (ROS# ships them precompiled)."""
    manifest = load_manifest(manifest_path)
    registry = load_registry(manifest, use_environment=False)
    items = (*manifest.topics, *manifest.services, *manifest.actions)
    roots = [registry.get(item.type) for item in items]
    # ROS#'s action base classes use the goal status classes it ships (and the ROS 1 action
    # scripts its GoalStatusArray).
    status_types = (
        ("action_msgs/msg/GoalInfo", "action_msgs/msg/GoalStatus")
        if manifest.ros == 2
        else tuple(f"actionlib_msgs/{name}" for name in ("GoalID", "GoalStatus", "GoalStatusArray"))
    )
    runtime_roots = roots + [registry.get(name) for name in status_types]
    everything = generate(registry, runtime_roots, Options(manifest.ros, include_shipped=True))
    ours = generate(registry, roots, Options(manifest.ros))
    generated = {f.path for f in ours.files}
    sources = [ROSSHARP_STUB, UNITY_STUBS[1]]
    for file in everything.files:
        if file.path not in generated:
            path = out / "shipped" / file.path
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(file.text, encoding="utf-8")
            sources.append(path)
    compiled = compile_cs(
        mcs, sources, out / "RosSharp.dll", ros2=manifest.ros == 2, references=(engine,)
    )
    compiled.assert_clean()
    return compiled.assembly


def compile_applied_project(
    mcs: str, manifest_path: Path, out: Path, *, ros2: bool, defines: tuple[str, ...] = ()
) -> None:
    """Compile as Unity would: UnityEngine, ROS#'s runtime, then the project's scripts.

    ``defines`` are Unity's version defines, such as ``UNITY_2023_1_OR_NEWER``."""
    out.mkdir(parents=True, exist_ok=True)
    engine = _unity_engine(mcs, out, defines)
    runtime = _runtime_assembly(mcs, manifest_path, out, engine)
    project = load_manifest(manifest_path).output_dir
    sources = sorted(project.rglob("*.cs"))
    assert any(p.name.endswith(".User.cs") for p in sources)
    compiled = compile_cs(
        mcs,
        sources,
        out / "Assembly-CSharp.dll",
        ros2=ros2,
        references=(engine, runtime),
        defines=defines,
    )
    compiled.assert_clean()
