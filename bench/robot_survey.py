"""Survey: real robot descriptions imported with `robots:` as a new user would, one verdict each.

For each robot of bench/robots.yaml (a public repository at a pinned commit, the folders it
needs, and the `robots:` entry a user would write), in a throwaway project made by
`scaffold init`: `scaffold apply`, then `apply` again (which must write nothing) and
`apply --check` (which must be clean), each a `python -m unityscaffold` process of this tree.
A robot is

- imported: all three as promised;
- refused: the first apply exits 2; every error is listed by its first line and grouped by
  cause (the message with quoted names and numbers left out);
- crashed: an exit status other than 0 and 2, or a traceback (a bug to report);
- unstable: imported, but the second apply wrote files or `--check` found drift (a bug too);
- unportable: imported, but what apply wrote holds the project's absolute path, so a clone
  elsewhere sees drift (a bug too);
- misshapen: imported, but the robot's object tree in the scene has another number of objects
  than ROS#'s importer makes for its links, visuals and collisions (a bug too);
- incomplete: refused only for files its checkout lacks but the upstream repository has
  (listed in ``<checkout>.missing`` beside the checkout, for a copy made without large files);
- missing: its checkout is not in the folder (see --clone-commands).

With --stand-ins, each file a ``.missing`` list names is replaced by a file of its kind from its
folder (the line says which): the verdict is then the robot's with those models changed.

The descriptions stay outside the repository (their licences vary): they are looked for in
--root, $UNITYSCAFFOLD_ROBOTS, or `robots` beside the clone, one folder per checkout.

Run: python3 bench/robot_survey.py [--root DIR] [--only NAME ...] [--set NAME]
                                   [--json] [--keep DIR] [--stand-ins] [--clone-commands]
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from collections import Counter
from collections.abc import Iterator
from dataclasses import asdict, dataclass, field
from pathlib import Path

import yaml

REPO = Path(__file__).resolve().parent.parent
LIST = REPO / "bench" / "robots.yaml"
ROOT_VARIABLE = "UNITYSCAFFOLD_ROBOTS"
SCENE = "Assets/Scenes/Main.unity"
#: Seconds one apply may take before the robot counts as hung (a crash).
TIMEOUT = 600


@dataclass(frozen=True)
class Checkout:
    """A public repository at a commit, of which the robots need ``paths``."""

    name: str
    url: str
    commit: str
    paths: tuple[str, ...]


@dataclass(frozen=True)
class Robot:
    """One robot: the `robots:` entry a user would write, with paths that start at a checkout."""

    name: str
    set: str
    urdf: str
    packages: dict[str, str]
    args: dict[str, str]
    #: values for the xacro's $(env) and $(optenv), the entry's `env`
    env: dict[str, str]
    #: what ROS#'s editor importer does with it, the yardstick of the verdict
    rossharp: str

    def checkouts(self) -> list[str]:
        """The checkouts the entry's files lie in, in the order the entry names them."""
        firsts = [self.urdf.split("/")[0]] + [p.split("/")[0] for p in self.packages.values()]
        return list(dict.fromkeys(firsts))


@dataclass
class Verdict:
    """What the survey found for one robot."""

    name: str
    set: str
    rossharp: str
    status: str = "imported"
    #: cause (the message without its names and numbers) -> first lines of its errors
    causes: dict[str, list[str]] = field(default_factory=dict)
    #: what went wrong beyond a refusal: a traceback, the files a second apply wrote, drift
    detail: str = ""
    #: files absent from the checkout that --stand-ins replaced, as paths in the checkouts
    stand_ins: list[str] = field(default_factory=list)
    seconds: dict[str, float] = field(default_factory=dict)


def load_list(path: Path = LIST) -> tuple[dict[str, Checkout], list[Robot]]:
    data = yaml.safe_load(path.read_text())
    checkouts = {
        name: Checkout(name, c["url"], c["commit"], tuple(c["paths"]))
        for name, c in data["checkouts"].items()
    }
    robots = [
        Robot(
            r["name"],
            r["set"],
            r["urdf"],
            dict(r.get("packages", {})),
            {k: str(v) for k, v in r.get("args", {}).items()},
            {k: str(v) for k, v in r.get("env", {}).items()},
            r["rossharp"],
        )
        for r in data["robots"]
    ]
    for robot in robots:
        unknown = set(robot.checkouts()) - set(checkouts)
        assert not unknown, f"{robot.name}: no checkout {sorted(unknown)} in {path}"
    return checkouts, robots


