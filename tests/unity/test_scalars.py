"""The scalar emitter: Unity's float digits and string quoting, checked against YAML readers."""

from __future__ import annotations

import io
import math
import struct

import pytest
import yaml
from hypothesis import given
from hypothesis import strategies as st
from ruamel.yaml import YAML

from unityscaffold.unity._emit import emit_field, value_equals
from unityscaffold.unity._folds import read_folds_unity_way
from unityscaffold.unity._scalars import format_float, format_string, keep_fold_spaces, to_float32
from unityscaffold.unity.scene import SceneDocument
from unityscaffold.unity.values import AssetRef, Enum, InlineMap, ObjectRef

# Written by Unity itself (docs/unity-yaml.md#scalars and the corpus).
UNITY_FLOATS = [
    (0.5, "0.5"),
    (0.95686275, "0.95686275"),
    (21.80208, "21.80208"),
    (1000.0, "1000"),
    (6570.0, "6570"),
    (0.000000089406925, "0.000000089406925"),
    (-7.1054147e-15, "-7.1054147e-15"),
    (1.5e11, "1.5e+11"),
    (3.4028235e38, "3.4028235e+38"),
    (-0.0, "-0"),
    (0.0, "0"),
    (math.inf, "Infinity"),
    (0.1, "0.1"),
    (0.022, "0.022"),
    (0.40821788, "0.40821788"),
    (-0.23456968, "-0.23456968"),
    (1 / 3, "0.33333334"),
]


@pytest.mark.parametrize(("value", "text"), UNITY_FLOATS)
def test_floats_are_written_as_unity_writes_them(value: float, text: str) -> None:
    assert format_float(value) == text


def _read_float(text: str) -> float:
    return {"Infinity": math.inf, "-Infinity": -math.inf, "NaN": math.nan}.get(text) or float(text)


@given(st.floats(width=32, allow_nan=False))
def test_every_float32_reads_back_exactly_from_its_shortest_digits(value: float) -> None:
    text = format_float(value)
    assert struct.pack("<f", _read_float(text)) == struct.pack("<f", value)
    # nothing shorter would do: dropping the last digit must lose the value
    digits = text.split("e")[0].lstrip("-").replace(".", "").strip("0")
    if len(digits) > 1 and math.isfinite(value) and value != 0:
        shorter = f"{abs(value):.{len(digits) - 2}e}"
        assert to_float32(float(shorter)) != abs(value)


def test_a_float_beyond_float32_is_refused() -> None:
    with pytest.raises(ValueError, match="float32"):
        format_float(1e39)


@pytest.mark.parametrize(
    ("text", "written"),
    [
        ("ws://localhost:9090", "ws://localhost:9090"),
        ("/joy", "/joy"),
        ("Unity", "Unity"),
        ("- dash", "'- dash'"),
        ("key: value", "'key: value'"),
        ("it's", "it's"),
        ("'quoted'", "'''quoted'''"),
        ("trailing ", "'trailing '"),
        ("a #comment", "'a #comment'"),
        ("@at", "'@at'"),
        ("ends:", "'ends:'"),
        ("---x", "'---x'"),
        ("line1\nline2", "'line1\n\n    line2'"),
        ("\u200b", '"\\u200B"'),
        ("\u041f\u0440\u0438", '"\\u041F\\u0440\\u0438"'),
        ("a\r\nb", '"a\\r\\nb"'),
        ("tab\there", '"tab\\there"'),
    ],
)
def test_strings_are_quoted_by_unitys_rules(text: str, written: str) -> None:
    assert format_string(text, column=9) == written


def test_a_trailing_bracket_is_quoted_only_in_6000_files() -> None:
    assert format_string("data[0]") == "data[0]"
    assert format_string("data[0]", quote_trailing_bracket=True) == "'data[0]'"


def test_a_long_plain_string_folds_at_a_single_space_past_column_80() -> None:
    lines = emit_field("Topic", " ".join(["segment"] * 20))
    assert len(lines) == 2
    assert lines[1].startswith("    segment")
    assert len(lines[0]) > 80 and len(lines[0]) - len("segment") - 1 <= 80


def _readers(text: str) -> list[object]:
    ruamel = YAML(typ="base", pure=True)  # string-only, as Unity reads by declared type
    return [yaml.load(text, Loader=yaml.BaseLoader), ruamel.load(io.StringIO(text))]


@given(
    st.text(st.characters(codec="utf-8", exclude_categories=["Cs"]), max_size=200),
    st.integers(min_value=0, max_value=70),
)
def test_every_emitted_string_reads_back_unchanged(value: str, indent: int) -> None:
    key = "k" * (indent + 1)
    doc = "\n".join(emit_field(key, value, 2)) + "\n"
    # A long double-quoted string is folded Unity's way (spaces before a fold kept), which a
    # YAML reader reads once those spaces are escaped: the reading ``parse_field`` does.
    for loaded in _readers(read_folds_unity_way(doc)):
        assert isinstance(loaded, dict)
        assert (loaded[key] or "") == value
    assert doc.isascii()


