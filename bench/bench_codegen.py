"""Benchmark: C# for all Debian ROS 1 types and all Jazzy interfaces, with --include-shipped.

Each run indexes, parses, generates, compares with the output folder and writes what changed.
Cold: a fresh registry and template environment and an empty output folder; warm: the same
again in the same process (parsed files and compiled templates cached), where every file is
unchanged and nothing is written. Prints total and per-class time and files written.

Then, side by side with genpy (ROS 1's own Python generator) when it can be imported: the
msg/srv files Debian ships under /usr/share, each side from parsing to files written into an
empty folder, in alternated rounds in this one process; prints the medians and the ratio.
genpy and genmsg are pure Python; when this interpreter does not see them (Debian installs
them for /usr/bin/python3 only) their Debian folder is appended to ``sys.path``, so both
sides run in the same interpreter. genpy gets a fresh ``MsgContext`` per package (as catkin
runs it); our side a fresh ``Registry`` per round. Both keep what is compiled once per
process: genpy its imported modules, we the jinja2 environment.

Wall time includes what the file system costs to create files (on some virtual disks far more
than generating them; run with TMPDIR on a tmpfs to compare the generators alone); CPU time is
the fairer figure on a shared machine.

    python3 bench/bench_codegen.py [--repeat N] [--rounds N]
"""

from __future__ import annotations

import argparse
import importlib
import os
import shutil
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from types import ModuleType

from unityscaffold.codegen import Options, generate
from unityscaffold.codegen.layout import output_files
from unityscaffold.fileout import plan_files, write_files
from unityscaffold.interfaces.model import Dialect, InterfaceKind
from unityscaffold.interfaces.registry import Registry
from unityscaffold.interfaces.sources import SearchRoot
from unityscaffold.resources import template_environment


def _run(
    dialect: Dialect, registry: Registry | None, out: Path
) -> tuple[Registry, int, int, float, float, int]:
    start = time.perf_counter()
    if registry is None:
        registry = Registry.load(dialect)
    interfaces, problems = registry.parse_all()
    assert not problems, problems
    code = generate(registry, interfaces, Options(dialect, include_shipped=True))
    generated = time.perf_counter() - start
    written = write_files(plan_files(output_files(code, out)))
    elapsed = time.perf_counter() - start
    return registry, len(code.files), len(written), generated, elapsed, len(interfaces)


DEBIAN_SHARE = Path("/usr/share")
DEBIAN_PYTHON = Path("/usr/lib/python3/dist-packages")


def _import_genpy() -> ModuleType | None:
    try:
        return importlib.import_module("genpy.generator")
    except ImportError:
        pass
    if not (DEBIAN_PYTHON / "genpy").is_dir():
        return None
    sys.path.append(str(DEBIAN_PYTHON))  # last: every other module still comes from here
    try:
        return importlib.import_module("genpy.generator")
    except ImportError:
        return None


def _debian_packages() -> dict[str, dict[str, list[Path]]]:
    """package -> {"msg": [files], "srv": [files]} for the msg/srv files under /usr/share."""
    found: dict[str, dict[str, list[Path]]] = {}
    for package in sorted(os.listdir(DEBIAN_SHARE)):
        for kind in ("msg", "srv"):
            folder = DEBIAN_SHARE / package / kind
            if folder.is_dir():
                names = sorted(f for f in os.listdir(folder) if f.endswith("." + kind))
                found.setdefault(package, {})[kind] = [folder / f for f in names]
    return {p: k for p, k in found.items() if any(k.values())}


def _genpy_round(gen: ModuleType, packages: dict[str, dict[str, list[Path]]], out: Path) -> int:
    search = {p: [str(DEBIAN_SHARE / p / "msg")] for p, k in packages.items() if k.get("msg")}
    written = 0
    for package, kinds in packages.items():
        for kind, maker in (("msg", gen.MsgGenerator), ("srv", gen.SrvGenerator)):
            files = [str(f) for f in kinds.get(kind, [])]
            if files:
                target = out / package / kind
                code = maker().generate_messages(package, files, str(target), search)
                assert code == 0, (package, kind, code)
                written += len(os.listdir(target))
    return written


