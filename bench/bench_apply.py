"""Benchmark: `scaffold apply` on the sample project as whole commands, interpreter start included.

Runs, side by side in one session: apply from clean (generated files, lock and scene wiring
removed first) and the no-op re-apply, each as a fresh `python -m unityscaffold` process on a
copy of sample_project. Prints median wall and CPU (user + system) times, beside those of a
process that only imports the dependencies. Aims: < 0.6 s from clean, < 0.3 s no-op. CPU time
is the fairer figure on a shared machine.

Then the manifest-size sweep: for N topics of standard ROS 1 types on a fresh `init` project,
apply (writes everything), the no-op re-apply and `apply --check`, each a whole process, with
the cost per topic; the cost per topic should stay flat as N grows.

Run: python3 bench/bench_apply.py [--rounds N] [--sizes N ...]
"""

from __future__ import annotations

import argparse
import resource
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


def run_timed(command: list[str], expect: int = 0) -> tuple[float, float]:
    """Wall and CPU (user + system) seconds of one child process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, check=False)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    assert done.returncode == expect, (command, done.returncode)
    return wall, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def timed_apply(project: Path) -> tuple[float, float]:
    return timed("apply", "--quiet", str(project / "robot.yaml"))


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


def timed(*args: str, expect: int = 0) -> tuple[float, float]:
    return run_timed([sys.executable, "-m", "unityscaffold", *args], expect)


def sweep(sizes: list[int]) -> None:
    print("manifest-size sweep, wall (CPU) seconds, and CPU ms per topic")
    print(
        f"{'topics':>7} {'apply':>13} {'no-op':>13} {'check':>13}   per topic: "
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
            cells = " ".join(f"{f'{w:.2f} ({c:.2f})':>13}" for w, c in (apply, noop, check))
            per = " / ".join(f"{c / count * 1000:.2f}" for _, c in (apply, noop, check))
            print(f"{count:7d} {cells}   {per}", flush=True)


def import_cost() -> tuple[float, float]:
    """A process that imports the dependencies the CLI needs, and nothing of ours."""
    return run_timed([sys.executable, "-c", "import jinja2, ruamel.yaml, typer, yaml"])


def _line(label: str, times: list[tuple[float, float]], note: str) -> str:
    wall = statistics.median(t[0] for t in times)
    cpu = statistics.median(t[1] for t in times)
    return f"{label:<18} median {wall * 1000:6.0f} ms wall, {cpu * 1000:6.0f} ms CPU  {note}"


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
        bare.append(run_timed([sys.executable, "-c", "pass"]))
        deps.append(import_cost())
    print(f"sample project, {args.rounds} rounds")
    print(_line("apply from clean", clean, "(aim < 600 ms)"))
    print(_line("no-op re-apply", noop, "(aim < 300 ms)"))
    print(_line("import deps alone", deps, "(jinja2, ruamel.yaml, typer, yaml)"))
    print(_line("bare python start", bare, ""))
    if args.sizes:
        sweep(args.sizes)


if __name__ == "__main__":
    main()
