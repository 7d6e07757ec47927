"""Comment blocks are dedented exactly as ``textwrap.dedent`` dedents the joined block."""

from __future__ import annotations

import textwrap

from hypothesis import given, settings
from hypothesis import strategies as st

from unityscaffold.interfaces._comments import clean_block


def _by_textwrap(lines: list[str]) -> tuple[str, ...]:
    kept: list[str] = []
    for line in lines:
        if line or (kept and kept[-1]):  # no empty line first, none twice in a row
            kept.append(line)
    while kept and not kept[-1]:
        kept.pop()
    return tuple(textwrap.dedent("\n".join(kept)).split("\n")) if kept else ()


_PIECES = ["", " ", "  ", "\t", "a", "b c", "\x0b", "\u3000", "\n", "\r"]


@settings(max_examples=300, deadline=None)
@given(st.lists(st.lists(st.sampled_from(_PIECES), max_size=4).map("".join), max_size=6))
def test_a_comment_block_is_dedented_as_textwrap_dedents_it(lines: list[str]) -> None:
    assert clean_block(lines) == _by_textwrap(lines)
