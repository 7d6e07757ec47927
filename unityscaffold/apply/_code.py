"""The code half of a plan: message classes, a script per topic, service and action, and their
``.meta`` files.

Layout under the manifest's ``output`` folder: ``Messages/<Pkg>/<msg|srv|action>/<Class>.cs``
(the C# generator's layout) and ``Scripts/<Class>.cs`` with the user's half beside it as
``Scripts/<Class>.User.cs`` (created once, never rewritten).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from unityscaffold.apply._moves import Moves
from unityscaffold.apply._target import RuntimeTarget, target_for
from unityscaffold.codegen import GeneratedCode, Options
from unityscaffold.codegen.layout import output_files
from unityscaffold.codegen.naming import ClassClash
from unityscaffold.errors import Diagnostic, LocatedError, UserError, located_at
from unityscaffold.fileout import DesiredFile
from unityscaffold.interfaces.model import (
    ActionSpec,
    Interface,
    InterfaceKind,
    MessageSpec,
    ServiceSpec,
)
from unityscaffold.interfaces.registry import Registry
from unityscaffold.interfaces.suffixes import ROS1_PART_SUFFIXES
from unityscaffold.manifest.model import Action, Manifest, Service, Topic
from unityscaffold.unity.meta import folder_meta, meta_guid, monoscript_meta
from unityscaffold.unity.project import ScriptInfo

if TYPE_CHECKING:
    from unityscaffold.codegen.scripts import Script

__all__ = ["CodePlan", "PlannedScript", "plan_code"]

Entry = Topic | Service | Action
_LABEL: dict[type, str] = {Topic: "topic", Service: "service", Action: "action"}


@dataclass(frozen=True, slots=True)
class PlannedScript:
    """One generated MonoBehaviour and where the manifest wants it attached."""

    entry: str  # the manifest entry it serves: "topic /odom", "service /reset", "action /dock"
    view: Script
    path: Path
    user_path: Path
    guid: str
    item: Entry


@dataclass(frozen=True, slots=True)
class CodePlan:
    generated: tuple[DesiredFile, ...]  # regenerated freely; tracked in the lock
    created_once: tuple[DesiredFile, ...]  # user halves and .meta files: written only if missing
    scripts: tuple[PlannedScript, ...]
    messages: GeneratedCode  # the message, service and action classes (under Messages/)


_Spec = MessageSpec | ServiceSpec | ActionSpec
_WANTED: dict[type, tuple[str, str, str, InterfaceKind]] = {
    # kind -> (what, an example, the manifest section, the files that define it)
    MessageSpec: ("a message", "geometry_msgs/Twist", "topics", InterfaceKind.MSG),
    ServiceSpec: ("a service", "std_srvs/Trigger", "services", InterfaceKind.SRV),
    ActionSpec: ("an action", "move_base_msgs/action/MoveBase", "actions", InterfaceKind.ACTION),
}


def _resolve(registry: Registry, item: Entry, kind: type[_Spec]) -> _Spec:
    """The interface an entry names, of the kind its section takes."""
    where = item.locations.of("type")
    with located_at(where):
        found = registry.get(item.type, kinds=(_WANTED[kind][3],))
    if not isinstance(found, kind):
        wanted, example, _, _ = _WANTED[kind]
        raise LocatedError.at(
            where,
            f"'{item.type}' is {_WANTED[type(found)][0]}, not {wanted}",
            expected=f"{wanted} type such as {example}",
            hint=_kind_hint(registry, item.type, found, kind),
        )
    return found


def _resolve_all(manifest: Manifest, registry: Registry) -> list[_Entry]:
    """Every entry's interface; the types not found are all reported at once."""
    kinds: list[tuple[Entry, type[_Spec]]] = [
        *((t, MessageSpec) for t in manifest.topics),
        *((s, ServiceSpec) for s in manifest.services),
        *((a, ActionSpec) for a in manifest.actions),
    ]
    items: list[_Entry] = []
    problems: list[Diagnostic] = []
    for item, kind in kinds:
        try:
            items.append((item, _resolve(registry, item, kind)))
        except LocatedError as error:
            problems += error.diagnostics
    if problems:
        raise LocatedError(problems)
    return items


def _kind_hint(registry: Registry, name: str, found: Interface, kind: type) -> str:
    """Where the type belongs, or the action a ROS 1 action message is part of."""
    if kind is ActionSpec and isinstance(found, MessageSpec):
        owner = _action_of(registry, found)
        if owner is not None:
            return (
                f"'{name}' is a message of the action {owner}; name the action itself: "
                f"type: {owner}"
            )
    spelled = f"{found.package}/action/{found.name}"
    if kind is ActionSpec and registry.find(spelled) is not None:
        return f"in ROS 1, pkg/Name means the {_WANTED[type(found)][0][2:]}; write {spelled}"
    return f"list it under '{_WANTED[type(found)][2]}'"


def _action_of(registry: Registry, message: MessageSpec) -> str | None:
    """The action whose messages include ``message`` (ROS 1 ``XActionGoal``...), if any."""
    for kind, suffix in ROS1_PART_SUFFIXES:
        if kind is InterfaceKind.ACTION and message.name.endswith(suffix):
            owner = f"{message.package}/action/{message.name[: -len(suffix)]}"
            if isinstance(registry.find(owner), ActionSpec):
                return owner
    return None


_Entry = tuple[Entry, _Spec]


