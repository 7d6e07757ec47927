"""The manifest's node graph composed from libyaml's events: the fast way for plain manifests.

ruamel.yaml's pure-Python scanner costs about a millisecond per topic line, most of ``apply``'s
time on a large manifest. PyYAML's C parser (libyaml) reads the same text into events some
twenty times faster; here those events become the very ruamel nodes ruamel's composer would
build (tags resolved by ruamel's YAML 1.2 resolver, so ``yes`` stays text), and the caller
converts them exactly as before.

Only the plain subset takes this way: one document with no ``...`` end, no ``%`` directive,
no explicit tag, no byte-order mark, no tab or line break other than LF and CRLF, no block
scalar (``|``, ``>``), no empty value other than a mapping's, at most ``MAX_DEPTH`` levels.
Anything else, and any text libyaml refuses, returns ``RUAMEL``: the caller composes it with
ruamel itself, whose errors and warnings stay the ones users see.
"""

from __future__ import annotations

import enum
import re
from typing import Any, Literal

import yaml
from ruamel.yaml.nodes import MappingNode, Node, ScalarNode, SequenceNode

__all__ = ["MAX_DEPTH", "RUAMEL", "compose_plain"]

# the C parser alone (its constructor and resolver are not used)
_Parser = getattr(yaml, "CBaseLoader", None)
# Where the two read text differently: ruamel refuses tabs that libyaml reads as spaces, and
# libyaml (YAML 1.1) breaks lines at NEL, LS, PS and a lone CR, which YAML 1.2 does not.
_UNLIKE = re.compile("[\t\x85\u2028\u2029]|\r(?!\n)")
# Far deeper than a manifest needs; deeper documents go through ruamel, which reports them.
MAX_DEPTH = 64


class _Way(enum.Enum):
    RUAMEL = "ruamel"


RUAMEL = _Way.RUAMEL


class _Unsupported(Exception):
    """The text is outside the plain subset: compose it with ruamel instead."""


def compose_plain(text: str, resolver: Any) -> Node | Literal[_Way.RUAMEL] | None:
    """The root node of ``text``, or ``None`` for a document-less stream; ``RUAMEL`` when the
    text is outside the plain subset (or libyaml is missing) and ruamel must compose it."""
    if _Parser is None or text.startswith("\ufeff") or _UNLIKE.search(text):
        return RUAMEL
    parser = _Parser(text)
    try:
        return _Composer(parser, resolver).stream()
    except (_Unsupported, yaml.YAMLError, ValueError):
        return RUAMEL
    finally:
        parser.dispose()


class _Composer:
    """Events to nodes without recursion; anchors register when their node starts, as ruamel
    does, so a recursive alias reaches the converter as it would from ruamel."""

    def __init__(self, parser: Any, resolver: Any) -> None:
        self.parser = parser
        self.resolver = resolver
        self.anchors: dict[str, Node] = {}
        # A plain scalar's tag depends only on its text (a manifest repeats its keys and
        # types), a collection's only on its kind: each is resolved by ruamel once.
        self.tags: dict[tuple[Any, Any, Any], Any] = {}

    def tag(self, kind: Any, value: Any, implicit: Any) -> Any:
        key = (kind, value, implicit)
        found = self.tags.get(key)
        if found is None:
            found = self.tags[key] = self.resolver.resolve(kind, value, implicit)
        return found

    def stream(self) -> Node | None:
        events = self.parser
        events.get_event()  # stream start
        start = events.get_event()
        if isinstance(start, yaml.StreamEndEvent):
            return None
        if start.version or start.tags:
            raise _Unsupported
        root = self.document()
        end = events.get_event()
        # after an explicit end ("..."), libyaml takes a second "..." as nothing, where ruamel
        # sees another document: such streams are ruamel's to read
        if end.explicit or not isinstance(events.get_event(), yaml.StreamEndEvent):
            raise _Unsupported  # several documents: ruamel says so
        return root

    def document(self) -> Node:
        stack: list[tuple[Node, list[Node | None]]] = []  # open collections, pending key
        while True:
            event = self.parser.get_event()
            if isinstance(event, (yaml.SequenceEndEvent, yaml.MappingEndEvent)):
                node, _ = stack.pop()
                node.end_mark = event.end_mark
            elif isinstance(event, yaml.AliasEvent):
                if event.anchor not in self.anchors:
                    raise _Unsupported  # ruamel reports the undefined alias
                node = self.anchors[event.anchor]
            else:
                node = self.start(event)
                if not isinstance(node, ScalarNode):
                    if len(stack) >= MAX_DEPTH:
                        raise _Unsupported
                    stack.append((node, [None]))
                    continue
            if not stack:
                if _is_empty(node):
                    raise _Unsupported
                return node
            self.add(stack[-1], node)

    def start(self, event: Any) -> Node:
        if event.tag is not None:
            raise _Unsupported
        if isinstance(event, yaml.ScalarEvent):
            if event.style in ("|", ">"):
                raise _Unsupported  # libyaml lets a comment touch the indicator, ruamel not
            node: Node = ScalarNode(
                self.tag(ScalarNode, event.value, event.implicit),
                event.value,
                event.start_mark,
                event.end_mark,
                style=event.style or None,  # libyaml says '' for plain, ruamel None
            )
        else:
            kind = SequenceNode if isinstance(event, yaml.SequenceStartEvent) else MappingNode
            node = kind(
                self.tag(kind, None, event.implicit),
                [],
                event.start_mark,
                None,
                flow_style=event.flow_style,
            )
        if event.anchor is not None:
            node.anchor = event.anchor
            self.anchors[event.anchor] = node
        return node

    @staticmethod
    def add(parent: tuple[Node, list[Node | None]], node: Node) -> None:
        collection, pending = parent
        key = pending[0]
        if _is_empty(node) and (key is None or key.value == "<<"):
            # Where an empty value sits, libyaml and ruamel disagree by a column or a line; the
            # converter places an empty mapping value at its key, any other empty one at its own
            # mark, so those go through ruamel.
            raise _Unsupported
        if isinstance(collection, SequenceNode):
            collection.value.append(node)
        elif key is None:
            pending[0] = node
        else:
            collection.value.append((key, node))
            pending[0] = None


def _is_empty(node: Node) -> bool:
    return isinstance(node, ScalarNode) and node.value == "" and node.style is None
