"""The ROS 2 grammar keeps rosidl_adapter's rules and locates every error."""

from __future__ import annotations

import pytest

from unityscaffold.errors import LocatedError
from unityscaffold.interfaces import ros2
from unityscaffold.interfaces.model import ArrayKind


def parse(text: str):
    return ros2.parse_message(text, "pkg", "Msg", "pkg/msg/Msg.msg")


def test_bounded_strings_and_sequences():
    spec = parse("string<=10 name\nint32[<=5] values\nwstring<=3[2] pair\n")
    assert [(f.type.base, f.type.string_bound, f.type.array, f.type.size) for f in spec.fields] == [
        ("string", 10, ArrayKind.NONE, None),
        ("int32", None, ArrayKind.BOUNDED, 5),
        ("wstring", 3, ArrayKind.FIXED, 2),
    ]


def test_defaults_scalars_arrays_and_quoted_strings():
    spec = parse(
        'int32 x 5\nfloat64[2] v [1.5, -2]\nstring s "a # b"\n'
        "string[] names ['x, y', \"z\"]\nbool flag TRUE\nint32 hex 0x10\n"
    )
    # The comment starts at the first "#", even inside quotes, exactly as in rosidl_adapter.
    assert [f.default for f in spec.fields] == [5, (1.5, -2.0), '"a', ("x, y", "z"), True, 16]


def test_string_constants_lose_one_pair_of_quotes():
    spec = parse('string GREETING="Hello world!"\nstring RAW=plain\n')
    assert [c.value for c in spec.constants] == ["Hello world!", "plain"]


def test_byte_is_unsigned_and_there_is_no_header_shorthand():
    spec = parse("byte b 255\nHeader header\nstd_msgs/Header h\n")
    assert spec.fields[0].default == 255
    assert [f.type.base for f in spec.fields[1:]] == ["pkg/msg/Header", "std_msgs/msg/Header"]


@pytest.mark.parametrize(
    ("text", "line", "col", "fragment"),
    [
        ("int32 BadName\n", 1, 7, "not a valid field name"),
        ("int32 bad__name\n", 1, 7, "not a valid field name"),
        ("int32 lower=1\n", 1, 7, "not a valid constant name"),
        ("int32[0] x\n", 1, 7, "invalid array size"),
        ("string<=0 s\n", 1, 9, "invalid string bound"),
        ("uint8 x 300\n", 1, 9, "out of range"),
        ("int32[2] v [1]\n", 1, 12, "exactly 2 elements"),
        ("pkg/msg/Deep x\n", 1, 1, "not a valid type name"),
        ("geometry_msgs/Point p 1\n", 1, 23, "cannot have default values"),
        ("int32\n", 1, 6, "not followed by a name"),
        (" int32 x\n", 1, 1, "beginning of the line"),
        ("string<=\u00b2 s\n", 1, 9, "invalid string bound"),
        ("string<=" + "9" * 5000 + " s\n", 1, 9, "invalid string bound"),
        ("wstring<=2147483648 s\n", 1, 10, "invalid string bound"),
        ("int32[" + "9" * 5000 + "] x\n", 1, 7, "invalid array size"),
        ("int32[<=2147483648] x\n", 1, 7, "invalid array size"),
        ("int32[11111111111111111111] x\n", 1, 7, "invalid array size"),
        ("int32 STATUS_MAX_LINEAR_VELOCITY_LIMITx=1\n", 1, 7, "not a valid constant name"),
        ("int32 A__B=1\n", 1, 7, "not a valid constant name"),
        ("int32 AB_=1\n", 1, 7, "not a valid constant name"),
    ],
)
def test_errors_name_line_and_column(text, line, col, fragment):
    with pytest.raises(LocatedError) as caught:
        parse("# doc\n\n" + text)
    diagnostic = caught.value.diagnostics[0]
    assert (diagnostic.location.line, diagnostic.location.col) == (line + 2, col)
    assert fragment in diagnostic.message


def test_sizes_and_bounds_are_read_as_rosidl_reads_them_with_int():
    spec = parse("string<=+5 a\nstring<=5_0 b\nint32[+3] c\nint32[<=2147483647] d\n")
    assert [(f.type.string_bound, f.type.size) for f in spec.fields] == [
        (5, None),
        (50, None),
        (None, 3),
        (None, 2**31 - 1),
    ]


def test_constant_names_are_rosidls_pattern_checked_in_linear_time():
    long_bad = "A" + "_A" * 20000 + "x"  # rosidl's own pattern would never finish on this
    with pytest.raises(LocatedError):
        parse(f"int32 {long_bad}=1\n")
    names = ["A", "A1", "A_B", "AB_C1_D", "A_1"]
    spec = parse("".join(f"int32 {n}=1\n" for n in names))
    assert [c.name for c in spec.constants] == names


@pytest.mark.parametrize("quote", ['"', "'"])
def test_a_lone_quote_is_the_empty_string_as_in_rosidl(quote):
    spec = parse(f"string S={quote}\nstring s {quote}\n")
    assert (spec.constants[0].value, spec.fields[0].default) == ("", "")


def test_service_needs_exactly_one_separator_line():
    with pytest.raises(LocatedError) as caught:
        ros2.parse_service("int32 a\n----\nint32 b\n", "pkg", "S", "S.srv")
    assert "exactly 1 separator" in caught.value.message


def test_service_derives_request_response_and_event():
    spec = ros2.parse_service("int32 a\n---\nint32 b\n", "pkg", "S", "S.srv")
    assert [m.full_name for m in spec.parts] == [
        "pkg/srv/S_Request",
        "pkg/srv/S_Response",
        "pkg/srv/S_Event",
    ]


def test_action_derives_send_goal_get_result_and_feedback_message():
    spec = ros2.parse_action("int32 order\n---\nint32[] seq\n---\nint32[] part\n", "pkg", "Fib")
    assert [s.full_name for s in spec.services] == [
        "pkg/action/Fib_SendGoal",
        "pkg/action/Fib_GetResult",
    ]
    assert spec.derived[0].full_name == "pkg/action/Fib_FeedbackMessage"
    assert [f.type.base for f in spec.services[0].request.fields] == [
        "unique_identifier_msgs/msg/UUID",
        "pkg/action/Fib_Goal",
    ]
