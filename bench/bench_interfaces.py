"""Benchmark: parse and identify every Debian ROS 1 type and every Jazzy interface, from cold.

"Cold" means a fresh Registry each round (directory scan, reading, parsing, md5 / RIHS01
hashing), in this process, after imports. Prints the best and median of several rounds, and the
time per type. Run: python3 bench/bench_interfaces.py [--rounds N]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

from unityscaffold.interfaces.identity_ros1 import Ros1Identity
from unityscaffold.interfaces.identity_ros2 import Ros2Identity
from unityscaffold.interfaces.model import ActionSpec, Dialect
from unityscaffold.interfaces.registry import Registry

ROS1_SHARE = Path("/usr/share")
ROS2_SHARE = Path(sys.prefix) / "share"


def ros1_round() -> int:
    packages = sorted(
        {p.parent for kind in ("msg", "srv", "action") for p in ROS1_SHARE.glob(f"*/{kind}")}
    )
    registry = Registry.load(Dialect.ROS1, packages, use_environment=False, use_builtin=False)
    identity = Ros1Identity(registry)
    interfaces, problems = registry.parse_all()
    assert not problems, problems
    for interface in interfaces:
        if not isinstance(interface, ActionSpec):
            identity.md5sum(interface)
            if interface.kind.value == "msg":
                identity.full_text(interface)
    return len(interfaces)


def ros2_round() -> int:
    packages = sorted(
        p.parent
        for p in ROS2_SHARE.glob("*/package.xml")
        if any((p.parent / k).is_dir() for k in ("msg", "srv", "action"))
    )
    registry = Registry.load(Dialect.ROS2, packages, use_environment=False, use_builtin=False)
    identity = Ros2Identity(registry)
    interfaces, problems = registry.parse_all()
    assert not problems, problems
    for interface in interfaces:
        identity.type_hash(interface)
    return len(interfaces)


def measure(label: str, work, rounds: int) -> float:
    times, count = [], 0
    for _ in range(rounds):
        start = time.perf_counter()
        count = work()
        times.append(time.perf_counter() - start)
    best, median = min(times), statistics.median(times)
    print(
        f"{label:<28} {count:4d} types  best {best * 1000:7.1f} ms  median {median * 1000:7.1f} ms"
        f"  ({median / count * 1e6:6.1f} µs/type)"
    )
    return median


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    args = parser.parse_args()
    total = measure("ROS 1 (Debian, genmsg md5)", ros1_round, args.rounds)
    total += measure("ROS 2 (Jazzy wheels, RIHS01)", ros2_round, args.rounds)
    print(f"{'both, median sum':<28}            {total * 1000:7.1f} ms  (aim: < 150 ms)")


if __name__ == "__main__":
    main()
