"""The model Unity imports from a COLLADA file, as far as a scene holding it can see.

A scene names a model's objects by fileIDs that follow from the model's node tree
(``unity.modelids``) and records its root's pose. Both follow from the file by these rules:

- **Objects.** The model's root GameObject is ``//RootNode/root``. A file whose visual scene
  has one top node is folded into the root (the node *is* the root, its children below it);
  otherwise every top node is a child of the root. A node's GameObject is at its parent's
  path and ``/<name>`` (the node's ``name``, else its ``id``). A node that instantiates a
  geometry has a MeshFilter and a MeshRenderer, and a Mesh named after the node. Seen in
  Unity-written files: the r2d2 sample's one-node models (root objects and the Mesh by the
  node's name), and a Unity 2020.3 scene holding URDF-Importer instances of UR3 models of
  2 to 12 top nodes (``m_Materials`` changes on every ``//RootNode/root/<node>`` renderer).
  Inferred from the same hash rule: nested nodes' paths, and the counter that tells apart
  objects of one class at one path (two siblings of one name), in depth-first order.
- **Root pose.** Unity turns the file's axes into its own on the top nodes (FBX SDK axis
  conversion: ``Z_UP`` -90° about x, ``X_UP`` 90° about z), then mirrors x (right- to
  left-handed); a folded root carries that node's pose, an unfolded one the identity. ROS#'s
  ``ColladaAssetPostProcessor`` then sets the root to its "position fix" of that position
  and turns it by ``Euler(-90, 90, 0)`` (``Y_UP`` and anything it cannot read), ``Euler(0,
  90, 0)`` (``Z_UP``) or ``Euler(-90, 90, 90)`` (``X_UP``). Seen: ``Y_UP`` one node (r2d2,
  ``(-0.5, 0.5, 0.5, 0.5)``), ``Z_UP`` one node (Unity's Niryo One scene, the same), ``Z_UP``
  several nodes (the UR3 scene, ``(-0, 0.7071068, -0, 0.7071068)``). Inferred: ``X_UP``, and a
  folded node that is moved or turned (its position scaled by ROS#'s global scale).
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass

from unityscaffold.unity.modelids import ROOT_PATH, model_file_id
from unityscaffold.urdf import transforms as t
from unityscaffold.urdf.collada import ColladaFacts, ColladaNode, Matrix

__all__ = [
    "DrawnNode",
    "drawn_nodes",
    "imported_root_pose",
    "rotate",
    "turn",
    "unchecked_objects",
]

Vector3 = tuple[float, float, float]


@dataclass(frozen=True, slots=True)
class DrawnNode:
    """A node of the model that draws a geometry: the node, its GameObject's ``path`` in the
    model, and the fileIDs of its GameObject, MeshFilter, MeshRenderer and Mesh."""

    node: ColladaNode
    path: str
    gameobject: int
    filter: int
    renderer: int
    mesh: int


def drawn_nodes(facts: ColladaFacts) -> tuple[DrawnNode, ...]:
    """Every node that draws a geometry, depth first in document order."""
    placed: list[tuple[ColladaNode, str]] = []
    if len(facts.nodes) == 1:
        _place(facts.nodes[0], ROOT_PATH, placed)
    else:
        for node in facts.nodes:
            _place(node, f"{ROOT_PATH}/{_name(node)}", placed)
    counts: Counter[tuple[str, str]] = Counter()

    def fid(class_name: str, key: str) -> int:
        index = counts[class_name, key]
        counts[class_name, key] += 1
        return model_file_id(class_name, key, index)

    drawn: list[DrawnNode] = []
    for node, path in placed:
        gameobject = fid("GameObject", path)
        if node.geometries:
            filter_, renderer = fid("MeshFilter", path), fid("MeshRenderer", path)
            mesh = fid("Mesh", _name(node))
            drawn.append(DrawnNode(node, path, gameobject, filter_, renderer, mesh))
    return tuple(drawn)


def _place(node: ColladaNode, path: str, placed: list[tuple[ColladaNode, str]]) -> None:
    placed.append((node, path))
    for child in node.children:
        _place(child, f"{path}/{_name(child)}", placed)


def _name(node: ColladaNode) -> str:
    return node.name or node.id


# the FBX SDK's turn of each axis system into Y up (right-handed), as a 3×3 matrix by rows
_CONVERSIONS: dict[str, tuple[float, ...]] = {
    "Y_UP": (1, 0, 0, 0, 1, 0, 0, 0, 1),
    "Z_UP": (1, 0, 0, 0, 0, 1, 0, -1, 0),  # -90° about x: z up becomes y up
    "X_UP": (0, -1, 0, 1, 0, 0, 0, 0, 1),  # 90° about z: x up becomes y up
}
# ColladaAssetPostProcessor.getColladaRotationFix, in degrees
_ROTATION_FIX: dict[str, Vector3] = {"X_UP": (-90, 90, 90), "Z_UP": (0, 90, 0)}
_DEFAULT_FIX: Vector3 = (-90, 90, 0)


def imported_root_pose(facts: ColladaFacts) -> tuple[Vector3, t.Quaternion]:
    """The model root's position and rotation once imported and post-processed by ROS#: the
    pose its instances start from (a scene records it in the root's changes)."""
    if len(facts.nodes) == 1:
        position, rotation = _unity_pose(facts.nodes[0].matrix, facts.up_axis, facts.meter)
    else:
        position, rotation = (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)
    if facts.ros_up_axis == "Z_UP":  # getColladaPositionFix; the other axes keep it
        position = (-position[2], position[1], -position[0])
    fix = _euler(*_ROTATION_FIX.get(facts.ros_up_axis, _DEFAULT_FIX))
    x, y, z = position
    return (x + 0.0, y + 0.0, z + 0.0), turn(fix, rotation)  # a zero is saved as 0


def _unity_pose(matrix: Matrix, up_axis: str, scale: float) -> tuple[Vector3, t.Quaternion]:
    """A top node's pose in Unity's axes: converted to Y up, then x mirrored."""
    c = _CONVERSIONS.get(up_axis, _CONVERSIONS["Y_UP"])
    m = [[matrix[4 * r + k] for k in range(4)] for r in range(3)]
    turned = [[sum(c[3 * r + k] * m[k][j] for k in range(3)) for j in range(4)] for r in range(3)]
    x, y, z = (turned[r][3] * scale for r in range(3))
    columns = [[turned[r][j] for r in range(3)] for j in range(3)]
    lengths = [math.sqrt(sum(v * v for v in col)) or 1.0 for col in columns]
    rotation = [[turned[r][j] / lengths[j] for j in range(3)] for r in range(3)]
    qx, qy, qz, qw = _quaternion(rotation)
    return (-x, y, z), (qx, -qy, -qz, qw)


def _quaternion(r: list[list[float]]) -> t.Quaternion:
    """The unit quaternion of a rotation matrix (Shepperd's method, largest term first)."""
    trace = r[0][0] + r[1][1] + r[2][2]
    if trace > 0:
        s = math.sqrt(trace + 1) * 2
        return ((r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s, s / 4)
    i = max(range(3), key=lambda k: r[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = math.sqrt(max(r[i][i] - r[j][j] - r[k][k] + 1, 0.0)) * 2 or 1.0
    q = [0.0, 0.0, 0.0, (r[k][j] - r[j][k]) / s]
    q[i], q[j], q[k] = s / 4, (r[j][i] + r[i][j]) / s, (r[k][i] + r[i][k]) / s
    return (q[0], q[1], q[2], q[3])


def _euler(x: float, y: float, z: float) -> t.Quaternion:
    """Unity's ``Quaternion.Euler`` in degrees (z, then x, then y), in double (rounded to
    float32 at the end, this gives the r2d2 scene's exact 0.5s)."""
    hx, hy, hz = (math.radians(a) / 2 for a in (x, y, z))
    sx, cx, sy, cy, sz, cz = (f(h) for h in (hx, hy, hz) for f in (math.sin, math.cos))
    return (
        cy * sx * cz + sy * cx * sz,
        sy * cx * cz - cy * sx * sz,
        cy * cx * sz - sy * sx * cz,
        cy * cx * cz + sy * sx * sz,
    )


def turn(a: t.Quaternion, b: t.Quaternion) -> t.Quaternion:
    """The rotation ``a * b`` (``b`` first, then ``a``), as Unity's quaternion product."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by + ay * bw + az * bx - ax * bz,
        aw * bz + az * bw + ax * by - ay * bx,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def rotate(q: t.Quaternion, v: Vector3) -> Vector3:
    """``v`` turned by ``q``."""
    x, y, z, _ = turn(turn(q, (v[0], v[1], v[2], 0.0)), (-q[0], -q[1], -q[2], q[3]))
    return (x, y, z)


def unchecked_objects(drawn: tuple[DrawnNode, ...]) -> str | None:
    """Why the objects of a model's drawn nodes do not follow from a rule seen in Unity's
    files, if they do not. The FBX SDK, which reads COLLADA for Unity, keeps a node's first
    attribute (geometry, camera, light or controller) on the node and makes a child node of
    each further one (its ``FbxReaderCollada::ImportNode``, as its public header documents);
    what it names those children no Unity-written file here shows, nor what Unity names a
    node with neither name nor id."""
    for node in drawn:
        attributes = node.node.geometries + node.node.others
        if attributes > 1:
            return (
                f"its node {_shown(node.node)} holds {attributes} geometries, cameras or "
                "lights, of which the FBX SDK that reads it for Unity makes a child node each "
                "but the first, under names no Unity-written file here shows"
            )
        if "//" in node.path.removeprefix("//") or node.path.endswith("/"):
            return (
                "a node without name or id leads to its node "
                f"{_shown(node.node)}, and what Unity names such a node is not checked"
            )
    return None


def _shown(node: ColladaNode) -> str:
    return f"{node.name or node.id!r} (line {node.location.line})"
