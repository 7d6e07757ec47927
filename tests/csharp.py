"""Compiling C# with Mono's mcs in tests, the same flags everywhere.

mcs 6.8 accepts C# up to 7.2: generated code must stay within what Unity 2019+ compiles, and
compiles with warnings as errors (XML doc comments are checked too).
"""

from __future__ import annotations

import subprocess
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
ROSSHARP_STUB = REPO / "tests" / "codegen" / "stubs" / "RosSharpStub.cs"
UNITY_STUBS = (REPO / "tests" / "apply" / "stubs" / "UnityEngine.cs",
               REPO / "tests" / "apply" / "stubs" / "RosSharpRuntime.cs")
MCS_FLAGS = ("-langversion:7.2", "-target:library", "-warnaserror+", "-warn:4", "-nowarn:1591",
             "-nologo")


@dataclass(frozen=True)
class Compiled:
    returncode: int
    output: str
    assembly: Path

    def assert_clean(self) -> None:
        assert self.returncode == 0, self.output
        assert "warning" not in self.output, self.output


def compile_cs(mcs: str, sources: list[Path], out: Path, *, ros2: bool,
               references: tuple[Path, ...] = ()) -> Compiled:
    args = [mcs, *MCS_FLAGS, f"-out:{out}", f"-doc:{out.with_suffix('.xml')}"]
    if ros2:
        args.append("-define:ROS2")
    args += [f"-r:{r}" for r in references]
    args += [str(s) for s in sources]
    done = subprocess.run(args, capture_output=True, text=True, check=False, timeout=300)
    return Compiled(done.returncode, done.stdout + done.stderr, out)
