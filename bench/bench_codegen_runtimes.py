"""Benchmark: the ROS-TCP-Connector classes against the ROS# classes, from the same types.

Both generators (``codegen.generate`` for ROS#, ``codegen.rostcp.generate`` for the connector)
get the same roots from one parsed registry: every Debian ROS 1 interface; every Jazzy message
of the wheels that the connector can carry (no wstring; ROS 2 actions and services of a
message's name are left out of both, as the connector refuses them). Each round times one
``generate`` call per target in alternated order, after one warm-up call each (templates
compiled, files parsed); prints the median CPU time and files of each and their ratio (the
issue's budget: the connector's at most 1.2 times ROS#'s).

    python3 bench/bench_codegen_runtimes.py [--rounds N]
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable

from unityscaffold.codegen import GeneratedCode, Options, generate, rostcp
from unityscaffold.interfaces.model import Dialect, Interface, MessageSpec
from unityscaffold.interfaces.registry import Registry

Generator = Callable[[Registry, list[Interface], Options], GeneratedCode]


def _roots(registry: Registry, dialect: Dialect) -> list[Interface]:
    interfaces, _ = registry.parse_all()
    if dialect is Dialect.ROS1:
        return interfaces
    messages = [i for i in interfaces if isinstance(i, MessageSpec)]
    return [
        m
        for m in messages
        if not any(f.type.base == "wstring" for s in [m, *registry.closure([m])] for f in s.fields)
    ]


def _time(
    generator: Generator, registry: Registry, roots: list[Interface], dialect: Dialect
) -> tuple[float, int]:
    start = time.process_time()
    code = generator(registry, roots, Options(dialect))
    return time.process_time() - start, len(code.files)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=7)
    args = parser.parse_args()
    targets: dict[str, Generator] = {"ROS#": generate, "ROS-TCP-Connector": rostcp.generate}
    for dialect in (Dialect.ROS1, Dialect.ROS2):
        registry = Registry.load(dialect, use_builtin=False)
        roots = _roots(registry, dialect)
        times: dict[str, list[float]] = {name: [] for name in targets}
        files: dict[str, int] = {}
        for generator in targets.values():
            _time(generator, registry, roots, dialect)  # warm-up
        for round_index in range(args.rounds):
            order = list(targets.items())
            if round_index % 2:
                order.reverse()
            for name, generator in order:
                spent, files[name] = _time(generator, registry, roots, dialect)
                times[name].append(spent)
        medians = {name: statistics.median(spent) for name, spent in times.items()}
        print(f"{dialect.label}: {len(roots)} root types, median of {args.rounds} rounds (CPU)")
        for name, median in medians.items():
            print(f"  {name:18} {median * 1000:8.1f} ms  {files[name]:4} files")
        ratio = medians["ROS-TCP-Connector"] / medians["ROS#"]
        print(f"  connector / ROS#   {ratio:8.2f}x")


if __name__ == "__main__":
    main()
