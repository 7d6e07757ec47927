"""Checks a scene must pass before it is written (and that a loaded file must pass to be edited).

Every guid-less ``{fileID: N}`` resolves in the file, fileIDs are unique, components and
GameObjects point at each other, each GameObject has one Transform listed first, parents and
children agree, no object is its own ancestor, ``SceneRoots`` lists exactly the roots, and every
changed document parses as YAML.
"""

from __future__ import annotations

import functools
import itertools
import operator
import re
from collections import Counter
from collections.abc import Collection, Mapping, Sequence

from unityscaffold.errors import Diagnostic, SourceLocation
from unityscaffold.unity import _fields as F
from unityscaffold.unity._classids import SCENE_ROOTS_CLASS, TRANSFORM_CLASSES
from unityscaffold.unity._links import Links
from unityscaffold.unity._split import Doc, is_reference_list
from unityscaffold.unity._yamlcheck import yaml_problem

__all__ = ["check_docs", "check_exemplar", "validate_docs"]


class _Locator:
    """Turns (document, key) into a file location, computing line numbers only when needed."""

    def __init__(self, path: str, prolog: str, docs: Sequence[Doc]) -> None:
        self.path, self.prolog, self.docs = path, prolog, docs
        self._lines: dict[int, int] | None = None

    def at(
        self,
        doc: Doc,
        key: str | None,
        message: str,
        hint: str | None = None,
        within: tuple[int, int] | None = None,
    ) -> Diagnostic:
        """``message`` at ``key``'s line in ``doc`` (its header without one), or at
        ``within``: (line, column) counted from 0 after the document's header line."""
        if self._lines is None:
            line, self._lines = self.prolog.count("\n") + 1, {}
            for each in self.docs:
                self._lines[id(each)] = line
                line += each.text.count("\n")
        line = self._lines.get(id(doc), 0)
        source, col = doc.header, 1
        start, col = _key_offset(doc, key) if key else (-1, 1)
        if within is not None and line:
            rows = doc.text.split("\n")[:-1]  # each row ends with a line break
            row = min(within[0] + 1, len(rows) - 1)  # a fault found at the end: the last row
            start = sum(len(r) + 1 for r in rows[:row])
            col = within[1] + 1 if row == within[0] + 1 else 1
        if start >= 0 and line:
            line += doc.text.count("\n", 0, start)
            source = doc.text[start : doc.text.index("\n", start)]
        where = f"{doc.header}: {key}" if key else doc.header
        return Diagnostic(
            SourceLocation(self.path, line, col if line else 0, source),
            f"{where}: {message}",
            hint=hint,
        )


def _key_offset(doc: Doc, key: str) -> tuple[int, int]:
    """Where ``key``'s line starts in ``doc`` and the key's column: a top-level key, else one
    nested a level down (a prefab instance's ``m_TransformParent``); (-1, 1) when absent."""
    span = F.field_span(doc, key)
    if span is not None:
        return span[0], 3
    at = doc.text.find(f"\n    {key}:")
    return (at + 1, 5) if at >= 0 else (-1, 1)


def validate_docs(
    path: str, prolog: str, docs: Sequence[Doc], changed: Collection[int] = ()
) -> list[Diagnostic]:
    """All problems found, in file order; an empty list means the file may be written."""
    return check_docs(path, prolog, docs, changed)[0]


def check_docs(
    path: str,
    prolog: str,
    docs: Sequence[Doc],
    changed: Collection[int] = (),
    checked: Links | None = None,
    recent: Collection[int] = (),
    index: Mapping[int, Doc] | None = None,
) -> tuple[list[Diagnostic], Links | None]:
    """``validate_docs``, plus the link table of a file found clean (None otherwise).

    Given ``checked``, the table of an earlier clean check of the same documents, and
    ``recent``, the fileIDs inserted, edited or removed since then, only those documents are
    read again: unchanged ones were found sound and still are, unless an object they refer to
    was removed (then everything is checked). The checks between objects (owners, parents,
    cycles, roots) still cover the whole table. Anything found sends it to the full check, so
    the diagnostics are the same either way. ``index``, the caller's fileID → document map,
    is used when it has an entry per document (the fileIDs are then unique and it names each).
    """
    if index is not None and len(index) == len(docs):
        by_id, unique = index, True
    else:
        own: dict[int, Doc] = {}
        for doc in docs:
            own.setdefault(doc.file_id, doc)
        by_id, unique = own, len(own) == len(docs)
    if checked is not None and unique and all(i in by_id for i in recent):
        loc = _Locator(path, prolog, docs)
        checked.refresh(recent, by_id)
        again = [by_id[i] for i in recent]
        if (
            not _any_dangling(again, by_id)
            and not _links_problems(loc, checked, by_id, docs)
            and not any(_parses(loc, doc) for doc in again)
        ):
            return [], checked
    return _check_all(path, prolog, docs, changed, by_id, unique)


