"""What a COLLADA (``.dae``) file tells about the model Unity makes of it.

A scene refers to a model's objects by fileIDs Unity derives from the model's node tree
(``unity.modelids``), and ROS#'s ``ColladaAssetPostProcessor`` turns the model's root by the
file's ``<up_axis>``. So a few facts of the file decide what a scene holding the model reads:
its up axis and unit, its top nodes (a file with one top node is folded into the model's root)
with their transforms, the geometries each instantiates and the parts those are drawn in (each
part a submesh, with a material slot of its own on the renderer), and the texture files its
images name (copied beside it, as ROS#'s transfer does). Nothing else of the file is read.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path, PurePosixPath

from unityscaffold.errors import LocatedError, SourceLocation, UserError
from unityscaffold.urdf._xml import Element, Text, XmlSource, parse_xml

__all__ = ["ColladaFacts", "ColladaNode", "read_collada"]

_TRANSFORMS = ("translate", "rotate", "scale", "matrix", "lookat", "skew")
# the elements of a <mesh> that each draw a part of it (COLLADA 1.4's primitives)
_PRIMITIVES = frozenset(
    ("lines", "linestrips", "polygons", "polylist", "triangles", "trifans", "tristrips")
)


@dataclass(frozen=True, slots=True)
class ColladaNode:
    """A ``<node>`` of the visual scene: its ``name`` and ``id``, how many geometries it
    instantiates, whether it has child nodes (or instantiates other nodes), and whether its
    transform moves or turns it (a scale alone does not); ``parts``: how many primitives
    (``<triangles>``, ``<polylist>``, …) the geometries it instantiates have in all."""

    name: str
    id: str
    geometries: int
    has_children: bool
    moved: bool
    location: SourceLocation
    parts: int


@dataclass(frozen=True, slots=True)
class ColladaFacts:
    """``up_axis`` as written (``Y_UP`` when absent, COLLADA's default), ``meter`` (the
    ``<unit meter>``, which ROS# makes the importer's global scale; 1 when absent or not a
    number, as ROS# reads it), the visual scene's top nodes and the image files named
    (relative to the file's folder, in document order, each once)."""

    up_axis: str
    meter: float
    nodes: tuple[ColladaNode, ...]
    images: tuple[PurePosixPath, ...]


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
    up_axis = _text(asset.first("up_axis")) if asset is not None else ""
    parts = _parts(root)
    return ColladaFacts(
        up_axis or "Y_UP",
        _meter(asset),
        tuple(_node(node, source, parts) for node in _top_nodes(root)),
        _images(root),
    )


def _text(element: Element | None) -> str:
    if element is None:
        return ""
    return "".join(c.text for c in element.children if isinstance(c, Text)).strip()


def _meter(asset: Element | None) -> float:
    unit = asset.first("unit") if asset is not None else None
    value = unit.get("meter") if unit is not None else None
    try:
        return float(value) if value is not None else 1.0
    except ValueError:  # ROS# falls back to 1 on anything it cannot parse
        return 1.0


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


def _node(node: Element, source: XmlSource, parts: dict[str, int]) -> ColladaNode:
    geometries = node.elements("instance_geometry")
    return ColladaNode(
        name=node.get("name") or "",
        id=node.get("id") or "",
        geometries=len(geometries),
        has_children=bool(node.elements("node") or node.elements("instance_node")),
        moved=_moved(node),
        location=source.at(node.offset),
        parts=sum(parts.get((g.get("url") or "").removeprefix("#"), 0) for g in geometries),
    )


def _moved(node: Element) -> bool:
    """Whether the node's own transform translates or rotates it."""
    for element in node.children:
        if not isinstance(element, Element) or element.tag not in _TRANSFORMS:
            continue
        numbers = _numbers(_text(element))
        if element.tag == "translate" and any(numbers):
            return True
        if element.tag == "rotate" and (len(numbers) != 4 or numbers[3] != 0):
            return True
        if element.tag == "matrix" and not _pure_scale(numbers):
            return True
        if element.tag in ("lookat", "skew"):
            return True
    return False


def _pure_scale(numbers: list[float]) -> bool:
    """A row-major 4×4 matrix that only scales (or is not one at all: then it moves)."""
    if len(numbers) != 16:
        return False
    return all(numbers[i] == 0 for i in range(16) if i not in (0, 5, 10, 15)) and numbers[15] == 1


def _numbers(text: str) -> list[float]:
    try:
        return [float(word) for word in text.split()]
    except ValueError:
        return [float("nan")]


def _images(root: Element) -> tuple[PurePosixPath, ...]:
    library = root.first("library_images")
    found: dict[PurePosixPath, None] = {}
    for image in library.elements("image") if library is not None else []:
        named = _text(image.first("init_from"))
        if named:
            found.setdefault(PurePosixPath(named.replace("\\", "/")), None)
    return tuple(found)
