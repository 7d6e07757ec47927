"""Benchmark: the urdf stage on generated robots of 100, 1,000 and 5,000 links.

Each link has an inertial, a posed box visual and a cylinder collision; the joints form a
binary tree of revolute joints with limits (the shape of a big humanoid or a multi-arm cell,
many times over). Prints, per size, the URDF's bytes and the CPU time of reading it
(``parse_urdf``: XML, grammar, tree checks) and of building the importer's GameObject tree
with its components (``importer_tree``). Both should grow linearly with the size.

    python3 bench/bench_urdf.py [--sizes 100,1000,5000]
"""

from __future__ import annotations

import argparse
import time

from unityscaffold.urdf import parse_urdf
from unityscaffold.urdf.objects import importer_tree

INERTIA = '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>'


def robot(links: int) -> bytes:
    parts = ['<?xml version="1.0"?>\n<robot name="big">']
    for i in range(links):
        parts.append(
            f'  <link name="l{i}"><inertial><mass value="1"/>{INERTIA}</inertial>\n'
            '    <visual><origin xyz="0 0 1" rpy="0 0.1 0"/><geometry><box size="1 1 1"/>'
            "</geometry></visual>\n"
            '    <collision><geometry><cylinder radius="1" length="1"/></geometry></collision>'
            "\n  </link>"
        )
    for i in range(1, links):
        parts.append(
            f'  <joint name="j{i}" type="revolute"><parent link="l{(i - 1) // 2}"/>'
            f'<child link="l{i}"/><limit effort="1" velocity="1" lower="-1" upper="1"/></joint>'
        )
    parts.append("</robot>\n")
    return "\n".join(parts).encode()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", default="100,1000,5000")
    sizes = [int(size) for size in parser.parse_args().sizes.split(",")]
    print(f"{'links':>6} {'bytes':>10} {'read s':>8} {'tree s':>8}")
    for size in sizes:
        raw = robot(size)
        start = time.process_time()
        parsed = parse_urdf(raw, "big.urdf")
        read = time.process_time() - start
        start = time.process_time()
        importer_tree(parsed)
        built = time.process_time() - start
        print(f"{size:>6} {len(raw):>10} {read:>8.2f} {built:>8.2f}")


if __name__ == "__main__":
    main()
