"""Add discovered topics, services and actions to a manifest, in place, keeping its layout.

ruamel.yaml's round-trip mode re-emits untouched nodes as they were written; what it cannot
keep by itself is the indentation style, so that is read from the text first. New entries copy
the style of the entries already listed (flow ``{…}`` maps by default, as ``scaffold init``
writes them). A topic, service or action already listed, under any type, is never added twice.
"""

from __future__ import annotations

import dataclasses
import io
import itertools
import os
import re
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ruamel.yaml import YAML
from ruamel.yaml.comments import CommentedMap, CommentedSeq
from ruamel.yaml.error import YAMLError
from ruamel.yaml.tokens import CommentToken

from unityscaffold.errors import LocatedError, SourceLocation, UserError
from unityscaffold.interfaces.live.model import (
    Direction,
    DiscoveredAction,
    DiscoveredService,
    DiscoveredTopic,
    Discovery,
)
from unityscaffold.interfaces.model import Dialect
from unityscaffold.manifest._spec_connector import TCP_CONNECTOR
from unityscaffold.manifest.runtime import Runtime

__all__ = [
    "DEFAULT_GAMEOBJECT",
    "ManifestEdit",
    "edit_manifest",
    "interface_folders",
    "manifest_fragment",
    "read_manifest",
]

DEFAULT_GAMEOBJECT = "RosConnector"
_TODO = "TODO: direction: publish (Unity sends) or subscribe (Unity receives)"
_ROLE_TODO = "TODO: role: client (Unity sends goals) or server (Unity carries them out)"
_HEADER_KEYS = ("version", "ros", "project", "output", "scene", "namespace")
_SEQUENCE_ITEM = re.compile(r"^( *)-( +)")
_KEY_ONLY = re.compile(r"^( *)(- )?[^\s#][^:#]*:\s*(#.*)?$")


@dataclass(frozen=True, slots=True)
class ManifestEdit:
    """The new manifest text and what changed."""

    text: str
    added_topics: tuple[str, ...] = ()
    added_services: tuple[str, ...] = ()
    already_listed: tuple[str, ...] = ()
    added_interface: str | None = None
    added_actions: tuple[str, ...] = ()

    @property
    def changed(self) -> bool:
        return bool(
            self.added_topics or self.added_services or self.added_actions or self.added_interface
        )


def _yaml(text: str) -> YAML:
    yaml = YAML(typ="rt")
    yaml.preserve_quotes = True
    yaml.width = 4096  # never re-wrap a user's long flow maps
    mapping, sequence, offset = _indentation(text)
    yaml.indent(mapping=mapping, sequence=sequence, offset=offset)
    return yaml


def _indentation(text: str) -> tuple[int, int, int]:
    """``(mapping, sequence, offset)`` as ruamel counts them, read from the first nested
    mapping and the first block sequence; ``scaffold init``'s style where there are none."""
    mapping, sequence, offset = 2, 4, 2
    lines = [
        line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")
    ]
    seen_mapping = seen_sequence = False
    for previous, line in itertools.pairwise(lines):
        parent = _KEY_ONLY.match(previous)
        if parent is None:
            continue
        parent_indent = len(parent.group(1)) + (2 if parent.group(2) else 0)
        indent = len(line) - len(line.lstrip(" "))
        if not seen_sequence and (item := _SEQUENCE_ITEM.match(line)):
            offset = max(0, len(item.group(1)) - parent_indent)
            sequence, seen_sequence = offset + 1 + len(item.group(2)), True
        elif not seen_mapping and indent > parent_indent:
            mapping, seen_mapping = indent - parent_indent, True
    return mapping, sequence, offset


def _load(text: str, path: str) -> tuple[YAML, CommentedMap]:
    yaml = _yaml(text)
    try:
        document = yaml.load(text)
    except YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = (
            SourceLocation(path, mark.line + 1, mark.column + 1) if mark else SourceLocation(path)
        )
        raise LocatedError.at(where, f"not valid YAML: {getattr(exc, 'problem', exc)}") from None
    if document is None:
        document = CommentedMap()
    if not isinstance(document, CommentedMap):
        raise LocatedError.at(
            SourceLocation(path, 1, 1),
            "the manifest is not a mapping",
            expected="keys such as version, ros, topics",
        )
    return yaml, document


def _check_dialect(document: CommentedMap, discovery: Discovery, path: str) -> None:
    ros = document.get("ros")
    if ros is not None and ros != int(discovery.dialect):
        line, col = document.lc.value("ros")
        raise LocatedError.at(
            SourceLocation(path, line + 1, col + 1),
            f"the manifest is for ROS {ros}, but {discovery.origin} is a "
            f"{discovery.dialect.label} system",
            hint="discover into a manifest for the same ROS",
        )


