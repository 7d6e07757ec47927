"""A material of Unity's built-in Standard shader, as Unity 2022.3 saves one made in code.

The layout is the one Unity wrote for the materials ROS#'s URDF importer made (``tests/urdf``):
every Standard property at its default except the colour, metallic and smoothness given here.
"""

from __future__ import annotations

from unityscaffold.unity._scalars import format_float, format_string

__all__ = ["MATERIAL_FILE_ID", "standard_material"]

#: The fileID of the Material in its own ``.mat`` (class 21 × 100000).
MATERIAL_FILE_ID = 2100000
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


def standard_material(
    name: str,
    color: tuple[float, float, float, float] = (1.0, 1.0, 1.0, 1.0),
    *,
    metallic: float = 0.0,
    smoothness: float = 0.5,
) -> str:
    """The text of ``<name>.mat``: a Standard material with ``color`` (r, g, b, a)."""
    textures = "".join(
        f"    - {texture}:\n        m_Texture: {{fileID: 0}}\n"
        "        m_Scale: {x: 1, y: 1}\n        m_Offset: {x: 0, y: 0}\n"
        for texture in _TEXTURES
    )
    chosen = {"_Glossiness": smoothness, "_Metallic": metallic}
    floats = "".join(
        f"    - {key}: {format_float(chosen[key] if value is None else value)}\n"
        for key, value in _FLOATS
    )
    r, g, b, a = (format_float(v) for v in color)
    return (
        "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n"
        f"--- !u!21 &{MATERIAL_FILE_ID}\nMaterial:\n  serializedVersion: 8\n"
        "  m_ObjectHideFlags: 0\n  m_CorrespondingSourceObject: {fileID: 0}\n"
        "  m_PrefabInstance: {fileID: 0}\n  m_PrefabAsset: {fileID: 0}\n"
        f"  m_Name: {format_string(name, column=10)}\n"
        "  m_Shader: {fileID: 46, guid: 0000000000000000f000000000000000, type: 0}\n"
        "  m_Parent: {fileID: 0}\n  m_ModifiedSerializedProperties: 0\n"
        "  m_ValidKeywords: []\n  m_InvalidKeywords: []\n  m_LightmapFlags: 4\n"
        "  m_EnableInstancingVariants: 0\n  m_DoubleSidedGI: 0\n  m_CustomRenderQueue: -1\n"
        "  stringTagMap: {}\n  disabledShaderPasses: []\n  m_LockedProperties: \n"
        "  m_SavedProperties:\n    serializedVersion: 3\n"
        f"    m_TexEnvs:\n{textures}    m_Ints: []\n    m_Floats:\n{floats}"
        f"    m_Colors:\n    - _Color: {{r: {r}, g: {g}, b: {b}, a: {a}}}\n"
        "    - _EmissionColor: {r: 0, g: 0, b: 0, a: 1}\n"
        "  m_BuildTextureStacks: []\n"
    )
