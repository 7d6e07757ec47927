"""The ``.meta`` files Unity 2022.3 writes for a model (``.dae``) and a texture (any format
its TextureImporter reads: one importer, one set of settings, docs/unity-yaml.md).

The settings are the ones Unity wrote for the r2d2 sample's COLLADA models and their textures
after ROS#'s ``ColladaAssetPostProcessor`` had set its own (no animation, cameras or lights;
the global scale from the file's ``<unit meter>``), so Unity imports the copied files with the
settings ROS#'s importer would have left and does not rewrite the ``.meta``. Only the GUID and,
for a model, the global scale change from file to file (``tests/unity/test_importers.py``
compares with Unity's files). The text is laid out by the ``unity_meta/`` templates.

A model ROS#'s post-processor leaves alone (any but a ``.dae``: it returns at once for the
rest) keeps Unity's defaults for the four settings it changes: ``globalScale: 1``,
``importCameras: 1``, ``importLights: 1``, ``animationType: 2`` (Generic), the values of
``.obj.meta`` files of default imports: a 2022.3 one (``serializedVersion: 22200``) in
github.com/Unity-Technologies/ml-agents at d7b7509c (``Project/Assets/3D-FUTURE-model/01fdf241-
67bb-482c-844c-61e261b8d484/normalized_model.obj.meta``), equal to ``default_model_meta`` in every
setting, and a 2021.3 one in github.com/Field-Robotics-Japan/UnitySensors at 66b5d7db
(``Packages/UnitySensors/Runtime/RawData/LivoxModels/mid-360.obj.meta``). The ml-agents file
lacks the empty ``rigImportErrors``/``rigImportWarnings`` lines the r2d2 ``.meta`` holds; the
r2d2 layout is kept (Unity reads both).
"""

from __future__ import annotations

from unityscaffold.resources import template_environment
from unityscaffold.unity._scalars import format_float

__all__ = ["default_model_meta", "model_meta", "texture_meta"]

# The platforms a default texture's importer lists settings for, in Unity's order.
_TEXTURE_BUILD_TARGETS = ("DefaultTexturePlatform", "Standalone", "Windows Store Apps")


def model_meta(guid: str, global_scale: float = 1.0) -> str:
    """A COLLADA model's ``.meta`` (ModelImporter) as ROS#'s post-processor leaves it: no
    animation, cameras or lights; ``global_scale`` from the file's unit."""
    return _model_meta(guid, global_scale, cameras_and_lights=0, animation_type=0)


def default_model_meta(guid: str) -> str:
    """The ``.meta`` of a model Unity imports with its defaults (an ``.obj``)."""
    return _model_meta(guid, 1.0, cameras_and_lights=1, animation_type=2)


def _model_meta(
    guid: str, global_scale: float, *, cameras_and_lights: int, animation_type: int
) -> str:
    template = template_environment().get_template("unity_meta/ModelImporter.meta.jinja")
    return template.render(
        guid=guid,
        global_scale=format_float(global_scale),
        import_cameras=cameras_and_lights,
        import_lights=cameras_and_lights,
        animation_type=animation_type,
    )


def texture_meta(guid: str) -> str:
    """A texture's ``.meta`` (TextureImporter, a default 2D texture)."""
    template = template_environment().get_template("unity_meta/TextureImporter.meta.jinja")
    return template.render(guid=guid, build_targets=_TEXTURE_BUILD_TARGETS)
