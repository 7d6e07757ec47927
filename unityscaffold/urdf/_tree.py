"""The links and joints of a robot must form one tree: checks, each a located diagnostic.

ROS#'s importer assumes a tree and, when it is not one, builds something else without a word
(a first-match link for a duplicate name, an empty GameObject ``link`` for a missing child,
the ancestor of the first joint as root, an endless walk for a cycle); these checks refuse it.
"""

from __future__ import annotations

from collections import Counter

from unityscaffold.errors import DiagnosticSink
from unityscaffold.urdf.model import Robot

__all__ = ["check_tree"]


def check_tree(robot: Robot, sink: DiagnosticSink, *, complete: bool = True) -> None:
    """Add a diagnostic to ``sink`` for everything that keeps ``robot`` from being a tree.

    ``complete`` is False when some links or joints could not be read: the checks that need
    all of them (roots, cycles, none at all) are then left out rather than reported on a
    partial picture.
    """
    _unique_names(robot, sink)
    _known_links(robot, sink)
    _one_parent(robot, sink)
    if complete and robot.links:
        _one_root_no_cycle(robot, sink)
    if complete and not robot.links:
        sink.error(
            robot.location,
            f"robot {robot.name!r} has no <link>",
            hint='a URDF needs at least one <link name="…">',
        )


def _unique_names(robot: Robot, sink: DiagnosticSink) -> None:
    for kind, items in (("link", robot.links), ("joint", robot.joints)):
        seen: set[str] = set()
        for item in items:
            if item.name in seen:
                sink.error(
                    item.location,
                    f"a second {kind} named {item.name!r}",
                    hint=f"give every {kind} a name of its own",
                )
            seen.add(item.name)


def _known_links(robot: Robot, sink: DiagnosticSink) -> None:
    names = {link.name for link in robot.links}
    for joint in robot.joints:
        for role, name in (("parent", joint.parent), ("child", joint.child)):
            if name not in names:
                sink.error(
                    joint.location,
                    f"joint {joint.name!r} names the {role} link {name!r}, "
                    "which the robot does not have",
                    hint=f"links: {', '.join(sorted(names)) or 'none'}",
                )


def _one_parent(robot: Robot, sink: DiagnosticSink) -> None:
    counts = Counter(joint.child for joint in robot.joints)
    reported: set[str] = set()
    for joint in robot.joints:
        if counts[joint.child] > 1 and joint.child in reported:
            sink.error(
                joint.location,
                f"link {joint.child!r} is the child of a second joint, {joint.name!r}",
                hint="in a URDF every link has at most one parent joint",
            )
        reported.add(joint.child)


def _one_root_no_cycle(robot: Robot, sink: DiagnosticSink) -> None:
    children = {joint.child for joint in robot.joints}
    # a duplicate name is reported on its own: a root named twice is one root here
    roots = list({link.name: link for link in robot.links if link.name not in children}.values())
    if len(roots) > 1:
        names = ", ".join(repr(link.name) for link in roots)
        for link in roots[1:]:
            sink.error(
                link.location,
                f"link {link.name!r} is a second root (no joint has it as child); roots: {names}",
                hint="connect every link but one to a parent with a <joint>",
            )
    _no_cycle(robot, sink)


def _no_cycle(robot: Robot, sink: DiagnosticSink) -> None:
    """Walk up from every link once; a walk that comes back to itself is a cycle."""
    parent_of = {joint.child: joint for joint in robot.joints}
    settled: set[str] = set()  # links already known to reach a root or a reported cycle
    for joint in robot.joints:
        path: dict[str, None] = {joint.child: None}  # ordered, with O(1) membership
        current = joint.parent
        while current in parent_of and current not in path and current not in settled:
            path[current] = None
            current = parent_of[current].parent
        walked = list(path)
        settled.update(walked)
        if current in path:
            cycle = walked[walked.index(current) :]
            loop = " → ".join([*reversed(cycle), cycle[-1]])
            sink.error(
                parent_of[current].location,
                f"the joints form a cycle: {loop}",
                hint="links and joints must form a tree; remove a joint of the cycle",
            )