def _list(document: CommentedMap, key: str, path: str) -> CommentedSeq:
    value = document.get(key)
    if value is None:
        value = CommentedSeq()
        _insert(document, key, value)
    if not isinstance(value, CommentedSeq):
        line, col = document.lc.value(key)
        raise LocatedError.at(SourceLocation(path, line + 1, col + 1), f"{key} is not a list")
    if value.fa.flow_style() and not value:
        value.fa.set_block_style()  # "topics: []" becomes a list that can grow readably
    return value


def _insert(document: CommentedMap, key: str, value: CommentedSeq) -> None:
    """Add a missing key where a reader looks for it: ``interfaces`` after the header keys
    (and after any commented-out example that follows them), lists at the end."""
    if key in document:
        document[key] = value
        return
    keys = list(document)
    header = [i for i, k in enumerate(keys) if k in _HEADER_KEYS]
    if key == "interfaces" and header:
        document.insert(header[-1] + 1, key, value)
    else:
        document[key] = value


def _listed_names(items: Iterable[Any]) -> set[str]:
    return {str(item["name"]) for item in items if isinstance(item, dict) and "name" in item}


def _entry(pairs: list[tuple[str, str]], like: CommentedSeq) -> CommentedMap:
    entry = CommentedMap(pairs)
    block = any(isinstance(i, CommentedMap) and not i.fa.flow_style() for i in like)
    if not block:
        entry.fa.set_flow_style()
    return entry


def _topic_pairs(topic: DiscoveredTopic, gameobject: str) -> list[tuple[str, str]]:
    pairs = [("name", topic.name), ("type", topic.type)]
    if topic.direction is not Direction.UNKNOWN:
        pairs.append(("direction", topic.direction.value))
    return [*pairs, ("gameobject", gameobject)]


def _service_pairs(service: DiscoveredService, gameobject: str) -> list[tuple[str, str]]:
    return [
        ("name", service.name),
        ("type", service.type),
        ("role", service.role),
        ("gameobject", gameobject),
    ]


def _is_tcp(document: CommentedMap) -> bool:
    return bool(document.get("runtime") == Runtime.TCP_CONNECTOR.value)


def _connection_gameobject(document: CommentedMap) -> str:
    """Where new entries go: the runtime's connection GameObject at its default name
    (ROS-TCP-Connector's ROSConnection, else ROS#'s RosConnector)."""
    if _is_tcp(document):
        return str(TCP_CONNECTOR.key("gameobject").default)
    return DEFAULT_GAMEOBJECT


def _add_topics(
    seq: CommentedSeq, topics: Iterable[DiscoveredTopic], gameobject: str
) -> tuple[list[str], list[str]]:
    listed = _listed_names(seq)
    added, skipped = [], []
    for topic in topics:
        if topic.name in listed:
            skipped.append(topic.name)
            continue
        entry = _entry(_topic_pairs(topic, gameobject), seq)
        _append(seq, entry)
        if topic.direction is Direction.UNKNOWN:
            _add_todo(seq, entry, _TODO)
        added.append(topic.name)
    return added, skipped


def _add_services(
    seq: CommentedSeq, services: Iterable[DiscoveredService], gameobject: str
) -> tuple[list[str], list[str]]:
    listed = _listed_names(seq)
    added, skipped = [], []
    for service in services:
        if service.name in listed:
            skipped.append(service.name)
            continue
        _append(seq, _entry(_service_pairs(service, gameobject), seq))
        added.append(service.name)
    return added, skipped


def _add_actions(
    seq: CommentedSeq, actions: Iterable[DiscoveredAction], gameobject: str
) -> tuple[list[str], list[str]]:
    """Actions with the role the graph shows; ``client`` with a TODO when it shows none."""
    listed = _listed_names(seq)
    added, skipped = [], []
    for action in actions:
        if action.name in listed:
            skipped.append(action.name)
            continue
        pairs = [
            ("name", action.name),
            ("type", action.type),
            ("role", action.role or "client"),
            ("gameobject", gameobject),
        ]
        entry = _entry(pairs, seq)
        _append(seq, entry)
        if action.role is None:
            _add_todo(seq, entry, _ROLE_TODO)
        added.append(action.name)
    return added, skipped


def _add_todo(seq: CommentedSeq, entry: CommentedMap, todo: str) -> None:
    """A flow map takes the comment at the end of its line; a block map on its first key."""
    if entry.fa.flow_style():
        seq.yaml_add_eol_comment(todo, len(seq) - 1)
    else:
        entry.yaml_add_eol_comment(todo, "name")


