"""The image files an import copies into the robot's asset folder, each with its ``.meta``.

Two kinds of file name one: a COLLADA model's ``<image>`` (copied beside the model, where
ROS#'s transfer puts a model's files and where Unity's model import looks for them), and a URDF
material's ``<texture filename>`` (``package://pkg/path``, which ROS#'s ``UrdfMaterial``
loads from ``<robot folder>/pkg/path``, as it does a mesh). Both go to ``<package>/<path>``
in the robot's asset folder.

Every format Unity's TextureImporter reads is copied, with the ``.meta`` Unity 2022.3 writes
for a default 2D texture (``unity.importers.texture_meta``): the importer's settings are the
same for every one of its formats (docs/unity-yaml.md says from what). Formats Unity imports
with another importer (``IHVImageFormatImporter``: ``.dds``, ``.ktx``, ``.pvr``, ``.astc``),
whose ``.meta`` no Unity-written file here shows, are a located error; a model's image in a
format Unity does not import as a texture, or missing, is left out, as Unity's model import
leaves it out.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import Protocol

from unityscaffold.errors import DiagnosticSink, SourceLocation
from unityscaffold.unity.importers import texture_meta
from unityscaffold.urdf._assets import GuidOf, PlannedAsset
from unityscaffold.urdf._packages import ResolvedMesh
from unityscaffold.urdf.materials import ImporterMaterial, TexturedMaterialAsset
from unityscaffold.urdf.model import Mesh

__all__ = ["TEXTURE_SUFFIXES", "TextureAsset", "material_textures", "model_textures"]

#: The file formats Unity's TextureImporter imports (Unity 2022.3 manual, "Built-in Importers").
TEXTURE_SUFFIXES = frozenset(
    ".jpg .jpeg .tif .tiff .tga .gif .png .psd .bmp .iff .pict .pic .pct .exr .hdr".split()
)
# the formats of Unity's IHVImageFormatImporter (same page)
_IHV_SUFFIXES = frozenset(".astc .dds .ktx .pvr".split())
_IHV_HINT = "convert the texture to PNG (or JPG, TGA…) and name that file instead"


class Resolver(Protocol):
    """Finds the file a URDF filename written at ``where`` names, or adds why not to
    ``sink`` (``_packages.resolve_file`` with the import's folders, as for a mesh)."""

    def __call__(
        self, filename: str, where: SourceLocation, *, sink: DiagnosticSink
    ) -> ResolvedMesh | None: ...


@dataclass(frozen=True, slots=True)
class TextureAsset:
    """A copy of the image ``source`` at ``path`` in the robot's asset folder."""

    path: str
    source: Path

    def content(self, guid_of: GuidOf) -> bytes:
        return self.source.read_bytes()

    def meta(self, guid: str) -> str:
        return texture_meta(guid)


def model_textures(
    mesh: Mesh, resolved: ResolvedMesh, images: Iterable[PurePosixPath], sink: DiagnosticSink
) -> Iterator[TextureAsset]:
    """The images the model at ``resolved`` names that Unity imports as its textures; an
    image outside the model's package, or in a format copied without a checked ``.meta``, is
    an error at ``mesh``."""
    for image in images:
        inside = inside_package(resolved.relative.parent, image)
        if inside is None:
            sink.error(
                mesh.location,
                f"model {mesh.filename!r} names the image {str(image)!r} outside its "
                "package folder",
                hint="keep the model's textures beside it, named by relative paths",
            )
            continue
        source = resolved.path.parent / image
        suffix = image.suffix.lower()
        if not source.is_file() or suffix not in TEXTURE_SUFFIXES | _IHV_SUFFIXES:
            continue
        if suffix in _IHV_SUFFIXES:
            sink.error(
                mesh.location,
                f"model {mesh.filename!r} uses the texture {str(image)!r}, which Unity imports "
                f"with its IHVImageFormatImporter, whose {suffix} .meta is not checked here",
                hint=_IHV_HINT + " in the model",
            )
            continue
        yield TextureAsset(str(PurePosixPath(resolved.package) / inside), source)


def material_textures(
    materials: Iterable[ImporterMaterial], resolve: Resolver, sink: DiagnosticSink
) -> Iterator[PlannedAsset]:
    """For each material of a texture alone, its texture (found by ``resolve``, as a mesh's
    file is) and its ``.mat``."""
    for material in materials:
        element = material.textured
        if element is None or not element.texture:
            continue
        found = resolve(element.texture, element.location, sink=sink)
        if found is None:
            continue
        suffix = found.relative.suffix.lower()
        if suffix not in TEXTURE_SUFFIXES:
            why = (
                f"with its IHVImageFormatImporter, whose {suffix} .meta is not checked here"
                if suffix in _IHV_SUFFIXES
                else "as no texture, so ROS#'s importer finds no Texture there"
            )
            sink.error(
                element.location,
                f"material {element.name!r}: its texture {element.texture!r} is a file Unity "
                f"imports {why}",
                hint=_IHV_HINT,
            )
            continue
        path = str(PurePosixPath(found.package) / found.relative)
        yield TextureAsset(path, found.path)
        yield TexturedMaterialAsset(material, path)


def inside_package(folder: PurePosixPath, image: PurePosixPath) -> PurePosixPath | None:
    """``folder / image`` with ``..`` resolved, or None if it leaves the package."""
    if image.is_absolute() or ":" in str(image):
        return None
    parts: list[str] = []
    for part in (*folder.parts, *image.parts):
        if part == "..":
            if not parts:
                return None
            parts.pop()
        elif part != ".":
            parts.append(part)
    return PurePosixPath(*parts)
