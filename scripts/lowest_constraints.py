"""Print a pip constraints file that pins every direct dependency to its declared floor.

``python3 scripts/lowest_constraints.py > lowest.txt`` then
``pip install -c lowest.txt -e '.[test,bag,xacro]'`` installs the oldest versions ``pyproject.toml``
claims to support (what ``uv pip install --resolution lowest-direct`` does), with pip alone.
Only direct requirements are pinned; what they depend on resolves as usual. A requirement with
no ``>=`` floor (the ROS 2 interface wheels) is left free, and so is an exact ``==`` pin.

``.ci/run`` runs the tests against these versions, so a floor that is not true fails CI.
Needs ``packaging`` (and ``tomli`` on Python 3.10), both installed with hatchling.
"""

from __future__ import annotations

import sys
from pathlib import Path

from packaging.requirements import Requirement

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10: tomli, which hatchling (a test dependency) brings
    import tomli as tomllib

PYPROJECT = Path(__file__).resolve().parent.parent / "pyproject.toml"
#: The extras whose floors are checked; ``lint`` pins exact versions already.
EXTRAS = ("bag", "xacro", "test")


def direct_requirements(project: dict[str, object]) -> list[Requirement]:
    """The runtime requirements and those of ``EXTRAS``, without the project itself."""
    texts = list(project["dependencies"])  # type: ignore[call-overload]
    extras = project["optional-dependencies"]
    for extra in EXTRAS:
        texts.extend(extras[extra])  # type: ignore[index]
    name = project["name"]
    return [r for r in map(Requirement, texts) if r.name != name]


def floor(requirement: Requirement) -> str | None:
    """The version after ``>=``, if the requirement has one."""
    floors = [s.version for s in requirement.specifier if s.operator == ">="]
    return floors[0] if len(floors) == 1 else None


def main() -> int:
    project = tomllib.loads(PYPROJECT.read_text(encoding="utf-8"))["project"]
    pins = {r.name.lower(): floor(r) for r in direct_requirements(project)}
    for name, version in sorted(pins.items()):
        if version is not None:
            print(f"{name}=={version}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