def clone_commands(checkouts: dict[str, Checkout], root: Path) -> list[str]:
    """Shell commands that put each checkout at its commit under ``root``, only its paths."""
    lines = []
    for c in checkouts.values():
        dest = root / c.name
        lines.append(f"git clone --filter=blob:none --no-checkout {c.url} {dest}")
        if "." not in c.paths:
            lines.append(f"git -C {dest} sparse-checkout set --no-cone {' '.join(c.paths)}")
        lines.append(f"git -C {dest} checkout --quiet {c.commit}")
    return lines


def copy_tree(source: Path, dest: Path) -> None:
    """``source`` copied to ``dest``; hard links where the file system allows (apply only reads
    a description, and PR2's meshes alone are tens of megabytes)."""

    def link(src: str, dst: str) -> object:
        try:
            os.link(src, dst)
        except OSError:
            shutil.copy2(src, dst)
        return dst

    shutil.copytree(source, dest, symlinks=True, copy_function=link, dirs_exist_ok=True)


def manifest(robot: Robot) -> str:
    """The manifest of the throwaway project: the scene and the robot's entry, its paths under
    ``ros/``, as a user who copied the checkouts there would write it."""
    entry: dict[str, object] = {"urdf": f"ros/{robot.urdf}"}
    if robot.packages:
        entry["packages"] = {k: os.path.normpath(f"ros/{v}") for k, v in robot.packages.items()}
    if robot.args:
        entry["args"] = robot.args
    if robot.env:
        entry["env"] = robot.env
    document = {"version": 1, "ros": 2, "project": ".", "scene": SCENE, "robots": [entry]}
    return yaml.safe_dump(document, sort_keys=False)


def prepare(robot: Robot, checkouts: dict[str, Checkout], root: Path, template: Path) -> Path:
    """A copy of the ``init`` project ``template`` holding the robot's checkouts and manifest."""
    project = template.parent / robot.name
    shutil.copytree(template, project, symlinks=True)
    for name in robot.checkouts():
        for part in checkouts[name].paths:
            copy_tree(root / name / part, project / "ros" / name / part)
    (project / "robot.yaml").write_text(manifest(robot))
    return project


def missing_checkouts(robot: Robot, checkouts: dict[str, Checkout], root: Path) -> list[str]:
    return [
        f"{name}/{part}"
        for name in robot.checkouts()
        for part in checkouts[name].paths
        if not (root / name / part).is_dir()
    ]


def child_env(work: Path) -> dict[str, str]:
    """This tree first on the path; caches in ``work``; the no-op record off, so that the second
    apply and ``--check`` plan the robot again rather than replay what the first one recorded."""
    env = {**os.environ, "PYTHONPATH": str(REPO), "XDG_CACHE_HOME": str(work / "cache")}
    env["UNITYSCAFFOLD_NO_REPLAY"] = "1"
    env.pop("UNITYSCAFFOLD_NO_CACHE", None)
    return env


def scaffold(env: dict[str, str], *args: str) -> tuple[int, str, float]:
    """Exit status, output (stdout then stderr) and seconds of one ``scaffold`` process."""
    start = time.perf_counter()
    try:
        done = subprocess.run(
            [sys.executable, "-m", "unityscaffold", *args],
            capture_output=True,
            text=True,
            env=env,
            timeout=TIMEOUT,
            check=False,
        )
    except subprocess.TimeoutExpired:
        return -1, f"no answer after {TIMEOUT} s", time.perf_counter() - start
    return done.returncode, done.stdout + done.stderr, time.perf_counter() - start


