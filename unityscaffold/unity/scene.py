"""``SceneDocument``: a Unity scene or prefab held as exact text, indexed and edited surgically.

Loading splits the file into documents whose concatenation is the input, byte for byte. Queries
go through a lazily built hierarchy index. Edits rewrite only the lines they must, insert new
documents where Unity would put them, and are idempotent: an existing component is recognised by
GameObject + script, and fileIDs of new objects derive from stable names.
"""

from __future__ import annotations

import bisect
import itertools
from collections.abc import Iterable, Iterator, Mapping, Sequence
from pathlib import Path

from unityscaffold.errors import Diagnostic, LocatedError, SourceLocation, UserError
from unityscaffold.fileout import write_if_changed
from unityscaffold.unity import _fields as F
from unityscaffold.unity._split import Doc, split_text
from unityscaffold.unity.generation import Generation, detect
from unityscaffold.unity.index import Component, GameObject, Hierarchy, build_hierarchy
from unityscaffold.unity.textdiff import diff
from unityscaffold.unity.validate import validate_docs
from unityscaffold.unity.values import MONOSCRIPT_FILE_ID, FieldValue, ScriptRef

__all__ = ["Fields", "SceneDocument"]

Fields = Mapping[str, FieldValue] | Sequence[tuple[str, FieldValue]]

_BINARY_HINT = (
    "set Edit > Project Settings > Editor > Asset Serialization Mode to 'Force Text' "
    "so Unity writes scenes as YAML text"
)


