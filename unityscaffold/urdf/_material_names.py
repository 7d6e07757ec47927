"""The ``.mat`` file each URDF material name becomes, the same on Windows, macOS and Linux.

ROS# 2.2.1 saves a material at ``Path.Combine(root, "Materials", Path.GetFileName(name) +
".mat")`` (``UrdfAssetPathHandler.GetMaterialAssetPath``) and, before making one, loads the
``.mat`` already at that path (``UrdfMaterial.CreateMaterial``). So:

- a name holding ``/`` keeps what follows its last ``/`` on every system (``pal/Orange`` is
  ``Orange.mat``), and names that end alike share one file, the first one's, as equal names do;
- what ROS# does with the rest differs by system or fails, so the file name is chosen here:
  Mono's ``Path.GetFileName`` also splits at ``\\`` and ``:`` on Windows only, and throws on
  ``"<>|`` and control characters there; Windows refuses ``*`` and ``?`` in file names and
  the device names (``CON``, ``NUL``, ``COM1``…) even with an extension; Unity's asset database
  ignores a file whose name starts with ``.`` (so ``..`` or an empty name make no asset). Each
  such character becomes ``_``, a leading ``.`` too, an empty name is ``_`` and a device name
  gets a leading ``_``;
- names that would still be one file on a case-insensitive disk (Windows', macOS') although
  ROS# on Linux makes two (``Red`` and ``red``), or that the replacements above made equal,
  are kept apart as Unity numbers a copy (``AssetDatabase.GenerateUniqueAssetPath``): the
  later one in ROS#'s order is ``red 1``, then ``red 2``.

The order is ROS#'s: its ``Default`` material first, the top-level materials, then the
visuals' materials in the order ROS# builds the links.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from unityscaffold.urdf._components import material_name
from unityscaffold.urdf.model import Link, Material, Robot

__all__ = ["DEFAULT_MATERIAL_NAME", "material_stems", "ordered_materials"]

DEFAULT_MATERIAL_NAME = "Default"
# characters Windows refuses in a file name (besides '/', taken by ROS#'s own rule)
_REPLACED = re.compile(r'[\\:*?"<>|\x00-\x1f]')
_DEVICES = re.compile(r"(CON|PRN|AUX|NUL|COM[1-9]|LPT[1-9])(\..*)?", re.IGNORECASE)


def material_stems(robot: Robot) -> dict[str, str]:
    """Each material name of ``robot`` (``material_name``'s) → its ``.mat`` file's name,
    without the extension; ``Default`` included."""
    stems: dict[str, str] = {}
    by_file: dict[str, str] = {}  # ROS#'s file name → ours
    taken: set[str] = set()  # ours, case-folded
    names = (material_name(material) for material in ordered_materials(robot))
    for name in (DEFAULT_MATERIAL_NAME, *names):
        if name in stems:
            continue
        rossharp = name.rsplit("/", 1)[-1]
        if rossharp not in by_file:
            by_file[rossharp] = _unique(_portable(rossharp), taken)
            taken.add(by_file[rossharp].casefold())
        stems[name] = by_file[rossharp]
    return stems


def _portable(name: str) -> str:
    """``name`` as a file name every system keeps and Unity imports."""
    stem = _REPLACED.sub("_", name)
    if stem.startswith("."):
        stem = "_" + stem[1:]
    if _DEVICES.fullmatch(stem):
        stem = "_" + stem
    return stem or "_"


def _unique(stem: str, taken: set[str]) -> str:
    """``stem``, or the first of ``stem 1``, ``stem 2``… no other name takes ignoring case."""
    found, number = stem, 0
    while found.casefold() in taken:
        number += 1
        found = f"{stem} {number}"
    return found


def ordered_materials(robot: Robot) -> Iterator[Material]:
    """The top-level materials, then the visuals' in the order ROS# builds the links (depth
    first, by joint order): the order in which ROS#'s importer makes their ``.mat`` files."""
    yield from robot.materials
    yield from _visual_materials(robot, robot.root)


def _visual_materials(robot: Robot, root: Link) -> Iterator[Material]:
    named = {link.name: link for link in reversed(robot.links)}  # the first of a name wins
    children: dict[str, list[str]] = {}
    for joint in robot.joints:
        children.setdefault(joint.parent, []).append(joint.child)
    stack = [root]
    while stack:
        link = stack.pop()
        yield from (visual.material for visual in link.visuals if visual.material is not None)
        stack += [named[child] for child in reversed(children.get(link.name, []))]
