"""The ROS 1 grammar keeps genmsg's rules, surprising ones included, and locates every error."""

from __future__ import annotations

import pytest

from unityscaffold.errors import LocatedError
from unityscaffold.interfaces import ros1
from unityscaffold.interfaces.model import ArrayKind


def parse(text: str):
    return ros1.parse_message(text, "pkg", "Msg", "pkg/msg/Msg.msg")


def test_string_constant_keeps_raw_text_after_the_first_equals_sign():
    spec = parse('string A = a # b=c\nstring B="x"\n')
    assert [(c.name, c.value, c.text) for c in spec.constants] == [
        ("A", "a # b=c", "a # b=c"),
        ("B", '"x"', '"x"'),
    ]


def test_numeric_constant_text_is_kept_as_written_for_the_md5():
    spec = parse("uint8 MODIFY = 0\nfloat64 PI=3.14159\nint8 NO_FIX =  -1  # comment\n")
    assert [(c.name, c.value, c.text) for c in spec.constants] == [
        ("MODIFY", 0, "0"),
        ("PI", 3.14159, "3.14159"),
        ("NO_FIX", -1, "-1"),
    ]


def test_bool_constants_are_python_literals():
    spec = parse("bool T=True\nbool F=0\n")
    assert [c.value for c in spec.constants] == [True, False]


def test_bare_header_means_std_msgs_header_and_other_names_get_the_package():
    spec = parse("Header header\nPoint p\ngeometry_msgs/Pose pose\ntime t\nbyte b\nchar c\n")
    assert [f.type.base for f in spec.fields] == [
        "std_msgs/Header",
        "pkg/Point",
        "geometry_msgs/Pose",
        "time",
        "byte",
        "char",
    ]


def test_arrays_fixed_and_unbounded():
    spec = parse("float64[9] k\nuint8[] data\n")
    assert [(f.type.array, f.type.size) for f in spec.fields] == [
        (ArrayKind.FIXED, 9),
        (ArrayKind.UNBOUNDED, None),
    ]
    assert [f.type_text for f in spec.fields] == ["float64[9]", "uint8[]"]


def test_tabs_before_comments_and_leading_spaces_are_harmless():
    spec = parse(" float64 x\t\t# comment\n")
    assert [(f.name, f.comment) for f in spec.fields] == [("x", ("comment",))]


def test_comments_document_the_message_and_the_declarations():
    spec = parse("# The message.\n\n# The x.\nfloat64 x  # in metres\n  # more about x\nint32 y\n")
    assert spec.comment == ("The message.",)
    assert spec.fields[0].comment == ("The x.", "in metres", "more about x")
    assert spec.fields[1].comment == ()


@pytest.mark.parametrize(
    ("text", "line", "col", "fragment"),
    [
        ("int32\tx\n", 1, 1, "invalid field declaration"),
        ("float64 x\nint32 1bad\n", 2, 7, "not a legal field name"),
        ("int32[3][2] grid\n", 1, 1, "more than one dimension"),
        ("int32[-1] x\n", 1, 1, "not a legal field type"),
        ("time T=1\n", 1, 1, "not a legal constant type"),
        ("uint8 X=256\n", 1, 9, "out of range"),
        ("int32 X=1=2\n", 1, 8, "exactly one '='"),
        ("int32 x\nint32 x\n", 2, 7, "duplicate field name"),
        ("bool B=maybe\n", 1, 8, "invalid bool constant value"),
        # int("²") fails, so genmsg's is_valid_msg_type refuses it too.
        ("int32[\u00b2] a\n", 1, 1, "not a legal field type"),
        ("int32[" + "9" * 5000 + "] a\n", 1, 7, "invalid array size"),
        ("int32[11111111111111111111] a\n", 1, 7, "invalid array size"),
        ("int32[2147483648] a\n", 1, 7, "invalid array size"),
        # genmsg accepts the line, then fails to load 'geometry_msgs/msg/Point'.
        ("geometry_msgs/msg/Point p\n", 1, 1, "not a ROS 1 type name"),
        ("geometry_msgs/ p\n", 1, 1, "not a ROS 1 type name"),
    ],
)
def test_errors_name_line_and_column(text, line, col, fragment):
    with pytest.raises(LocatedError) as caught:
        parse(text)
    diagnostic = caught.value.diagnostics[0]
    assert (diagnostic.location.line, diagnostic.location.col) == (line, col)
    assert fragment in diagnostic.message
    assert caught.value.render().startswith(f"pkg/msg/Msg.msg:{line}:{col}: error:")