class SceneDocument:
    """One ``.unity``/``.prefab`` file: exact text, an index over it, and surgical edits.

    Use :meth:`load` or :meth:`parse`; :meth:`text` returns the current content (equal to the
    input until something is edited); :meth:`write` validates and writes atomically if changed.
    """

    def __init__(self, path: str, prolog: str, docs: list[Doc], crlf: bool, original: str):
        self.path = path
        self.original_text = original
        self._prolog = prolog
        self._docs = docs
        self._crlf = crlf
        self._by_id: dict[int, Doc] = {}
        for doc in docs:
            self._by_id.setdefault(doc.file_id, doc)
        self._changed: set[int] = set()
        self._hierarchy: Hierarchy | None = None
        self._sorted = all(a.file_id <= b.file_id for a, b in itertools.pairwise(docs))
        self.generation: Generation = detect(docs, path)

    # ----- loading and output -----------------------------------------------------------------

    @classmethod
    def parse(cls, text: str, path: str = "<scene>") -> SceneDocument:
        """Split ``text``; raise ``LocatedError`` if it is not complete Unity YAML."""
        split = split_text(text, path)
        return cls(path, split.prolog, split.docs, split.crlf, text)

    @classmethod
    def load(cls, path: str | Path) -> SceneDocument:
        """Read a text scene or prefab; binary, non-UTF-8 or truncated files are refused."""
        name = str(path)
        try:
            data = Path(path).read_bytes()
        except OSError as exc:
            raise UserError(f"cannot read {name}: {exc.strerror or exc}") from None
        if not data.startswith(b"%YAML"):
            looks_binary = b"\0" in data[:4096]
            what = "a binary-serialized Unity file" if looks_binary else "not a Unity YAML file"
            raise UserError(f"{name} is {what}", hint=_BINARY_HINT)
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise UserError(f"{name} is not UTF-8 text (byte {exc.start})") from None
        return cls.parse(text, name)

    def text(self) -> str:
        """The current content; byte-identical to the input when nothing was edited."""
        joined = self._prolog + "".join(doc.text for doc in self._docs)
        return joined.replace("\n", "\r\n") if self._crlf else joined

    @property
    def changed(self) -> bool:
        return bool(self._changed) and self.text() != self.original_text

    def diff(self) -> str:
        """Unified diff from the loaded text to the current one (empty when unchanged)."""
        return diff(self.original_text, self.text(), self.path) if self._changed else ""

    def validate(self) -> list[Diagnostic]:
        """Every problem that would make the file unsafe to write (empty list: all good)."""
        return validate_docs(self.path, self._prolog, self._docs, self._changed)

    def write(self, path: str | Path | None = None) -> bool:
        """Validate, then write atomically if the bytes changed; return whether it wrote."""
        problems = self.validate()
        if problems:
            raise LocatedError(problems)
        return write_if_changed(path if path is not None else self.path, self.text())

    # ----- queries ------------------------------------------------------------------------------

    @property
    def hierarchy(self) -> Hierarchy:
        if self._hierarchy is None:
            self._hierarchy = build_hierarchy(self._docs, self._by_id)
        return self._hierarchy

    def documents(self) -> list[Doc]:
        return list(self._docs)

    def document(self, file_id: int) -> Doc | None:
        return self._by_id.get(file_id)

    def gameobjects(self) -> list[GameObject]:
        """Every GameObject (and PrefabInstance node), in hierarchy order."""
        return [self._view(node.file_id) for _, node in self.hierarchy.walk()]

    def tree(self) -> Iterator[tuple[int, GameObject]]:
        """(depth, GameObject) for the whole hierarchy, parents before children."""
        for depth, node in self.hierarchy.walk():
            yield depth, self._view(node.file_id)

    def gameobject(self, file_id: int) -> GameObject:
        """The GameObject (or PrefabInstance node) with ``file_id``."""
        if file_id not in self.hierarchy.nodes:
            raise UserError(f"{self.path}: no GameObject with fileID {file_id}")
        return self._view(file_id)

    def roots(self) -> list[GameObject]:
        return [self._view(i) for i in self.hierarchy.roots]

    def children(self, go: GameObject) -> list[GameObject]:
        return [self._view(i) for i in self.hierarchy.nodes[go.file_id].children]

    def find_gameobject(self, path: str) -> GameObject:
        """The unique GameObject at ``path`` (``Robot/base_link/camera``).

        Raises ``UserError`` listing the candidates when the path is ambiguous, or the names
        that do exist at the first level that does not match.
        """
        found, missing_at = self._search(path)
        if missing_at is not None:
            raise self._missing_error(path, found, missing_at)
        return self._view(self._unique(path, found))

    def components_of(self, go: GameObject | str) -> list[Component]:
        """Components of ``go`` in ``m_Component`` order (Transform first)."""
        target = self._go(go)
        return [self.component(i) for i in target.component_ids if i in self._by_id]

    def component(self, file_id: int) -> Component:
        doc = self._by_id.get(file_id)
        if doc is None:
            raise UserError(f"{self.path}: no object with fileID {file_id}")
        script = F.script_of(doc) if doc.class_id == 114 else None
        ref = ScriptRef(script[1], script[0], script[2]) if script else None
        owner = F.ref_value(doc, "m_GameObject") or 0
        return Component(doc.file_id, doc.class_id, doc.type_name, owner, ref, doc.stripped)

    def find_component(
        self, go: GameObject | str, script_guid: str, script_file_id: int = MONOSCRIPT_FILE_ID
    ) -> Component | None:
        """The first component of ``go`` running that script, or None."""
        for comp in self.components_of(go):
            if (
                comp.script
                and comp.script.guid == script_guid
                and comp.script.file_id == script_file_id
            ):
                return comp
        return None

    def field(self, component: Component | int, name: str) -> object:
        """A top-level field read with a string-only YAML loader (None when absent)."""
        return F.parse_field(self._doc_of(component), name)

    # ----- edits (implemented in _edits) ------------------------------------------------------

    def ensure_gameobject(self, path: str, create: bool = True) -> GameObject:
        """The GameObject at ``path``; missing levels are created (with a Transform) if asked."""
        from unityscaffold.unity._edits import ensure_gameobject

        return ensure_gameobject(self, path, create)

    def ensure_component(
        self, go: GameObject | str, script: ScriptRef, fields: Fields = ()
    ) -> Component:
        """Attach ``script`` to ``go`` or update the one already there; idempotent.

        ``fields`` are written in the given order on a new component; on an existing one,
        values that already match keep their bytes and missing fields are inserted following
        that order (which should be the script's declaration order).
        """
        from unityscaffold.unity._edits import ensure_component

        return ensure_component(self, go, script, _field_list(fields))

    def set_fields(self, component: Component | int, fields: Fields) -> bool:
        """Set top-level fields of a component; return whether the text changed."""
        from unityscaffold.unity._edits import set_fields

        return set_fields(self, self._doc_of(component), _field_list(fields))

    def remove_component(self, component: Component | int) -> bool:
        """Remove a component; references to it elsewhere in the file become ``{fileID: 0}``."""
        from unityscaffold.unity._edits import remove_component

        file_id = component if isinstance(component, int) else component.file_id
        return remove_component(self, file_id)

    # ----- internals shared with _edits ---------------------------------------------------------

    def _view(self, node_id: int) -> GameObject:
        node = self.hierarchy.nodes[node_id]
        doc = self._by_id.get(node_id)
        components = (
            tuple(F.list_refs(doc, "m_Component")) if doc is not None and doc.class_id == 1 else ()
        )
        return GameObject(
            node_id,
            node.name,
            self.hierarchy.paths[node_id],
            node.transform_id,
            components,
            node.prefab_instance_id,
        )

    def _go(self, go: GameObject | str) -> GameObject:
        if isinstance(go, str):
            return self.find_gameobject(go)
        if go.file_id not in self.hierarchy.nodes:
            raise UserError(f"{self.path}: GameObject &{go.file_id} ({go.path}) is not in the file")
        return self._view(go.file_id)

    def _doc_of(self, component: Component | int) -> Doc:
        file_id = component if isinstance(component, int) else component.file_id
        doc = self._by_id.get(file_id)
        if doc is None:
            raise UserError(f"{self.path}: no object with fileID {file_id}")
        return doc

    def _search(self, path: str) -> tuple[list[int], int | None]:
        """Candidates for each level of ``path``; the index of the first level with none."""
        names = _split_path(path)
        candidates: list[int | None] = [None]
        for level, name in enumerate(names):
            nxt = [c for parent in candidates for c in self.hierarchy.children_named(parent, name)]
            if not nxt:
                return [c for c in candidates if c is not None], level
            candidates = list(nxt)
        return [c for c in candidates if c is not None], None

    def _unique(self, path: str, found: list[int]) -> int:
        if len(found) == 1:
            return found[0]
        listed = ", ".join(f"'{self.hierarchy.paths[i]}' (&{i})" for i in found)
        raise UserError(
            f"{self.path}: {len(found)} GameObjects match '{path}': {listed}",
            hint="rename one of them in Unity so the path is unique",
        )

    def _missing_error(self, path: str, parents: list[int], level: int) -> UserError:
        names = _split_path(path)
        prefix = "/".join(names[:level])
        opaque = [i for i in parents if self.hierarchy.nodes[i].prefab_instance_id == i]
        if opaque and len(parents) == 1:
            return UserError(
                f"{self.path}: '{prefix}' is a prefab instance; its children live in the prefab "
                "asset and cannot be addressed here",
                hint="edit the prefab itself, or unpack the instance in Unity",
            )
        pool = parents or [None]
        existing = sorted({n for p in pool for n in self.hierarchy.names_under(p)})
        where = f"under '{prefix}'" if prefix else "at the root"
        shown = ", ".join(repr(n) for n in existing[:30]) or "none"
        return UserError(
            f"{self.path}: no GameObject named '{names[level]}' {where}; names there: {shown}",
            hint="ask for it to be created: `scene attach --create`, "
            "or `create: true` in the manifest",
        )

    def _insert(self, doc: Doc, index: int | None = None) -> None:
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

    def _location(self, doc: Doc) -> SourceLocation:
        """Where ``doc``'s header is in the current text (line 0 if it is no longer there)."""
        line = self._prolog.count("\n") + 1
        for each in self._docs:
            if each is doc:
                return SourceLocation(self.path, line, 0, doc.header)
            line += each.text.count("\n")
        return SourceLocation(self.path, 0, 0, doc.header)

    def _touch(self, doc: Doc) -> None:
        self._changed.add(doc.file_id)

    def _remove(self, doc: Doc) -> None:
        self._docs.remove(doc)
        del self._by_id[doc.file_id]
        self._changed.add(doc.file_id)

    def _invalidate(self) -> None:
        self._hierarchy = None


def _split_path(path: str) -> list[str]:
    names = path.strip("/").split("/")
    if not path.strip("/") or any(not n for n in names):
        raise UserError(f"invalid GameObject path '{path}'", hint="write it as Parent/Child/Name")
    return names


def _field_list(fields: Fields | Iterable[tuple[str, FieldValue]]) -> list[tuple[str, FieldValue]]:
    items = list(fields.items()) if isinstance(fields, Mapping) else list(fields)
    seen: set[str] = set()
    for name, _ in items:
        if name in seen:
            raise UserError(f"field '{name}' is given more than once")
        seen.add(name)
    return items
