"""What a COLLADA (``.dae``) file tells about the model Unity makes of it.

A scene refers to a model's objects by fileIDs Unity derives from the model's node tree
(``unity.modelids``), and ROS#'s ``ColladaAssetPostProcessor`` turns and moves the model's
root by the file's ``<up_axis>``. So a few facts of the file decide what a scene holding the
model reads: its up axis and unit, the tree of nodes of its visual scene (``<instance_node>``
resolved from ``<library_nodes>``), each node's own transform, the geometries it instantiates
and the parts those are drawn in (each part a submesh, with a material slot of its own on the
renderer), and the texture files its images name (copied beside it, as ROS#'s transfer does).
Nothing else of the file is read.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

from unityscaffold.errors import LocatedError, SourceLocation, UserError
from unityscaffold.urdf._xml import Element, Text, XmlSource, parse_xml

__all__ = ["IDENTITY_MATRIX", "ColladaFacts", "ColladaNode", "Matrix", "read_collada"]

#: A node's transform: a 4×4 matrix, row by row, acting on column vectors (COLLADA's own form).
Matrix = tuple[float, ...]
IDENTITY_MATRIX: Matrix = (1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0)

_NAMESPACE = "http://www.collada.org/2005/11/COLLADASchema"
_TRANSFORMS = ("translate", "rotate", "scale", "matrix", "lookat", "skew")
# the elements of a <mesh> that each draw a part of it (COLLADA 1.4's primitives)
_PRIMITIVES = frozenset(
    ("lines", "linestrips", "polygons", "polylist", "triangles", "trifans", "tristrips")
)
_DECIMAL = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
# C#'s float.Parse(s, CultureInfo.InvariantCulture): Float | AllowThousands
_CSHARP_FLOAT = re.compile(r"\s*([+-]?(?:\d[\d,]*\.?\d*|\.\d+))([eE][+-]?\d+)?\s*")
_FLOAT_MAX = 3.4028234663852886e38
# bounds on a tree <instance_node>s can multiply: far past any real model, short of a hang
_MAX_DEPTH, _MAX_NODES = 256, 100_000


@dataclass(frozen=True, slots=True)
class ColladaNode:
    """A ``<node>`` of the visual scene: its ``name`` and ``id`` (empty when absent), how many
    geometries it instantiates, ``parts``: how many primitives (``<triangles>``, ``<polylist>``,
    …) those geometries have in all, ``others``: how many cameras, lights and controllers it
    instantiates, its child nodes (its own, then those it instantiates, in
    document order), and ``matrix``: its own transform, every ``<translate>``, ``<rotate>``,
    ``<scale>``, ``<matrix>`` and ``<lookat>`` composed in order (``skew`` is kept apart:
    ``skewed``)."""

    name: str
    id: str
    geometries: int
    parts: int
    children: tuple[ColladaNode, ...]
    matrix: Matrix
    location: SourceLocation
    skewed: bool = False
    # its other node attributes, as the FBX SDK counts them: cameras, lights, controllers
    others: int = 0

    @property
    def has_children(self) -> bool:
        return bool(self.children)

    @property
    def moved(self) -> bool:
        """Whether the node's own transform translates or turns it (a scale alone does not)."""
        m = self.matrix
        if any(math.isnan(v) for v in m) or self.skewed:
            return True
        if m[3] or m[7] or m[11]:
            return True
        return any(m[4 * r + c] for r in range(3) for c in range(3) if r != c)


@dataclass(frozen=True, slots=True)
class ColladaFacts:
    """``up_axis`` as Unity's importer reads it (``Y_UP`` when absent, COLLADA's default),
    ``ros_up_axis`` as ROS#'s post-processor reads it (the element's exact text; ``undefined``
    when absent or outside COLLADA 1.4's namespace), ``meter`` (the ``<unit meter>``, which
    ROS# makes the importer's global scale; 1 where ROS# reads none or no number), the visual
    scene's top nodes and the image files named (relative to the file's folder, in document
    order, each once)."""

    up_axis: str
    meter: float
    nodes: tuple[ColladaNode, ...]
    images: tuple[PurePosixPath, ...]
    ros_up_axis: str = "undefined"


