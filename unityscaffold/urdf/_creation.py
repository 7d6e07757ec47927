"""How ROS#'s importer poses the objects it creates, as a scene saves them.

ROS# makes a link's visuals and collisions before it poses the link (``UrdfLinkExtensions.
Create``), then parents each geometry object with ``SetParentAndAlign``, which keeps its world
pose: so a model root's saved pose depends on how the links above it are turned
(``creation_turns``), and a rotation carries the sign of zero re-parenting leaves.
"""

from __future__ import annotations

from unityscaffold.urdf import transforms as t
from unityscaffold.urdf.colladamodel import rotate, turn
from unityscaffold.urdf.model import Robot, Vector3

__all__ = ["creation_turns", "local_position", "saved_rotation"]


def creation_turns(robot: Robot) -> dict[str, t.Quaternion]:
    """How each link's geometries' parents are turned in the world when ROS# makes them: as
    the link's parent link is, since ROS# poses a link (its joint's origin) only after making
    its visuals and collisions, and its children after that (``UrdfLinkExtensions.Create``),
    with the robot's root at the origin unturned."""
    turns: dict[str, t.Quaternion] = {}
    # (a link, how its parent is turned in the world, its own turn in its parent)
    stack: list[tuple[str, t.Quaternion, t.Quaternion]] = [
        (robot.root.name, t.IDENTITY, t.IDENTITY)
    ]
    while stack:
        name, above, own = stack.pop()
        if name in turns:
            continue
        turns[name] = above
        posed = turn(above, own)
        for joint in robot.child_joints(name):
            stack.append((joint.child, posed, t.origin_rotation(joint.origin)))
    return {link.name: turns.get(link.name, t.IDENTITY) for link in robot.links}


def local_position(position: Vector3, turned: t.Quaternion) -> Vector3:
    """Where ROS#'s ``SetParentAndAlign`` leaves the instance's root: at the model's root
    position in world axes, under a parent turned by ``turned`` (the links above it, posed
    before this link is), so in its parent's axes that position turned back."""
    if position == (0.0, 0.0, 0.0):
        return position
    inverse = (-turned[0], -turned[1], -turned[2], turned[3])
    x, y, z = (t.f32(v) + 0.0 for v in rotate(inverse, position))
    return (x, y, z)


def saved_rotation(rotation: t.Quaternion) -> t.Quaternion:
    """A rotation as the scene saves the instance root's: float32, with the sign of zero that
    re-parenting leaves on x, y and z (-0: the r2d2 and UR3 scenes, ``unity.transforms``'s
    ``ALIGNED``). What double arithmetic leaves of an exact 0 (below 1e-9) is 0, as Unity's
    float arithmetic has it."""
    x, y, z, w = (t.f32(v) if abs(v) >= 1e-9 else 0.0 for v in rotation)
    return (x or -0.0, y or -0.0, z or -0.0, w)
