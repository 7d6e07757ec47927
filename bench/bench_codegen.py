"""Benchmark: C# for all Debian ROS 1 types and all Jazzy interfaces, with --include-shipped.

Each run indexes, parses, generates, compares with the output folder and writes what changed.
Cold: a fresh registry and template environment and an empty output folder; warm: the same
again in the same process (parsed files and compiled templates cached), where every file is
unchanged and nothing is written. Prints total and per-class time and files written.

    python3 bench/bench_codegen.py [--repeat N]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

from unityscaffold.codegen import Options, generate
from unityscaffold.codegen.layout import output_files
from unityscaffold.fileout import plan_files, write_files
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry
from unityscaffold.resources import template_environment


def _run(
    dialect: Dialect, registry: Registry | None, out: Path
) -> tuple[Registry, int, int, float, float]:
    start = time.perf_counter()
    if registry is None:
        registry = Registry.load(dialect)
    interfaces, problems = registry.parse_all()
    assert not problems, problems
    code = generate(registry, interfaces, Options(dialect, include_shipped=True))
    generated = time.perf_counter() - start
    written = write_files(plan_files(output_files(code, out)))
    elapsed = time.perf_counter() - start
    return registry, len(code.files), len(written), generated, elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="warm runs (best is reported)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "RosMessages"
        totals = {"cold": 0.0, "warm": 0.0, "cold generate": 0.0, "warm generate": 0.0}
        for dialect in (Dialect.ROS1, Dialect.ROS2):
            template_environment.cache_clear()
            registry, classes, files, cold_gen, cold = _run(dialect, None, out / dialect.name)
            warm_runs = [_run(dialect, registry, out / dialect.name) for _ in range(args.repeat)]
            warm = min(r[4] for r in warm_runs)
            warm_gen = min(r[3] for r in warm_runs)
            totals["cold generate"] += cold_gen
            totals["warm generate"] += warm_gen
            rewritten = max(r[2] for r in warm_runs)
            totals["cold"] += cold
            totals["warm"] += warm
            print(
                f"{dialect.label}: {classes} classes; cold {cold * 1000:.0f} ms "
                f"({cold / classes * 1e6:.0f} us/class, {files} files written incl. .meta), "
                f"warm {warm * 1000:.0f} ms ({warm / classes * 1e6:.0f} us/class, "
                f"{rewritten} files written); generation alone: cold {cold_gen * 1000:.0f} ms, "
                f"warm {warm_gen * 1000:.0f} ms"
            )
        print(", ".join(f"{k} {v * 1000:.0f} ms" for k, v in totals.items()).join(("total: ", "")))


if __name__ == "__main__":
    main()
