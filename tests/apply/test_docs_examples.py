"""Every manifest example the documentation shows, and the starter ``scaffold init`` writes with
its commented entries turned on, applies on a fresh ``init`` project: apply exits 0, ``--check``
is clean, and a second apply writes nothing.

A documentation example is a fenced ``yaml`` block of README.md or docs/*.md with a top-level
``version:`` key, or a fragment whose top-level keys are manifest sections (``objects:``,
``components:``...), which is applied under a minimal header (ROS 2, the init scene). Other
blocks, such as the pre-commit hook, are not manifests.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from helpers import run_cli

REPO = Path(__file__).resolve().parents[2]
DOCS = [REPO / "README.md", *sorted((REPO / "docs").glob("*.md"))]
_FENCE = re.compile(r"(?ms)^```yaml\n(.*?)^```")
# The starter's commented entries: "#  - {...}" items and their "#    key: ..." lines. Its
# commented `interfaces:` folder is not an example: it names the user's own workspace.
_ENTRY = re.compile(r"(?m)^#(  - |    \w)")
_SECTIONS = ("connector", "topics", "services", "components", "objects", "robots")
# What a robot example's URDF stands for here: a robot of two links named after its file
# (r2d2.urdf: "r2d2"), base_link and head, which the examples' components name.
_URDF = (
    '<robot name="{name}"><link name="base_link"><visual><geometry><box size="1 1 1"/>'
    '</geometry></visual></link><link name="head"/><joint name="neck" type="fixed">'
    '<parent link="base_link"/><child link="head"/></joint></robot>'
)
_HEADER = "version: 1\nros: 2\nscene: Assets/Scenes/Main.unity\n"


def _examples() -> list[tuple[str, str]]:
    found = []
    for path in DOCS:
        text = path.read_text(encoding="utf-8")
        for match in _FENCE.finditer(text):
            block = match.group(1)
            keys = re.findall(r"(?m)^(\w+):", block)
            if "version" not in keys and keys and set(keys) <= set(_SECTIONS):
                block = _HEADER + block
            elif "version" not in keys:
                continue
            line = text.count("\n", 0, match.start()) + 2
            found.append((f"{path.relative_to(REPO).as_posix()}:{line}", block))
    return found


EXAMPLES = _examples()


def _ros(manifest: str) -> str:
    found = re.search(r"(?m)^ros: *([12])\b", manifest)
    assert found is not None, "an example without `ros:`"
    return found.group(1)


def _robot_files(project: Path, manifest: str) -> None:
    """The URDF files and package folders the example's robots name, made up (see _URDF)."""
    for urdf in re.findall(r"(?m)^  - urdf: (\S+)$", manifest):
        path = project / urdf
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(_URDF.format(name=Path(urdf).stem), encoding="utf-8")
    for packages in re.findall(r"(?m)^    packages: \{(.*)\}$", manifest):
        for folder in re.findall(r": ([^,]+)", packages):
            (project / folder.strip()).mkdir(parents=True, exist_ok=True)


def _applies_and_settles(project: Path, manifest: str) -> None:
    _robot_files(project, manifest)
    path = project / "robot.yaml"
    path.write_text(manifest, encoding="utf-8")
    first = run_cli("apply", str(path))
    assert first.code == 0, manifest + first.err
    check = run_cli("apply", "--check", str(path))
    assert check.code == 0, manifest + check.out + check.err
    again = run_cli("apply", str(path))
    assert again.out.endswith("wrote 0 files, removed 0\n"), again.out


def test_the_documentation_has_manifest_examples() -> None:
    shown = [where for where, _ in EXAMPLES if where.startswith("docs/manifest.md:")]
    assert len(shown) >= 3, shown  # the whole manifest, components with ids, objects


@pytest.mark.parametrize(("where", "manifest"), EXAMPLES, ids=[w for w, _ in EXAMPLES])
def test_a_documented_manifest_applies_on_a_fresh_project(
    tmp_path: Path, where: str, manifest: str
) -> None:
    project = tmp_path / "p"
    assert run_cli("init", str(project), "--ros", _ros(manifest)).code == 0
    _applies_and_settles(project, manifest)


@pytest.mark.parametrize("ros", ["1", "2"])
def test_the_starter_applies_with_its_examples_turned_on(tmp_path: Path, ros: str) -> None:
    project = tmp_path / "p"
    assert run_cli("init", str(project), "--ros", ros).code == 0
    starter = (project / "robot.yaml").read_text(encoding="utf-8")
    uncommented = _ENTRY.sub(r"\1", starter)
    assert uncommented.count("  - ") >= 4, uncommented  # two topics, a service, a component
    _applies_and_settles(project, uncommented)