ERROR = re.compile(r"(?:^|: )error: (?P<message>.*)$")
#: What varies between errors of one cause: quoted names, paths, numbers.
VARYING = (
    (re.compile(r"\$\((\w+) [^)]*\)"), r"$(\1 …)"),
    (re.compile(r"\(listed: [^)]*\)"), "(listed: …)"),
    (re.compile(r"(?<![A-Za-z])'[^']*'|\"[^\"]*\"|`[^`]*`"), "…"),
    (re.compile(r"(?:[\w.+-]*/)+[\w.+-]+"), "…"),
    (re.compile(r"\b\d+(\.\d+)?\b"), "N"),
)
#: The cause shown for files that are not in a checkout because it was made without them.
ABSENT = "(file absent from this checkout, listed in <checkout>.missing)"


def cause(message: str) -> str:
    """The cause an error names: its message without this robot's names, paths and numbers,
    cut to its first 150 characters (xacro's messages repeat themselves)."""
    for pattern, stand_in in VARYING:
        message = pattern.sub(stand_in, message)
    return message if len(message) <= 150 else message[:150] + "…"


def group_errors(output: str, absent: set[str]) -> dict[str, list[str]]:
    """Each error's first line, under its cause; an error that names a file missing only from the
    checkout (one the upstream repository has, listed in ``absent``) under ``ABSENT``."""
    causes: dict[str, list[str]] = {}
    for line in output.splitlines():
        found = ERROR.search(line)
        if found:
            message = found.group("message").strip()
            missing = any(path in message for path in absent)
            causes.setdefault(ABSENT if missing else cause(message), []).append(message)
    if not causes:
        causes["(no error line)"] = [output.strip().splitlines()[-1] if output.strip() else ""]
    return causes


def absent_files(robot: Robot, root: Path, project: Path) -> set[str]:
    """The files of the robot's packages (and its URDF's folder) that
    ``<root>/<checkout>.missing`` lists (a checkout made from a snapshot without its large
    files), as paths in ``project``."""
    folders = [*robot.packages.values(), os.path.dirname(robot.urdf)]
    mine = tuple(os.path.normpath(f"{project}/ros/{folder}") + os.sep for folder in folders)
    found = set()
    for name in robot.checkouts():
        listing = root / f"{name}.missing"
        if listing.is_file():
            paths = (str(project / "ros" / name / line) for line in listing.read_text().split())
            found |= {path for path in paths if path.startswith(mine)}
    return found


def crashed(status: int, output: str) -> bool:
    return status not in (0, 2) or "Traceback (most recent call last)" in output


def fingerprint(project: Path) -> dict[str, str]:
    """Each file under the project (the checkouts aside) by its path and digest."""
    found = {}
    for path in sorted(project.rglob("*")):
        relative = path.relative_to(project).as_posix()
        if path.is_file() and not relative.startswith("ros/"):
            found[relative] = hashlib.sha256(path.read_bytes()).hexdigest()
    return found


def changes(before: dict[str, str], after: dict[str, str]) -> list[str]:
    names = sorted(set(before) | set(after))
    return [name for name in names if before.get(name) != after.get(name)]


def stand_in(project: Path, absent: set[str]) -> list[str]:
    """Each absent file replaced by the first file of its kind (its extension, in any case) in
    its folder, else in its checkout, else in any checkout: the robot's tree stays, one model's
    content changes, and the survey sees past a checkout made without its large files."""
    placed = []
    for path in sorted(absent):
        target = Path(path)
        checkout = project.joinpath(*target.relative_to(project).parts[:2])
        for folder in (target.parent, checkout, project / "ros"):
            kind = sorted(
                f
                for f in folder.rglob("*")
                if f.suffix.lower() == target.suffix.lower() and f.is_file()
            )
            if kind:
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(kind[0], target)
                placed.append(target.relative_to(project / "ros").as_posix())
                break
    return placed


