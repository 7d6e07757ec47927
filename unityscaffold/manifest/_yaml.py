"""YAML text to a small tree whose every node knows its ``SourceLocation``.

We compose with ruamel.yaml (YAML 1.2, so ``yes`` stays text; plain manifests are read by
libyaml into the same nodes, see ``_libyaml``) and convert the node graph
ourselves instead of constructing Python objects: construction forgets positions, and doing it
here lets us report duplicate keys, custom tags and alias bombs as located errors.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

from ruamel.yaml import YAML
from ruamel.yaml.error import MarkedYAMLError, YAMLError
from ruamel.yaml.events import (
    MappingEndEvent,
    MappingStartEvent,
    SequenceEndEvent,
    SequenceStartEvent,
)
from ruamel.yaml.nodes import MappingNode, Node, ScalarNode, SequenceNode
from ruamel.yaml.reader import ReaderError

from unityscaffold.errors import LocatedError, SourceLocation
from unityscaffold.manifest._libyaml import RUAMEL, compose_plain

__all__ = ["YEntry", "YMap", "YNode", "YScalar", "YSeq", "compose"]

_CORE = "tag:yaml.org,2002:"
_STR = f"{_CORE}str"
_SCALAR_TAGS = {f"{_CORE}{t}" for t in ("str", "int", "float", "bool", "null", "timestamp")}
# What an explicitly tagged scalar must look like, for the tags whose values can be wrong.
_TAGGED_FORMS = {
    "int": "an integer such as 10 or 0x1F",
    "float": "a number such as 1.5",
    "bool": "true or false",
}
# Tens of thousands of nodes is far beyond any real manifest; the cap stops alias bombs.
_MAX_NODES = 50_000


@dataclass(frozen=True, slots=True)
class YScalar:
    value: object  # str, int, float, bool or None (timestamps are kept as their text)
    location: SourceLocation


@dataclass(frozen=True, slots=True)
class YSeq:
    items: tuple[YNode, ...]
    location: SourceLocation


@dataclass(frozen=True, slots=True)
class YEntry:
    key: str
    key_location: SourceLocation
    value: YNode


@dataclass(frozen=True, slots=True)
class YMap:
    entries: tuple[YEntry, ...]
    location: SourceLocation

    def get(self, key: str) -> YEntry | None:
        return next((e for e in self.entries if e.key == key), None)


YNode = YScalar | YSeq | YMap


def compose(text: str, path: str) -> YNode | None:
    """Parse one YAML document; None when it holds no value at all (empty or comments only)."""
    lines = text.splitlines()
    yaml = YAML(typ="safe", pure=True)
    node = compose_plain(text, yaml.resolver)
    try:
        with warnings.catch_warnings():
            # Reused anchors are legal YAML; ruamel only warns, and library code must not print.
            warnings.simplefilter("ignore")
            if node is RUAMEL:
                node = yaml.compose(text)
    except MarkedYAMLError as exc:
        raise _syntax_error(exc, path, lines) from None
    except ReaderError as exc:
        loc = _location_of_offset(text, exc.position, path)
        raise LocatedError.at(
            loc,
            f"invalid character {exc.character!r} in YAML text",
            hint="save the manifest as plain UTF-8 text",
        ) from None
    except YAMLError as exc:
        raise LocatedError.at(SourceLocation(path), f"invalid YAML: {exc}") from None
    except RecursionError:
        raise _too_deep(text, path, lines) from None
    if node is None:
        return None
    try:
        return _Converter(path, lines, yaml).convert(node)
    except RecursionError:
        raise _too_deep(text, path, lines) from None


# Far deeper than any manifest (which needs about five levels), far below where ruamel's
# recursive composer runs out of stack.
_MAX_DEPTH = 100


def _too_deep(text: str, path: str, lines: list[str]) -> LocatedError:
    """The error for a document too deep to compose, at the list or mapping that goes past
    ``_MAX_DEPTH`` levels. Only reached after a ``RecursionError``: the event parser is not
    recursive, so reading the events again finds the place at no cost to valid manifests."""
    depth, where = 0, SourceLocation(path, 1, 1, lines[0] if lines else "")
    try:
        for event in YAML(typ="safe", pure=True).parse(text):
            if isinstance(event, (MappingStartEvent, SequenceStartEvent)):
                depth += 1
                if depth > _MAX_DEPTH:
                    mark = event.start_mark
                    where = _location(path, lines, mark.line, mark.column)
                    break
            elif isinstance(event, (MappingEndEvent, SequenceEndEvent)):
                depth -= 1
    except YAMLError:
        pass  # the place found so far is the best there is
    return LocatedError.at(
        where,
        f"the YAML is nested more than {_MAX_DEPTH} levels deep",
        hint="a manifest needs a few levels: look for runaway brackets or indentation here",
    )


def _syntax_error(exc: MarkedYAMLError, path: str, lines: list[str]) -> LocatedError:
    mark = exc.problem_mark or exc.context_mark
    problem = exc.problem or exc.context or "syntax error"
    problem = problem.replace("'<stream end>'", "the end of the file")
    if exc.context and problem.startswith("but "):
        problem = f"{exc.context}, {problem}"  # ruamel splits some sentences in two
    loc = _location(path, lines, mark.line, mark.column) if mark else SourceLocation(path)
    hint = None
    if "'\\t'" in problem:
        hint = "YAML indents with spaces, never tabs"
    elif "another document" in problem:
        hint = "a manifest is one YAML document: remove the '---' separator"
    elif exc.context and exc.context_mark and exc.problem_mark:
        what = next((name for key, name in _CONTEXTS.items() if key in exc.context), None)
        if what:
            hint = f"look at the {what} that starts on line {exc.context_mark.line + 1}"
    return LocatedError.at(loc, f"invalid YAML: {problem}", hint=hint)


_CONTEXTS = {
    "flow sequence": "[...] list",
    "flow mapping": "{...} mapping",
    "block mapping": "mapping",
    "block collection": "list or mapping",
    "quoted scalar": "quoted text",
}


def _location(path: str, lines: list[str], line: int, col: int) -> SourceLocation:
    """A 1-based location from ruamel's 0-based mark, with the source line for the caret."""
    if lines and line >= len(lines):
        # the end of a file that ends with a newline: show the end of its last line
        line, col = len(lines) - 1, len(lines[-1])
    source = lines[line] if 0 <= line < len(lines) else None
    return SourceLocation(path, line + 1, col + 1, source)