def _check_all(
    path: str,
    prolog: str,
    docs: Sequence[Doc],
    changed: Collection[int],
    by_id: Mapping[int, Doc],
    unique: bool,
) -> tuple[list[Diagnostic], Links | None]:
    loc = _Locator(path, prolog, docs)
    found: list[Diagnostic] = []
    if not unique:
        seen: set[int] = set()
        for doc in docs:
            if doc.file_id in seen:
                found.append(
                    loc.at(
                        doc,
                        None,
                        f"fileID {doc.file_id} is used by more than one object",
                        hint="every object in a file needs its own fileID",
                    )
                )
            seen.add(doc.file_id)
    # reading every reference once is cheap; finding where a dangling one sits is not, so only
    # documents are scanned when something is actually missing
    if _any_dangling(docs, by_id):
        for doc in docs:
            found += _dangling(loc, doc, by_id)
    links = Links.read(docs)
    found += _links_problems(loc, links, by_id, docs)
    for doc in docs:
        if doc.file_id in changed:
            found += _parses(loc, doc)
    return found, (links if not found else None)


def _links_problems(
    loc: _Locator, links: Links, by_id: Mapping[int, Doc], docs: Sequence[Doc]
) -> list[Diagnostic]:
    return [
        *_gameobjects(loc, links, by_id),
        *_transforms(loc, links, by_id),
        *_cycles(loc, links, by_id),
        *_scene_roots(loc, links, docs),
    ]


# A guid-less reference to anything but fileID 0 (0 is "none", never dangling): a third of a
# scene's references are {fileID: 0}, and not making a string of each halves the scan.
_NONZERO_REF_RE = re.compile(r"\{fileID: (-?0*[1-9]\d*)\}")
_TEXT = operator.attrgetter("text")


def _any_dangling(docs: Sequence[Doc], by_id: Mapping[int, Doc]) -> bool:
    # One regex call per document, iterated in C (map, chain, set): joining documents into
    # bigger pieces first was slower, the copy costing more than the calls it saved.
    # References are kept as written until the set is made: int() once per distinct fileID.
    spelled = set(itertools.chain.from_iterable(map(_NONZERO_REF_RE.findall, map(_TEXT, docs))))
    return not by_id.keys() >= set(map(int, spelled))


def _key_at(doc: Doc, offset: int) -> str | None:
    return next((k for k, (s, e) in F.spans(doc).items() if s <= offset < e), None)


def _dangling(loc: _Locator, doc: Doc, by_id: Mapping[int, Doc]) -> list[Diagnostic]:
    out = []
    for match in F.local_refs(doc.text):
        target = int(match.group(1))
        if target != 0 and target not in by_id:
            out.append(
                loc.at(
                    doc,
                    _key_at(doc, match.start()),
                    f"refers to fileID {target}, which is not in the file",
                )
            )
    return out


def _gameobjects(loc: _Locator, links: Links, by_id: Mapping[int, Doc]) -> list[Diagnostic]:
    out = []
    for go_id, components in links.components.items():
        doc = by_id[go_id]
        for ref in components:
            if ref in links.owner and links.owner[ref] != go_id:
                out.append(
                    loc.at(
                        doc,
                        "m_Component",
                        f"lists {by_id[ref].header}, whose m_GameObject is not this GameObject",
                    )
                )
        transforms = [
            c for c in components if c in by_id and by_id[c].class_id in TRANSFORM_CLASSES
        ]
        if len(transforms) != 1 or components[0] != transforms[0]:
            out.append(
                loc.at(doc, "m_Component", "a GameObject needs exactly one Transform, listed first")
            )
    for comp_id, go_id in links.owner.items():
        listed = links.components.get(go_id)
        if listed is not None and comp_id not in listed:
            out.append(
                loc.at(
                    by_id[comp_id],
                    "m_GameObject",
                    f"points at {by_id[go_id].header}, whose m_Component does not list it",
                )
            )
    return out