def survey(robot: Robot, project: Path, env: dict[str, str], absent: set[str]) -> Verdict:
    verdict = Verdict(robot.name, robot.set, robot.rossharp)
    manifest_path = str(project / "robot.yaml")
    status, output, verdict.seconds["apply"] = scaffold(env, "apply", manifest_path)
    if crashed(status, output):
        verdict.status, verdict.detail = "crashed", f"exit {status}\n{output.strip()}"
        return verdict
    if status == 2:
        verdict.causes = group_errors(output, absent)
        verdict.status = "incomplete" if set(verdict.causes) == {ABSENT} else "refused"
        return verdict
    before = fingerprint(project)
    status, output, verdict.seconds["again"] = scaffold(env, "apply", manifest_path)
    written = changes(before, fingerprint(project))
    if status != 0 or written:
        verdict.status = "crashed" if crashed(status, output) else "unstable"
        verdict.detail = f"second apply: exit {status}, wrote {written}\n{output.strip()}"
        return verdict
    status, output, verdict.seconds["check"] = scaffold(env, "apply", "--check", manifest_path)
    if status != 0:
        verdict.status = "crashed" if crashed(status, output) else "unstable"
        verdict.detail = f"apply --check after apply: exit {status}\n{output.strip()}"
        return verdict
    bound = machine_bound(project)
    if bound:
        verdict.status = "unportable"
        verdict.detail = "this machine's path of the project is written in:\n" + "\n".join(bound)
        return verdict
    wrong = misshapen(robot, project)
    if wrong:
        verdict.status, verdict.detail = "misshapen", wrong
    return verdict


def misshapen(robot: Robot, project: Path) -> str:
    """What is wrong with the robot's object tree in the scene, or nothing: ROS#'s importer
    makes 2 + 3·links + 2·visuals + 2·collisions objects, the robot's own included (the robot
    and its Plugins; per link its object, Visuals and Collisions; per visual or collision its
    object and its geometry, a mesh's being its model's instance, whose objects are the model's)
    (Editor/Urdf/UrdfComponents: UrdfRobot, UrdfLink, UrdfVisuals, UrdfCollisions)."""
    from unityscaffold.unity import SceneDocument
    from unityscaffold.urdf import read_urdf

    folder = project / "ros"
    packages = {name: folder / path for name, path in robot.packages.items()}
    urdf = read_urdf(
        folder / robot.urdf, packages=packages, xacro_args=robot.args, xacro_env=robot.env
    )
    visuals = sum(len(link.visuals) for link in urdf.links)
    collisions = sum(len(link.collisions) for link in urdf.links)
    expected = 2 + 3 * len(urdf.links) + 2 * visuals + 2 * collisions
    scene = SceneDocument.load(project / SCENE)
    roots = [root for root in scene.roots() if root.name == urdf.name]
    if len(roots) != 1:
        return f"{len(roots)} root objects named {urdf.name!r} in the scene, not 1"
    count, below = 0, [roots[0]]
    while below:
        go = below.pop()
        count += 1
        if not go.is_prefab_instance:
            below.extend(scene.children(go))
    if count == expected:
        return ""
    return (
        f"{count} objects under and with the robot, where ROS# makes {expected} "
        f"(2 + 3·{len(urdf.links)} links + 2·{visuals} visuals + 2·{collisions} collisions)"
    )


def machine_bound(project: Path) -> list[str]:
    """The files apply wrote that hold the project's absolute path: a clone elsewhere would see
    them as drift, so output must not depend on where the project lies."""
    where = str(project).encode()
    found = []
    for path in sorted(project.rglob("*")):
        relative = path.relative_to(project).as_posix()
        data = path.read_bytes() if path.is_file() and not relative.startswith("ros/") else b""
        at = data.find(where)
        if at >= 0:
            line = data[max(0, at - 60) : at + len(where) + 60].decode(errors="replace")
            found.append(f"{relative}: …{line}…")
    return found


def run(
    robots: list[Robot],
    checkouts: dict[str, Checkout],
    root: Path,
    keep: Path | None,
    stand_ins: bool = False,
) -> Iterator[Verdict]:
    work = Path(tempfile.mkdtemp(prefix="robot-survey-")) if keep is None else keep
    work.mkdir(parents=True, exist_ok=True)
    env = child_env(work)
    template = work / "init"
    if not template.exists():
        status, output, _ = scaffold(env, "init", str(template), "--ros", "2")
        assert status == 0, output
    try:
        for robot in robots:
            not_there = missing_checkouts(robot, checkouts, root)
            if not_there:
                detail = f"not in {root}: {not_there}"
                yield Verdict(robot.name, robot.set, robot.rossharp, "missing", detail=detail)
                continue
            shutil.rmtree(work / robot.name, ignore_errors=True)
            project = prepare(robot, checkouts, root, template)
            lacking = absent_files(robot, root, project)
            placed = stand_in(project, lacking) if stand_ins else []
            still = {path for path in lacking if not Path(path).exists()}
            verdict = survey(robot, project, env, still)
            verdict.stand_ins = placed
            yield verdict
    finally:
        if keep is None:
            shutil.rmtree(work, ignore_errors=True)


