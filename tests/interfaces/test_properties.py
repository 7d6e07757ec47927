"""Property tests: valid definitions parse to what was written; junk never escapes as a crash."""

from __future__ import annotations

import keyword

from hypothesis import given, settings
from hypothesis import strategies as st

from unityscaffold.errors import LocatedError
from unityscaffold.interfaces import ros1, ros2

ROS1_TYPES = [
    "bool",
    "int8",
    "uint8",
    "int16",
    "uint16",
    "int32",
    "uint32",
    "int64",
    "uint64",
    "float32",
    "float64",
    "string",
    "time",
    "duration",
    "byte",
    "char",
]
ROS2_TYPES = [
    "bool",
    "byte",
    "char",
    "float32",
    "float64",
    "int8",
    "uint8",
    "int16",
    "uint16",
    "int32",
    "uint32",
    "int64",
    "uint64",
    "string",
    "wstring",
]

ros1_names = st.from_regex(r"\A[A-Za-z][A-Za-z0-9_]{0,12}\Z").filter(
    lambda n: not keyword.iskeyword(n)
)
ros2_names = st.from_regex(r"\A[a-z](?:[a-z0-9]|_(?=[a-z0-9])){0,12}\Z")
arrays = st.one_of(st.just(""), st.just("[]"), st.integers(1, 64).map(lambda n: f"[{n}]"))
comments = st.one_of(
    st.just(""), st.from_regex(r"\A[A-Za-z0-9 .,<>&]{0,20}\Z").map(lambda t: "  # " + t)
)


@st.composite
def ros1_message(draw):
    names = draw(st.lists(ros1_names, min_size=1, max_size=8, unique=True))
    rows = [
        (draw(st.sampled_from(ROS1_TYPES)) + draw(arrays), name, draw(comments)) for name in names
    ]
    return rows, "".join(f"{t} {n}{c}\n" for t, n, c in rows)


@given(ros1_message())
@settings(max_examples=150, deadline=None)
def test_ros1_fields_parse_back_to_what_was_written(message):
    rows, text = message
    spec = ros1.parse_message(text, "pkg", "Gen", "Gen.msg")
    assert [(f.type_text, f.name) for f in spec.fields] == [(t, n) for t, n, _ in rows]
    expected_docs = [(c[4:].strip(),) if c[4:].strip() else () for _, _, c in rows]
    assert [f.comment for f in spec.fields] == expected_docs


@st.composite
def ros2_message(draw):
    names = draw(st.lists(ros2_names, min_size=1, max_size=8, unique=True))
    rows = []
    for name in names:
        base = draw(st.sampled_from(ROS2_TYPES))
        if base in ("string", "wstring") and draw(st.booleans()):
            base += f"<={draw(st.integers(1, 99))}"
        suffix = draw(st.one_of(arrays, st.integers(1, 9).map(lambda n: f"[<={n}]")))
        rows.append((base + suffix, name))
    return rows, "".join(f"{t} {n}\n" for t, n in rows)


@given(ros2_message())
@settings(max_examples=150, deadline=None)
def test_ros2_fields_parse_back_to_what_was_written(message):
    rows, text = message
    spec = ros2.parse_message(text, "pkg", "Gen", "Gen.msg")
    assert [(str(f.type), f.name) for f in spec.fields] == rows


@st.composite
def ros1_constant(draw):
    kind = draw(st.sampled_from(["int8", "uint16", "int64", "float64", "bool", "string"]))
    if kind == "string":
        value = draw(
            st.text(st.characters(min_codepoint=33, max_codepoint=126), min_size=1, max_size=10)
        )
    elif kind == "bool":
        value = draw(st.sampled_from(["True", "False", "1", "0"]))
    elif kind == "float64":
        value = repr(draw(st.floats(allow_nan=False, allow_infinity=False)))
    else:
        low, high = {"int8": (-128, 127), "uint16": (0, 65535), "int64": (-(2**63), 2**63 - 1)}[
            kind
        ]
        value = str(draw(st.integers(low, high)))
    return kind, value


@given(st.lists(ros1_constant(), min_size=1, max_size=5))
@settings(max_examples=150, deadline=None)
def test_ros1_constants_keep_their_text(constants):
    text = "".join(f"{k} C{i}={v}\n" for i, (k, v) in enumerate(constants))
    spec = ros1.parse_message(text, "pkg", "Gen", "Gen.msg")
    assert [(c.type, c.text) for c in spec.constants] == [(k, v.strip()) for k, v in constants]


junk_lines = st.lists(st.text(max_size=40), min_size=1, max_size=6).map("\n".join)


@given(junk_lines)
@settings(max_examples=300, deadline=None)
def test_ros1_junk_raises_only_located_errors(text):
    try:
        ros1.parse_message(text, "pkg", "Junk", "Junk.msg")
    except LocatedError as error:
        assert all(d.location.line >= 1 and d.location.col >= 1 for d in error.diagnostics)


@given(junk_lines)
@settings(max_examples=300, deadline=None)
def test_ros2_junk_raises_only_located_errors(text):
    for parse in (ros2.parse_message, ros2.parse_service, ros2.parse_action):
        try:
            parse(text, "pkg", "Junk", "Junk.msg")
        except LocatedError as error:
            assert all(d.location.line >= 1 for d in error.diagnostics)
