"""The hierarchy of a scene or prefab: GameObjects by path, their components and scripts.

Built from ``m_Name``/``m_Component`` of GameObjects, ``m_GameObject``/``m_Father``/``m_Children``
of Transforms, ``SceneRoots`` or ``m_RootOrder`` for the order of roots, and PrefabInstances
(whose insides live in another file and so are opaque here).
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field

import yaml

from unityscaffold.unity import _fields as F
from unityscaffold.unity._classids import SCENE_ROOTS_CLASS, TRANSFORM_CLASSES
from unityscaffold.unity._folds import read_folds_unity_way
from unityscaffold.unity._split import Doc
from unityscaffold.unity.values import ScriptRef

__all__ = ["GameObject", "Hierarchy", "Node", "SceneComponent", "build_hierarchy"]

# The value may go on over deeper-indented lines: a long name Unity folded.
_PI_NAME_RE = re.compile(r"propertyPath: m_Name\n( +)value: (.*(?:\n\1  .*)*)")
_PI_ROOT_ORDER_RE = re.compile(r"propertyPath: m_RootOrder\n\s+value: (-?\d+)")
_PI_PARENT_RE = re.compile(r"^    m_TransformParent: \{fileID: (-?\d+)\}", re.M)


@dataclass(frozen=True, slots=True)
class GameObject:
    """A snapshot of one GameObject (or of a PrefabInstance, seen from outside) in the hierarchy.

    ``prefab_instance_id`` is non-zero when the object lives in a prefab instance: it then cannot
    be edited in this file. For a PrefabInstance node ``file_id == prefab_instance_id``.
    """

    file_id: int
    name: str
    path: str
    transform_id: int | None
    component_ids: tuple[int, ...] = ()
    prefab_instance_id: int = 0

    @property
    def editable(self) -> bool:
        return self.prefab_instance_id == 0

    @property
    def is_prefab_instance(self) -> bool:
        return self.prefab_instance_id != 0 and self.file_id == self.prefab_instance_id


@dataclass(frozen=True, slots=True)
class SceneComponent:
    """A snapshot of one component document (a Transform, a script, any class on a GameObject)."""

    file_id: int
    class_id: int
    type_name: str
    gameobject_id: int
    script: ScriptRef | None = None
    stripped: bool = False


@dataclass(slots=True)
class Node:
    file_id: int
    name: str
    transform_id: int | None
    prefab_instance_id: int = 0
    parent: int | None = None
    children: list[int] = field(default_factory=list)
    order: tuple[int, int] = (0, 0)  # (m_RootOrder, file position): sorts roots without SceneRoots


@dataclass(slots=True)
class Hierarchy:
    nodes: dict[int, Node]
    roots: list[int]
    paths: dict[int, str] = field(default_factory=dict)

    def walk(self) -> Iterator[tuple[int, Node]]:
        """(depth, node) in hierarchy order, each node once.

        A corrupt file can make an object its own ancestor; validation reports that, and this
        walk still ends (a node met again is not entered again).
        """
        stack = [(0, node_id) for node_id in reversed(self.roots)]
        seen: set[int] = set()
        while stack:
            depth, node_id = stack.pop()
            if node_id in seen:
                continue
            seen.add(node_id)
            node = self.nodes[node_id]
            yield depth, node
            stack.extend((depth + 1, child) for child in reversed(node.children))

    def children_named(self, parent: int | None, name: str) -> list[int]:
        ids = self.roots if parent is None else self.nodes[parent].children
        return [i for i in ids if self.nodes[i].name == name]

    def names_under(self, parent: int | None) -> list[str]:
        ids = self.roots if parent is None else self.nodes[parent].children
        return sorted({self.nodes[i].name for i in ids})


def build_hierarchy(docs: Sequence[Doc], by_id: Mapping[int, Doc]) -> Hierarchy:
    """Index GameObjects and PrefabInstances into a tree of nodes keyed by fileID."""
    nodes: dict[int, Node] = {}
    owner: dict[int, int] = {}  # Transform fileID → node fileID
    for position, doc in enumerate(docs):
        if doc.class_id == 1 and not doc.stripped:
            node = _gameobject_node(doc, by_id)
            node.order = (1 << 62, position)
            nodes[doc.file_id] = node
            if node.transform_id is not None:
                owner[node.transform_id] = doc.file_id
        elif doc.class_id == 1001 and doc.type_name == "PrefabInstance":
            nodes[doc.file_id] = _prefab_node(doc, position)
        elif doc.class_id in TRANSFORM_CLASSES and doc.stripped:
            owner[doc.file_id] = F.ref_value(doc, "m_PrefabInstance") or 0
    scene_roots = next((d for d in reversed(docs) if d.class_id == SCENE_ROOTS_CLASS), None)
    # with a SceneRoots document, roots are in its order and Transforms' m_RootOrder is unused
    _link(nodes, owner, by_id, root_order=scene_roots is None)
    roots = _order_roots(nodes, owner, scene_roots)
    hierarchy = Hierarchy(nodes, roots)
    for depth, node in hierarchy.walk():
        parent_path = hierarchy.paths.get(node.parent) if node.parent is not None else None
        hierarchy.paths[node.file_id] = node.name if depth == 0 else f"{parent_path}/{node.name}"
    return hierarchy


def _gameobject_node(doc: Doc, by_id: Mapping[int, Doc]) -> Node:
    transform = None
    for component in F.list_refs(doc, "m_Component"):
        found = by_id.get(component)
        if found is not None and found.class_id in TRANSFORM_CLASSES:
            transform = component
            break
    source = F.ref_value(doc, "m_CorrespondingSourceObject")
    if source is None:  # before 2018.3
        source = F.ref_value(doc, "m_PrefabParentObject")
    instance = 0
    if source:
        instance = F.ref_value(doc, "m_PrefabInstance") or F.ref_value(doc, "m_PrefabInternal") or 0
    name = F.scalar_value(doc, "m_Name") or ""
    # an object that comes from a prefab (old-format instance) is not ours to edit
    return Node(doc.file_id, name, transform, (instance or -1) if source else 0)


def _prefab_node(doc: Doc, position: int) -> Node:
    match = _PI_NAME_RE.search(doc.text)
    name = _value_text(match.group(2)) if match else f"PrefabInstance &{doc.file_id}"
    parent = _PI_PARENT_RE.search(doc.text)
    order = _PI_ROOT_ORDER_RE.search(doc.text)
    node = Node(doc.file_id, name, None, doc.file_id)
    node.parent = int(parent.group(1)) if parent else 0  # a Transform id until _link
    node.order = (int(order.group(1)) if order else 1 << 62, position)
    return node


def _value_text(raw: str) -> str:
    """A modification's string value, unquoted and unfolded as Unity reads it."""
    if "\n" not in raw and not raw.startswith(("'", '"')):
        return raw
    try:
        loaded = yaml.load(read_folds_unity_way(f"value: {raw}\n"), Loader=yaml.BaseLoader)
    except yaml.YAMLError:
        return raw
    value = loaded.get("value") if isinstance(loaded, dict) else None
    return value if isinstance(value, str) else raw


