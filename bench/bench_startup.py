"""Benchmark: where `scaffold apply` spends its time before its work, on the sample and on r2d2.

Times, each as a fresh `python -m unityscaffold apply --quiet` process (CPU, user + system):
the sample project's planned no-op (its no-op record removed first, so the command plans),
and ROS#'s r2d2 (the tutorial's URDF and its two COLLADA models, in a ROS 2 `init` project)
from clean, as a planned no-op and as a replayed no-op. Then the same commands once more,
each in an interpreter that counts the CPU time spent importing from the command's start on
(every outermost import statement and ``importlib.import_module`` call, with all they load;
the interpreter's own start is not counted) and the modules loaded by its end; beside them a
bare interpreter and one that imports only the dependencies.

With ``--tree DIR`` (repeatable) the same runs are made from other source trees (an earlier
commit: ``git worktree add --detach DIR <rev>``), alternated round by round with this one so
that a busy machine slows every side alike, and each figure's ratio to this tree is printed.
Aims: r2d2 from clean under 1 s, every no-op under 300 ms.

    python3 bench/bench_startup.py [--rounds N] [--tree DIR ...]
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
VENDOR = Path(os.environ.get("UNITYSCAFFOLD_VENDOR", REPO.parent / "shared" / "vendor"))
R2D2 = VENDOR / "ros-sharp" / "samples" / "gazebo-ros2-step1"
DEPS = "import jinja2, ruamel.yaml, typer, yaml"
# `scaffold` in an interpreter that times its outermost imports (CPU), then prints that time
# in ms and the number of modules loaded
_COUNTING = """
import builtins, importlib, sys, time
depth, spent = [0], [0.0]
def timed(real):
    def outermost(*args, **kwargs):
        if depth[0]:
            return real(*args, **kwargs)
        depth[0] += 1
        start = time.process_time()
        try:
            return real(*args, **kwargs)
        finally:
            spent[0] += time.process_time() - start
            depth[0] -= 1
    return outermost
