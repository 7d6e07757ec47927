"""The URDF model: a robot as its file says it, typed and frozen.

Values keep the distinctions ROS#'s importer makes: an absent ``<origin>`` (``None``) differs
from one written with zeros, an absent attribute of an origin is ``None`` too, and an absent
optional number (``<dynamics>``, ``<limit>``, ``<mimic>``, ``<safety_controller>``,
``<calibration>``) is NaN, as ROS# reads it. Lists keep document order. Every element carries
the place it was written (``location``), which is not part of its value.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field

from unityscaffold.errors import SourceLocation

__all__ = [
    "Box",
    "Calibration",
    "Collision",
    "Cylinder",
    "Dynamics",
    "Geometry",
    "Inertia",
    "Inertial",
    "Joint",
    "JointType",
    "Limit",
    "Link",
    "Material",
    "Mesh",
    "Mimic",
    "Origin",
    "Plugin",
    "Robot",
    "SafetyController",
    "Sphere",
    "Vector3",
    "Visual",
]

Vector3 = tuple[float, float, float]
NAN = math.nan
_NOWHERE = SourceLocation("<urdf>")


@dataclass(frozen=True, slots=True)
class Origin:
    """``<origin xyz rpy>``: metres and radians (roll about x, pitch about y, yaw about z)."""

    xyz: Vector3 | None = None
    rpy: Vector3 | None = None
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Box:
    size: Vector3
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Cylinder:
    radius: float
    length: float
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Sphere:
    radius: float
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Mesh:
    """``<mesh filename scale>``; the filename as written (``package://…``), not resolved."""

    filename: str
    scale: Vector3 | None = None
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


Geometry = Box | Cylinder | Sphere | Mesh


@dataclass(frozen=True, slots=True)
class Material:
    """A material: by name only (``color`` and ``texture`` None), or defined inline."""

    name: str
    color: tuple[float, float, float, float] | None = None
    texture: str | None = None
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Visual:
    geometry: Geometry
    name: str | None = None
    origin: Origin | None = None
    material: Material | None = None
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Collision:
    geometry: Geometry
    name: str | None = None
    origin: Origin | None = None
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Inertia:
    ixx: float
    ixy: float
    ixz: float
    iyy: float
    iyz: float
    izz: float


@dataclass(frozen=True, slots=True)
class Inertial:
    mass: float
    inertia: Inertia
    origin: Origin | None = None
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Link:
    name: str
    inertial: Inertial | None = None
    visuals: tuple[Visual, ...] = ()
    collisions: tuple[Collision, ...] = ()
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


class JointType(enum.Enum):
    """URDF's joint types; the value is the name a URDF writes."""

    REVOLUTE = "revolute"
    CONTINUOUS = "continuous"
    PRISMATIC = "prismatic"
    FIXED = "fixed"
    FLOATING = "floating"
    PLANAR = "planar"


@dataclass(frozen=True, slots=True)
class Limit:
    effort: float
    velocity: float
    lower: float = NAN
    upper: float = NAN


@dataclass(frozen=True, slots=True)
class Dynamics:
    damping: float = NAN
    friction: float = NAN


@dataclass(frozen=True, slots=True)
class Mimic:
    joint: str
    multiplier: float = NAN
    offset: float = NAN


@dataclass(frozen=True, slots=True)
class SafetyController:
    k_velocity: float = NAN
    k_position: float = NAN
    soft_lower_limit: float = NAN
    soft_upper_limit: float = NAN


@dataclass(frozen=True, slots=True)
class Calibration:
    rising: float = NAN
    falling: float = NAN


@dataclass(frozen=True, slots=True)
class Joint:
    """A joint; ``axis`` is None when ``<axis>`` is absent (ROS# then uses its own default)."""

    name: str
    type: JointType
    parent: str
    child: str
    origin: Origin | None = None
    axis: Vector3 | None = None
    limit: Limit | None = None
    dynamics: Dynamics | None = None
    mimic: Mimic | None = None
    safety_controller: SafetyController | None = None
    calibration: Calibration | None = None
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Plugin:
    """A top-level element that is not a link, joint or material (``<gazebo>``,
    ``<transmission>``, …), as ROS#'s importer keeps it: its XML text, with ``\\n`` newlines."""

    tag: str
    text: str
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Robot:
    """A URDF robot. ``root`` is the one link that is no joint's child; ``notes`` are what
    reading it warned about (xacro's warnings), each ``<file>: <text>``."""

    name: str
    links: tuple[Link, ...]
    joints: tuple[Joint, ...]
    materials: tuple[Material, ...] = ()
    plugins: tuple[Plugin, ...] = ()
    location: SourceLocation = field(default=_NOWHERE, compare=False, repr=False)
    notes: tuple[str, ...] = field(default=(), compare=False, repr=False)

    @property
    def root(self) -> Link:
        children = {joint.child for joint in self.joints}
        return next(link for link in self.links if link.name not in children)

    def link(self, name: str) -> Link:
        return next(link for link in self.links if link.name == name)

    def child_joints(self, link: str) -> tuple[Joint, ...]:
        """The joints whose parent is ``link``, in document order."""
        return tuple(joint for joint in self.joints if joint.parent == link)

    def material(self, name: str) -> Material | None:
        """The first top-level material named ``name``."""
        return next((m for m in self.materials if m.name == name), None)
