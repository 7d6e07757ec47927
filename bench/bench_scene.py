"""Benchmark of the scene patcher against unityparser, on synthetic scenes of 1, 10 and 100 MB.

Synthetic scenes replicate the GameObjects of a real 2022.3 ROS# scene (tests/data/unity) with
fresh fileIDs and names, keeping Unity's order (sorted by fileID, SceneRoots last). Each case
runs in its own process so its peak memory (ru_maxrss) is its own.

    python3 bench/bench_scene.py            # 1, 10, 100 MB; unityparser on 1 and 10 MB
    python3 bench/bench_scene.py --sizes 1 10 --unityparser-sizes 1
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SOURCE = ROOT / "tests" / "data" / "unity" / "ros-sharp" / "ROSVersionSwitch.unity"
sys.path.insert(0, str(ROOT))

from unityscaffold.unity.scene import SceneDocument  # noqa: E402
from unityscaffold.unity.values import AssetRef, Enum, ObjectRef, ScriptRef  # noqa: E402

HEADER_RE = re.compile(r"^--- !u!(\d+) &(-?\d+)", re.M)
REF_RE = re.compile(r"\{fileID: (-?\d+)\}")
SCRIPTS = [ScriptRef(f"{i:x}" * 32) for i in range(1, 6)]


def build_scene(megabytes: float, path: Path) -> int:
    """Write a synthetic scene of about ``megabytes``; return how many copies it holds."""
    text = SOURCE.read_text(encoding="utf-8")
    starts = [m.start() for m in HEADER_RE.finditer(text)]
    docs = [text[a:b] for a, b in zip(starts, [*starts[1:], len(text)], strict=True)]
    prolog = text[: starts[0]]
    settings = [d for d in docs if int(HEADER_RE.match(d).group(2)) in (1, 2, 3, 4)]  # type: ignore[union-attr]
    movable = [d for d in docs if d not in settings and "SceneRoots:" not in d]
    old_ids = [int(HEADER_RE.match(d).group(2)) for d in movable]  # type: ignore[union-attr]
    roots = [int(m) for m in re.findall(r"- \{fileID: (\d+)\}", docs[-1])]
    unit = sum(len(d) for d in movable)
    copies = max(1, int(megabytes * 1_000_000 / unit))
    first = {old: 1_000_000_000 + j for j, old in enumerate(old_ids)}
    with path.open("w", encoding="utf-8", newline="") as out:
        # settings objects point at the first copy (RenderSettings.m_Sun is the light)
        out.write(
            prolog
            + REF_RE.sub(
                lambda m: f"{{fileID: {first.get(int(m.group(1)), int(m.group(1)))}}}",
                "".join(settings),
            )
        )
        root_ids: list[int] = []
        for k in range(copies):
            mapping = {old: 1_000_000_000 + k * 100 + j for j, old in enumerate(old_ids)}
            root_ids += [mapping[r] for r in roots]
            for doc in movable:
                doc = HEADER_RE.sub(
                    lambda m, mp=mapping: f"--- !u!{m.group(1)} &{mp[int(m.group(2))]}", doc
                )
                doc = REF_RE.sub(
                    lambda m, mp=mapping: f"{{fileID: {mp.get(int(m.group(1)), int(m.group(1)))}}}",
                    doc,
                )
                out.write(re.sub(r"^  m_Name: (\S.*)$", rf"  m_Name: \1 {k}", doc, flags=re.M))
        out.write(
            "--- !u!1660057539 &9223372036854775807\nSceneRoots:\n  m_ObjectHideFlags: 0\n"
            "  m_Roots:\n" + "".join(f"  - {{fileID: {r}}}\n" for r in root_ids)
        )
    return copies


def patch(path: Path, target: str) -> tuple[float, float, bool]:
    """Load, attach 5 components with fields, validate, write if changed (wall s, CPU s)."""
    start, cpu = time.perf_counter(), time.process_time()
    scene = SceneDocument.load(path)
    go = scene.ensure_gameobject(target)
    previous = None
    for index, script in enumerate(SCRIPTS):
        fields = [
            ("Topic", f"/topic{index}"),
            ("Rate", 0.1 * (index + 1)),
            ("Enabled", True),
            ("Mode", Enum(index)),
            ("Connector", ObjectRef(go.file_id)),
            ("Material", AssetRef(2100000, "e84c5fd102288448a8e2305335f05d28", 2)),
            ("Names", ["a", "b"]),
        ]
        if previous is not None:
            fields.append(("Previous", ObjectRef(previous)))
        previous = scene.ensure_component(go, script, fields).file_id
    wrote = scene.write()
    return time.perf_counter() - start, time.process_time() - cpu, wrote


def unityparser_round_trip(path: Path) -> float:
    from unityparser import UnityDocument

    start = time.perf_counter()
    UnityDocument.load_yaml(str(path)).dump_yaml(str(path.with_suffix(".up.unity")))
    return time.perf_counter() - start


def _peak_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def child(case: str, path: Path, copies: int) -> None:
    if case == "patch":  # the first run attaches; run again on its output, it is a no-op
        seconds, cpu, wrote = patch(path, f"RosSocket {copies // 2}")
        print(f"{seconds:.3f} {cpu:.3f} {int(wrote)} {_peak_mb():.0f}")
    else:
        cpu = time.process_time()
        seconds = unityparser_round_trip(path)
        print(f"{seconds:.3f} {time.process_time() - cpu:.3f} 0 {_peak_mb():.0f}")


def run_case(case: str, path: Path, copies: int) -> tuple[float, float, bool, float]:
    """(wall s, CPU s, wrote, peak MB) of one case, run in a fresh process."""
    out = subprocess.run(
        [sys.executable, __file__, "--child", case, str(path), str(copies)],
        check=True,
        capture_output=True,
        text=True,
    ).stdout.split()
    return float(out[0]), float(out[1]), out[2] == "1", float(out[3])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", type=float, nargs="+", default=[1, 10, 100])
    parser.add_argument("--unityparser-sizes", type=float, nargs="*", default=[1, 10])
    parser.add_argument("--child", nargs=3, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        child(args.child[0], Path(args.child[1]), int(args.child[2]))
        return
    print("times are wall (CPU) seconds; the machine may be shared, so CPU is the fairer figure")
    print(
        "aims: 100 MB patched in < 3 s, 10 MB in < 0.3 s, CPU per MB flat from 1 MB, peak < 3x size"
    )
    print("load average " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    print(
        f"{'size':>8} {'docs':>7} {'patch s':>14} {'no-op s':>14} {'CPU ms/MB':>10} "
        f"{'peak MB':>8} {'x size':>6} {'unityparser s':>16} {'up peak MB':>10} {'speed-up':>9}"
    )
    with tempfile.TemporaryDirectory() as tmp:
        for size in args.sizes:
            path = Path(tmp) / f"scene_{size:g}mb.unity"
            copies = build_scene(size, path)
            megabytes = path.stat().st_size / 1e6
            docs = path.read_bytes().count(b"\n--- !u!")
            first, first_cpu, wrote, peak = run_case("patch", path, copies)
            again, again_cpu, wrote_again, peak2 = run_case("patch", path, copies)
            assert wrote and not wrote_again, "second run must not write"
            up = up_peak = ratio = "-"
            if size in args.unityparser_sizes:
                seconds, cpu, _, mem = run_case("unityparser", path, copies)
                up, up_peak = f"{seconds:.2f} ({cpu:.2f})", f"{mem:.0f}"
                ratio = f"{cpu / first_cpu:.0f}x"
            print(
                f"{megabytes:7.1f}M {docs:7d} {first:6.3f} ({first_cpu:.3f}) "
                f"{again:6.3f} ({again_cpu:.3f}) {first_cpu / megabytes * 1000:10.1f} "
                f"{max(peak, peak2):8.0f} {max(peak, peak2) / megabytes:6.1f} "
                f"{up:>16} {up_peak:>10} "
                f"{ratio:>9}",
                flush=True,
            )
            path.unlink()


if __name__ == "__main__":
    main()
