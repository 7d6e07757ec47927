"""The references that tie a file's objects together, read once per document for validation.

A ``Links`` table holds, per fileID, what validation checks against each other: components'
``m_GameObject``, GameObjects' ``m_Component``, Transforms' ``m_Father``/``m_Children``, the link
up the hierarchy that cycles are followed through, and which objects are roots. After edits it
is brought up to date by re-reading only the documents that changed (``refresh``).
"""

from __future__ import annotations

import re
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass, field

from unityscaffold.unity import _fields as F
from unityscaffold.unity._classids import TRANSFORM_CLASSES
from unityscaffold.unity._split import Doc

__all__ = ["Links"]

_TRANSFORM_PARENT_RE = re.compile(r"^    m_TransformParent: \{fileID: (-?\d+)\}", re.M)
_INT_RE = re.compile(r"-?\d+")


def _is_prefab_instance(doc: Doc) -> bool:
    """``doc.type_name == "PrefabInstance"`` without slicing the type name out of the text."""
    text = doc.text
    return text.startswith("PrefabInstance:", text.index("\n") + 1)


@dataclass(slots=True)
class Links:
    """The structural references of a file's documents, keyed by fileID."""

    owner: dict[int, int] = field(default_factory=dict)  # component → m_GameObject
    components: dict[int, list[int]] = field(default_factory=dict)  # GameObject → m_Component
    father: dict[int, int] = field(default_factory=dict)  # Transform → m_Father
    children: dict[int, list[int]] = field(default_factory=dict)  # Transform → m_Children
    # object → (the object above it in the hierarchy, the key saying so), for cycles: a
    # Transform's father; a prefab instance's stripped Transform stands for the instance,
    # which points at the Transform it is parented to
    up: dict[int, tuple[int, str]] = field(default_factory=dict)
    roots: set[int] = field(default_factory=set)  # what SceneRoots must list

    @classmethod
    def read(cls, docs: Sequence[Doc]) -> Links:
        links = cls()
        owner = links.owner
        special = {1, *TRANSFORM_CLASSES}
        for doc in docs:
            # Most documents are components whose only link is their owner: that case is
            # written out here (this loop runs once per document, 175,000 times in 100 MB),
            # everything else goes through _add.
            text = doc.text
            if (
                doc.class_id in special
                or doc.stripped
                or text.startswith("PrefabInstance:", text.index("\n") + 1)
            ):
                links._add(doc)
                continue
            at = text.find("\n  m_GameObject:")
            if at < 0:
                continue
            if text.startswith(" {fileID: ", at + 16):
                match = _INT_RE.match(text, at + 26)
                if match is not None:
                    owner[doc.file_id] = int(match.group(0))
            else:
                links._add_owner(doc)
        return links

    def refresh(self, changed: Collection[int], by_id: Mapping[int, Doc]) -> None:
        """Forget what ``changed`` fileIDs said and re-read the ones still in the file.

        Only valid when fileIDs are unique (``by_id`` then names every document).
        """
        for file_id in changed:
            self.owner.pop(file_id, None)
            self.components.pop(file_id, None)
            self.father.pop(file_id, None)
            self.children.pop(file_id, None)
            self.up.pop(file_id, None)
            self.roots.discard(file_id)
        for file_id in changed:
            doc = by_id.get(file_id)
            if doc is not None:
                self._add(doc)

    def _add(self, doc: Doc) -> None:
        file_id, class_id = doc.file_id, doc.class_id
        prefab_instance = _is_prefab_instance(doc)
        if prefab_instance and "\n    m_TransformParent: {fileID: 0}\n" in doc.text:
            self.roots.add(file_id)
        if class_id in TRANSFORM_CLASSES:
            if doc.stripped:
                parent = F.ref_value(doc, "m_PrefabInstance") or 0
                if parent:
                    self.up[file_id] = (parent, "m_PrefabInstance")
                return
            self._add_owner(doc)
            father = F.ref_value(doc, "m_Father") or 0
            self.father[file_id] = father
            self.children[file_id] = F.list_refs(doc, "m_Children")
            if father:
                self.up[file_id] = (father, "m_Father")
            else:
                self.roots.add(file_id)
            return
        if prefab_instance:
            match = _TRANSFORM_PARENT_RE.search(doc.text)
            parent = int(match.group(1)) if match else 0
            if parent:
                self.up[file_id] = (parent, "m_TransformParent")
        if doc.stripped:
            return
        if class_id == 1:
            self.components[file_id] = F.list_refs(doc, "m_Component")
        else:
            self._add_owner(doc)

    def _add_owner(self, doc: Doc) -> None:
        owner = _owner_of(doc)
        if owner is not None:
            self.owner[doc.file_id] = owner


def _owner_of(doc: Doc) -> int | None:
    """``F.ref_value(doc, "m_GameObject")`` in fewer steps and not cached: validation reads the
    owner of every component once, and the usual line is the first one with the key."""
    text = doc.text
    at = text.find("\n  m_GameObject:")
    if at < 0:
        return None
    if text.startswith(" {fileID: ", at + 16):
        match = _INT_RE.match(text, at + 26)
        return int(match.group(0)) if match else None
    return F.ref_value(doc, "m_GameObject")
