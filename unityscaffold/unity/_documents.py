"""The documents of one scene or prefab file, in file order and by fileID, with what changed.

``SceneDocument`` answers queries from this state and ``_edits`` changes it, both through the
methods below: neither module touches the other's internals. Every change goes through
``insert``, ``remove`` or ``touch`` so that validation knows which documents to re-parse and
``text`` knows something changed.
"""

from __future__ import annotations

import bisect
from collections.abc import Iterator, Mapping, Sequence, Set

from unityscaffold.errors import SourceLocation, UserError
from unityscaffold.unity._classids import SCENE_ROOTS_CLASS, SETTINGS_CLASSES
from unityscaffold.unity._eras import SerializationEra, detect_era
from unityscaffold.unity._gcpause import gc_paused
from unityscaffold.unity._split import Doc
from unityscaffold.unity.index import Hierarchy, build_hierarchy

__all__ = ["Documents"]

_CHUNK = 1 << 20


class Documents:
    """A file's prolog and documents, indexed by fileID, with a lazily built hierarchy.

    ``era`` and ``is_scene`` are read once at load: edits follow the layout the file already has.
    """

    def __init__(self, path: str, prolog: str, docs: list[Doc], crlf: bool) -> None:
        self.path = path
        self.prolog = prolog
        self.era: SerializationEra = detect_era(docs)
        self.is_scene = path.endswith(".unity") or any(
            d.class_id in SETTINGS_CLASSES or d.class_id == SCENE_ROOTS_CLASS for d in docs
        )
        self._docs = docs
        self._crlf = crlf
        self._by_id: dict[int, Doc] = {}
        for doc in docs:
            self._by_id.setdefault(doc.file_id, doc)
        self._changed: set[int] = set()
        self._recent: set[int] = set()  # the part of _changed since the last take_recent()
        self._revision = 0
        self._hierarchy: Hierarchy | None = None
        # Unity writes scenes sorted by fileID; a file that is not keeps its own order.
        ids = [doc.file_id for doc in docs]
        self._sorted = ids == sorted(ids)  # sorting a sorted list is one pass in C

    # ----- reading ------------------------------------------------------------------------------

    @property
    def in_order(self) -> Sequence[Doc]:
        """The documents in file order (a live view: edit through the methods below)."""
        return self._docs

    def scene_roots(self) -> Doc | None:
        """The scene's SceneRoots document (the last one: Unity writes it at the end), which
        lists its root Transforms since 2022.2; None in a file of an earlier layout."""
        return next((d for d in reversed(self._docs) if d.class_id == SCENE_ROOTS_CLASS), None)

    @property
    def changed(self) -> Set[int]:
        """fileIDs of the documents inserted, edited or removed since loading."""
        return self._changed

    def take_recent(self) -> set[int]:
        """fileIDs inserted, edited or removed since the last call (since loading at first)."""
        recent, self._recent = self._recent, set()
        return recent

    @property
    def revision(self) -> int:
        """The number of ``insert``, ``remove`` and ``touch`` calls so far."""
        return self._revision

    def __contains__(self, file_id: object) -> bool:
        return file_id in self._by_id

    @property
    def by_id(self) -> Mapping[int, Doc]:
        """fileID → document; when a fileID is used twice it names only one of them."""
        return self._by_id

    def get(self, file_id: int) -> Doc | None:
        return self._by_id.get(file_id)

    def require(self, file_id: int) -> Doc:
        """The document with ``file_id``; a ``UserError`` naming the file if there is none."""
        doc = self._by_id.get(file_id)
        if doc is None:
            raise UserError(f"{self.path}: no object with fileID {file_id}")
        return doc

    def text(self) -> str:
        return self.render([doc.text for doc in self._docs])

    def render(self, texts: Sequence[str]) -> str:
        """The file made of the prolog and ``texts`` (documents' texts), line endings as loaded."""
        joined = self.prolog + "".join(texts)
        return joined.replace("\n", "\r\n") if self._crlf else joined

    def chunks(self) -> Iterator[bytes]:
        """``text()`` as UTF-8 in pieces of about a megabyte: no whole-file copy on the way."""
        batch, size = [self.prolog], len(self.prolog)
        for doc in self._docs:
            batch.append(doc.text)
            size += len(doc.text)
            if size >= _CHUNK:
                yield self._encode(batch)
                batch, size = [], 0
        yield self._encode(batch)

    def _encode(self, texts: list[str]) -> bytes:
        joined = "".join(texts)
        return (joined.replace("\n", "\r\n") if self._crlf else joined).encode("utf-8")

    def location(self, doc: Doc) -> SourceLocation:
        """Where ``doc``'s header is in the current text (line 0 if it is no longer there)."""
        line = self.prolog.count("\n") + 1
        for each in self._docs:
            if each is doc:
                return SourceLocation(self.path, line, 0, doc.header)
            line += each.text.count("\n")
        return SourceLocation(self.path, 0, 0, doc.header)

    @property
    def hierarchy(self) -> Hierarchy:
        if self._hierarchy is None:
            with gc_paused():
                self._hierarchy = build_hierarchy(self._docs, self._by_id)
        return self._hierarchy

    # ----- changing -----------------------------------------------------------------------------

    def insert(self, doc: Doc, index: int | None = None) -> None:
        """Insert a new document at ``index``, or by fileID order as Unity sorts scenes."""
        if index is None:
            if self._sorted:
                index = bisect.bisect_right(self._docs, doc.file_id, key=lambda d: d.file_id)
            else:
                index = next(
                    (i for i, d in enumerate(self._docs) if d.file_id > doc.file_id),
                    len(self._docs),
                )
        else:
            self._sorted = False
        self._docs.insert(index, doc)
        self._by_id[doc.file_id] = doc
        self._changed.add(doc.file_id)
        self._recent.add(doc.file_id)
        self._revision += 1

    def remove(self, doc: Doc) -> None:
        self._docs.remove(doc)
        del self._by_id[doc.file_id]
        self._changed.add(doc.file_id)
        self._recent.add(doc.file_id)
        self._revision += 1

    def touch(self, doc: Doc) -> None:
        """Record that ``doc``'s text was edited in place."""
        self._changed.add(doc.file_id)
        self._recent.add(doc.file_id)
        self._revision += 1

    def invalidate(self) -> None:
        """Drop the hierarchy index after the tree changed (it is rebuilt on the next query)."""
        self._hierarchy = None
