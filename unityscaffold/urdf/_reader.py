"""URDF's grammar, one function per element, into the frozen model of ``model``.

Follows what ROS#'s importer reads (first-match children, optional numbers as NaN, unknown
elements ignored) but refuses, with a located diagnostic, what would make it fail or guess: a
missing required attribute or element, a number that is not one, a vector of the wrong length,
an unknown joint type. Every problem of a file is collected before stopping.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import TypeVar

from unityscaffold.errors import DiagnosticSink
from unityscaffold.urdf import model as m
from unityscaffold.urdf._plugins import plugin_text
from unityscaffold.urdf._xml import Element, XmlSource

__all__ = ["read_robot"]

T = TypeVar("T")
_NUMBER_RE = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_FLOAT32_MAX = 3.4028234663852886e38
_NOT_PLUGINS = frozenset({"link", "joint", "material"})


class _Missing(Exception):
    """A required part is absent or bad; its diagnostic is already in the sink."""


class _Reader:
    def __init__(self, source: XmlSource, sink: DiagnosticSink) -> None:
        self.source = source
        self.sink = sink

    # -- primitives --------------------------------------------------------------------------

    def error(self, offset: int, message: str, hint: str | None = None) -> _Missing:
        self.sink.error(self.source.at(offset), message, hint=hint)
        return _Missing()

    def text(self, element: Element, name: str) -> str:
        value = element.get(name)
        if value is None:
            raise self.error(
                element.offset,
                f'<{element.tag}> has no {name}="…" attribute',
                hint=f"URDF requires {name} on <{element.tag}>",
            )
        return value

    def child(self, element: Element, tag: str) -> Element:
        found = element.first(tag)
        if found is None:
            raise self.error(
                element.offset,
                f"<{element.tag}> has no <{tag}> element",
                hint=f"URDF requires <{tag}> inside <{element.tag}>",
            )
        return found

    def numbers(self, element: Element, name: str, count: int) -> tuple[float, ...]:
        words = self.text(element, name).split()
        values = [self._number(word) for word in words]
        if len(words) != count or any(v is None for v in values):
            raise self.error(
                element.attribute_offset(name),
                f'{name}="{element.get(name)}" on <{element.tag}> is not {count} numbers',
                hint=f"write {count} decimal numbers (within ±3.4e38) separated by spaces",
            )
        return tuple(v for v in values if v is not None)

    def number(self, element: Element, name: str) -> float:
        return self.numbers(element, name, 1)[0]

    def optional_number(self, element: Element, name: str) -> float:
        return math.nan if element.get(name) is None else self.number(element, name)

    def vector(self, element: Element, name: str) -> m.Vector3:
        x, y, z = self.numbers(element, name, 3)
        return (x, y, z)

    def optional_vector(self, element: Element, name: str) -> m.Vector3 | None:
        return None if element.get(name) is None else self.vector(element, name)

    @staticmethod
    def _number(word: str) -> float | None:
        if not _NUMBER_RE.fullmatch(word):
            return None
        value = float(word)
        # Unity stores float32: a larger number cannot be imported
        return value if abs(value) <= _FLOAT32_MAX else None

    def gather(self, read: Callable[[Element], T], elements: list[Element]) -> tuple[T, ...]:
        """``read`` over ``elements``, keeping those that read without problems."""
        out = []
        for element in elements:
            try:
                out.append(read(element))
            except _Missing:
                continue
        return tuple(out)

    def optional(self, read: Callable[[Element], T], element: Element | None) -> T | None:
        """``read(element)``; None when the element is absent or had a problem (in the sink),
        so that the rest of its parent is still read and checked."""
        try:
            return None if element is None else read(element)
        except _Missing:
            return None

    # -- grammar rules -----------------------------------------------------------------------

    def robot(self, element: Element) -> m.Robot:
        if element.tag != "robot":
            raise self.error(
                element.offset,
                f"the document element is <{element.tag}>",
                hint='a URDF\'s document element is <robot name="…">',
            )
        name = self.text(element, "name")
        return m.Robot(
            name=name,
            links=self.gather(self.link, element.elements("link")),
            joints=self.gather(self.joint, element.elements("joint")),
            materials=self.gather(self.material, element.elements("material")),
            plugins=tuple(
                m.Plugin(child.tag, plugin_text(child), self.source.at(child.offset))
                for child in element.elements()
                if child.tag not in _NOT_PLUGINS
            ),
            location=self.source.at(element.offset),
        )

    def origin(self, element: Element) -> m.Origin:
        return m.Origin(
            xyz=self.optional_vector(element, "xyz"),
            rpy=self.optional_vector(element, "rpy"),
            location=self.source.at(element.offset),
        )

    def material(self, element: Element) -> m.Material:
        color = element.first("color")
        texture = element.first("texture")
        rgba = None if color is None else self.numbers(color, "rgba", 4)
        return m.Material(
            name=self.text(element, "name"),
            color=None if rgba is None else (rgba[0], rgba[1], rgba[2], rgba[3]),
            texture=None if texture is None else self.text(texture, "filename"),
            location=self.source.at(element.offset),
        )

    def link(self, element: Element) -> m.Link:
        name = self.text(element, "name")
        inertial = self.optional(self.inertial, element.first("inertial"))
        return m.Link(
            name=name,
            inertial=inertial,
            visuals=self.gather(self.visual, element.elements("visual")),
            collisions=self.gather(self.collision, element.elements("collision")),
            location=self.source.at(element.offset),
        )

    def inertial(self, element: Element) -> m.Inertial:
        inertia = self.child(element, "inertia")
        values = [self.number(inertia, key) for key in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")]
        return m.Inertial(
            mass=self.number(self.child(element, "mass"), "value"),
            inertia=m.Inertia(*values),
            origin=self.optional(self.origin, element.first("origin")),
            location=self.source.at(element.offset),
        )

    def visual(self, element: Element) -> m.Visual:
        return m.Visual(
            geometry=self.geometry(self.child(element, "geometry")),
            name=element.get("name"),
            origin=self.optional(self.origin, element.first("origin")),
            material=self.optional(self.material, element.first("material")),
            location=self.source.at(element.offset),
        )

    def collision(self, element: Element) -> m.Collision:
        return m.Collision(
            geometry=self.geometry(self.child(element, "geometry")),
            name=element.get("name"),
            origin=self.optional(self.origin, element.first("origin")),
            location=self.source.at(element.offset),
        )

    def geometry(self, element: Element) -> m.Geometry:
        # ROS# tries box, cylinder, sphere, mesh in this order, whatever the document's order
        where = self.source.at
        if (box := element.first("box")) is not None:
            return m.Box(self.vector(box, "size"), where(box.offset))
        if (cylinder := element.first("cylinder")) is not None:
            radius, length = self.number(cylinder, "radius"), self.number(cylinder, "length")
            return m.Cylinder(radius, length, where(cylinder.offset))
        if (sphere := element.first("sphere")) is not None:
            return m.Sphere(self.number(sphere, "radius"), where(sphere.offset))
        if (mesh := element.first("mesh")) is not None:
            scale = self.optional_vector(mesh, "scale")
            return m.Mesh(self.text(mesh, "filename"), scale, where(mesh.offset))
        raise self.error(
            element.offset,
            "<geometry> has no shape",
            hint="put one of <box>, <cylinder>, <sphere> or <mesh> inside <geometry>",
        )

    def joint(self, element: Element) -> m.Joint:
        name = self.text(element, "name")
        kind = self.text(element, "type")
        if kind not in {t.value for t in m.JointType}:
            known = ", ".join(t.value for t in m.JointType)
            raise self.error(
                element.attribute_offset("type"),
                f"joint {name!r} has the unknown type {kind!r}",
                hint=f"URDF's joint types are {known}",
            )
        axis = element.first("axis")
        return m.Joint(
            name=name,
            type=m.JointType(kind),
            parent=self.text(self.child(element, "parent"), "link"),
            child=self.text(self.child(element, "child"), "link"),
            origin=self.optional(self.origin, element.first("origin")),
            axis=None if axis is None else self.optional_vector(axis, "xyz"),
            limit=self.optional(self.limit, element.first("limit")),
            dynamics=self.optional(self.dynamics, element.first("dynamics")),
            mimic=self.optional(self.mimic, element.first("mimic")),
            safety_controller=self.optional(self.safety, element.first("safety_controller")),
            calibration=self.optional(self.calibration, element.first("calibration")),
            location=self.source.at(element.offset),
        )

    def limit(self, element: Element) -> m.Limit:
        return m.Limit(
            effort=self.number(element, "effort"),
            velocity=self.number(element, "velocity"),
            lower=self.optional_number(element, "lower"),
            upper=self.optional_number(element, "upper"),
        )

    def dynamics(self, element: Element) -> m.Dynamics:
        return m.Dynamics(
            damping=self.optional_number(element, "damping"),
            friction=self.optional_number(element, "friction"),
        )

    def mimic(self, element: Element) -> m.Mimic:
        return m.Mimic(
            joint=self.text(element, "joint"),
            multiplier=self.optional_number(element, "multiplier"),
            offset=self.optional_number(element, "offset"),
        )

    def safety(self, element: Element) -> m.SafetyController:
        return m.SafetyController(
            k_velocity=self.number(element, "k_velocity"),
            k_position=self.optional_number(element, "k_position"),
            soft_lower_limit=self.optional_number(element, "soft_lower_limit"),
            soft_upper_limit=self.optional_number(element, "soft_upper_limit"),
        )

    def calibration(self, element: Element) -> m.Calibration:
        return m.Calibration(
            rising=self.optional_number(element, "rising"),
            falling=self.optional_number(element, "falling"),
        )


def read_robot(source: XmlSource, document: Element, sink: DiagnosticSink) -> m.Robot | None:
    """The robot of a parsed URDF; None when its ``<robot name>`` itself is unusable.

    Problems inside links, joints and materials go to ``sink`` and leave that part out.
    """
    try:
        return _Reader(source, sink).robot(document)
    except _Missing:
        return None