def _transforms(loc: _Locator, links: Links, by_id: Mapping[int, Doc]) -> list[Diagnostic]:
    out = []
    for tr_id, father in links.father.items():
        siblings = links.children.get(father)
        if siblings is not None and tr_id not in siblings:
            out.append(
                loc.at(
                    by_id[tr_id],
                    "m_Father",
                    f"points at {by_id[father].header}, whose m_Children does not list it",
                )
            )
    for tr_id, children in links.children.items():
        for child in children:
            if child not in links.father or links.father[child] == tr_id:
                continue  # a Transform that is its own father is reported as a cycle
            if child == tr_id:
                out.append(loc.at(by_id[tr_id], "m_Children", "lists this Transform itself"))
            else:
                out.append(
                    loc.at(
                        by_id[tr_id],
                        "m_Children",
                        f"lists {by_id[child].header}, whose m_Father is not this Transform",
                    )
                )
    return out


_CYCLE_HINT = (
    "every chain of m_Father (and a prefab instance's m_TransformParent) must end at a root, "
    "{fileID: 0}; restore the file from version control, or fix the parents in Unity"
)


def _cycles(loc: _Locator, links: Links, by_id: Mapping[int, Doc]) -> list[Diagnostic]:
    """Objects that are their own ancestor: a walk down from the roots would never end.

    Each object is visited once (three colours), so this is linear in the file's size.
    """
    up = links.up
    state: dict[int, int] = {}  # 1: on the chain being followed, 2: known to end at a root
    out = []
    for start in up:
        chain: list[int] = []
        node: int | None = start
        while node is not None and node in up and state.get(node) is None:
            state[node] = 1
            chain.append(node)
            node = up[node][0]
        if node is not None and state.get(node) == 1:
            ring = chain[chain.index(node) :]
            first = min(ring)
            ring = ring[ring.index(first) :] + ring[: ring.index(first)]
            names = " → ".join(f"&{i}" for i in [*ring, first])
            what = "is its own parent" if len(ring) == 1 else f"is its own ancestor: {names}"
            out.append(loc.at(by_id[first], up[first][1], what, hint=_CYCLE_HINT))
        for each in chain:
            state[each] = 2
    return out


def _scene_roots(loc: _Locator, links: Links, docs: Sequence[Doc]) -> list[Diagnostic]:
    scene_roots = [d for d in docs if d.class_id == SCENE_ROOTS_CLASS]
    if not scene_roots:
        return []
    listed = F.list_refs(scene_roots[-1], "m_Roots")
    expected = links.roots
    if set(listed) == expected and len(listed) == len(expected):
        return []
    parts = [f"omits root &{i}" for i in sorted(expected - set(listed))]
    parts += [f"lists &{i}, which is not a root" for i in sorted(set(listed) - expected)]
    parts += [f"lists &{i} twice" for i, n in sorted(Counter(listed).items()) if n > 1]
    return [
        loc.at(scene_roots[-1], "m_Roots", "does not match the scene's roots: " + "; ".join(parts))
    ]


def check_exemplar(path: str, prolog: str, docs: Sequence[Doc], doc: Doc) -> list[Diagnostic]:
    """Problems of ``doc``, whose layout a new object of its class is about to copy: it must be
    valid YAML, or the copy inherits what is broken (a key a bad indent hid, left out).

    Unchanged documents are otherwise not parsed (a whole-file parse would cost more than the
    edit); this one is, since the new object would carry its fault into a document apply made.
    """
    return _parses(
        _Locator(path, prolog, docs),
        doc,
        f"new {doc.type_name}s copy its layout",
        hint="fix it (in Unity, or from version control) and run again",
    )


def _parses(
    loc: _Locator,
    doc: Doc,
    why: str = "after editing",
    hint: str | None = None,
) -> list[Diagnostic]:
    body = doc.text[doc.text.index("\n") + 1 :]
    if is_reference_list(body):
        return []  # SceneRoots gaining a root: no YAML parse of a list with a line per root
    found = _yaml_problem(body)
    if found is None:
        return []
    problem, within = found
    if why == "after editing":
        return [loc.at(doc, None, f"is not valid YAML after editing ({problem})", hint, within)]
    return [loc.at(doc, None, f"is not valid YAML ({problem}); {why}", hint, within)]


@functools.lru_cache(maxsize=32)
def _yaml_problem(body: str) -> tuple[str, tuple[int, int] | None] | None:
    """What keeps a document's body from being YAML, and where; None when it is. Kept for a
    few bodies: an import writes the same large one many times (ROS#'s cylinder collider
    Mesh, 124 KB, once per collider), whose documents differ only in their header."""
    return yaml_problem(body)