def read_collada(path: Path) -> ColladaFacts:
    """The facts above; a file that is not well-formed XML is a located error."""
    try:
        raw = path.read_bytes()
    except OSError as error:
        raise UserError(
            f"cannot read the model {str(path)!r}: {error.strerror or error}",
            hint="check that the file exists and can be read",
        ) from None
    source = XmlSource(str(path), raw)
    try:
        root = parse_xml(source)
    except LocatedError as error:
        first = error.diagnostics[0]
        raise LocatedError.at(
            first.location, first.message, hint="export the model again as COLLADA 1.4"
        ) from None
    asset = root.first("asset")
    axis = asset.first("up_axis") if asset is not None else None
    reader = _Reader(source, _parts(root), _library_nodes(root))
    # ROS# looks the two elements up in COLLADA 1.4's namespace, and takes a file in any other
    # (1.5's, or none) as one without them
    ros_reads = root.tag == "COLLADA" and root.get("xmlns") == _NAMESPACE
    return ColladaFacts(
        _text(axis).strip() or "Y_UP",
        _meter(asset) if ros_reads else 1.0,
        tuple(reader.node(node) for node in _top_nodes(root)),
        _images(root),
        _text(axis) if axis is not None and ros_reads else "undefined",
    )


def _text(element: Element | None) -> str:
    if element is None:
        return ""
    return "".join(c.text for c in element.children if isinstance(c, Text))


def _meter(asset: Element | None) -> float:
    """The unit as ROS# reads it: ``float.Parse`` with the invariant culture (digits, a sign,
    a point, an exponent, ``,`` between the whole digits), and 1 where that fails or
    overflows (Mono's ``OverflowException``) or gives no finite number."""
    unit = asset.first("unit") if asset is not None else None
    value = unit.get("meter") if unit is not None else None
    match = _CSHARP_FLOAT.fullmatch(value) if value is not None else None
    if match is None:
        return 1.0
    number = float(match.group(1).replace(",", "") + (match.group(2) or ""))
    return number if math.isfinite(number) and abs(number) <= _FLOAT_MAX else 1.0


def _top_nodes(root: Element) -> list[Element]:
    """The nodes of the visual scene the file's ``<scene>`` names (or its first one)."""
    library = root.first("library_visual_scenes")
    if library is None:
        return []
    scenes = library.elements("visual_scene")
    scene = root.first("scene")
    chosen = scene.first("instance_visual_scene") if scene is not None else None
    url = (chosen.get("url") or "").lstrip("#") if chosen is not None else ""
    named = [s for s in scenes if s.get("id") == url]
    picked = named[0] if named else (scenes[0] if scenes else None)
    return picked.elements("node") if picked is not None else []


def _parts(root: Element) -> dict[str, int]:
    """How many primitives each geometry's ``<mesh>`` has, by the geometry's id."""
    library = root.first("library_geometries")
    found: dict[str, int] = {}
    for geometry in library.elements("geometry") if library is not None else []:
        mesh = geometry.first("mesh")
        count = sum(e.tag in _PRIMITIVES for e in mesh.elements()) if mesh is not None else 0
        found.setdefault(geometry.get("id") or "", count)
    return found


def _library_nodes(root: Element) -> dict[str, Element]:
    """Every node with an id, anywhere in the file, for ``<instance_node url>`` (the first of
    an id wins)."""
    found: dict[str, Element] = {}
    stack = [root]
    while stack:
        element = stack.pop()
        if element.tag == "node" and element.get("id"):
            found.setdefault(element.get("id") or "", element)
        stack.extend(reversed(element.elements()))
    return found


@dataclass(frozen=True, slots=True)
class _Reader:
    source: XmlSource
    parts: dict[str, int]
    library: dict[str, Element]
    count: list[int] = field(default_factory=list)  # every node read so far

    def node(self, node: Element, within: tuple[int, ...] = ()) -> ColladaNode:
        """``node`` and the tree below it; ``within``: the nodes it lies in (by offset), where
        an ``<instance_node>`` back to one of them would make the tree endless."""
        geometries = node.elements("instance_geometry")
        inside = (*within, node.offset)
        self.count.append(node.offset)
        if len(inside) > _MAX_DEPTH or len(self.count) > _MAX_NODES:
            raise LocatedError.at(
                self.source.at(node.offset),
                f"the model's tree goes deeper than {_MAX_DEPTH} nodes or holds more than "
                f"{_MAX_NODES:,} (its <instance_node>s counted each time): no robot part does",
                hint="export the model again, without nested instances",
            )
        children = [self.node(child, inside) for child in node.elements("node")]
        for instance in node.elements("instance_node"):
            target = self.library.get((instance.get("url") or "").removeprefix("#"))
            if target is not None and target.offset in inside:
                raise LocatedError.at(
                    self.source.at(instance.offset),
                    f"<instance_node> names {instance.get('url')!r}, a node it lies in: the "
                    "model's tree would never end",
                    hint="instantiate a node outside this one, or export the model again",
                )
            if target is not None:
                children.append(self.node(target, inside))
        matrix, skewed = _matrix(node)
        return ColladaNode(
            name=node.get("name") or "",
            id=node.get("id") or "",
            geometries=len(geometries),
            parts=sum(
                self.parts.get((g.get("url") or "").removeprefix("#"), 0) for g in geometries
            ),
            children=tuple(children),
            matrix=matrix,
            location=self.source.at(node.offset),
            skewed=skewed,
            others=sum(
                len(node.elements(tag))
                for tag in ("instance_camera", "instance_light", "instance_controller")
            ),
        )


