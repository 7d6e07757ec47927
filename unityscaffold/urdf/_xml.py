"""A small XML tree with byte positions, read with the standard library's expat.

The URDF reader needs what the usual tree builders drop: where each element and attribute
starts (for located errors), whether an element was written ``<x/>`` or ``<x></x>``, comments,
and text exactly as written (ROS#'s importer keeps plugin elements as text, see ``_plugins``).
"""

from __future__ import annotations

import bisect
import re
import xml.parsers.expat as expat
from dataclasses import dataclass, field

from unityscaffold.errors import LocatedError, SourceLocation

__all__ = ["Comment", "Element", "Text", "XmlSource", "parse_xml"]


class XmlSource:
    """A file's path and raw bytes: turns byte offsets into ``SourceLocation`` values.

    Every element of the model carries one, so the line table is built once and each line
    decoded once (``SourceLocation.at_byte`` rescans the file up to the offset every time).
    """

    __slots__ = ("_lines", "_texts", "path", "raw")

    def __init__(self, path: str, raw: bytes) -> None:
        self.path = path
        self.raw = raw
        self._lines: list[int] | None = None  # the offset where each line starts
        self._texts: dict[int, tuple[str, bool]] = {}  # line → its text, whether ASCII

    def at(self, offset: int) -> SourceLocation:
        if self._lines is None:
            self._lines = [0] + [m.end() for m in re.finditer(rb"\n", self.raw)]
        line = bisect.bisect_right(self._lines, offset) - 1
        start = self._lines[line]
        text, ascii_only = self._line(line, start)
        if ascii_only:
            column = offset - start + 1
        else:
            column = len(self.raw[start:offset].decode("utf-8", "replace")) + 1
        return SourceLocation(self.path, line + 1, column, text)

    def _line(self, line: int, start: int) -> tuple[str, bool]:
        if line not in self._texts:
            end = self.raw.find(b"\n", start)
            chunk = self.raw[start : end if end >= 0 else len(self.raw)]
            self._texts[line] = (chunk.decode("utf-8", "replace").rstrip("\r"), chunk.isascii())
        return self._texts[line]


@dataclass(frozen=True, slots=True)
class Text:
    text: str
    cdata: bool = False


@dataclass(frozen=True, slots=True)
class Comment:
    text: str


@dataclass(frozen=True, slots=True)
class Element:
    """An element: its name, attributes in document order, content, and where it starts."""

    tag: str
    attributes: tuple[tuple[str, str], ...]
    children: tuple[Element | Text | Comment, ...]
    offset: int
    empty_tag: bool = False  # written as <x/>, not <x></x>
    attribute_offsets: tuple[int, ...] = field(default=(), compare=False)

    def get(self, name: str) -> str | None:
        return next((value for key, value in self.attributes if key == name), None)

    def attribute_offset(self, name: str) -> int:
        """Where ``name="…"`` starts in the file, or the element's start if it has none."""
        for (key, _), offset in zip(self.attributes, self.attribute_offsets, strict=True):
            if key == name:
                return offset
        return self.offset

    def elements(self, tag: str | None = None) -> list[Element]:
        """Child elements, all or those named ``tag``, in document order."""
        return [c for c in self.children if isinstance(c, Element) and tag in (None, c.tag)]

    def first(self, tag: str) -> Element | None:
        """The first child named ``tag`` (ROS#'s importer reads only that one)."""
        return next(iter(self.elements(tag)), None)


_ATTRIBUTE_RE = re.compile(rb"""\s([^\s=/>]+)\s*=\s*("[^"]*"|'[^']*')""")
_START_TAG_RE = re.compile(rb"""<[^\s/>]+(?:\s+[^\s=/>]+\s*=\s*(?:"[^"]*"|'[^']*'))*\s*/?>""")


#: How deeply elements may nest. A URDF nests a few levels (plugin elements a few more); the
#: elements are written and compared recursively, and a document thousands of levels deep
#: went past Python's recursion limit.
MAX_DEPTH = 100