@given(
    st.one_of(
        st.booleans(),
        st.integers(-(2**63), 2**63 - 1),
        st.floats(width=32, allow_nan=False),
        st.builds(ObjectRef, st.integers(-(2**63), 2**63 - 1)),
        st.builds(
            AssetRef,
            st.integers(-(2**31), 2**31),
            st.text("0123456789abcdef", min_size=32, max_size=32),
            st.integers(0, 3),
        ),
        st.lists(st.text(max_size=20), max_size=4),
        st.builds(Enum, st.integers(0, 9)),
    )
)
def test_every_emitted_value_compares_equal_to_itself_once_read_back(value: object) -> None:
    text = "\n".join(emit_field("field", value)) + "\n"  # type: ignore[arg-type]
    stored = yaml.load(text, Loader=yaml.BaseLoader)["field"]
    assert value_equals(stored, value)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("stored", "value", "equal"),
    [
        ("0.50", 0.5, True),
        ("0.5", 0.25, False),
        ("1", True, True),
        ("0", True, False),
        ("10", 10, True),
        ("10", "10", True),
        ("abc", 3, False),
        ({"fileID": "5"}, ObjectRef(5), True),
        ({"fileID": "5", "guid": "a" * 32, "type": "3"}, ObjectRef(5), False),
        ({"x": "0", "y": "1"}, InlineMap.of(x=0, y=1.0), True),
        ([], [], True),
        ("", "", True),
        (["1", "2"], [1, 2], True),
        (["1"], [1, 2], False),
        ("-0", 0.0, False),
    ],
)
def test_a_stored_value_equals_a_requested_one_by_meaning_not_bytes(
    stored: object, value: object, equal: bool
) -> None:
    assert value_equals(stored, value) is equal  # type: ignore[arg-type]


@pytest.mark.parametrize("value", [" \n", "a \nb", "a\n b", "x\n ", "\n \n"])
def test_spaces_around_line_breaks_survive(value: str) -> None:
    """Found by the property test above: a single-quoted scalar drops them on reading."""
    doc = "\n".join(emit_field("k", value, 2)) + "\n"
    for loaded in _readers(doc):
        assert loaded["k"] == value


# A field as Unity 2022.3 saved it (ROS#'s UrdfPlugin.PluginText in ROS#'s r2d2 sample scene):
# Unity folds a long double-quoted string at a space and keeps the spaces before each fold, so
# the line ending "\r\n   " and the fold after it are four spaces of the text.
UNITY_FOLDED = (
    '  PluginText: "<gazebo>\\r\\n  <plugin filename=\\"gz-sim-diff-drive-system\\"\n'
    '    name=\\"gz::sim::systems::DiffDrive\\">\\r\\n   \n'
    "    <left_joint>left_front_wheel_joint</left_joint>\\r\\n \n"
    '    </plugin>\\r\\n</gazebo>"\n'
)
UNITY_FOLDED_TEXT = (
    '<gazebo>\r\n  <plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::DiffDrive">'
    "\r\n    <left_joint>left_front_wheel_joint</left_joint>\r\n  </plugin>\r\n</gazebo>"
)
MONOBEHAVIOUR = (
    """%YAML 1.1
%TAG !u! tag:unity3d.com,2011:
--- !u!1 &1
GameObject:
  m_ObjectHideFlags: 0
  serializedVersion: 6
  m_Component:
  - component: {fileID: 2}
  - component: {fileID: 3}
  m_Layer: 0
  m_Name: Plugins
  m_IsActive: 1
--- !u!4 &2
Transform:
  m_ObjectHideFlags: 0
  m_GameObject: {fileID: 1}
  m_LocalRotation: {x: 0, y: 0, z: 0, w: 1}
  m_LocalPosition: {x: 0, y: 0, z: 0}
  m_LocalScale: {x: 1, y: 1, z: 1}
  m_Children: []
  m_Father: {fileID: 0}
--- !u!114 &3
MonoBehaviour:
  m_ObjectHideFlags: 0
  m_GameObject: {fileID: 1}
  m_Enabled: 1
  m_Script: {fileID: 11500000, guid: 76add797bdb1d8c4b8276633f6e67167, type: 3}
"""
    + "  m_Name: \n"
)


def test_a_double_quoted_string_unity_folded_reads_with_the_spaces_before_each_fold() -> None:
    scene = SceneDocument.parse(MONOBEHAVIOUR + UNITY_FOLDED)
    assert scene.field(3, "PluginText") == UNITY_FOLDED_TEXT


def test_a_string_unity_folded_equals_the_same_string_written_on_one_line() -> None:
    """What ``apply`` relies on not to rewrite a field Unity refolded on save."""
    scene = SceneDocument.parse(MONOBEHAVIOUR + UNITY_FOLDED)
    assert scene.set_fields(3, [("PluginText", UNITY_FOLDED_TEXT)]) is False
    assert not scene.changed


@pytest.mark.parametrize(
    ("folded", "text"),
    [
        ('  k: "a  \n    b"\n', "a   b"),  # two kept, one for the fold
        ('  k: "a\\\\  \n    b"\n', "a\\   b"),  # an escaped backslash, then kept spaces
        ('  k: "a\\  \n    b"\n', "a   b"),  # an escaped space, then a kept one
        ('  k: "a\n    b"\n', "a b"),  # a fold at a single space
        ('  k: "a\\\n    b"\n', "ab"),  # an escaped line break joins
    ],
)
def test_spaces_before_a_fold_are_kept_next_to_escapes(folded: str, text: str) -> None:
    assert yaml.load(keep_fold_spaces(folded), Loader=yaml.BaseLoader)["k"] == text
