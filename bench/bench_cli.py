"""Benchmark: whole `scaffold` commands as a user runs them, interpreter start included.

Times, each as a fresh `python -m unityscaffold` process: `msgs list --ros 1`, `msgs show` of
one type, and `apply` on a copy of sample_project from clean and as a no-op (the first no-op
plans and writes the no-op record, the next one replays it; "no record" plans with the record
turned off); beside them a process that only imports the dependencies and a bare interpreter.
Prints the median wall and CPU (user + system) time of each. Aims: msgs list/show < 250 ms,
apply no-op < 300 ms, apply from clean < 600 ms.

With ``--tree DIR`` (repeatable) the same commands also run from other source trees, for
example an earlier commit (``git archive <commit> | tar -x -C DIR``), alternated round by round
with this one so that a busy machine slows every side alike; the ratio to the first tree is
printed. The load average is printed before and after, since the machine may be shared.
Every side runs with compiled bytecode, kept in the temporary folder, as an installed package
does.

    python3 bench/bench_cli.py [--rounds N] [--tree DIR ...]
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
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
# the template scene init writes (older trees keep templates/ at the top)
CLEAN_SCENES = [
    Path(folder) / "templates/unity_project/Assets/Scenes/Main.unity"
    for folder in ("unityscaffold", ".")
]


def run_timed(command: list[str], env: dict[str, str], cwd: Path | None = None) -> float:
    """CPU seconds (user + system) of one child process; wall time is returned by ``timed``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run(command, stdout=subprocess.DEVNULL, env=env, cwd=cwd, check=False)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    assert done.returncode == 0, (command, done.returncode)
    return after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def reset_to_clean(tree: Path, project: Path) -> None:
    shutil.rmtree(project / "unity" / "Assets" / "RosGenerated", ignore_errors=True)
    (project / "unity" / "Assets" / "RosGenerated.meta").unlink(missing_ok=True)
    (project / "robot.lock.json").unlink(missing_ok=True)
    clean = next(tree / p for p in CLEAN_SCENES if (tree / p).is_file())
    shutil.copy(clean, project / "unity" / "Assets" / "Scenes" / "Main.unity")


class Side:
    """One source tree: its environment and its own copy of the sample project."""

    def __init__(self, tree: Path, work: Path, pycache: Path) -> None:
        self.tree = tree
        # Bytecode is written under one shared prefix in the temporary folder (not into the
        # trees) and reused from the uncounted warm-up round on, as an installed package's
        # is. Without it, a shell with PYTHONDONTWRITEBYTECODE set, or a tree whose
        # __pycache__ is stale, compiles every module in every run: about 180 ms CPU more.
        self.env = {**os.environ, "PYTHONPATH": str(tree), "PYTHONPYCACHEPREFIX": str(pycache)}
        self.env.pop("PYTHONDONTWRITEBYTECODE", None)
        self.env.pop("UNITYSCAFFOLD_NO_CACHE", None)
        # compiled templates and no-op records in the temporary folder, not the user's
        self.env["XDG_CACHE_HOME"] = str(work / "cache")
        self.records = work / "cache" / "unityscaffold" / "noop"
        self.project = work / "sample_project"
        shutil.copytree(tree / "sample_project", self.project)
        # the sample's first line names ../unityscaffold/schema/robot.schema.json: copied too, so
        # apply checks it as in the repository instead of printing that it is missing
        schema = Path("unityscaffold/schema/robot.schema.json")
        if (tree / schema).is_file():
            (work / schema).parent.mkdir(parents=True)
            shutil.copy(tree / schema, work / schema)
        self.times: dict[str, list[tuple[float, float]]] = {}

    def timed(self, label: str, command: list[str], *, replay: bool = True) -> None:
        env = self.env if replay else {**self.env, "UNITYSCAFFOLD_NO_REPLAY": "1"}
        start = time.perf_counter()
        # from the side's own folder: `python -m` puts the current folder first on sys.path,
        # so run from inside a source tree every side would import that tree
        cpu = run_timed(command, env, cwd=self.project.parent)
        self.times.setdefault(label, []).append((time.perf_counter() - start, cpu))

    def round(self) -> None:
        scaffold = [sys.executable, "-m", "unityscaffold"]
        manifest = str(self.project / "robot.yaml")
        self.timed("msgs list --ros 1", [*scaffold, "msgs", "list", "--ros", "1"])
        self.timed("msgs show (1 type)", [*scaffold, "msgs", "show", "nav_msgs/Odometry"])
        reset_to_clean(self.tree, self.project)
        self.timed("apply from clean", [*scaffold, "apply", "--quiet", manifest])
        # a record before format 2 did not trust files changed in its last 50 ms (the record
        # now compares content): kept, so that an older tree is timed as its users saw it
        time.sleep(0.1)
        # the project is byte for byte as in the last round, whose record would be replayed
        shutil.rmtree(self.records, ignore_errors=True)
        self.timed("apply no-op", [*scaffold, "apply", "--quiet", manifest])
        self.timed("no-op, replayed", [*scaffold, "apply", "--quiet", manifest])
        self.timed("no-op, no record", [*scaffold, "apply", "--quiet", manifest], replay=False)
        self.timed("apply --check", [*scaffold, "apply", "--check", manifest])
        deps = "import jinja2, ruamel.yaml, typer, yaml"
        self.timed("import deps alone", [sys.executable, "-c", deps])
        self.timed("bare python", [sys.executable, "-c", "pass"])


AIMS = {
    "msgs list --ros 1": "< 250",
    "msgs show (1 type)": "< 250",
    "apply from clean": "< 600",
    "apply no-op": "< 300",
    "no-op, replayed": "< 300",
    "no-op, no record": "< 300",
}


def _load() -> str:
    return "load average " + " ".join(f"{x:.2f}" for x in os.getloadavg())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=9)
    parser.add_argument("--tree", type=Path, action="append", default=[], help="another tree")
    args = parser.parse_args()
    print(f"before: {_load()}")
    with tempfile.TemporaryDirectory() as tmp:
        sides = [
            Side(tree.resolve(), Path(tmp) / str(index), Path(tmp) / "pycache")
            for index, tree in enumerate([REPO, *args.tree])
        ]
        for index in range(args.rounds + 1):  # round 0 warms caches and is not counted
            for side in sides if index % 2 else reversed(sides):
                side.round()
        print(f"after:  {_load()}")
        for side in sides:
            for times in side.times.values():
                del times[0]
    print(f"median of {args.rounds} alternated rounds, ms wall (ms CPU)")
    header = "".join(f"{str(side.tree)[-24:]:>26}" for side in sides)
    print(f"{'command':<20}{header}   aim")
    for label in sides[0].times:
        cells = []
        for side in sides:
            wall = statistics.median(t[0] for t in side.times[label]) * 1000
            cpu = statistics.median(t[1] for t in side.times[label]) * 1000
            cells.append(f"{wall:.0f} ({cpu:.0f})")
        print(f"{label:<20}" + "".join(f"{c:>26}" for c in cells) + f"   {AIMS.get(label, '')}")
    if len(sides) > 1:
        for side in sides[1:]:
            ratios = [
                statistics.median(t[1] for t in side.times[label])
                / statistics.median(t[1] for t in sides[0].times[label])
                for label in AIMS
            ]
            print(
                f"CPU of {side.tree} / this tree: "
                + ", ".join(f"{label} {r:.2f}x" for label, r in zip(AIMS, ratios, strict=True))
            )


if __name__ == "__main__":
    main()