class _TooDeep(Exception):
    def __init__(self, offset: int) -> None:
        super().__init__(offset)
        self.offset = offset


class _Builder:
    """Expat handlers that assemble ``Element`` values bottom-up."""

    def __init__(self, raw: bytes, parser: expat.XMLParserType) -> None:
        self.raw = raw
        self.parser = parser
        self.stack: list[tuple[str, list[tuple[str, str]], int, list[Element | Text | Comment]]]
        self.stack = []
        self.root: Element | None = None
        self.in_cdata = False

    def start(self, tag: str, attributes: list[str]) -> None:
        if len(self.stack) >= MAX_DEPTH:
            raise _TooDeep(self.parser.CurrentByteIndex)
        pairs = list(zip(attributes[::2], attributes[1::2], strict=True))
        self.stack.append((tag, pairs, self.parser.CurrentByteIndex, []))

    def end(self, tag: str) -> None:
        name, pairs, offset, children = self.stack.pop()
        end = self.parser.CurrentByteIndex
        element = Element(
            name,
            tuple(pairs),
            tuple(children),
            offset,
            empty_tag=not self.raw.startswith(b"</", end),
            attribute_offsets=self._attribute_offsets(offset, [k for k, _ in pairs]),
        )
        if self.stack:
            self.stack[-1][3].append(element)
        else:
            self.root = element

    def _attribute_offsets(self, offset: int, names: list[str]) -> tuple[int, ...]:
        """Where each attribute of the start tag at ``offset`` is written (expat tells only
        where the tag starts)."""
        tag = _START_TAG_RE.match(self.raw, offset) if names else None
        found: dict[str, int] = {}
        if tag is not None:
            for match in _ATTRIBUTE_RE.finditer(self.raw, offset, tag.end()):
                found.setdefault(match.group(1).decode("utf-8", "replace"), match.start(1))
        return tuple(found.get(name, offset) for name in names)

    def text(self, data: str) -> None:
        if not self.stack:
            return
        children = self.stack[-1][3]
        last = children[-1] if children else None
        if isinstance(last, Text) and last.cdata == self.in_cdata:
            children[-1] = Text(last.text + data, last.cdata)  # expat splits text at will
        else:
            children.append(Text(data, self.in_cdata))

    def comment(self, data: str) -> None:
        if self.stack:
            self.stack[-1][3].append(Comment(data))

    def start_cdata(self) -> None:
        self.in_cdata = True
        if self.stack:
            self.stack[-1][3].append(Text("", cdata=True))

    def end_cdata(self) -> None:
        self.in_cdata = False


def parse_xml(source: XmlSource) -> Element:
    """The document element of ``source``; malformed XML is a located error."""
    parser = expat.ParserCreate()
    builder = _Builder(source.raw, parser)
    parser.buffer_text = True
    parser.ordered_attributes = True
    parser.StartElementHandler = builder.start
    parser.EndElementHandler = builder.end
    parser.CharacterDataHandler = builder.text
    parser.CommentHandler = builder.comment
    parser.StartCdataSectionHandler = builder.start_cdata
    parser.EndCdataSectionHandler = builder.end_cdata
    try:
        parser.Parse(source.raw, True)
    except _TooDeep as deep:
        raise LocatedError.at(
            source.at(deep.offset),
            f"elements nested more than {MAX_DEPTH} deep",
            hint="a URDF's elements nest a few levels; check for tags left open",
        ) from None
    except expat.ExpatError as error:
        reason = expat.errors.messages[error.code]
        raise LocatedError.at(
            source.at(parser.ErrorByteIndex),
            f"malformed XML: {reason}",
            hint="a URDF must be well-formed XML; check the tags and quotes around here",
        ) from None
    assert builder.root is not None  # expat refuses a document without an element
    return builder.root
