"""Full definition texts back into ``.msg`` files, in a definitions cache, verified.

A full definition is the root type's text followed, for each type it uses, by a line of 80
``=``, ``MSG: pkg/Type`` (ROS 2 sources may write ``pkg/msg/Type``) and that type's text, so
splitting at those separators gives each file back byte for byte. The files are written to
``<cache>/<pkg>/msg/<Type>.msg`` in a staging folder next to the cache; each ROS 1 type whose
md5sum the system reported is checked against the md5sum of its reconstruction (each ROS 2 type
the graph reported a RIHS01 hash for, against that hash, ``_rihs``), and only when
everything checks out does the staging folder replace the cache.

A ROS 1 action's topics carry genaction's messages (``XActionGoal``, ``XGoal``, …), not the
``.action`` file; its goal, result and feedback texts (without genaction's banner) joined by
``---`` lines are that file again, written to ``<cache>/<pkg>/action/<X>.action``.
"""

from __future__ import annotations

import re
import shutil
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from unityscaffold.errors import LocatedError, UserError
from unityscaffold.interfaces.identity_ros1 import Ros1Identity
from unityscaffold.interfaces.live._rihs import check_type_hashes
from unityscaffold.interfaces.live.model import (
    DiscoveredAction,
    DiscoveredService,
    DiscoveredTopic,
    Discovery,
)
from unityscaffold.interfaces.model import ActionSpec, Dialect, MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry
from unityscaffold.interfaces.ros1 import ACTION_BANNER
from unityscaffold.interfaces.suffixes import (
    ROS1_ACTION_PARTS,
    ROS1_ACTION_WRAPPERS,
)

__all__ = ["Definition", "StagedCache", "split_full_text", "stage_definitions"]

_SEPARATOR = re.compile(r"\n={80}\n(MSG|IDL): ([^\n]*)\n")
_IDL_START = "=" * 80 + "\nIDL: "
_NAME = re.compile(r"^([A-Za-z][\w]*)/(?:msg/)?([A-Za-z][\w]*)$")


@dataclass(frozen=True, slots=True)
class Definition:
    """One message's (or service's) own text, as its ``.msg`` (``.srv``) file held it."""

    package: str
    name: str
    text: str
    kind: str = "msg"

    @property
    def relative_path(self) -> Path:
        return Path(self.package) / self.kind / f"{self.name}.{self.kind}"


def _split_name(type_name: str, root: str) -> tuple[str, str]:
    match = _NAME.match(type_name.strip())
    if match is None:
        raise UserError(
            f"the definition of {root} names a type {type_name!r}, which is not pkg/Type"
        )
    return match.group(1), match.group(2)


def split_full_text(type_name: str, text: str) -> list[Definition]:
    """The root type and every type it uses, in the order the text lists them."""
    if text.startswith(_IDL_START):
        raise UserError(
            f"the definition of {type_name} is in IDL form, which cannot be turned into .msg files",
            hint="record with the ros2msg definition format",
        )
    pieces = _SEPARATOR.split(text)
    package, name = _split_name(type_name, type_name)
    found = [Definition(package, name, pieces[0])]
    for index in range(1, len(pieces), 3):
        form, dependency, body = pieces[index : index + 3]
        if form == "IDL":
            raise UserError(
                f"the definition of {type_name} embeds {dependency} in IDL form, "
                "which cannot be turned into a .msg file"
            )
        found.append(Definition(*_split_name(dependency, type_name), body))
    return found


class StagedCache:
    """A verified copy of the cache, waiting to replace it (``commit``) or to go (``discard``)."""

    def __init__(
        self, target: Path, staging: Path, changed: list[Path], warnings: list[str]
    ) -> None:
        self.target, self.staging = target, staging
        self.changed = changed
        self.warnings = warnings

    def commit(self) -> None:
        """Swap the staging folder into place with two renames, keeping nothing half-written."""
        old = None
        if self.target.exists():
            old = self.target.with_name(f".{self.target.name}.old-{self.staging.name}")
            self.target.rename(old)
        self.staging.rename(self.target)
        if old is not None:
            shutil.rmtree(old, ignore_errors=True)

    def discard(self) -> None:
        shutil.rmtree(self.staging, ignore_errors=True)


