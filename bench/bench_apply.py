"""Benchmark: `scaffold apply` on the sample project as whole commands, interpreter start included.

Runs, side by side in one session: apply from clean (generated files, lock and scene wiring
removed first) and the no-op re-apply, each as a fresh `python -m unityscaffold` process on a
copy of sample_project. The first no-op plans and writes the no-op record; the next one
replays it; "no record" plans with the record turned off (UNITYSCAFFOLD_NO_REPLAY=1). Prints
median wall and CPU (user + system) times, beside those of a process that only imports the
dependencies. Aims: < 0.6 s from clean, < 0.3 s no-op. CPU time is the fairer figure on a
shared machine. Children run this tree, with compiled bytecode and caches in a temporary
folder.

Then the manifest-size sweep: for N topics of standard ROS 1 types on a fresh `init` project,
apply (writes everything), the no-op re-apply (plans, records), the next no-op (replayed), a
no-op with the record off and `apply --check`, each a whole process, with the cost per topic;
the cost per topic should stay flat as N grows.

Robots: `robots:` entries applied into a scene from clean (scene, lock and the robot's assets
reset) and the no-op re-apply, as whole processes: ROS#'s r2d2 (the tutorial's URDF and its two
COLLADA models, read from $UNITYSCAFFOLD_VENDOR or ../shared/vendor); the largest real
descriptions of the robot survey (--large; by default PR2: 88 links, 50 visuals and 50
collisions, TIAGo: 89 links, TALOS: 68 links, each from its xacro, mostly COLLADA and STL
models), read from the survey's checkouts (see robot_survey.py) and left out with a message
when those are absent; a generated robot of 500 links (bench_urdf's) and one of 500 links with
STL visuals and collisions (bench_models', 50 files of 2,000 facets). Aims: r2d2 from clean
under 1 s, its no-op within the sample's no-op aim; a large real robot under 1.5 s from clean.
A robot apply refuses is timed to its refusal (exit 2), and the line says so.

Run: python3 bench/bench_apply.py [--rounds N] [--sizes N ...] [--parts sample,robots,sweep]
                                  [--large NAME,...] [--robots-root DIR]
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
SAMPLE = REPO / "sample_project"
CLEAN_SCENE = REPO / "unityscaffold/templates/unity_project/Assets/Scenes/Main.unity"


def reset_to_clean(project: Path) -> None:
    shutil.rmtree(project / "unity" / "Assets" / "RosGenerated", ignore_errors=True)
    (project / "unity" / "Assets" / "RosGenerated.meta").unlink(missing_ok=True)
    (project / "robot.lock.json").unlink(missing_ok=True)
    shutil.copy(CLEAN_SCENE, project / "unity" / "Assets" / "Scenes" / "Main.unity")


#: The children's environment: this tree first on the path, compiled bytecode kept (under a
#: prefix in a temporary folder, as an installed package has it; PYTHONDONTWRITEBYTECODE or a
#: stale __pycache__ would make every run compile every module) and caches (compiled
#: templates, no-op records) in a temporary folder. Set up by ``main``.
ENV: dict[str, str] = {}


def child_env(work: Path) -> dict[str, str]:
    env = {**os.environ, "PYTHONPATH": str(REPO), "PYTHONPYCACHEPREFIX": str(work / "pycache")}
    env["XDG_CACHE_HOME"] = str(work / "cache")
    for name in ("PYTHONDONTWRITEBYTECODE", "UNITYSCAFFOLD_NO_CACHE", "UNITYSCAFFOLD_NO_REPLAY"):
        env.pop(name, None)
    return env


def run_timed(command: list[str], expect: int = 0, *, replay: bool = True) -> tuple[float, float]:
    """Wall and CPU (user + system) seconds of one child process."""
    env = ENV if replay else {**ENV, "UNITYSCAFFOLD_NO_REPLAY": "1"}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    # a refusal's errors are expected (the caller says which exit), so they are not shown
    errors = subprocess.DEVNULL if expect else None
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=errors, env=env, check=False)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    assert done.returncode == expect, (command, done.returncode)
    return wall, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def timed_apply(project: Path, *, replay: bool = True, expect: int = 0) -> tuple[float, float]:
    return timed("apply", "--quiet", str(project / "robot.yaml"), replay=replay, expect=expect)


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


def timed(*args: str, expect: int = 0, replay: bool = True) -> tuple[float, float]:
    return run_timed([sys.executable, "-m", "unityscaffold", *args], expect, replay=replay)


def sweep(sizes: list[int]) -> None:
    print("manifest-size sweep, wall (CPU) seconds, and CPU ms per topic")
    print("(no-op: plans and records; replayed: the next no-op; no record: plans, record off)")
    names = ("apply", "no-op", "replayed", "no record", "check")
    print(" ".join([f"{'topics':>7}", *(f"{n:>13}" for n in names)]) + "   per topic (CPU ms)")
    for count in sizes:
        with tempfile.TemporaryDirectory() as tmp:
            project = Path(tmp) / "robot"
            subprocess.run(
                [sys.executable, "-m", "unityscaffold", "init", "--ros", "1", str(project)],
                check=True,
                stdout=subprocess.DEVNULL,
                env=ENV,
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
            replayed = timed("apply", "--quiet", str(manifest))
            plain = timed("apply", "--quiet", str(manifest), replay=False)
            check = timed("apply", "--check", str(manifest))
            runs = (apply, noop, replayed, plain, check)
            cells = " ".join(f"{f'{w:.2f} ({c:.2f})':>13}" for w, c in runs)
            per = " / ".join(f"{c / count * 1000:.2f}" for _, c in runs)
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
    parser.add_argument("--parts", default="sample,robots,sweep")
    parser.add_argument(
        "--large", default="pr2,tiago,talos", help="the robot survey's robots to time (a,b,…)"
    )
    parser.add_argument("--robots-root", type=Path, help="the survey's checkouts")
    args = parser.parse_args()
    parts = args.parts.split(",")
    with tempfile.TemporaryDirectory() as work:
        ENV.update(child_env(Path(work)))
        # `python -m` puts the current folder first on sys.path: run from inside another
        # source tree, the children would import that tree instead of this one
        here = os.getcwd()
        os.chdir(work)
        print(f"load average before: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
        if "sample" in parts:
            sample(args.rounds, Path(work))
        if "robots" in parts:
            robots(args.rounds, Path(work), args.large, args.robots_root)
        if args.sizes and "sweep" in parts:
            sweep(args.sizes)
        print(f"load average after: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
        os.chdir(here)


def sample(rounds: int, work: Path) -> None:
    clean, noop, replayed, plain = [], [], [], []
    project = work / "sample_project"
    shutil.copytree(SAMPLE, project)
    timed_apply(project)  # uncounted: compiles the bytecode and the templates
    for _ in range(rounds):
        reset_to_clean(project)
        clean.append(timed_apply(project))
        # the project is byte for byte as in the last round, whose record would be replayed
        shutil.rmtree(work / "cache" / "unityscaffold" / "noop", ignore_errors=True)
        noop.append(timed_apply(project))
        replayed.append(timed_apply(project))
        plain.append(timed_apply(project, replay=False))
    bare, deps = [], []
    for _ in range(rounds):
        bare.append(run_timed([sys.executable, "-c", "pass"]))
        deps.append(import_cost())
    print(f"sample project, {rounds} rounds")
    print(_line("apply from clean", clean, "(aim < 600 ms)"))
    print(_line("no-op re-apply", noop, "(aim < 300 ms; plans, writes the no-op record)"))
    print(_line("no-op, replayed", replayed, "(the next no-op: the record replayed)"))
    print(_line("no-op, no record", plain, "(UNITYSCAFFOLD_NO_REPLAY=1: plans)"))
    print(_line("import deps alone", deps, "(jinja2, ruamel.yaml, typer, yaml)"))
    print(_line("bare python start", bare, ""))


# ROS#'s r2d2 tutorial sample: in UNITYSCAFFOLD_VENDOR, as for the tests, else where CI puts it
VENDOR = Path(os.environ.get("UNITYSCAFFOLD_VENDOR", REPO.parent / "shared" / "vendor"))
R2D2 = VENDOR / "ros-sharp" / "samples" / "gazebo-ros2-step1"


def robots(rounds: int, work: Path, large: str, root: Path | None) -> None:
    from bench_models import stl_robot  # 500 links with STL visuals and collisions
    from bench_urdf import robot  # the generated robot of bench_urdf.py

    print(f"robots, {rounds} rounds")
    r2d2 = new_project(work / "robots" / "r2d2", (R2D2 / "custom_r2d2.urdf").read_text())
    # its package beside the URDF, where ROS# looks for it
    models = R2D2 / "Urdf/file_server2/urdf_tutorial"
    shutil.copytree(models, r2d2 / "urdf_tutorial", ignore=_metas)
    measure("r2d2", r2d2, rounds, work, "(aim < 1000 ms)")
    for name in large.split(","):
        real = survey_project(name, work / "robots", root)
        if real is not None:
            measure(name, real, rounds, work, "(aim < 1500 ms)")
    measure("500 links", new_project(work / "robots" / "500", robot(500).decode()), rounds, work)
    stl = new_project(work / "robots" / "500_stl", "")
    urdf = stl_robot(stl / "stl", 500, 50, 2000).read_text(encoding="utf-8")
    shutil.move(stl / "stl" / "desc", stl / "desc")
    (stl / "robot.urdf").write_text(urdf, encoding="utf-8")
    measure("500 STL links", stl, rounds, work)


def new_project(project: Path, urdf: str) -> Path:
    """A new ROS 2 project whose manifest imports ``robot.urdf``, written as ``urdf``."""
    subprocess.run(
        [sys.executable, "-m", "unityscaffold", "init", "--ros", "2", str(project)],
        check=True,
        stdout=subprocess.DEVNULL,
        env=ENV,
    )
    (project / "robot.urdf").write_text(urdf, encoding="utf-8")
    manifest = project / "robot.yaml"
    text = manifest.read_text(encoding="utf-8")
    manifest.write_text(text.replace("\nrobots:\n", "\nrobots:\n  - urdf: robot.urdf\n", 1))
    return project


def survey_project(name: str, work: Path, root: Path | None) -> Path | None:
    """A project of the robot survey's robot ``name`` (bench/robots.yaml) as the survey builds
    it, from the survey's checkouts; None, saying so, when they are not there."""
    import robot_survey

    checkouts, listed = robot_survey.load_list()
    chosen = next((r for r in listed if r.name == name), None)
    if chosen is None:
        raise SystemExit(f"no robot {name!r} in {robot_survey.LIST}")
    root = root or robot_survey.default_root()
    absent = robot_survey.missing_checkouts(chosen, checkouts, root)
    if absent:
        print(f"{name}: left out, its checkouts are not in {root} ({', '.join(absent)});")
        print("  python3 bench/robot_survey.py --clone-commands prints how to get them")
        return None
    template = work / "survey-init"
    if not template.exists():
        subprocess.run(
            [sys.executable, "-m", "unityscaffold", "init", "--ros", "2", str(template)],
            check=True,
            stdout=subprocess.DEVNULL,
            env=ENV,
        )
    return robot_survey.prepare(chosen, checkouts, root, template)