def _link(
    nodes: dict[int, Node], owner: dict[int, int], by_id: Mapping[int, Doc], root_order: bool
) -> None:
    """Set parents and ordered children from Transforms' m_Father/m_Children (and roots' order
    from m_RootOrder if ``root_order``)."""
    # one pass for parents and children (neither depends on the other), once per GameObject
    for node in nodes.values():
        transform = by_id.get(node.transform_id) if node.transform_id is not None else None
        if transform is None:
            father = node.parent or 0  # PrefabInstance: its m_TransformParent
        else:
            father = F.ref_value(transform, "m_Father") or 0
            order = F.field_value(transform, "m_RootOrder") if root_order else None
            if order is not None and order.lstrip("-").isdigit():
                node.order = (int(order), node.order[1])
            listed = F.list_refs(transform, "m_Children")
            if listed:
                below = [owner[c] for c in listed if c in owner]
                node.children = [c for c in dict.fromkeys(below) if c in nodes]
        parent = owner.get(father) if father else None
        node.parent = parent if parent in nodes else None
    for node in nodes.values():  # children that point up but are not listed: keep them visible
        if node.parent is not None and node.file_id not in nodes[node.parent].children:
            nodes[node.parent].children.append(node.file_id)


def _order_roots(
    nodes: dict[int, Node], owner: dict[int, int], scene_roots: Doc | None
) -> list[int]:
    roots = [n for n in nodes.values() if n.parent is None]
    if scene_roots is not None:
        listed = F.list_refs(scene_roots, "m_Roots")
        rank = {owner.get(ref, ref): index for index, ref in enumerate(listed)}
        roots.sort(key=lambda n: (rank.get(n.file_id, len(rank)), n.order[1]))
    else:
        roots.sort(key=lambda n: n.order)
    return [n.file_id for n in roots]
