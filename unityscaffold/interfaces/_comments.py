"""Which comment documents what, shared by both dialects.

The rule is rosidl_adapter's, the nearest thing ROS has to a documented convention: the
``#`` lines at the very top of a file document the message; a block of comment lines documents
the next declaration, together with that declaration's trailing comment; an indented comment
line continues the documentation of the declaration above it.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass, field

__all__ = ["CommentTracker", "clean_block"]


def clean_block(lines: list[str]) -> tuple[str, ...]:
    """Dedent a comment block and drop empty lines at its ends and runs of empty lines."""
    if len(lines) < 2:
        # Most blocks are one line or none; dedenting one line strips its leading spaces and
        # tabs, which is what textwrap.dedent does to it (and costs a tenth of it).
        if not lines or not lines[0]:
            return ()
        line = lines[0]
        if "\n" not in line:
            return (line.lstrip(" \t"),)
    kept: list[str] = []
    for line in lines:
        if line == "" and (not kept or kept[-1] == ""):
            continue
        kept.append(line)
    while kept and kept[-1] == "":
        kept.pop()
    if not kept:
        return ()
    joined = "\n".join(kept)
    if joined.count("\n") >= len(kept):  # a line holds a line break: textwrap splits it
        return tuple(textwrap.dedent(joined).split("\n"))
    return _dedent(kept)


def _dedent(lines: list[str]) -> tuple[str, ...]:
    """``textwrap.dedent`` of lines without line breaks, line by line (a third of its cost):
    the indent (spaces and tabs) all non-blank lines share is cut, blank lines become empty."""
    rest = [line.lstrip(" \t") for line in lines]
    indents = [line[: len(line) - len(r)] for line, r in zip(lines, rest, strict=True) if r]
    cut = _shared_start(indents)
    return tuple(line[cut:] if r else "" for line, r in zip(lines, rest, strict=True))


def _shared_start(texts: list[str]) -> int:
    """The length of the start all ``texts`` share (that of the first and last in order)."""
    if not texts:
        return 0
    low, high = min(texts), max(texts)
    for index, char in enumerate(low):
        if char != high[index]:
            return index
    return len(low)


def comment_text(raw: str) -> str:
    """The text of a comment, given everything from its first ``#`` on."""
    return raw.lstrip("#").rstrip()


@dataclass(slots=True)
class CommentTracker:
    """Feeds on lines in file order and hands each declaration its documentation."""

    header: list[str] = field(default_factory=list)
    pending: list[str] = field(default_factory=list)
    in_header: bool = True
    last: list[str] | None = None

    def comment_line(self, raw_line: str, comment: str) -> None:
        """A line holding only a comment; ``comment`` starts at its ``#``."""
        text = comment_text(comment)
        if self.in_header and raw_line.startswith("#"):
            self.header.append(text)
            return
        self.in_header = False
        if raw_line[:1].isspace() and self.last is not None:
            self.last.append(text)
        else:
            self.pending.append(text)

    def blank_line(self) -> None:
        self.in_header = False

    def declaration(self, trailing: str | None) -> list[str]:
        """A declaration line; returns the (still growing) list of its comment lines."""
        self.in_header = False
        docs = self.pending
        if trailing is not None:
            docs.append(comment_text(trailing))
        self.pending = []
        self.last = docs
        return docs

    @property
    def message_doc(self) -> tuple[str, ...]:
        return clean_block(self.header)