def _matrix(node: Element) -> tuple[Matrix, bool]:
    """The node's transforms composed in document order (each one applied inside the ones
    before it, as COLLADA defines), and whether one was a ``<skew>``."""
    result, skewed = IDENTITY_MATRIX, False
    for element in node.children:
        if not isinstance(element, Element) or element.tag not in _TRANSFORMS:
            continue
        numbers = _numbers(_text(element))
        if element.tag == "skew":
            skewed = True
            continue
        result = _multiply(result, _element_matrix(element.tag, numbers))
    return result, skewed


def _element_matrix(tag: str, n: list[float]) -> Matrix:
    nan = (math.nan,) * 16
    if tag == "matrix":
        return tuple(n) if len(n) == 16 else nan
    if tag == "translate" and len(n) == 3:
        return (1, 0, 0, n[0], 0, 1, 0, n[1], 0, 0, 1, n[2], 0, 0, 0, 1)
    if tag == "scale" and len(n) == 3:
        return (n[0], 0, 0, 0, 0, n[1], 0, 0, 0, 0, n[2], 0, 0, 0, 0, 1)
    if tag == "rotate" and len(n) == 4:
        return _rotation(n[0], n[1], n[2], math.radians(n[3]))
    if tag == "lookat" and len(n) == 9:
        return _look_at(n)
    return nan


def _rotation(x: float, y: float, z: float, angle: float) -> Matrix:
    length = math.sqrt(x * x + y * y + z * z)
    if length == 0:
        return IDENTITY_MATRIX
    x, y, z = x / length, y / length, z / length
    c, s, t = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
    return (
        *(t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0.0),
        *(t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0.0),
        *(t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0.0),
        *(0.0, 0.0, 0.0, 1.0),
    )


def _look_at(n: list[float]) -> Matrix:
    """COLLADA's ``<lookat>``: an eye at ``n[0:3]`` looking at ``n[3:6]``, up ``n[6:9]``."""
    eye, target, up = n[0:3], n[3:6], n[6:9]
    back = _normal([eye[i] - target[i] for i in range(3)])
    side = _normal(_cross(up, back))
    above = _cross(back, side)
    return (
        *(side[0], above[0], back[0], eye[0]),
        *(side[1], above[1], back[1], eye[1]),
        *(side[2], above[2], back[2], eye[2]),
        *(0.0, 0.0, 0.0, 1.0),
    )


def _cross(a: list[float], b: list[float]) -> list[float]:
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _normal(v: list[float]) -> list[float]:
    length = math.sqrt(sum(c * c for c in v))
    return [c / length for c in v] if length else [math.nan] * 3


def _multiply(a: Matrix, b: Matrix) -> Matrix:
    return tuple(
        sum(a[4 * r + k] * b[4 * k + c] for k in range(4)) for r in range(4) for c in range(4)
    )


def _numbers(text: str) -> list[float]:
    """The decimal numbers of ``text`` (COLLADA's ``xs:double`` lists); one NaN if a word is
    none, or no finite number (``inf``, ``1e400``), which the caller takes as a broken
    transform."""
    numbers = []
    for word in text.split():
        number = float(word) if _DECIMAL.fullmatch(word) else math.nan
        if not math.isfinite(number):
            return [math.nan]
        numbers.append(number)
    return numbers


def _images(root: Element) -> tuple[PurePosixPath, ...]:
    library = root.first("library_images")
    found: dict[PurePosixPath, None] = {}
    for image in library.elements("image") if library is not None else []:
        named = _text(image.first("init_from")).strip()
        if named:
            found.setdefault(PurePosixPath(named.replace("\\", "/")), None)
    return tuple(found)
