"""Benchmark: `scaffold apply` on the sample project as whole commands, interpreter start included.

Runs, side by side in one session: apply from clean (generated files, lock and scene wiring
removed first) and the no-op re-apply, each as a fresh `python -m unityscaffold` process on a
copy of sample_project. Prints best and median wall times, beside the time a process takes to
import the dependencies alone. Aims: < 0.6 s from clean, < 0.3 s no-op.

Then the manifest-size sweep: for N topics of standard ROS 1 types on a fresh `init` project,
apply (writes everything), the no-op re-apply and `apply --check`, each a whole process, with
the cost per topic; the cost per topic should stay flat as N grows.

Run: python3 bench/bench_apply.py [--rounds N] [--sizes N ...]
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
SAMPLE = REPO / "sample_project"
CLEAN_SCENE = REPO / "unityscaffold/templates/unity_project/Assets/Scenes/Main.unity"


def reset_to_clean(project: Path) -> None:
    shutil.rmtree(project / "unity" / "Assets" / "RosGenerated", ignore_errors=True)
    (project / "unity" / "Assets" / "RosGenerated.meta").unlink(missing_ok=True)
    (project / "robot.lock.json").unlink(missing_ok=True)
    shutil.copy(CLEAN_SCENE, project / "unity" / "Assets" / "Scenes" / "Main.unity")


def timed_apply(project: Path) -> float:
    start = time.perf_counter()
    subprocess.run(
        [sys.executable, "-m", "unityscaffold", "apply", "--quiet", str(project / "robot.yaml")],
        check=True,
    )
    return time.perf_counter() - start


STANDARD_TYPES = [
    ("geometry_msgs/Twist", "publish"),
    ("nav_msgs/Odometry", "subscribe"),
    ("sensor_msgs/LaserScan", "subscribe"),
    ("std_msgs/String", "publish"),
    ("sensor_msgs/Imu", "subscribe"),
    ("geometry_msgs/PoseStamped", "publish"),
    ("sensor_msgs/JointState", "subscribe"),
    ("std_msgs/Float64", "publish"),
]


def timed(*args: str, expect: int = 0) -> float:
    start = time.perf_counter()
    done = subprocess.run(
        [sys.executable, "-m", "unityscaffold", *args], stdout=subprocess.DEVNULL, check=False
    )
    elapsed = time.perf_counter() - start
    assert done.returncode == expect, (args, done.returncode)
    return elapsed


def sweep(sizes: list[int]) -> None:
    print(
        f"{'topics':>7} {'apply s':>8} {'no-op s':>8} {'check s':>8}   per topic (ms): "
        "apply / no-op / check"
    )
    for count in sizes:
        with tempfile.TemporaryDirectory() as tmp:
            project = Path(tmp) / "robot"
            subprocess.run(
                [sys.executable, "-m", "unityscaffold", "init", "--ros", "1", str(project)],
                check=True,
                stdout=subprocess.DEVNULL,
            )
            manifest = project / "robot.yaml"
            lines = [
                f"  - {{name: /t{i}, type: {STANDARD_TYPES[i % len(STANDARD_TYPES)][0]}, "
                f"direction: {STANDARD_TYPES[i % len(STANDARD_TYPES)][1]}, "
                f"gameobject: Robot{i % 50}}}\n"
                for i in range(count)
            ]
            text = manifest.read_text(encoding="utf-8")
            text = text.replace("topics:\n", "topics:\n" + "".join(lines), 1)
            manifest.write_text(text, encoding="utf-8")
            apply = timed("apply", "--quiet", str(manifest))
            noop = timed("apply", "--quiet", str(manifest))
            check = timed("apply", "--check", str(manifest))
            per = "/".join(f"{t / count * 1000:.2f}" for t in (apply, noop, check))
            print(f"{count:7d} {apply:8.2f} {noop:8.2f} {check:8.2f}   {per}", flush=True)


def import_cost() -> float:
    """A process that imports the dependencies the CLI needs, and nothing of ours."""
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", "import jinja2, ruamel.yaml, typer, yaml"], check=False)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=9)
    parser.add_argument(
        "--sizes", type=int, nargs="*", default=[100, 500, 1000, 2000, 4000], help="topics"
    )
    args = parser.parse_args()
    clean, noop = [], []
    with tempfile.TemporaryDirectory() as tmp:
        project = Path(tmp) / "sample_project"
        shutil.copytree(SAMPLE, project)
        for _ in range(args.rounds):
            reset_to_clean(project)
            clean.append(timed_apply(project))
            noop.append(timed_apply(project))
    bare, deps = [], []
    for _ in range(args.rounds):
        start = time.perf_counter()
        subprocess.run([sys.executable, "-c", "pass"], check=True)
        bare.append(time.perf_counter() - start)
        deps.append(import_cost())
    for label, times, aim in (("apply from clean", clean, 0.6), ("no-op re-apply", noop, 0.3)):
        print(
            f"{label:<18} best {min(times) * 1000:6.0f} ms  median "
            f"{statistics.median(times) * 1000:6.0f} ms  (aim < {aim * 1000:.0f} ms)"
        )
    for label, times in (("bare python start", bare), ("import deps alone", deps)):
        print(
            f"{label:<18} best {min(times) * 1000:6.0f} ms  median "
            f"{statistics.median(times) * 1000:6.0f} ms  (for reference)"
        )
    if args.sizes:
        sweep(args.sizes)


if __name__ == "__main__":
    main()