def test_largest_array_csharp_can_hold_and_decimal_digits_int_reads_are_sizes():
    spec = parse("int32[2147483647] big\nint32[\u0663] arabic\nint32[007] padded\n")
    assert [f.type.size for f in spec.fields] == [2**31 - 1, 3, 7]


def test_a_ros2_style_name_gets_the_ros1_form_as_hint():
    with pytest.raises(LocatedError) as caught:
        parse("geometry_msgs/msg/Point[2] p\n")
    assert caught.value.diagnostics[0].hint == (
        "ROS 1 names types pkg/Name, without the msg/ of ROS 2 (here geometry_msgs/Point[2])"
    )


def test_every_bad_line_is_reported_not_just_the_first():
    with pytest.raises(LocatedError) as caught:
        parse("int32\tx\nfloat64 ok\nstring 2bad\n")
    assert [d.location.line for d in caught.value.diagnostics] == [1, 3]


def test_service_halves_split_at_any_line_starting_with_three_dashes():
    spec = ros1.parse_service("int64 a\n----\nint64 sum\n", "pkg", "Add", "Add.srv")
    assert (spec.request.full_name, spec.response.full_name) == (
        "pkg/AddRequest",
        "pkg/AddResponse",
    )
    assert spec.request.text == "int64 a\n"
    assert spec.response.text == "int64 sum\n\n"
    assert spec.response.fields[0].location.line == 3


def test_action_needs_three_parts():
    with pytest.raises(LocatedError) as caught:
        ros1.parse_action("int32 order\n---\nint32[] sequence\n", "pkg", "Fib", "Fib.action")
    assert "exactly 3 parts" in caught.value.message


def test_action_gives_genactions_seven_messages():
    spec = ros1.parse_action("int32 order\n---\nint32[] seq\n---\nint32[] part\n", "pkg", "Fib")
    names = sorted(m.name for m in spec.messages)
    assert names == sorted(
        [
            "FibGoal",
            "FibResult",
            "FibFeedback",
            "FibAction",
            "FibActionGoal",
            "FibActionResult",
            "FibActionFeedback",
        ]
    )
    assert spec.goal.text == ros1.ACTION_BANNER + "int32 order\n"
    assert [f.type.base for f in spec.derived[1].fields] == [
        "std_msgs/Header",
        "actionlib_msgs/GoalID",
        "pkg/FibGoal",
    ]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            "bool B=maybe\n",
            "pkg/msg/Msg.msg:1:8: error: invalid bool constant value 'maybe': "
            "not a Python literal such as True, False, 1 or 0 (expected a bool literal)",
        ),
        (
            "bool B=1 +\n",
            "pkg/msg/Msg.msg:1:8: error: invalid bool constant value '1 +': "
            "not a Python literal such as True, False, 1 or 0 (expected a bool literal)",
        ),
        (
            "float64 F=abc\n",
            "pkg/msg/Msg.msg:1:11: error: invalid float64 constant value 'abc': "
            "not a number (expected a float64 literal)",
        ),
        (
            "int32 I=1.5\n",
            "pkg/msg/Msg.msg:1:9: error: invalid int32 constant value '1.5': "
            "not an integer (expected a int32 literal)",
        ),
    ],
)
def test_bad_constant_values_are_explained_without_python_internals(text, message):
    """genmsg converts constants with Python; its error texts (``invalid literal for int()``,
    ``<ast.Name object at 0x...>``) never reach the user."""
    with pytest.raises(LocatedError) as caught:
        parse(text)
    assert caught.value.render().split("\n")[0] == message
