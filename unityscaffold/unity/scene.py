"""``SceneDocument``: a Unity scene or prefab held as exact text, indexed and edited surgically.

Loading splits the file into documents whose concatenation is the input, byte for byte. Queries
go through a lazily built hierarchy index. Edits rewrite only the lines they must, insert new
documents where Unity would put them, and are idempotent: an existing component is recognised by
GameObject + script, and fileIDs of new objects derive from stable names.
"""

from __future__ import annotations

import itertools
from collections.abc import Collection, Iterable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import cast

from unityscaffold.errors import Diagnostic, LocatedError, UserError
from unityscaffold.fileout import write_chunks_if_changed
from unityscaffold.unity import _declared, _edits, _owned, _siblings
from unityscaffold.unity import _fields as F
from unityscaffold.unity._documents import Documents
from unityscaffold.unity._eras import SerializationEra
from unityscaffold.unity._fileids import candidate_file_ids
from unityscaffold.unity._gcpause import gc_paused
from unityscaffold.unity._links import Links
from unityscaffold.unity._split import Doc, split_text
from unityscaffold.unity._validate import check_docs
from unityscaffold.unity.builtins import BuiltinClass
from unityscaffold.unity.index import GameObject, Hierarchy, SceneComponent
from unityscaffold.unity.owned import OwnedDocument, OwnedObject
from unityscaffold.unity.textdiff import diff
from unityscaffold.unity.values import MONOSCRIPT_FILE_ID, FieldValue, ScriptRef, Verbatim

__all__ = ["Fields", "GameObjectNotFound", "SceneDocument"]

Fields = Mapping[str, FieldValue] | Sequence[tuple[str, FieldValue]]

_BINARY_HINT = (
    "set Edit > Project Settings > Editor > Asset Serialization Mode to 'Force Text' "
    "so Unity writes scenes as YAML text"
)


class GameObjectNotFound(UserError):
    """No GameObject at a path; the message lists the names that do exist where it stopped.

    It carries no hint: how to get the object created depends on the command (a flag, a
    manifest key), so the caller that knows adds it.
    """


