"""A material of Unity's built-in Standard shader, as Unity 2022.3 saves one made in code.

The layout is the one Unity wrote for the materials ROS#'s URDF importer made (``tests/urdf``):
every Standard property at its default except the colour, metallic and smoothness given here,
and the albedo texture (``_MainTex``) when one is given. A texture is referred to as Unity
refers to an imported texture's Texture2D, ``{fileID: 2800000, guid: <its .meta's>, type: 3}``
(a ``.mat`` Unity 2022.3.0 saved, docs/unity-yaml.md). The text is laid out by the
``unity_assets/StandardMaterial.mat.template`` template from the data below (a
``string.Template``: a robot's apply loads no jinja).
"""

from __future__ import annotations

import string

from unityscaffold.resources import template_text
from unityscaffold.unity._emit import flow_text
from unityscaffold.unity._scalars import format_float, format_string
from unityscaffold.unity.values import AssetRef, InlineMap

__all__ = ["MATERIAL_FILE_ID", "TEXTURE_FILE_ID", "standard_material"]

#: The fileID of the Material in its own ``.mat`` (class 21 × 100000).
MATERIAL_FILE_ID = 2100000
#: The fileID of the Texture2D an image file's TextureImporter makes (class 28 × 100000).
TEXTURE_FILE_ID = 2800000
_TYPE_IMPORTED = 3  # a reference to an object an importer made from a source file
_TEXTURES = (
    "_BumpMap",
    "_DetailAlbedoMap",
    "_DetailMask",
    "_DetailNormalMap",
    "_EmissionMap",
    "_MainTex",
    "_MetallicGlossMap",
    "_OcclusionMap",
    "_ParallaxMap",
)
_FLOATS = (
    ("_BumpScale", 1.0),
    ("_Cutoff", 0.5),
    ("_DetailNormalMapScale", 1.0),
    ("_DstBlend", 0.0),
    ("_GlossMapScale", 1.0),
    ("_Glossiness", None),
    ("_GlossyReflections", 1.0),
    ("_Metallic", None),
    ("_Mode", 0.0),
    ("_OcclusionStrength", 1.0),
    ("_Parallax", 0.02),
    ("_SmoothnessTextureChannel", 0.0),
    ("_SpecularHighlights", 1.0),
    ("_SrcBlend", 1.0),
    ("_UVSec", 0.0),
    ("_ZWrite", 1.0),
)
_NO_TEXTURE = "{fileID: 0}"
# one entry of m_TexEnvs, and one of m_Floats or m_Colors
_TEXTURE_ENTRY = string.Template(
    "    - $property:\n        m_Texture: $texture\n"
    "        m_Scale: {x: 1, y: 1}\n        m_Offset: {x: 0, y: 0}\n"
)
_ENTRY = string.Template("    - $property: $value\n")
_BLACK = (0.0, 0.0, 0.0, 1.0)


def standard_material(
    name: str,
    color: tuple[float, float, float, float] = (1.0, 1.0, 1.0, 1.0),
    *,
    metallic: float = 0.0,
    smoothness: float = 0.5,
    main_texture: str | None = None,
) -> str:
    """The text of ``<name>.mat``: a Standard material with ``color`` (r, g, b, a) and, when
    ``main_texture`` (a texture's GUID) is given, that texture as its albedo (``_MainTex``,
    what Unity's ``Material.mainTexture`` sets)."""
    albedo = _NO_TEXTURE
    if main_texture is not None:
        albedo = _flow(AssetRef(TEXTURE_FILE_ID, main_texture, _TYPE_IMPORTED))
    chosen = {"_Glossiness": smoothness, "_Metallic": metallic}
    textures = (
        _TEXTURE_ENTRY.substitute(property=t, texture=albedo if t == "_MainTex" else _NO_TEXTURE)
        for t in _TEXTURES
    )
    floats = (
        _ENTRY.substitute(property=k, value=format_float(chosen[k] if v is None else v))
        for k, v in _FLOATS
    )
    colours = (
        _ENTRY.substitute(property=k, value=_colour(v))
        for k, v in (("_Color", color), ("_EmissionColor", _BLACK))
    )
    document = string.Template(template_text("unity_assets/StandardMaterial.mat.template"))
    return document.substitute(
        file_id=MATERIAL_FILE_ID,
        name=format_string(name, column=10),
        textures="".join(textures),
        floats="".join(floats),
        colours="".join(colours),
    )


def _colour(rgba: tuple[float, float, float, float]) -> str:
    r, g, b, a = rgba
    return _flow(InlineMap.of(r=r, g=g, b=b, a=a))


def _flow(value: AssetRef | InlineMap) -> str:
    text = flow_text(value)
    assert text is not None  # a reference or an inline map always has one
    return text
