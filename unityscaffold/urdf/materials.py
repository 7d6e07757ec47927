"""The ``.mat`` files ROS#'s importer makes in the robot's ``Materials`` folder.

``Default`` (grey, transparent: what a mesh visual without a material of its own gets), one
per top-level ``<material>``, and one per material a visual defines inline under a name not
yet taken: the first definition of a ``.mat`` wins, as ROS# reuses a ``.mat`` that exists. A
material without a name is named after its colour (``rgba-1-0-0-1``) or texture
(``texture-<file>``); the file a name becomes is ``_material_names``'. All are Standard
materials with ROS#'s metallic and smoothness of 0.75 (``UrdfMaterial.InitializeMaterial``).

As ``UrdfMaterial.CreateMaterial`` does, a material with a ``<color>`` takes that colour and
ignores its ``<texture>``; one with a ``<texture>`` alone keeps Standard's white and has the
texture as its albedo (``material.mainTexture``). That ``.mat`` names the texture's GUID, so it
is written with the texture (``TexturedMaterialAsset``, ``urdf.textures``).
"""

from __future__ import annotations

from dataclasses import dataclass

from unityscaffold.unity.material import MATERIAL_FILE_ID, standard_material
from unityscaffold.unity.meta import native_format_meta
from unityscaffold.urdf._assets import GuidOf
from unityscaffold.urdf._components import material_name
from unityscaffold.urdf._material_names import (
    DEFAULT_MATERIAL_NAME,
    material_stems,
    ordered_materials,
)
from unityscaffold.urdf.model import Material, Robot

__all__ = [
    "DEFAULT_MATERIAL_NAME",
    "ImporterMaterial",
    "TexturedMaterialAsset",
    "importer_materials",
    "material_stems",
]

Rgba = tuple[float, float, float, float]
_DEFAULT_COLOR: Rgba = (0.33, 0.33, 0.33, 0.0)
_WHITE: Rgba = (1.0, 1.0, 1.0, 1.0)  # a new Standard material's colour


@dataclass(frozen=True, slots=True)
class ImporterMaterial:
    """One ``.mat``: its file's name (``stem``), its colour and, for a material of a texture
    alone, that ``<material>`` (whose ``texture`` is the albedo's file)."""

    stem: str
    color: Rgba
    textured: Material | None = None

    @property
    def path(self) -> str:
        """The file's path in the robot's asset folder."""
        return f"Materials/{self.stem}.mat"

    def text(self, texture_guid: str | None = None) -> str:
        """The ``.mat`` text; ``texture_guid`` is the albedo texture's, for a textured one."""
        return standard_material(
            self.stem, self.color, metallic=0.75, smoothness=0.75, main_texture=texture_guid
        )


@dataclass(frozen=True, slots=True)
class TexturedMaterialAsset:
    """A textured material's ``.mat``, written once the GUID of its texture (``texture``, a
    path in the robot's asset folder) is known."""

    material: ImporterMaterial
    texture: str

    @property
    def path(self) -> str:
        return self.material.path

    def content(self, guid_of: GuidOf) -> bytes:
        return self.material.text(guid_of(self.texture)).encode("utf-8")

    def meta(self, guid: str) -> str:
        return native_format_meta(guid, MATERIAL_FILE_ID)


def importer_materials(robot: Robot) -> tuple[ImporterMaterial, ...]:
    """Every ``.mat`` of ``robot``, by file name."""
    stems = material_stems(robot)
    made = {DEFAULT_MATERIAL_NAME: ImporterMaterial(DEFAULT_MATERIAL_NAME, _DEFAULT_COLOR)}
    for material in ordered_materials(robot):
        stem = stems[material_name(material)]
        if stem in made:
            continue
        # ROS# loads no texture for an empty filename (UrdfMaterial.LoadTexture)
        if material.color is None and material.texture:
            made[stem] = ImporterMaterial(stem, _WHITE, material)
        else:
            made[stem] = ImporterMaterial(stem, material.color or _WHITE)
    return tuple(made[stem] for stem in sorted(made))