class SceneDocument:
    """One ``.unity``/``.prefab`` file: exact text, an index over it, and surgical edits.

    Use :meth:`load` or :meth:`parse`; :meth:`text` returns the current content (equal to the
    input until something is edited); :meth:`write` validates and writes atomically if changed.
    """

    def __init__(self, path: str, prolog: str, docs: list[Doc], crlf: bool):
        self._docs = Documents(path, prolog, docs, crlf)
        # The loaded text as references to the documents' texts (edits replace a document's
        # text, they never change a string): the original costs no copy of the file.
        self._original = [doc.text for doc in docs]
        self._checked: Links | None = None  # the link table of the last clean validation
        self._preferred: dict[str, int] = {}  # path -> the one of same-named siblings meant

    @property
    def path(self) -> str:
        return self._docs.path

    @property
    def era(self) -> SerializationEra:
        """The serialization era the file was written in; new objects follow its layout."""
        return self._docs.era

    @property
    def is_scene(self) -> bool:
        """A ``.unity`` scene (it has the settings objects) rather than a prefab."""
        return self._docs.is_scene

    # ----- loading and output -----------------------------------------------------------------

    @classmethod
    def parse(cls, text: str, path: str = "<scene>") -> SceneDocument:
        """Split ``text``; raise ``LocatedError`` if it is not complete Unity YAML."""
        with gc_paused():
            split = split_text(text, path)
            return cls(path, split.prolog, split.docs, split.crlf)

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
        del data  # the text is kept: the bytes would be one more copy at the peak
        return cls.parse(text, name)

    def text(self) -> str:
        """The current content; byte-identical to the input when nothing was edited."""
        return self._docs.text()

    @property
    def revision(self) -> int:
        """How many edits were recorded so far: the text can change only when this grows."""
        return self._docs.revision

    @property
    def original_text(self) -> str:
        """The text as loaded."""
        return self._docs.render(self._original)

    @property
    def changed(self) -> bool:
        if not self._docs.changed:
            return False
        texts = [doc.text for doc in self._docs.in_order]
        return texts != self._original

    def diff(self) -> str:
        """Unified diff from the loaded text to the current one (empty when unchanged)."""
        return diff(self.original_text, self.text(), self.path) if self._docs.changed else ""

    def validate(self) -> list[Diagnostic]:
        """Every problem that would make the file unsafe to write (empty list: all good).

        After a validation that found nothing, the next one reads again only the documents
        edited since (see ``check_docs``): apply validates before editing and after.
        """
        docs = self._docs
        recent = docs.take_recent()
        with gc_paused():
            problems, self._checked = check_docs(
                self.path,
                docs.prolog,
                docs.in_order,
                docs.changed,
                self._checked,
                recent,
                docs.by_id,
            )
        return problems

    def write(self, path: str | Path | None = None) -> bool:
        """Validate, then write atomically if the bytes changed; return whether it wrote."""
        problems = self.validate()
        if problems:
            raise LocatedError(problems)
        return write_chunks_if_changed(path if path is not None else self.path, self._docs.chunks)

    # ----- queries ------------------------------------------------------------------------------

    @property
    def hierarchy(self) -> Hierarchy:
        return self._docs.hierarchy

    def documents(self) -> list[Doc]:
        return list(self._docs.in_order)

    def document(self, file_id: int) -> Doc | None:
        return self._docs.get(file_id)

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

        Raises ``UserError`` listing the candidates when the path is ambiguous, or
        ``GameObjectNotFound`` with the names that do exist at the first level that does not
        match.
        """
        found, missing_at = self._search(path)
        if missing_at is not None:
            raise self._missing_error(path, found, missing_at)
        return self._view(self._unique(path, found))

    def prefer(self, known: Mapping[str, int]) -> None:
        """Tell same-named siblings apart: where a path, or a path on the way to it, matches
        several GameObjects and one of them has the fileID ``known`` gives for that path, that
        one is meant (apply passes the GameObjects its lock recorded)."""
        self._preferred = dict(known)

    def components_of(self, go: GameObject | str) -> list[SceneComponent]:
        """Components of ``go`` in ``m_Component`` order (Transform first)."""
        target = self._go(go)
        return [self.component(i) for i in target.component_ids if i in self._docs]

    def component(self, file_id: int) -> SceneComponent:
        doc = self._docs.require(file_id)
        script = F.script_of(doc) if doc.class_id == 114 else None
        ref = ScriptRef(script[1], script[0], script[2]) if script else None
        owner = F.ref_value(doc, "m_GameObject") or 0
        return SceneComponent(doc.file_id, doc.class_id, doc.type_name, owner, ref, doc.stripped)

    def find_component(
        self, go: GameObject | str, script_guid: str, script_file_id: int = MONOSCRIPT_FILE_ID
    ) -> SceneComponent | None:
        """The first component of ``go`` running that script, or None."""
        target = self._go(go)
        go_doc = self._docs.get(target.file_id)
        # Indexed on the GameObject's document: its cache is dropped when its text (the
        # m_Component list) changes, and _edits drops it when a component's m_Script does.
        cached = go_doc.cache.get("scripts") if go_doc is not None else None
        index = cast("dict[tuple[int, str], int] | None", cached)
        if index is None:
            index = {}
            for file_id in target.component_ids:
                doc = self._docs.get(file_id)
                script = F.script_of(doc) if doc is not None and doc.class_id == 114 else None
                if script is not None:
                    index.setdefault((script[0], script[1]), file_id)
            if go_doc is not None:
                go_doc.cache["scripts"] = index
        found = index.get((script_file_id, script_guid))
        return self.component(found) if found is not None and found in self._docs else None

    def field(self, component: SceneComponent | int, name: str) -> object:
        """A top-level field read with a string-only YAML loader (None when absent)."""
        return F.parse_field(self._doc_of(component), name)

    # ----- edits (found here, carried out by _edits) --------------------------------------------

    def ensure_gameobject(self, path: str, create: bool = True, ui: bool = False) -> GameObject:
        """The GameObject at ``path``; missing levels are created (with a Transform) if asked.

        Without ``create`` a missing level raises ``GameObjectNotFound``. With ``ui`` a created
        last level gets a RectTransform (and the UI layer).
        """
        found, missing_at = self._search(path)
        if missing_at is None:
            return self._view(self._unique(path, found))
        if not create:
            raise self._missing_error(path, found, missing_at)
        names = _split_path(path)
        parent = None
        if missing_at > 0:
            parent = self._view(self._unique("/".join(names[:missing_at]), found))
        return self._view(_edits.create_path(self._docs, parent, names, missing_at, ui))

    def ensure_component(
        self,
        go: GameObject | str,
        script: ScriptRef,
        fields: Fields = (),
        key: str | None = None,
        adopt: SceneComponent | None = None,
        defaults: Sequence[tuple[str, FieldValue | Verbatim]] = (),
    ) -> SceneComponent:
        """Attach ``script`` to ``go`` or update the one already there; idempotent.

        ``fields`` are written in the given order on a new component; on an existing one,
        values that already match keep their bytes and missing fields are inserted following
        that order (which should be the script's declaration order). With ``key`` the instance
        is the one made for that key (see :meth:`keyed_component`), else ``adopt`` if given.
        A new component is written with every field of ``defaults`` (see
        ``_edits.ensure_component``).
        """
        items = _field_list(fields)
        target = self._go(go)
        if key is None:
            existing = self.find_component(target, script.guid, script.file_id)
        else:
            existing = self.keyed_component(target, script, key) or adopt
        file_id = _edits.ensure_component(
            self._docs, target, existing, script, items, key, defaults
        )
        return self.component(file_id)

    def keyed_component(
        self, go: GameObject | str, script: ScriptRef, key: str
    ) -> SceneComponent | None:
        """The instance of ``script`` on ``go`` that was attached for ``key``, or None."""
        found = _declared.find_keyed_component(self._docs, self._go(go), script, key)
        return self.component(found) if found is not None else None

    def instances(self, go: GameObject | str, script: ScriptRef) -> list[SceneComponent]:
        """Every component of ``go`` running ``script``, in ``m_Component`` order."""
        return [
            c
            for c in self.components_of(go)
            if c.script is not None
            and (c.script.guid, c.script.file_id) == (script.guid, script.file_id)
        ]

    def ensure_builtin(
        self, go: GameObject | str, builtin: BuiltinClass, key: str | None, fields: Fields = ()
    ) -> SceneComponent:
        """Add the built-in component (``key``'s one) to ``go`` or set fields on it; idempotent."""
        items = _field_list(fields)
        file_id = _declared.ensure_builtin(self._docs, self._go(go), builtin, key, items)
        return self.component(file_id)

    def sync_owned(
        self, objects: Sequence[OwnedObject], documents: Sequence[OwnedDocument] = ()
    ) -> list[str]:
        """Create or keep as declared objects known by their fileIDs (see ``unity.owned``);
        one line per object created or changed."""
        return _owned.sync_owned(self._docs, objects, documents)

    def remove_owned(self, file_ids: Collection[int]) -> tuple[list[str], dict[int, str]]:
        """Remove owned objects no longer made (see ``unity.owned``): the paths of the
        GameObjects removed, and the objects kept (something else is on them) by fileID."""
        return _owned.remove_owned(self._docs, file_ids)

    def place_siblings(self, parent: GameObject | None, wanted: Mapping[int, int]) -> bool:
        """Put GameObjects (fileID -> sibling index, 0 first) at their places among
        ``parent``'s children (the scene's roots when None); whether the text changed."""
        return _siblings.place_siblings(self._docs, parent.file_id if parent else None, wanted)

    def find_builtin(
        self, go: GameObject | str, builtin: BuiltinClass, key: str | None = None
    ) -> SceneComponent | None:
        found = _declared.find_builtin(self._docs, self._go(go), builtin, key)
        return self.component(found) if found is not None else None

    def set_fields(self, component: SceneComponent | int, fields: Fields) -> bool:
        """Set top-level fields of a component; return whether the text changed."""
        return _edits.set_fields(self._docs, self._doc_of(component), _field_list(fields))

    def remove_component(self, component: SceneComponent | int) -> bool:
        """Remove a component; references to it elsewhere in the file become ``{fileID: 0}``."""
        file_id = component if isinstance(component, int) else component.file_id
        return _edits.remove_component(self._docs, file_id)

    def remove_made_gameobject(self, file_id: int, path: str) -> bool:
        """Remove the GameObject ``file_id`` if an edit made it at ``path`` (its fileID is the
        one derived from that path, which Unity never picks), only its Transform is on it, it
        has no children and nothing in the file refers to it; return whether it was removed."""
        made = itertools.islice(candidate_file_ids(("GameObject", path)), 8)
        if file_id not in set(made):
            return False
        return _edits.remove_empty_gameobject(self._docs, file_id)

    # ----- lookups ------------------------------------------------------------------------------

    def _view(self, node_id: int) -> GameObject:
        node = self.hierarchy.nodes[node_id]
        doc = self._docs.get(node_id)
        components = (
            tuple(F.list_refs(doc, "m_Component")) if doc is not None and doc.class_id == 1 else ()
        )
        return GameObject(
            node_id,
            node.name,
            self.hierarchy.paths.get(node_id, node.name),  # unreachable only in a corrupt file
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

    def _doc_of(self, component: SceneComponent | int) -> Doc:
        file_id = component if isinstance(component, int) else component.file_id
        return self._docs.require(file_id)

    def _search(self, path: str) -> tuple[list[int], int | None]:
        """Candidates for each level of ``path``; the index of the first level with none."""
        names = _split_path(path)
        candidates: list[int | None] = [None]
        for level, name in enumerate(names):
            nxt = [c for parent in candidates for c in self.hierarchy.children_named(parent, name)]
            if not nxt:
                return [c for c in candidates if c is not None], level
            meant = self._preferred.get("/".join(names[: level + 1]))
            if len(nxt) > 1 and meant in nxt:
                nxt = [meant]
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
        pool: list[int | None] = [*parents] or [None]
        existing = sorted({n for p in pool for n in self.hierarchy.names_under(p)})
        where = f"under '{prefix}'" if prefix else "at the root"
        shown = ", ".join(repr(n) for n in existing[:30]) or "none"
        return GameObjectNotFound(
            f"{self.path}: no GameObject named '{names[level]}' {where}; names there: {shown}"
        )


def _split_path(path: str) -> list[str]:
    # The manifest's rule: a path starts at a root GameObject, so no leading or trailing '/'.
    names = path.split("/")
    if any(not n for n in names):
        raise UserError(
            f"invalid GameObject path '{path}'",
            hint="write it as Parent/Child/Name, from a root GameObject, with no empty parts "
            "and no '/' at either end",
        )
    return names


def _field_list(fields: Fields | Iterable[tuple[str, FieldValue]]) -> list[tuple[str, FieldValue]]:
    items = list(fields.items()) if isinstance(fields, Mapping) else list(fields)
    seen: set[str] = set()
    for name, _ in items:
        if name in seen:
            raise UserError(f"field '{name}' is given more than once")
        seen.add(name)
    return items
