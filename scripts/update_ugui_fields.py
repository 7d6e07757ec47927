"""Regenerate ``unityscaffold/unity/ugui_fields.json``: every field Unity serializes for uGUI's
components, in Unity's order, with the text Unity writes for a freshly added one.

apply writes a new uGUI component in full, so that Unity's next save of the scene changes
nothing; a manifest's values replace the defaults and are checked against each field's kind.

Inputs: documents Unity 2022.3 saved (default: the test fixture
``tests/data/unity/ros-sharp/ROS2_3_With_UI.documents.txt``, copied unchanged from ROS#'s
"Gazebo Simulation Scenes ROS2" sample). The field order and layout of a class come from its
real document; a class with no real document here (Text, Button, Toggle) takes its base class's
fields from the real document of a sibling (Graphic's from Image, Selectable's from Slider) and
its own from the table below.

The table holds facts about uGUI (``com.unity.ugui`` 1.0, the version Unity 2022.3 bundles):
each field's C# type and what Unity stores for it (the kinds of ``unityscaffold/unity/catalog.py``;
``raw:`` for a nested struct or event, written as given), and, where a saved document holds the
user's value rather than the default, the default from uGUI's C# initializers (a default the
table gives wins over the sample). Every real document is checked against the table: a field
missing from either side stops the script (exit 2).

Run:
    python3 scripts/update_ugui_fields.py [DOCUMENTS...] [--output FILE] [--check]
"""

from __future__ import annotations

import argparse
import itertools
import json
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # the package's GUID table, also when run from a bare checkout

from _derived import write_or_check  # noqa: E402

from unityscaffold.unity.ugui import UGUI_SCRIPTS  # noqa: E402

TARGET = ROOT / "unityscaffold" / "unity" / "ugui_fields.json"
SAMPLES = [ROOT / "tests" / "data" / "unity" / "ros-sharp" / "ROS2_3_With_UI.documents.txt"]
_EVENT = "\n    m_PersistentCalls:\n      m_Calls: []"
_NULL = " {fileID: 0}"
_UI = "enum:UnityEngine.UI."

# (field, C# type, kind, default text after "field:" or None to take the real document's)
Field = tuple[str, str, str, "str | None"]

_GRAPHIC: list[Field] = [
    ("m_Material", "Material", "ref:Material", None),
    ("m_Color", "Color", "Color", None),
    ("m_RaycastTarget", "bool", "bool", None),
    ("m_RaycastPadding", "Vector4", "Vector4", None),
    ("m_Maskable", "bool", "bool", None),  # MaskableGraphic's
    ("m_OnCullStateChanged", "CullStateChangedEvent", "raw:CullStateChangedEvent", None),
]
_SELECTABLE: list[Field] = [
    ("m_Navigation", "Navigation", "raw:Navigation", None),
    ("m_Transition", "Transition", _UI + "Selectable.Transition", None),
    ("m_Colors", "ColorBlock", "raw:ColorBlock", None),
    ("m_SpriteState", "SpriteState", "raw:SpriteState", None),
    ("m_AnimationTriggers", "AnimationTriggers", "raw:AnimationTriggers", None),
    ("m_Interactable", "bool", "bool", None),
    ("m_TargetGraphic", "Graphic", "ref:Graphic", _NULL),
]
_MASKABLE = ("MaskableGraphic", "Graphic", "UIBehaviour", "MonoBehaviour")
_SELECTABLE_BASES = ("Selectable", "UIBehaviour", "MonoBehaviour")