def _location_of_offset(text: str, offset: int, path: str) -> SourceLocation:
    before = text[:offset]
    line = before.count("\n")
    col = offset - (before.rfind("\n") + 1)
    return _location(path, text.splitlines(), line, col)


class _Converter:
    """Walks ruamel's node graph into Y-nodes, checking what YAML allows but a manifest not."""

    def __init__(self, path: str, lines: list[str], yaml: YAML) -> None:
        self._path = path
        self._lines = lines
        self._yaml = yaml
        self._active: set[int] = set()  # nodes on the current path, to catch recursive aliases
        self._count = 0

    def loc(self, node: Node) -> SourceLocation:
        return _location(self._path, self._lines, node.start_mark.line, node.start_mark.column)

    def fail(self, node: Node, message: str, hint: str | None = None) -> LocatedError:
        return LocatedError.at(self.loc(node), message, hint=hint)

    def convert(self, node: Node) -> YNode:
        self._count += 1
        if self._count > _MAX_NODES:
            raise self.fail(
                node,
                "the manifest expands to too many values",
                hint="check for YAML aliases (*name) that repeat large blocks",
            )
        if id(node) in self._active:
            raise self.fail(node, "a YAML alias refers to a block that contains it")
        self._active.add(id(node))
        try:
            if isinstance(node, ScalarNode):
                return self.scalar(node)
            if isinstance(node, SequenceNode):
                self.check_tag(node, f"{_CORE}seq")
                return YSeq(tuple(self.convert(item) for item in node.value), self.loc(node))
            if isinstance(node, MappingNode):
                self.check_tag(node, f"{_CORE}map")
                return YMap(self.entries(node), self.loc(node))
            raise self.fail(node, "unsupported YAML node")
        finally:
            self._active.discard(id(node))

    def check_tag(self, node: Node, allowed: str) -> None:
        tag = _tag(node)
        if tag != allowed:
            raise self.fail(
                node,
                f"unsupported YAML tag {tag!r}",
                hint="the manifest uses plain YAML values; remove the tag",
            )

    def scalar(self, node: ScalarNode) -> YScalar:
        tag = _tag(node)
        if tag not in _SCALAR_TAGS:
            raise self.fail(
                node,
                f"unsupported YAML tag {tag!r}",
                hint="the manifest uses plain YAML values; remove the tag",
            )
        if tag == _STR:
            # what ruamel's str constructor returns: the text itself
            return YScalar(node.value, self.loc(node))
        if tag == f"{_CORE}timestamp":
            # Dates mean nothing to a manifest; keep what was written rather than a datetime.
            return YScalar(str(node.value), self.loc(node))
        try:
            value = self._yaml.constructor.construct_object(node, deep=True)
        # ruamel's constructors raise plain Python errors on odd text (IndexError: an empty !!int).
        except (YAMLError, ValueError, TypeError, KeyError, IndexError):
            kind = tag.removeprefix(_CORE)
            form = _TAGGED_FORMS.get(kind)
            raise self.fail(
                node,
                f"invalid {kind} value {node.value!r}",
                hint=f"a !!{kind} value is {form}" if form else None,
            ) from None
        return YScalar(value, self.loc(node))

    def entries(self, node: MappingNode) -> tuple[YEntry, ...]:
        explicit: list[YEntry] = []
        merged: list[YEntry] = []
        seen: dict[str, YEntry] = {}
        for key_node, value_node in node.value:
            if _tag(key_node) == f"{_CORE}merge":
                merged.extend(self.merge(value_node))
                continue
            if not isinstance(key_node, ScalarNode):
                raise self.fail(key_node, "a mapping key must be plain text")
            if _tag(key_node) not in _SCALAR_TAGS:
                raise self.fail(
                    key_node,
                    f"unsupported YAML tag {_tag(key_node)!r}",
                    hint="the manifest uses plain YAML values; remove the tag",
                )
            key = str(key_node.value)
            value = self.convert(value_node)
            if _is_empty(value_node):
                # An empty value's mark is the next token, often on a later line; point just
                # after the key's colon instead.
                mark = key_node.end_mark
                value = YScalar(
                    None, _location(self._path, self._lines, mark.line, mark.column + 1)
                )
            entry = YEntry(key, self.loc(key_node), value)
            if key in seen:
                first = seen[key].key_location
                raise self.fail(
                    key_node,
                    f"duplicate key '{key}'",
                    hint=f"'{key}' is already set on line {first.line}",
                )
            seen[key] = entry
            explicit.append(entry)
        # YAML merge keys (<<: *base) fill in only what the mapping does not set itself.
        for entry in merged:
            if entry.key not in seen:
                seen[entry.key] = entry
                explicit.append(entry)
        return tuple(explicit)

    def merge(self, node: Node) -> list[YEntry]:
        sources = node.value if isinstance(node, SequenceNode) else [node]
        result: list[YEntry] = []
        for source in sources:
            converted = self.convert(source)
            if not isinstance(converted, YMap):
                raise self.fail(source, "a YAML merge key (<<) needs a mapping or list of them")
            result.extend(e for e in converted.entries if e.key not in {r.key for r in result})
        return result


def _is_empty(node: Node) -> bool:
    return isinstance(node, ScalarNode) and node.value == "" and node.style is None


def _tag(node: Node) -> str:
    tag = node.tag
    return str(getattr(tag, "value", tag))