def _append(seq: CommentedSeq, value: Any) -> None:
    """Append ``value`` inside the list, before what follows its last item.

    ruamel keeps the blank lines and comments after a list on its last item, with that item's
    own end-of-line comment (``# ours\n\n``): a plain append would leave them between the old
    last item and the new one. The item keeps its first line; the rest moves to ``value``.
    """
    last = len(seq) - 1
    trailer = seq.ca.items.get(last) if last >= 0 else None
    seq.append(value)
    token = trailer[0] if trailer else None
    if token is None:
        return
    if not token.value.startswith("#"):  # no comment of its own: all of it follows the list
        del seq.ca.items[last]
        seq.ca.items[len(seq) - 1] = trailer
        return
    own, _, rest = token.value.partition("\n")
    if rest:
        token.value = own + "\n"
        moved = CommentToken("\n" + rest, token.start_mark, None)
        seq.ca.items[len(seq) - 1] = [moved, None, None, None]


def _add_interface(document: CommentedMap, cache_entry: str, path: str) -> str | None:
    folders = _list(document, "interfaces", path)
    wanted = os.path.normpath(cache_entry)
    if any(isinstance(f, str) and os.path.normpath(f) == wanted for f in folders):
        return None
    _append(folders, cache_entry)
    return cache_entry


def edit_manifest(
    text: str, discovery: Discovery, *, cache_entry: str, path: str = "robot.yaml"
) -> ManifestEdit:
    """``text`` with the discovered topics, services and actions and the cache folder added."""
    yaml, document = _load(text, path)
    _check_dialect(document, discovery, path)
    added_interface = _add_interface(document, cache_entry, path)
    gameobject = _connection_gameobject(document)
    # A list is touched only when something is found for it: an empty "services:" whose
    # entries are commented out would otherwise become "services: []", and uncommenting an
    # example under it would then be a YAML error.
    topics, skipped_topics = (
        _add_topics(_list(document, "topics", path), discovery.topics, gameobject)
        if discovery.topics
        else ([], [])
    )
    services, skipped_services = (
        _add_services(_list(document, "services", path), discovery.services, gameobject)
        if discovery.services
        else ([], [])
    )
    # An action whose topics are listed as topics (discovered before actions were recognised)
    # counts as listed: adding it would make a second set of scripts on the same topics.
    as_topics = _listed_names(document.get("topics") or ())
    by_topics = [a.name for a in discovery.actions if any(t.name in as_topics for t in a.topics)]
    wanted = [a for a in discovery.actions if a.name not in by_topics]
    # ROS-TCP-Endpoint's ROS 2 node carries no actions: the manifest would refuse them
    carried = not (_is_tcp(document) and discovery.dialect is Dialect.ROS2)
    unusable = [] if carried else [a.name for a in wanted]
    wanted = wanted if carried else []
    actions, skipped_actions = (
        _add_actions(_list(document, "actions", path), wanted, gameobject) if wanted else ([], [])
    )
    skipped_actions += by_topics + unusable
    result = ManifestEdit(
        text,
        tuple(topics),
        tuple(services),
        tuple(skipped_topics + skipped_services + skipped_actions),
        added_interface,
        tuple(actions),
    )
    if not result.changed:
        return result
    out = io.StringIO()
    yaml.dump(document, out)
    return dataclasses.replace(result, text=out.getvalue())


def manifest_fragment(discovery: Discovery, *, cache_entry: str) -> str:
    """The ``interfaces``, ``topics``, ``services`` and ``actions`` entries to paste into a
    manifest."""
    fragment = f"# discovered from {discovery.origin}\nros: {int(discovery.dialect)}\n"
    edit = edit_manifest(fragment, discovery, cache_entry=cache_entry, path="<fragment>")
    return edit.text


def read_manifest(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise UserError(
            f"manifest not found: {path}", hint="create one with `scaffold init`, or use --print"
        ) from None
    except OSError as exc:
        raise UserError(f"cannot read manifest {path}: {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise UserError(f"the manifest {path} is not UTF-8 text", hint="save it as UTF-8") from None


def interface_folders(text: str, base: Path) -> list[Path]:
    """The manifest's ``interfaces`` folders that exist, resolved against ``base``."""
    try:
        _, document = _load(text, "<manifest>")
    except LocatedError:
        return []
    folders = document.get("interfaces") or []
    found = [base / f for f in folders if isinstance(f, str)] if isinstance(folders, list) else []
    return [f for f in found if f.is_dir()]