# class -> (bases, [RequireComponent]s with the bases', the class a base's fields come from,
#           fields in Unity's order)
CLASSES: dict[str, tuple[tuple[str, ...], tuple[str, ...], str, list[Field]]] = {
    "Image": (
        _MASKABLE,
        ("CanvasRenderer", "RectTransform"),
        "Image",
        [
            *_GRAPHIC,
            ("m_Sprite", "Sprite", "ref:Sprite", None),
            ("m_Type", "Type", _UI + "Image.Type", None),
            ("m_PreserveAspect", "bool", "bool", None),
            ("m_FillCenter", "bool", "bool", None),
            ("m_FillMethod", "FillMethod", _UI + "Image.FillMethod", None),
            ("m_FillAmount", "float", "float", None),
            ("m_FillClockwise", "bool", "bool", None),
            ("m_FillOrigin", "int", "int", None),
            ("m_UseSpriteMesh", "bool", "bool", None),
            ("m_PixelsPerUnitMultiplier", "float", "float", None),
        ],
    ),
    "Text": (
        _MASKABLE,
        ("CanvasRenderer", "RectTransform"),
        "Image",
        [
            *_GRAPHIC,
            # FontData.defaultFontData, with the font Text.Reset assigns in the editor (the
            # built-in LegacyRuntime.ttf)
            (
                "m_FontData",
                "FontData",
                "raw:FontData",
                "\n    m_Font: {fileID: 10102, guid: 0000000000000000e000000000000000, type: 0}"
                "\n    m_FontSize: 14\n    m_FontStyle: 0\n    m_BestFit: 0\n    m_MinSize: 10"
                "\n    m_MaxSize: 40\n    m_Alignment: 0\n    m_AlignByGeometry: 0"
                "\n    m_RichText: 1\n    m_HorizontalOverflow: 0\n    m_VerticalOverflow: 0"
                "\n    m_LineSpacing: 1",
            ),
            ("m_Text", "string", "string", " "),  # String.Empty
        ],
    ),
    "Button": (
        _SELECTABLE_BASES,
        (),
        "Slider",
        [*_SELECTABLE, ("m_OnClick", "ButtonClickedEvent", "raw:ButtonClickedEvent", _EVENT)],
    ),
    "Toggle": (
        _SELECTABLE_BASES,
        ("RectTransform",),
        "Slider",
        [
            *_SELECTABLE,
            ("toggleTransition", "ToggleTransition", _UI + "Toggle.ToggleTransition", " 1"),
            ("graphic", "Graphic", "ref:Graphic", _NULL),
            ("m_Group", "ToggleGroup", "ref:ToggleGroup", _NULL),
            ("onValueChanged", "ToggleEvent", "raw:ToggleEvent", _EVENT),
            ("m_IsOn", "bool", "bool", " 0"),
        ],
    ),
    "Slider": (
        _SELECTABLE_BASES,
        ("RectTransform",),
        "Slider",
        [
            *_SELECTABLE,
            ("m_FillRect", "RectTransform", "ref:RectTransform", _NULL),
            ("m_HandleRect", "RectTransform", "ref:RectTransform", _NULL),
            ("m_Direction", "Direction", _UI + "Slider.Direction", None),
            ("m_MinValue", "float", "float", " 0"),
            ("m_MaxValue", "float", "float", " 1"),
            ("m_WholeNumbers", "bool", "bool", None),
            ("m_Value", "float", "float", None),
            ("m_OnValueChanged", "SliderEvent", "raw:SliderEvent", None),
        ],
    ),
    "CanvasScaler": (
        ("UIBehaviour", "MonoBehaviour"),
        ("Canvas",),
        "CanvasScaler",
        [
            ("m_UiScaleMode", "ScaleMode", _UI + "CanvasScaler.ScaleMode", None),
            ("m_ReferencePixelsPerUnit", "float", "float", None),
            ("m_ScaleFactor", "float", "float", None),
            ("m_ReferenceResolution", "Vector2", "Vector2", None),
            ("m_ScreenMatchMode", "ScreenMatchMode", _UI + "CanvasScaler.ScreenMatchMode", None),
            ("m_MatchWidthOrHeight", "float", "float", None),
            ("m_PhysicalUnit", "Unit", _UI + "CanvasScaler.Unit", None),
            ("m_FallbackScreenDPI", "float", "float", None),
            ("m_DefaultSpriteDPI", "float", "float", None),
            ("m_DynamicPixelsPerUnit", "float", "float", None),
            ("m_PresetInfoIsWorld", "bool", "bool", None),
        ],
    ),
    "GraphicRaycaster": (
        ("BaseRaycaster", "UIBehaviour", "MonoBehaviour"),
        ("Canvas",),
        "GraphicRaycaster",
        [
            ("m_IgnoreReversedGraphics", "bool", "bool", None),
            (
                "m_BlockingObjects",
                "BlockingObjects",
                _UI + "GraphicRaycaster.BlockingObjects",
                None,
            ),
            ("m_BlockingMask", "LayerMask", "raw:LayerMask", None),
        ],
    ),
    "EventSystem": (
        ("UIBehaviour", "MonoBehaviour"),
        (),
        "EventSystem",
        [
            ("m_FirstSelected", "GameObject", "ref:GameObject", None),
            ("m_sendNavigationEvents", "bool", "bool", None),
            ("m_DragThreshold", "int", "int", None),
        ],
    ),
    "StandaloneInputModule": (
        ("PointerInputModule", "BaseInputModule", "UIBehaviour", "MonoBehaviour"),
        ("EventSystem",),
        "StandaloneInputModule",
        [
            ("m_SendPointerHoverToParent", "bool", "bool", None),  # BaseInputModule's
            ("m_HorizontalAxis", "string", "string", None),
            ("m_VerticalAxis", "string", "string", None),
            ("m_SubmitButton", "string", "string", None),
            ("m_CancelButton", "string", "string", None),
            ("m_InputActionsPerSecond", "float", "float", None),
            ("m_RepeatDelay", "float", "float", None),
            ("m_ForceModuleActive", "bool", "bool", None),
        ],
    ),
}

