"""The GameObjects ROS#'s importer builds for a robot: tree, names, order, components, poses.

``importer_tree(robot)`` is the whole hierarchy as ROS# 2.2.1's editor importer creates it
(``docs/architecture.md``, "The urdf stage"):

    <robot name>                  UrdfRobot
      Plugins                     UrdfPlugins, one UrdfPlugin per plugin element
      <root link>                 UrdfLink (+ Rigidbody, UrdfInertial with an <inertial>)
        Visuals                   UrdfVisuals                    (not editable: hide flags 8)
          <visual name|unnamed>   UrdfVisual, posed by <origin>, scaled to the shape
            Cube|Cylinder|Sphere  MeshFilter, MeshRenderer  |  <mesh file stem>: the model
        Collisions                UrdfCollisions                 (not editable: hide flags 8)
          unnamed                 UrdfCollision (a collision's name is not used)
            Box|Cylinder|Sphere   BoxCollider | MeshCollider | SphereCollider  |  <mesh stem>
        <child link>              … + the joint's components, posed by the joint's <origin>

Child links follow Visuals and Collisions in the order of the ``<joint>`` elements naming
their parent. A link gets its joint's components only when it has an ``<inertial>`` and its
parent has one too (ROS# needs both Rigidbodies). Each object carries ``key``, the URDF
element it comes from by position (``link[3]/visual[0]``), stable across renames of siblings.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from pathlib import PurePosixPath

from unityscaffold.urdf import transforms as t
from unityscaffold.urdf._components import (
    CYLINDER_MESH,
    DEFAULT_MATERIAL,
    ComponentRef,
    ImportedComponent,
    MaterialRef,
    Value,
    geometry_components,
    joint_components,
    link_components,
    material_name,
    part_components,
    plugin_components,
)
from unityscaffold.urdf._material_names import material_stems
from unityscaffold.urdf.model import (
    Box,
    Collision,
    Cylinder,
    Geometry,
    Joint,
    Link,
    Mesh,
    Robot,
    Sphere,
    Vector3,
    Visual,
)

__all__ = [
    "CYLINDER_MESH",
    "DEFAULT_MATERIAL",
    "ComponentRef",
    "ImportedComponent",
    "ImportedObject",
    "LocalTransform",
    "MaterialRef",
    "Role",
    "Value",
    "importer_tree",
]


class Role(enum.Enum):
    ROBOT = "robot"
    PLUGINS = "plugins"
    LINK = "link"
    VISUALS = "visuals"
    COLLISIONS = "collisions"
    VISUAL = "visual"
    COLLISION = "collision"
    SHAPE = "shape"  # a primitive or collider object made in the scene
    MODEL = "model"  # an instance of the mesh file's model or prefab


@dataclass(frozen=True, slots=True)
class LocalTransform:
    """A Transform's local values; the default is how ROS#'s ``SetParentAndAlign`` leaves an
    object it does not move after (a negative-zero identity rotation)."""

    position: Vector3 = (0.0, 0.0, 0.0)
    rotation: t.Quaternion = t.ALIGNED
    scale: Vector3 = (1.0, 1.0, 1.0)


@dataclass(frozen=True, slots=True)
class ImportedObject:
    """One GameObject: ``components`` follow the Transform in the order ROS# adds them, each
    with the fields the importer sets (none for a model instance: its components are the
    model's)."""

    name: str
    role: Role
    key: str
    transform: LocalTransform
    components: tuple[ImportedComponent, ...]
    children: tuple[ImportedObject, ...] = ()
    not_editable: bool = False

    @property
    def component_names(self) -> list[str]:
        return [component.name for component in self.components]

    def walk(self, depth: int = 0) -> list[tuple[int, ImportedObject]]:
        """This object and everything under it, depth first, with their depths (without
        recursion, as a long chain of links is deeper than Python's stack)."""
        found: list[tuple[int, ImportedObject]] = []
        pending = [(depth, self)]
        while pending:
            level, item = pending.pop()
            found.append((level, item))
            pending.extend((level + 1, child) for child in reversed(item.children))
        return found


def importer_tree(robot: Robot, *, plugin_newline: str = "\r\n") -> ImportedObject:
    """The robot's GameObjects as ROS#'s importer creates them (``robot`` must be a tree, as
    ``read_urdf`` guarantees). ``plugin_newline`` is the importing machine's newline, which
    ends the lines of the plugin texts (the default is Windows', as in ROS#'s samples)."""
    texts = [plugin.text.replace("\n", plugin_newline) for plugin in robot.plugins]
    plugins = ImportedObject(
        "Plugins", Role.PLUGINS, "plugins", LocalTransform(), tuple(plugin_components(texts))
    )
    root = _links_tree(_Links(robot), robot.root)
    # a new GameObject, placed where the user's selection is: not ROS#'s alignment
    placed = LocalTransform(rotation=t.IDENTITY)
    robot_script = (ImportedComponent("UrdfRobot"),)
    return ImportedObject(robot.name, Role.ROBOT, "robot", placed, robot_script, (plugins, root))


class _Links:
    """The robot's links by name (the first of a name, as ROS# finds it) and the joints
    under each link in document order: looked up once per link, not searched. With them, the
    ``.mat`` file each material name became."""

    def __init__(self, robot: Robot) -> None:
        self.material_stems = material_stems(robot)  # each material's .mat file name
        self.index: dict[str, int] = {}
        self.named: dict[str, Link] = {}
        for i, link in enumerate(robot.links):
            self.index.setdefault(link.name, i)
            self.named.setdefault(link.name, link)
        self.children: dict[str, list[Joint]] = {name: [] for name in self.named}
        for joint in robot.joints:
            self.children[joint.parent].append(joint)

    def key(self, link: Link) -> str:
        return f"link[{self.index[link.name]}]"


def _links_tree(links: _Links, root: Link) -> ImportedObject:
    """The root link and everything under it, children built before their parents without
    recursion (a serial chain of some 500 links went past Python's recursion limit)."""
    visits: list[tuple[Link, Joint | None, str | None]] = []
    pending: list[tuple[Link, Joint | None, str | None]] = [(root, None, None)]
    while pending:
        link, joint, parent_key = pending.pop()
        visits.append((link, joint, parent_key))
        body = links.key(link) if link.inertial is not None else None
        for child in reversed(links.children[link.name]):
            pending.append((links.named[child.child], child, body))
    built: dict[str, ImportedObject] = {}
    for link, joint, parent_key in reversed(visits):  # every child before its parent
        children = tuple(
            built.pop(links.key(links.named[j.child])) for j in links.children[link.name]
        )
        built[links.key(link)] = _link(links, link, joint, parent_key=parent_key, children=children)
    return built[links.key(root)]


def _link(
    links: _Links,
    link: Link,
    joint: Joint | None,
    *,
    parent_key: str | None,
    children: tuple[ImportedObject, ...],
) -> ImportedObject:
    """A link with its child links already built; ``parent_key`` is the parent link's key
    when that link has a Rigidbody."""
    key = links.key(link)
    components = link_components(link, key, has_joint=joint is not None)
    if link.inertial is not None and joint is not None and parent_key is not None:
        components += joint_components(joint, key, parent_key)
    origin = None if joint is None else joint.origin
    pose = LocalTransform(t.origin_position(origin), t.origin_rotation(origin))
    visuals = ImportedObject(
        "Visuals",
        Role.VISUALS,
        f"{key}/visuals",
        LocalTransform(),
        (ImportedComponent("UrdfVisuals"),),
        tuple(_part(links, v, f"{key}/visual[{i}]") for i, v in enumerate(link.visuals)),
        not_editable=True,
    )
    collisions = ImportedObject(
        "Collisions",
        Role.COLLISIONS,
        f"{key}/collisions",
        LocalTransform(),
        (ImportedComponent("UrdfCollisions"),),
        tuple(_part(links, c, f"{key}/collision[{i}]") for i, c in enumerate(link.collisions)),
        not_editable=True,
    )
    return ImportedObject(
        link.name, Role.LINK, key, pose, tuple(components), (visuals, collisions, *children)
    )


def _part(links: _Links, part: Visual | Collision, key: str) -> ImportedObject:
    visual = isinstance(part, Visual)
    pose = LocalTransform(
        t.origin_position(part.origin),
        t.origin_rotation(part.origin),
        t.geometry_scale(part.geometry),
    )
    material = None
    if isinstance(part, Visual) and part.material is not None:
        material = MaterialRef(links.material_stems[material_name(part.material)])
    return ImportedObject(
        (part.name or "unnamed") if visual else "unnamed",
        Role.VISUAL if visual else Role.COLLISION,
        key,
        pose,
        tuple(part_components(part.geometry, visual=visual)),
        (_shape(part.geometry, material, f"{key}/shape", visual=visual),),
    )


_VISUAL_SHAPES = {Box: "Cube", Cylinder: "Cylinder", Sphere: "Sphere"}
_COLLISION_SHAPES = {Box: "Box", Cylinder: "Cylinder", Sphere: "Sphere"}


def _shape(
    geometry: Geometry, material: MaterialRef | None, key: str, *, visual: bool
) -> ImportedObject:
    components = tuple(geometry_components(geometry, material, visual=visual))
    if isinstance(geometry, Mesh):
        stem = PurePosixPath(geometry.filename).stem
        return ImportedObject(stem, Role.MODEL, key, LocalTransform(), components)
    name = (_VISUAL_SHAPES if visual else _COLLISION_SHAPES)[type(geometry)]
    return ImportedObject(name, Role.SHAPE, key, LocalTransform(), components)