def describe(verdict: Verdict) -> list[str]:
    """The verdict as text: a line for the robot, one per cause of a refusal (with its count
    and first error), the first lines of what went wrong otherwise."""
    took = sum(verdict.seconds.values())
    lines = [f"{verdict.name:<20} {verdict.set:<8} {verdict.status:<10} {took:6.2f} s"]
    if verdict.stand_ins:
        lines[0] += f"  ({len(verdict.stand_ins)} stand-in files: {', '.join(verdict.stand_ins)})"
    for reason, messages in verdict.causes.items():
        lines.append(f"    {len(messages):>3} x {reason}")
        lines.extend(f"          {message}" for message in messages[:1])
    lines.extend(f"    {line}" for line in verdict.detail.splitlines()[-12:])
    if verdict.status != "imported":
        lines.append(f"    ROS#: {verdict.rossharp}")
    return lines


def summary(verdicts: list[Verdict]) -> list[str]:
    lines = []
    for name in [*sorted({v.set for v in verdicts}), "all"]:
        chosen = [v for v in verdicts if name in ("all", v.set)]
        counts = Counter(v.status for v in chosen)
        shown = ", ".join(f"{n} {status}" for status, n in sorted(counts.items()))
        lines.append(f"{name}: {shown} (of {len(chosen)})")
    causes = Counter(reason for v in verdicts for reason in v.causes)
    if causes:
        lines.append("refusals by cause (robots):")
    lines.extend(f"  {n:>3}  {reason}" for reason, n in causes.most_common())
    return lines


def default_root() -> Path:
    """Where the checkouts are: ``$UNITYSCAFFOLD_ROBOTS``, else ``robots`` beside the clone."""
    return Path(os.environ.get(ROOT_VARIABLE) or REPO.parent / "robots")


def parse(argv: list[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", type=Path, default=default_root(), help="the checkouts")
    parser.add_argument("--only", action="append", default=[], metavar="NAME")
    parser.add_argument("--set", help="only the robots of this set (popular, more, extra)")
    parser.add_argument("--json", action="store_true", help="the verdicts as JSON")
    parser.add_argument("--keep", type=Path, help="make the projects here and keep them")
    parser.add_argument("--list", type=Path, default=LIST, help="the list of robots")
    parser.add_argument(
        "--stand-ins",
        action="store_true",
        help="replace the files <checkout>.missing lists by files of their kind",
    )
    parser.add_argument("--clone-commands", action="store_true", help="print, run nothing")
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    # the scene and the URDF are read back with this tree's unityscaffold, as apply runs it
    sys.path.insert(0, str(REPO))
    options = parse(argv)
    checkouts, robots = load_list(options.list)
    if options.clone_commands:
        print("\n".join(clone_commands(checkouts, options.root)))
        return 0
    unknown = set(options.only) - {r.name for r in robots}
    if unknown:
        print(f"no robot {sorted(unknown)} in {options.list}", file=sys.stderr)
        return 2
    chosen = [
        r
        for r in robots
        if (not options.only or r.name in options.only) and options.set in (None, r.set)
    ]
    verdicts = []
    for verdict in run(chosen, checkouts, options.root, options.keep, options.stand_ins):
        verdicts.append(verdict)
        if not options.json:
            print("\n".join(describe(verdict)), flush=True)
    if options.json:
        print(json.dumps([asdict(v) for v in verdicts], indent=2))
    else:
        print("\n".join(summary(verdicts)))
    bugs = ("crashed", "unstable", "unportable", "misshapen")
    return 1 if any(v.status in bugs for v in verdicts) else 0


if __name__ == "__main__":
    sys.exit(main())
