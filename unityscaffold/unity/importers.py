"""The ``.meta`` files Unity 2022.3 writes for a model (``.dae``) and a texture (any format
its TextureImporter reads: one importer, one set of settings, docs/unity-yaml.md).

The settings are the ones Unity wrote for the r2d2 sample's COLLADA models and their textures
after ROS#'s ``ColladaAssetPostProcessor`` had set its own (no animation, cameras or lights;
the global scale from the file's ``<unit meter>``), so Unity imports the copied files with the
settings ROS#'s importer would have left and does not rewrite the ``.meta``. Only the GUID and,
for a model, the global scale change from file to file (``tests/unity/test_importers.py``
compares with Unity's files). The text is laid out by the ``unity_meta/`` templates.
"""

from __future__ import annotations

from unityscaffold.resources import template_environment
from unityscaffold.unity._scalars import format_float

__all__ = ["model_meta", "texture_meta"]

# The platforms a default texture's importer lists settings for, in Unity's order.
_TEXTURE_BUILD_TARGETS = ("DefaultTexturePlatform", "Standalone", "Windows Store Apps")


def model_meta(guid: str, global_scale: float = 1.0) -> str:
    """A model's ``.meta`` (ModelImporter); ``global_scale`` is ROS#'s from the file's unit."""
    template = template_environment().get_template("unity_meta/ModelImporter.meta.jinja")
    return template.render(guid=guid, global_scale=format_float(global_scale))


def texture_meta(guid: str) -> str:
    """A texture's ``.meta`` (TextureImporter, a default 2D texture)."""
    template = template_environment().get_template("unity_meta/TextureImporter.meta.jinja")
    return template.render(guid=guid, build_targets=_TEXTURE_BUILD_TARGETS)