builtins.__import__ = timed(builtins.__import__)
importlib.import_module = timed(importlib.import_module)
from unityscaffold.cli import main
status = main(sys.argv[1:])
print(status, spent[0] * 1000, len(sys.modules))
"""


def _r2d2_project(folder: Path, env: dict[str, str]) -> Path:
    """A ROS 2 `init` project with r2d2 as its one robot, its package beside the URDF."""
    command = [sys.executable, "-m", "unityscaffold", "init", "--ros", "2", str(folder)]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, env=env)
    models = R2D2 / "Urdf/file_server2/urdf_tutorial"
    shutil.copytree(models, folder / "urdf_tutorial", ignore=shutil.ignore_patterns("*.meta"))
    shutil.copy(R2D2 / "custom_r2d2.urdf", folder / "robot.urdf")
    manifest = folder / "robot.yaml"
    text = manifest.read_text(encoding="utf-8")
    manifest.write_text(text.replace("\nrobots:\n", "\nrobots:\n  - urdf: robot.urdf\n", 1))
    return folder


class Side:
    """One source tree: its environment, its copies of the sample and of the r2d2 project."""

    def __init__(self, tree: Path, work: Path, pycache: Path, r2d2: Path) -> None:
        self.tree = tree
        # compiled bytecode kept under one prefix (as an installed package has it) and caches
        # (compiled templates, no-op records) in the temporary folder, not the user's
        self.env = {**os.environ, "PYTHONPATH": str(tree), "PYTHONPYCACHEPREFIX": str(pycache)}
        for name in ("PYTHONDONTWRITEBYTECODE", "UNITYSCAFFOLD_NO_CACHE"):
            self.env.pop(name, None)
        self.env.pop("UNITYSCAFFOLD_NO_REPLAY", None)
        self.env["XDG_CACHE_HOME"] = str(work / "cache")
        self.records = work / "cache" / "unityscaffold" / "noop"
        self.sample = work / "sample_project"
        shutil.copytree(tree / "sample_project", self.sample)
        # the sample's first line names ../unityscaffold/schema/robot.schema.json
        schema = work / "unityscaffold" / "schema"
        schema.mkdir(parents=True)
        shutil.copy(tree / "unityscaffold/schema/robot.schema.json", schema)
        self.r2d2 = work / "r2d2"
        shutil.copytree(r2d2, self.r2d2)
        self.scene = self.r2d2 / "Assets/Scenes/Main.unity"
        self.start = self.scene.read_bytes()
        self.times: dict[str, list[float]] = {}

    def _run(self, label: str, manifest: Path, counting: bool) -> None:
        python = ["-c", _COUNTING] if counting else ["-m", "unityscaffold"]
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        done = subprocess.run(
            [sys.executable, *python, "apply", "--quiet", str(manifest)],
            capture_output=True,
            env=self.env,
            cwd=manifest.parent.parent,  # not a source tree: `-m` puts the folder first
            text=True,
            check=False,
        )
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        assert done.returncode == 0, (self.tree, label, done.stderr)
        if counting:
            status, spent, count = done.stdout.split()
            assert status == "0", (self.tree, label, done.stderr)
            self.times.setdefault(f"{label}: imports", []).append(float(spent))
            self.times.setdefault(f"{label}: modules", []).append(float(count))
        else:
            cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
            self.times.setdefault(label, []).append(cpu * 1000)

    def _clean_r2d2(self) -> None:
        self.scene.write_bytes(self.start)
        (self.r2d2 / "robot.lock.json").unlink(missing_ok=True)
        shutil.rmtree(self.r2d2 / "Assets/Urdf", ignore_errors=True)

    def round(self) -> None:
        for counting in (False, True):
            shutil.rmtree(self.records, ignore_errors=True)
            self._run("sample no-op", self.sample / "robot.yaml", counting)
            self._clean_r2d2()
            self._run("r2d2 from clean", self.r2d2 / "robot.yaml", counting)
            shutil.rmtree(self.records, ignore_errors=True)
            self._run("r2d2 no-op", self.r2d2 / "robot.yaml", counting)
            self._run("r2d2 replayed", self.r2d2 / "robot.yaml", counting)
        for label, code in (("bare python", "pass"), ("import deps alone", DEPS)):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            subprocess.run([sys.executable, "-c", code], check=True, env=self.env)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
            self.times.setdefault(label, []).append(cpu * 1000)


UNITS = {"imports": "ms CPU importing", "modules": "modules loaded"}


def _unit(label: str) -> str:
    return UNITS.get(label.rpartition(": ")[2], "ms CPU")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--tree", type=Path, action="append", default=[], help="another tree")
    args = parser.parse_args()
    print(f"before: load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        first = {**os.environ, "PYTHONPATH": str(REPO), "XDG_CACHE_HOME": str(work / "cache")}
        r2d2 = _r2d2_project(work / "r2d2", first)
        sides = [
            Side(tree.resolve(), work / str(index), work / "pycache", r2d2)
            for index, tree in enumerate([REPO, *args.tree])
        ]
        for index in range(args.rounds + 1):  # round 0 compiles bytecode and is not counted
            for side in sides if index % 2 else reversed(sides):
                side.round()
        for side in sides:
            for values in side.times.values():
                del values[0]
    print(f"after:  load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    print(f"median of {args.rounds} alternated rounds")
    print(f"{'':<30}" + "".join(f"{str(side.tree)[-22:]:>24}" for side in sides))
    for label in sides[0].times:
        cells = [statistics.median(side.times[label]) for side in sides]
        ratios = "".join(f"  {c / cells[0]:.2f}x" if cells[0] else "" for c in cells[1:])
        row = "".join(f"{c:>24.0f}" for c in cells)
        print(f"{label:<30}{row}  {_unit(label)}{ratios}")


if __name__ == "__main__":
    main()
