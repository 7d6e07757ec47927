"""C# literals for constants and defaults: typed, escaped, exact."""

from __future__ import annotations

import math

import pytest

from unityscaffold.codegen._literals import (
    array_literal,
    literal,
    string_literal,
    zero_literal,
)


@pytest.mark.parametrize(
    ("value", "cs_type", "text"),
    [
        (0.5, "float", "0.5f"),
        (1, "float", "1.0f"),
        (0.1, "double", "0.1"),
        (2, "double", "2.0"),
        (1e-20, "double", "1e-20"),
        (math.nan, "float", "float.NaN"),
        (math.inf, "double", "double.PositiveInfinity"),
        (-math.inf, "float", "float.NegativeInfinity"),
        (-9223372036854775808, "long", "-9223372036854775808L"),
        (18446744073709551615, "ulong", "18446744073709551615UL"),
        (4294967295, "uint", "4294967295U"),
        (-128, "sbyte", "-128"),
        (255, "byte", "255"),
        (True, "bool", "true"),
        (False, "bool", "false"),
    ],
)
def test_literals_carry_their_csharp_type(value: object, cs_type: str, text: str) -> None:
    assert literal(value, cs_type) == text  # type: ignore[arg-type]


def test_out_of_range_integers_are_refused() -> None:
    with pytest.raises(ValueError, match="does not fit in a C# sbyte"):
        literal(200, "sbyte")


def test_strings_escape_quotes_controls_and_non_ascii() -> None:
    assert string_literal('say "hi"\\\n\t') == '"say \\"hi\\"\\\\\\n\\t"'
    assert string_literal("café") == '"caf\\u00E9"'
    assert string_literal("🤖") == '"\\uD83E\\uDD16"'
    assert string_literal("\x01") == '"\\u0001"'


def test_printable_ascii_is_its_own_text_except_quote_and_backslash() -> None:
    for code in range(0x20, 0x7F):
        char = chr(code)
        expected = {'"': '\\"', "\\": "\\\\"}.get(char, char)
        assert string_literal(f"a{char}b") == f'"a{expected}b"'
    assert string_literal("") == '""'
    assert string_literal("\x7f") == '"\\u007F"'  # DEL is not printable


@pytest.mark.parametrize(
    "cs_type",
    ["bool", "sbyte", "byte", "short", "ushort", "int", "uint", "long", "ulong", "float", "double"],
)
def test_the_zero_of_each_type_is_its_literal_of_0(cs_type: str) -> None:
    assert zero_literal(cs_type) == literal(0, cs_type)


def test_array_defaults_list_their_values() -> None:
    assert array_literal((1, 2), "long") == "new long[] { 1L, 2L }"
    assert array_literal((), "float") == "new float[0]"