# uGUI's enums the fields use: members in declaration order, numbered from 0
ENUMS: dict[str, dict[str, int]] = {
    f"UnityEngine.UI.{name}": {member: value for value, member in enumerate(members.split())}
    for name, members in (
        ("CanvasScaler.ScaleMode", "ConstantPixelSize ScaleWithScreenSize ConstantPhysicalSize"),
        ("CanvasScaler.ScreenMatchMode", "MatchWidthOrHeight Expand Shrink"),
        ("CanvasScaler.Unit", "Centimeters Millimeters Inches Points Picas"),
        ("GraphicRaycaster.BlockingObjects", "None TwoD ThreeD All"),
        ("Image.FillMethod", "Horizontal Vertical Radial90 Radial180 Radial360"),
        ("Image.Type", "Simple Sliced Tiled Filled"),
        ("Selectable.Transition", "None ColorTint SpriteSwap Animation"),
        ("Slider.Direction", "LeftToRight RightToLeft BottomToTop TopToBottom"),
        ("Toggle.ToggleTransition", "None Fade"),
    )
}

_HEADER = re.compile(r"^--- !u!(\d+) &(-?\d+)", re.M)
_SCRIPT = re.compile(r"^  m_Script: \{fileID: 11500000, guid: ([0-9a-f]{32}), type: 3\}$", re.M)


class SampleError(Exception):
    """A real document and the table disagree."""


def script_fields(document: str) -> list[tuple[str, str]]:
    """(field, its text after ``field:``) for each field after ``m_EditorClassIdentifier``."""
    lines = document.rstrip("\n").split("\n")
    start = next(i for i, line in enumerate(lines) if line.startswith("  m_EditorClassIdentifier:"))
    fields: list[tuple[str, str]] = []
    for line in lines[start + 1 :]:
        if line.startswith("  ") and not line.startswith(("   ", "  - ")):
            name, _, rest = line[2:].partition(":")
            fields.append((name, rest))
        else:
            name, rest = fields[-1]
            fields[-1] = (name, f"{rest}\n{line}")
    return fields


def read_samples(paths: list[Path]) -> dict[str, list[tuple[str, str]]]:
    """uGUI class -> the fields of its first real document in ``paths``."""
    by_guid = {guid: name for name, (_, guid) in UGUI_SCRIPTS.items()}
    found: dict[str, list[tuple[str, str]]] = {}
    for path in paths:
        text = path.read_text(encoding="utf-8")
        starts = [m.start() for m in _HEADER.finditer(text)] + [len(text)]
        for begin, end in itertools.pairwise(starts):
            document = text[begin:end]
            script = _SCRIPT.search(document)
            name = by_guid.get(script.group(1)) if script else None
            if name is not None and name not in found:
                found[name] = script_fields(document)
    return found


def build(samples: dict[str, list[tuple[str, str]]]) -> dict:
    classes = {}
    for name, (bases, requires, source, table) in sorted(CLASSES.items()):
        real = samples.get(source)
        if real is None:
            raise SampleError(f"no real {source} document in the samples (for {name})")
        real_text = dict(real)
        if source == name and [f for f, _ in real] != [f[0] for f in table]:
            raise SampleError(
                f"{name}: the table's fields {[f[0] for f in table]} differ from Unity's "
                f"{[f for f, _ in real]}"
            )
        fields = []
        for field, csharp, kind, default in table:
            if default is None and field not in real_text:
                raise SampleError(f"{name}.{field}: no default and no real {source} value")
            text = real_text[field] if default is None else default
            line = f"  {field}:{text}"
            fields.append({"name": field, "type": csharp, "unity": kind, "text": line})
        namespace = UGUI_SCRIPTS[name][0]
        classes[name] = {
            "namespace": namespace,
            "bases": list(bases),
            "requires": list(requires),
            "sample": "real" if source == name else f"{source}'s base fields",
            "fields": fields,
        }
    return {
        "about": (
            "Every field Unity 2022.3 serializes for uGUI's components, in its order, with the "
            "text it writes for a freshly added one; read from documents Unity saved, defaults "
            "from uGUI's C# initializers. Written by scripts/update_ugui_fields.py; do not edit "
            "by hand."
        ),
        "enums": dict(sorted(ENUMS.items())),
        "classes": classes,
    }


def render(data: dict) -> str:
    return json.dumps(data, indent=1, ensure_ascii=False) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("documents", nargs="*", type=Path, default=SAMPLES)
    parser.add_argument("--output", type=Path, default=TARGET)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args(argv)
    try:
        text = render(build(read_samples(args.documents)))
    except (SampleError, OSError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    return write_or_check(args.output, text, args.check)


if __name__ == "__main__":
    sys.exit(main())
