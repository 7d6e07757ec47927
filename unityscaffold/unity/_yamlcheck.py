"""Whether one document's body is YAML, as PyYAML's base loader sees it, and if not, where.

``yaml.load`` parses, composes a tree of nodes and builds a Python value of every node; a
check needs only the verdict. What the two later steps can refuse is narrow: the composer an
alias (undefined, or an anchor given twice) and a second document, the base constructor a key
that is a list or a mapping (unhashable) and an alias to its own ancestor. So a body whose
parse has no anchor, no alias, at most one document and only scalar keys loads, and its parse
events (in C, like the loader's) answer for it at about a third of the load's cost: an import
writes hundreds of new documents, each checked before the scene is written. Any other body, or
one the parser refuses, is loaded in full, so a problem and its place are the loader's own.
"""

from __future__ import annotations

import yaml
from yaml.events import (
    AliasEvent,
    DocumentStartEvent,
    MappingEndEvent,
    MappingStartEvent,
    NodeEvent,
    ScalarEvent,
    SequenceEndEvent,
    SequenceStartEvent,
)

__all__ = ["yaml_problem"]

_BaseLoader = getattr(yaml, "CBaseLoader", yaml.BaseLoader)


def yaml_problem(body: str) -> tuple[str, tuple[int, int] | None] | None:
    """What keeps ``body`` from being one YAML document, and its (line, column) from 0 when
    known; None when it is one."""
    try:
        if _loads_plainly(body):
            return None
    except yaml.YAMLError:
        pass  # loaded below, which reports it as the load would
    try:
        yaml.load(body, Loader=_BaseLoader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        problem = getattr(exc, "problem", None) or str(exc).strip().split("\n")[0]
        return problem, (mark.line, mark.column) if mark is not None else None
    return None


def _loads_plainly(body: str) -> bool:
    """True when ``body`` parses as at most one document without anchors, aliases or keys
    that are collections: then ``yaml.load`` loads it. False means "load it to know"."""
    documents = 0
    # per open collection: -1 for a sequence, else how many nodes the mapping has had (a key
    # at every even count)
    open_counts: list[int] = []
    for event in yaml.parse(body, Loader=_BaseLoader):
        kind = type(event)
        if kind is MappingEndEvent or kind is SequenceEndEvent:
            open_counts.pop()
        elif kind is DocumentStartEvent:
            documents += 1
            if documents > 1:
                return False
        elif isinstance(event, NodeEvent):
            if kind is AliasEvent or event.anchor is not None:
                return False
            if open_counts and open_counts[-1] >= 0:
                if open_counts[-1] % 2 == 0 and kind is not ScalarEvent:
                    return False
                open_counts[-1] += 1
            if kind is MappingStartEvent:
                open_counts.append(0)
            elif kind is SequenceStartEvent:
                open_counts.append(-1)
    return True