def collect(discovery: Discovery) -> list[Definition]:
    """Every type the discovery carries a definition of; the first text seen wins."""
    found: dict[Path, Definition] = {}
    for topic in discovery.topics:
        if topic.definition:
            for definition in split_full_text(topic.type, topic.definition):
                found.setdefault(definition.relative_path, definition)
    for service in discovery.services:
        if service.definition:
            package, name = _split_name(service.type.replace("/srv/", "/"), service.type)
            definition = Definition(package, name, service.definition, "srv")
            found.setdefault(definition.relative_path, definition)
    for action in discovery.actions:
        for definition in _action_definitions(action):
            found.setdefault(definition.relative_path, definition)
    for relative, text in discovery.files:
        package, kind, file_name = relative.split("/")
        definition = Definition(package, file_name.rsplit(".", 1)[0], text, kind)
        found.setdefault(definition.relative_path, definition)
    return [found[path] for path in sorted(found)]


def _action_definitions(action: DiscoveredAction) -> list[Definition]:
    """The ``.action`` file (when the goal, result and feedback texts all came) and the
    messages the action uses; genaction's own messages are left out, the file makes them."""
    package, _, name = action.type.partition("/action/")
    own = {name + part for part in (*ROS1_ACTION_PARTS, *ROS1_ACTION_WRAPPERS)}
    parts: dict[str, str] = {}
    used = []
    for topic in action.topics:
        if not topic.definition:
            continue
        for definition in split_full_text(topic.type, topic.definition):
            if definition.package != package or definition.name not in own:
                used.append(definition)
            elif definition.name in (name + part for part in ROS1_ACTION_PARTS):
                parts[definition.name] = _part_text(definition.text)
    if len(parts) == len(ROS1_ACTION_PARTS):
        goal, result, feedback = (parts[name + part] for part in ROS1_ACTION_PARTS)
        # genaction ends every line of a section with a newline, the file's last line too
        # (which gives the feedback one more when the file ends with a newline): undo that.
        text = f"{goal}---\n{result}---\n{feedback.removesuffix(chr(10))}"
        used.append(Definition(package, name, text, "action"))
    return used


def _part_text(text: str) -> str:
    """A goal, result or feedback section's lines, each ended by a newline as genaction does."""
    text = text.removeprefix(ACTION_BANNER)
    return text if not text or text.endswith("\n") else text + "\n"  # "": no lines at all


def _write(staging: Path, definitions: Sequence[Definition], cache: Path) -> list[Path]:
    """Write into ``staging``; return the files that differ from ``cache``."""
    changed = []
    for definition in definitions:
        relative = definition.relative_path
        old = cache / relative
        if not old.is_file() or old.read_text(encoding="utf-8") != definition.text:
            changed.append(relative)
        path = staging / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(definition.text, encoding="utf-8")
    return changed


def stage_definitions(
    discovery: Discovery, cache: Path, *, search_paths: Sequence[Path] = ()
) -> StagedCache:
    """Write the discovered definitions over a copy of ``cache`` and verify them.

    Raises ``UserError`` naming the type when a reconstruction does not parse or its md5sum
    (ROS 2: RIHS01 hash) differs from the one the system reported; nothing is left behind then.
    """
    definitions = collect(discovery)
    cache.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{cache.name}-", dir=cache.parent))
    try:
        if cache.is_dir():
            shutil.copytree(cache, staging, dirs_exist_ok=True)
        changed = _write(staging, definitions, cache)
        warnings = _verify(discovery, staging, search_paths)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    return StagedCache(cache, staging, changed, warnings)


