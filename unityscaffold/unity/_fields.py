"""A tolerant scanner for the top-level fields of one document (keys indented two spaces).

A field's span is its key line plus every following line that is not another top-level key:
deeper-indented lines, indentless ``  - `` sequence items, and the empty lines of a folded or
multi-line quoted scalar. Results are cached on the ``Doc`` and dropped when its text changes.
"""

from __future__ import annotations

import re
from typing import cast

import yaml

from unityscaffold.unity._folds import read_folds_unity_way
from unityscaffold.unity._split import Doc

__all__ = [
    "field_names",
    "field_span",
    "field_value",
    "list_refs",
    "parse_field",
    "ref_value",
    "script_of",
]

_KEY_RE = re.compile(r"^  ([^\s\-#'\"][^:\n]*):(?: |$)", re.M)
LOCAL_REF_RE = re.compile(r"\{fileID: (-?\d+)\}")
_SCRIPT_RE = re.compile(r"\{fileID: (-?\d+), guid: ([0-9a-f]{32}),\s+type: (\d+)\}")
_ITEM_REF_RE = re.compile(r"^  - (?:component: |\d+: )?\{fileID: (-?\d+)\}", re.M)
_BaseLoader = getattr(yaml, "CBaseLoader", yaml.BaseLoader)


def spans(doc: Doc) -> dict[str, tuple[int, int]]:
    """Top-level key → (start, end) character offsets of its lines within ``doc.text``."""
    cached = doc.cache.get("spans")
    if cached is None:
        found: dict[str, tuple[int, int]] = {}
        matches = list(_KEY_RE.finditer(doc.text))
        for index, match in enumerate(matches):
            end = matches[index + 1].start() if index + 1 < len(matches) else len(doc.text)
            found.setdefault(match.group(1), (match.start(), end))
        doc.cache["spans"] = cached = found
    return cached  # type: ignore[return-value]


def field_names(doc: Doc) -> list[str]:
    return list(spans(doc))


def field_span(doc: Doc, key: str) -> tuple[int, int] | None:
    return spans(doc).get(key)


def field_text(doc: Doc, key: str) -> str | None:
    """The exact lines of ``key`` (with the key itself), or None when the key is absent."""
    span = field_span(doc, key)
    return None if span is None else doc.text[span[0] : span[1]]


_INT_AT = re.compile(r"-?\d+")
_ITEMS_AT = re.compile(r"(?:  - .*\n|    .*\n)*")


_NEEDLES: dict[str, str] = {}  # key -> its line's start, made once per key, not per read


def _key_line(text: str, key: str) -> int:
    """Offset just past ``key:`` on a top-level line, or -1 (str.find beats a regex scan)."""
    needle = _NEEDLES.get(key)
    if needle is None:
        needle = _NEEDLES[key] = f"\n  {key}:"
    at = text.find(needle)
    while at >= 0:
        end = at + len(needle)
        if end < len(text) and text[end] in " \n":
            return end
        at = text.find(needle, end)
    return -1


def field_value(doc: Doc, key: str) -> str | None:
    """The raw text after ``key: `` on a one-line field (None when absent or multi-line)."""
    text = doc.text
    at = _key_line(text, key)
    if at < 0:
        return None
    eol = text.find("\n", at)
    following = text[eol + 1 : eol + 5]
    if following.startswith(("    ", "  - ", "\n")):
        return None
    return text[at + 1 : eol]


def parse_field(doc: Doc, key: str) -> object:
    """The field's value read with a string-only YAML loader (scalars stay ``str``)."""
    text = field_text(doc, key)
    if text is None:
        return None
    text = read_folds_unity_way(text)  # double-quoted strings Unity folded, read its way
    loaded = yaml.load(text, Loader=_BaseLoader)
    return loaded[key] if isinstance(loaded, dict) else None


def scalar_value(doc: Doc, key: str) -> str | None:
    """A string field's value, unquoted and unfolded."""
    raw = field_value(doc, key)
    if raw is not None and not raw.startswith(("'", '"')):
        return raw
    value = parse_field(doc, key)
    return value if isinstance(value, str) else None


# One string per cache key, shared by every document's cache (not one per document); looked up
# by the field's name alone because these are read tens of thousands of times per file.
_REF_KEYS: dict[str, str] = {}
_REFS_KEYS: dict[str, str] = {}
_UNSET = object()


def ref_value(doc: Doc, key: str) -> int | None:
    """The fileID of a ``key: {fileID: N}`` (or ``{fileID: N, guid: …}``) field."""
    # cached: the hierarchy and validation read the same links of every document
    name = _REF_KEYS.get(key)
    if name is None:
        name = _REF_KEYS[key] = "ref " + key
    cached = doc.cache.get(name, _UNSET)
    if cached is not _UNSET:
        return cached  # type: ignore[return-value]
    text = doc.text
    at = _key_line(text, key)
    found = None
    if at >= 0 and text.startswith(" {fileID: ", at):
        match = _INT_AT.match(text, at + 10)
        found = int(match.group(0)) if match else None
    doc.cache[name] = found
    return found


def list_refs(doc: Doc, key: str) -> list[int]:
    """fileIDs in an indentless list: ``- {fileID: N}``, ``- component: {…}`` or ``- 4: {…}``."""
    name = _REFS_KEYS.get(key)
    if name is None:
        name = _REFS_KEYS[key] = "refs " + key
    cached = cast("tuple[int, ...] | None", doc.cache.get(name))
    if cached is None:
        text = doc.text
        at = _key_line(text, key)
        block = _ITEMS_AT.match(text, at + 1) if at >= 0 and text[at] == "\n" else None
        found = tuple(map(int, _ITEM_REF_RE.findall(block.group(0)))) if block else ()
        doc.cache[name] = cached = found
    return list(cached)


def script_of(doc: Doc) -> tuple[int, str, int] | None:
    """(fileID, guid, type) of ``m_Script``, tolerating a flow mapping folded over lines."""
    if "script" in doc.cache:
        return doc.cache["script"]  # type: ignore[return-value]
    text = field_text(doc, "m_Script")
    match = _SCRIPT_RE.search(text) if text is not None else None
    found = (int(match.group(1)), match.group(2), int(match.group(3))) if match else None
    doc.cache["script"] = found
    return found


def local_refs(text: str) -> list[re.Match[str]]:
    """Every guid-less ``{fileID: N}`` in ``text``: references to objects in the same file."""
    return list(LOCAL_REF_RE.finditer(text))
