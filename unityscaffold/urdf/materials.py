"""The ``.mat`` files ROS#'s importer makes in the robot's ``Materials`` folder.

``Default`` (grey, transparent: what a mesh visual without a material of its own gets), one
per top-level ``<material>``, and one per material a visual defines inline under a name not
yet taken: the first definition of a name wins, as ROS# reuses a ``.mat`` that exists. A
material without a name is named after its colour (``rgba-1-0-0-1``) or texture. All are
Standard materials with ROS#'s metallic and smoothness of 0.75.
"""

from __future__ import annotations

from collections.abc import Iterator

from unityscaffold.errors import LocatedError
from unityscaffold.unity.material import standard_material
from unityscaffold.urdf._components import material_name
from unityscaffold.urdf.model import Link, Material, Robot

__all__ = ["DEFAULT_MATERIAL_NAME", "importer_materials"]

DEFAULT_MATERIAL_NAME = "Default"
_DEFAULT_COLOR = (0.33, 0.33, 0.33, 0.0)


def importer_materials(robot: Robot) -> dict[str, str]:
    """``{file name: text}`` of every ``.mat`` file, by name."""
    colours: dict[str, tuple[float, float, float, float]] = {DEFAULT_MATERIAL_NAME: _DEFAULT_COLOR}
    for material in (*robot.materials, *_visual_materials(robot, robot.root)):
        name = material_name(material)
        if name in colours:
            continue
        _check_file_name(material, name)
        if material.color is None and material.texture is not None:
            raise LocatedError.at(
                material.location,
                f"material {name!r} has a texture, which is not supported yet",
                hint='give the material a <color rgba="…"/> instead',
            )
        colours[name] = material.color or (1.0, 1.0, 1.0, 1.0)  # Standard's own white
    return {
        f"{name}.mat": standard_material(name, colour, metallic=0.75, smoothness=0.75)
        for name, colour in sorted(colours.items())
    }


# Unity refuses these in an asset's name on every platform; a separator or '..' would put the
# .mat file outside the Materials folder
_NOT_IN_FILE_NAMES = frozenset('/\\:*?"<>|')


def _check_file_name(material: Material, name: str) -> None:
    bad = sorted({c for c in name if c in _NOT_IN_FILE_NAMES or not c.isprintable()})
    if name.strip(". ") and not bad:
        return
    shown = ", ".join(repr(c) for c in bad) if bad else "no letters" if name else "no name"
    raise LocatedError.at(
        material.location,
        f"material {name!r} cannot name its .mat file ({shown})",
        hint="rename the material with letters, digits, '_', '-' or spaces",
    )


def _visual_materials(robot: Robot, root: Link) -> Iterator[Material]:
    """Visual materials in the order ROS# builds the links (depth first, by joint order)."""
    named = {link.name: link for link in reversed(robot.links)}  # the first of a name wins
    children: dict[str, list[str]] = {}
    for joint in robot.joints:
        children.setdefault(joint.parent, []).append(joint.child)
    stack = [root]
    while stack:
        link = stack.pop()
        yield from (visual.material for visual in link.visuals if visual.material is not None)
        stack += [named[child] for child in reversed(children.get(link.name, []))]