def _verify(discovery: Discovery, staging: Path, search_paths: Sequence[Path]) -> list[str]:
    """Check every reconstruction against the cache alone, and every other type against the
    cache plus the user's folders and the environment; unknown ones become warnings."""
    own = Registry.load(discovery.dialect, [staging], use_environment=False, use_builtin=False)
    wider = Registry.load(discovery.dialect, [staging, *search_paths])
    warnings: list[str] = []
    items: tuple[DiscoveredTopic | DiscoveredService, ...] = (
        *discovery.topics,
        *discovery.services,
    )
    for item in items:
        reconstructed = bool(item.definition)
        registry = own if reconstructed else wider
        spec = _lookup(registry, item.type, discovery.origin)
        if spec is None:
            warnings.append(
                f"no definition of {item.type} (used by {item.name}): add the folder "
                "with its package to the manifest's interfaces"
            )
            continue
        if discovery.dialect is Dialect.ROS1 and item.md5:
            _check_md5(
                registry, spec, item.md5, item.name, discovery.origin, reconstructed=reconstructed
            )
    for action in discovery.actions:
        warnings.extend(_verify_action(action, discovery.origin, own, wider))
    if discovery.dialect is Dialect.ROS2:
        check_type_hashes(discovery, own, wider)
    return warnings


def _verify_action(
    action: DiscoveredAction, origin: str, own: Registry, wider: Registry
) -> list[str]:
    """The action's file from the cache when its texts came, else from the user's folders;
    each of its topics' md5sums checked against what that file (or the cache) gives."""
    reconstructed = _is_action(own, action.type, origin)
    registry = own if reconstructed else wider
    if not reconstructed and not _is_action(wider, action.type, origin):
        if not action.topics:  # ROS 2: the graph names the action's type, never its text
            return [
                f"no definition of {action.type} (used by {action.name}): add the folder "
                "with its package to the manifest's interfaces, or install its package"
            ]
        return [
            f"no definition of {action.type} (used by {action.name}): its goal, result and "
            "feedback texts did not all come (a ROS 1 node sends the texts of what it publishes "
            "only); add the folder with its package to the manifest's interfaces, or discover "
            "through a rosbridge, which sends them all"
        ]
    for topic in action.topics:
        where = registry if _lookup(registry, topic.type, origin) is not None else wider
        spec = _lookup(where, topic.type, origin)
        if topic.md5 and isinstance(spec, MessageSpec):
            _check_md5(where, spec, topic.md5, topic.name, origin, reconstructed=where is own)
    return []


def _is_action(registry: Registry, type_name: str, origin: str) -> bool:
    try:
        return isinstance(registry.find(type_name), ActionSpec)
    except LocatedError as error:
        first = error.diagnostics[0]
        raise UserError(
            f"the definition of {type_name} rebuilt from {origin}'s texts does not parse: "
            f"line {first.location.line}: {first.message}"
        ) from None


def _lookup(registry: Registry, type_name: str, origin: str) -> MessageSpec | ServiceSpec | None:
    try:
        found = registry.find(type_name)
    except LocatedError as error:
        first = error.diagnostics[0]
        raise UserError(
            f"the definition of {type_name} reported by {origin} does not parse: "
            f"line {first.location.line}: {first.message}"
        ) from None
    return found if isinstance(found, MessageSpec | ServiceSpec) else None


def _check_md5(
    registry: Registry,
    spec: MessageSpec | ServiceSpec,
    reported: str,
    name: str,
    origin: str,
    *,
    reconstructed: bool,
) -> None:
    try:
        computed = Ros1Identity(registry).md5sum(spec)
    except UserError as error:
        raise UserError(
            f"the definition of {spec.full_name} (used by {name}) is incomplete: {error.message}"
        ) from None
    if computed == reported:
        return
    if reconstructed:
        hint = (
            f"the definition {origin} sent for {spec.full_name} does not match its own "
            "md5sum; the publisher may have been built from other .msg files than it runs"
        )
    else:
        hint = (
            f"the system runs a different version of {spec.full_name} than "
            f"{spec.source or 'the local definition'}"
        )
    raise UserError(
        f"md5sum mismatch for {spec.full_name} (used by {name}): {origin} reported "
        f"{reported}, the definition gives {computed}",
        hint=hint,
    )
