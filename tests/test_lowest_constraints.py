"""scripts/lowest_constraints.py pins every direct dependency with a floor to that floor, so
CI's run against the oldest allowed versions (.ci/run) covers all of them."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from packaging.requirements import Requirement

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10: tomli, which hatchling (a test dependency) brings
    import tomli as tomllib

REPO = Path(__file__).resolve().parent.parent


def _pins() -> dict[str, str]:
    out = subprocess.run(
        [sys.executable, str(REPO / "scripts" / "lowest_constraints.py")],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    return dict(line.split("==") for line in out.splitlines())


def test_every_runtime_bag_xacro_and_test_floor_is_pinned() -> None:
    project = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    extras = project["optional-dependencies"]
    texts = [*project["dependencies"], *extras["bag"], *extras["xacro"], *extras["test"]]
    declared = [Requirement(t) for t in texts]
    expected = {
        r.name.lower(): s.version
        for r in declared
        if r.name != project["name"]
        for s in r.specifier
        if s.operator == ">="
    }
    assert _pins() == expected
    # the runtime dependencies a user installs are all among them
    runtime = {Requirement(t).name.lower() for t in project["dependencies"]}
    assert runtime <= set(expected)
    known = {"typer", "jinja2", "ruamel.yaml", "pyyaml", "websockets", "rosbags", "xacro"}
    assert known <= set(expected)
