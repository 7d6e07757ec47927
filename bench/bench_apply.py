"""Benchmark: `scaffold apply` on the sample project as whole commands, interpreter start included.

Runs, side by side in one session: apply from clean (generated files, lock and scene wiring
removed first) and the no-op re-apply, each as a fresh `python -m unityscaffold` process on a
copy of sample_project. Prints best and median wall times. Aims: < 1 s from clean, < 0.4 s no-op.
Run: python3 bench/bench_apply.py [--rounds N]
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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    args = parser.parse_args()
    clean, noop = [], []
    with tempfile.TemporaryDirectory() as tmp:
        project = Path(tmp) / "sample_project"
        shutil.copytree(SAMPLE, project)
        for _ in range(args.rounds):
            reset_to_clean(project)
            clean.append(timed_apply(project))
            noop.append(timed_apply(project))
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", "pass"], check=True)
    bare = time.perf_counter() - start
    for label, times, aim in (("apply from clean", clean, 1.0), ("no-op re-apply", noop, 0.4)):
        print(
            f"{label:<18} best {min(times) * 1000:6.0f} ms  median "
            f"{statistics.median(times) * 1000:6.0f} ms  (aim < {aim * 1000:.0f} ms)"
        )
    print(f"{'bare python start':<18} {bare * 1000:6.0f} ms  (for reference)")


if __name__ == "__main__":
    main()
