"""The byte check shared by both ROS versions: reference cases in, the connector's real
serializer run over them in one Mono process, verdicts out, and which failures the shipped
classes' warnings excuse."""

from __future__ import annotations

import subprocess
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from csharp import compile_cs

from tests.codegen.rostcp.tcp_helpers import HERE, compile_generated, compile_runtime, write_files
from unityscaffold.codegen import GeneratedCode
from unityscaffold.interfaces.model import MessageSpec
from unityscaffold.interfaces.registry import Registry

WIRE_CHECK = HERE / "csharp" / "WireCheck.cs"


@dataclass(frozen=True)
class Case:
    """One reference instance: its C# class, bytes, padding mask, payload end and values."""

    ros_type: str
    label: str
    cs_class: str
    reference: str
    values: str
    mask: str = "-"
    end: int = -1

    def line(self) -> str:
        end = self.end if self.end >= 0 else len(self.reference) // 2
        key = f"{self.ros_type} {self.label}"
        return f"{self.cs_class}\t{key}\t{self.reference}\t{self.mask}\t{end}\t{self.values}\n"


@dataclass(frozen=True)
class Verdict:
    ros_type: str
    label: str
    problem: str | None
    ours: str


def build_checker(
    mcs: str, mono_package: Path, code: GeneratedCode, out: Path, *, ros2: bool
) -> Path:
    """WireCheck.exe beside the connector runtime and the generated classes (compiled with
    warnings as errors)."""
    references = compile_runtime(mcs, mono_package, out, ros2=ros2)
    generated = compile_generated(
        mcs, write_files(code, out / "src"), references, out / "Generated.dll", ros2=ros2
    )
    generated.assert_clean()
    exe = compile_cs(
        mcs,
        [WIRE_CHECK],
        out / "WireCheck.exe",
        ros2=ros2,
        references=(*references, generated.assembly),
        extra=("-target:exe",),
    )
    exe.assert_clean()
    return exe.assembly


def run_checker(mono: str, exe: Path, cases: Iterable[Case], work: Path) -> list[Verdict]:
    given, results = work / "cases.tsv", work / "verdicts.tsv"
    given.write_text("".join(c.line() for c in cases), encoding="utf-8")
    assemblies = [str(exe.with_name(n)) for n in ("RosTcpMessages.dll", "Generated.dll")]
    command = [mono, str(exe), str(given), str(results), *assemblies]
    subprocess.run(command, check=True, timeout=1800)
    verdicts = []
    for line in results.read_text(encoding="utf-8").splitlines():
        key, verdict, ours = line.split("\t")
        ros_type, _, label = key.partition(" ")
        problem = None if verdict == "OK" else verdict.removeprefix("FAIL ")
        verdicts.append(Verdict(ros_type, label, problem, ours))
    return verdicts


def excused(verdict: Verdict, spec: MessageSpec, registry: Registry, code: GeneratedCode) -> bool:
    """Whether a failure is one a shipped class's warning announced: any case of a type that
    holds a class garbled on the wire; only the default instance where a shipped class
    merely starts with other values."""
    warnings = {
        s.cs_class.full_name: s.warning
        for s in code.skipped
        if s.warning and "never registers" not in s.warning  # says nothing of the bytes
    }
    held = {m.full_name for m in registry.closure([spec])} | {spec.full_name}
    classes = {code.message_class(name).full_name for name in held}
    found = [warnings[name] for name in classes if name in warnings]
    if any("starts with" not in w for w in found):
        return True
    problem = verdict.problem or ""
    return bool(found) and verdict.label == "default" and problem.startswith("DEFAULT")