def _our_round(out: Path) -> int:
    registry = Registry(Dialect.ROS1, [SearchRoot(DEBIAN_SHARE, "Debian", recursive=False)])
    wanted = (InterfaceKind.MSG, InterfaceKind.SRV)
    roots = [registry.parse(f) for f in registry.files() if f.kind in wanted]
    code = generate(registry, roots, Options(Dialect.ROS1, include_shipped=True))
    return len(write_files(plan_files(output_files(code, out))))


def side_by_side(rounds: int) -> None:
    gen = _import_genpy()
    if gen is None:
        print("genpy: not importable (Debian's python3-genpy); side-by-side comparison skipped")
        return
    packages = _debian_packages()
    types = sum(len(files) for kinds in packages.values() for files in kinds.values())
    sides: dict[str, Callable[[Path], int]] = {
        "genpy": lambda out: _genpy_round(gen, packages, out),
        "unityscaffold": _our_round,
    }
    times: dict[str, list[float]] = {name: [] for name in sides}
    cpu: dict[str, list[float]] = {name: [] for name in sides}
    written: dict[str, int] = {}
    with tempfile.TemporaryDirectory() as tmp:
        for index in range(rounds + 1):  # round 0 warms imports and templates; not counted
            order = list(sides) if index % 2 else list(reversed(sides))
            for name in order:
                out = Path(tmp) / f"{name}{index}"
                start, start_cpu = time.perf_counter(), time.process_time()
                written[name] = sides[name](out)
                elapsed = time.perf_counter() - start
                if index:
                    times[name].append(elapsed)
                    cpu[name].append(time.process_time() - start_cpu)
                shutil.rmtree(out)
    median = {name: statistics.median(values) for name, values in times.items()}
    median_cpu = {name: statistics.median(values) for name, values in cpu.items()}
    print(
        f"side by side on the {types} msg/srv types under {DEBIAN_SHARE}, parse to files "
        f"written, median of {rounds} alternated rounds (genpy: {Path(gen.__file__).parent}):"
    )
    for name in sides:
        print(
            f"  {name:<14} {median[name] * 1000:6.1f} ms wall, {median_cpu[name] * 1000:6.1f} ms "
            f"CPU ({median[name] / types * 1000:.2f} ms/type, {written[name]} files written)"
        )
    print(
        f"  unityscaffold is {median['genpy'] / median['unityscaffold']:.2f}x genpy's speed "
        f"(CPU: {median_cpu['genpy'] / median_cpu['unityscaffold']:.2f}x; "
        "load average " + " ".join(f"{x:.2f}" for x in os.getloadavg()) + ")"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="warm runs (best is reported)")
    parser.add_argument("--rounds", type=int, default=7, help="side-by-side rounds with genpy")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "RosMessages"
        totals = {"cold": 0.0, "warm": 0.0, "cold generate": 0.0, "warm generate": 0.0}
        for dialect in (Dialect.ROS1, Dialect.ROS2):
            template_environment.cache_clear()
            registry, classes, files, cold_gen, cold, types = _run(
                dialect, None, out / dialect.name
            )
            warm_runs = [_run(dialect, registry, out / dialect.name) for _ in range(args.repeat)]
            warm = min(r[4] for r in warm_runs)
            warm_gen = min(r[3] for r in warm_runs)
            totals["cold generate"] += cold_gen
            totals["warm generate"] += warm_gen
            rewritten = max(r[2] for r in warm_runs)
            totals["cold"] += cold
            totals["warm"] += warm
            print(
                f"{dialect.label}: {types} types, {classes} classes; cold {cold * 1000:.0f} ms "
                f"({cold / types * 1000:.2f} ms/type, "
                f"{cold / classes * 1e6:.0f} us/class, {files} files written incl. .meta), "
                f"warm {warm * 1000:.0f} ms ({warm / classes * 1e6:.0f} us/class, "
                f"{rewritten} files written); generation alone: cold {cold_gen * 1000:.0f} ms, "
                f"warm {warm_gen * 1000:.0f} ms"
            )
        print(", ".join(f"{k} {v * 1000:.0f} ms" for k, v in totals.items()).join(("total: ", "")))
    side_by_side(args.rounds)


if __name__ == "__main__":
    main()