def _generate(
    manifest: Manifest, registry: Registry, entries: list[_Entry], target: RuntimeTarget
) -> GeneratedCode:
    """The C# for every entry's type; a problem is shown at the entry that brings it in."""
    options = Options(manifest.ros, manifest.include_shipped, manifest.namespace)
    specs = [spec for _, spec in entries]
    try:
        return target.classes(registry, specs, options)
    except LocatedError:
        raise  # it points into the interface file at fault
    except UserError as error:
        failure, where = error, None
    # Codegen knows types, not manifest entries: point at the first entry whose types, with those
    # of the entries before it, make generation fail (a clash can take two entries).
    for count, (item, _) in enumerate(entries, start=1):
        try:
            target.classes(registry, specs[:count], options)
        except UserError as error:
            failure, where = error, item.locations.of("type")
            break
    if isinstance(failure, LocatedError):
        raise failure  # the entry's types stop at a problem inside an interface file
    hint = failure.hint
    if isinstance(failure, ClassClash) and failure.with_shipped:
        hint = "choose another root namespace with the manifest key `namespace:`"
    if where is None:  # no entries: only the types every generation needs
        raise UserError(failure.message, hint=hint)
    raise LocatedError.at(where, failure.message, hint=hint)


def _folder_metas(manifest: Manifest, folders: set[Path], salt: str) -> list[DesiredFile]:
    assets = manifest.project_root / "Assets"
    metas = []
    for folder in sorted(folders):
        if folder == assets or assets not in folder.parents:
            continue
        meta = folder.with_name(folder.name + ".meta")
        guid = meta_guid(meta, salt, manifest.asset_path(folder))
        metas.append(DesiredFile(meta, folder_meta(guid).encode(), create_only=True))
    return metas


def _script_guid(
    manifest: Manifest, path: Path, salt: str, moves: Moves | None, known: dict[str, str]
) -> str:
    """The script's GUID: from its ``.meta`` (as the project index read it, ``known`` by asset
    path, so the file is not read twice), a moved script's, or derived from its path."""
    meta = path.with_name(path.name + ".meta")
    if moves is not None and not meta.exists():
        moved = moves.guid(path.name)
        if moved is not None:
            return moved
    asset = manifest.asset_path(path)
    return known.get(asset) or meta_guid(meta, salt, asset)


def _check_class_names(
    manifest: Manifest,
    scripts: dict[str, ScriptInfo],
    moves: Moves | None,
    target: RuntimeTarget,
) -> None:
    """A generated script must not share its class name with ROS#'s or another script's:
    Unity and the manifest's ``components`` find scripts by that name. Scripts an earlier
    apply generated in another output folder do not count: they move (``moves``)."""
    ours = manifest.asset_path(manifest.output_dir / "Scripts")
    elsewhere = {
        info.class_name: info.path
        for info in scripts.values()
        if not info.path.startswith(ours + "/")
        and not (moves is not None and info.path in moves.owned)
    }
    items: tuple[Entry, ...] = (*manifest.topics, *manifest.services, *manifest.actions)
    for item in items:
        clash = (
            f"{target.label}'s stock script"
            if item.class_name in target.reserved_names
            else elsewhere.get(item.class_name)
        )
        if clash:
            where = (
                item.locations.of("class")
                if item.locations.has("class")
                else item.locations.of("name")
            )
            raise LocatedError.at(
                where,
                f"the script generated for {item.name} would be named "
                f"{item.class_name}, like {clash}",
                hint="give this entry another name with `class:`",
            )


def plan_code(
    manifest: Manifest,
    registry: Registry,
    salt: str,
    scripts: dict[str, ScriptInfo],
    moves: Moves | None = None,
) -> CodePlan:
    """Everything the manifest's topics, services and actions need in C#, as desired files; a
    script moved from an earlier output folder keeps its GUIDs (``moves``)."""
    target = target_for(manifest)
    _check_class_names(manifest, scripts, moves, target)
    items = _resolve_all(manifest, registry)
    target.check(manifest, registry, items)
    messages = _generate(manifest, registry, items, target)
    messages_dir = manifest.output_dir / "Messages"
    scripts_dir = manifest.output_dir / "Scripts"
    generated: list[DesiredFile] = []
    created_once: list[DesiredFile] = []
    for file in output_files(messages, messages_dir, project=manifest.project_root):
        (created_once if file.create_only else generated).append(file)
    planned: list[PlannedScript] = []
    known = {info.path: guid for guid, info in scripts.items()}
    for item, spec in items:
        from unityscaffold.codegen.scripts import render_script  # loaded with the first script

        view = target.script_view(manifest, item, spec, messages)
        rendered = render_script(view)
        path, user_path = scripts_dir / rendered.plumbing_name, scripts_dir / rendered.user_name
        guid = _script_guid(manifest, path, salt, moves, known)
        user_guid = _script_guid(manifest, user_path, salt, moves, known)
        generated.append(DesiredFile(path, rendered.plumbing.encode()))
        created_once += [
            DesiredFile(user_path, rendered.user.encode(), create_only=True),
            DesiredFile(path.with_name(path.name + ".meta"), monoscript_meta(guid).encode(), True),
            DesiredFile(
                user_path.with_name(user_path.name + ".meta"),
                monoscript_meta(user_guid).encode(),
                True,
            ),
        ]
        label = _LABEL[type(item)]
        planned.append(PlannedScript(f"{label} {item.name}", view, path, user_path, guid, item))
    # Every folder that will hold a planned file needs a folder .meta (the generator's own
    # covers Messages/ and below; these are the ones above it and Scripts/).
    folders = {
        parent
        for folder in {d.path.parent for d in (*generated, *created_once)}
        for parent in (folder, *folder.parents)
        if messages_dir not in parent.parents and parent != messages_dir
    }
    created_once += _folder_metas(manifest, folders, salt)
    return CodePlan(tuple(generated), tuple(created_once), tuple(planned), messages)
