"""Line operations on one document's text; every edit replaces only the lines it must."""

from __future__ import annotations

import re
from collections.abc import Sequence

from unityscaffold.unity import _fields as F
from unityscaffold.unity._split import Doc

__all__ = [
    "append_list_item",
    "insert_field",
    "remove_list_item",
    "replace_field",
    "set_text",
]


def set_text(doc: Doc, text: str) -> None:
    doc.text = text
    doc.cache.clear()


def _lines(lines: Sequence[str]) -> str:
    return "".join(line + "\n" for line in lines)


def replace_field(doc: Doc, key: str, lines: Sequence[str]) -> None:
    """Replace the whole span of ``key`` with ``lines``."""
    span = F.field_span(doc, key)
    if span is None:
        raise KeyError(key)
    set_text(doc, doc.text[: span[0]] + _lines(lines) + doc.text[span[1] :])


def insert_field(
    doc: Doc, lines: Sequence[str], *, after: str | None = None, before: str | None = None
) -> None:
    """Insert ``lines`` after the span of ``after``, before ``before``, or at the end."""
    if after is not None:
        at = F.spans(doc)[after][1]
    elif before is not None:
        at = F.spans(doc)[before][0]
    else:
        at = len(doc.text)
    set_text(doc, doc.text[:at] + _lines(lines) + doc.text[at:])


def append_list_item(doc: Doc, key: str, item: str) -> None:
    """Append ``item`` (a full line such as ``  - {fileID: 5}``) to an indentless list."""
    span = F.field_span(doc, key)
    if span is None:
        raise KeyError(key)
    start, end = span
    if doc.text[start:end] == f"  {key}: []\n":
        set_text(doc, doc.text[:start] + f"  {key}:\n{item}\n" + doc.text[end:])
    else:
        set_text(doc, doc.text[:end] + item + "\n" + doc.text[end:])


def remove_list_item(doc: Doc, key: str, file_id: int) -> bool:
    """Remove the item referring to ``file_id``; an emptied list becomes ``[]``."""
    span = F.field_span(doc, key)
    if span is None:
        return False
    start, end = span
    block = doc.text[start:end]
    pattern = re.compile(rf"^  - (?:component: |\d+: )?\{{fileID: {file_id}\}}\n", re.M)
    reduced, count = pattern.subn("", block, count=1)
    if not count:
        return False
    if reduced == f"  {key}:\n":
        reduced = f"  {key}: []\n"
    set_text(doc, doc.text[:start] + reduced + doc.text[end:])
    return True