def measure(label: str, project: Path, rounds: int, work: Path, aim: str = "") -> None:
    """From clean (scene, lock and the robot's assets reset) and the no-op re-apply, planned and
    replayed; a robot apply refuses, only to its refusal."""
    scene = project / "Assets/Scenes/Main.unity"
    start = scene.read_bytes()
    # uncounted: compiles the bytecode and the templates, and tells whether apply imports it
    expect = subprocess.run(
        [sys.executable, "-m", "unityscaffold", "apply", "--quiet", str(project / "robot.yaml")],
        capture_output=True,
        env=ENV,
        check=False,
    ).returncode
    clean: list[tuple[float, float]] = []
    noop: list[tuple[float, float]] = []
    replayed: list[tuple[float, float]] = []
    for _ in range(rounds):
        scene.write_bytes(start)
        (project / "robot.lock.json").unlink(missing_ok=True)
        shutil.rmtree(project / "Assets/Urdf", ignore_errors=True)
        clean.append(timed_apply(project, expect=expect))
        if expect == 0:
            shutil.rmtree(work / "cache" / "unityscaffold" / "noop", ignore_errors=True)
            noop.append(timed_apply(project))
            replayed.append(timed_apply(project))
    if expect != 0:
        note = f"(REFUSED, exit {expect}: the time to the refusal, nothing written)"
        print(_line(f"{label} refused", clean, note), flush=True)
        return
    print(_line(f"{label} from clean", clean, aim), flush=True)
    print(_line(f"{label} no-op", noop, "(plans, writes the no-op record)"), flush=True)
    print(_line(f"{label} replayed", replayed, "(the next no-op)"), flush=True)


def _metas(folder: str, names: list[str]) -> list[str]:
    return [name for name in names if name.endswith(".meta")]


if __name__ == "__main__":
    main()
