"""The code half of a plan: message classes, per-topic scripts, and their ``.meta`` files.

Layout under the manifest's ``output`` folder: ``Messages/<Pkg>/<msg|srv|action>/<Class>.cs``
(the C# generator's layout) and ``Scripts/<Class>.cs`` with the user's half beside it as
``Scripts/<Class>.User.cs`` (created once, never rewritten).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TypeVar

from unityscaffold.apply._moves import Moves
from unityscaffold.apply._rossharp import RESERVED_NAMES
from unityscaffold.codegen import ClassRole, GeneratedCode, Options, generate
from unityscaffold.codegen.layout import output_files
from unityscaffold.codegen.naming import ClassClash
from unityscaffold.codegen.scripts import (
    PublisherScript,
    ServiceClientScript,
    ServiceServerScript,
    SubscriberScript,
    render_script,
)
from unityscaffold.errors import LocatedError, UserError, located_at
from unityscaffold.fileout import DesiredFile
from unityscaffold.interfaces.model import Dialect, MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry
from unityscaffold.manifest.model import Direction, Manifest, Role, Service, Topic
from unityscaffold.unity.meta import folder_meta, meta_guid, monoscript_meta
from unityscaffold.unity.project import ScriptInfo

__all__ = ["CodePlan", "PlannedScript", "plan_code"]

Script = PublisherScript | SubscriberScript | ServiceClientScript | ServiceServerScript


@dataclass(frozen=True, slots=True)
class PlannedScript:
    """One generated MonoBehaviour and where the manifest wants it attached."""

    entry: str  # the manifest entry it serves: "topic /odom", "service /reset"
    view: Script
    path: Path
    user_path: Path
    guid: str
    item: Topic | Service


@dataclass(frozen=True, slots=True)
class CodePlan:
    generated: tuple[DesiredFile, ...]  # regenerated freely; tracked in the lock
    created_once: tuple[DesiredFile, ...]  # user halves and .meta files: written only if missing
    scripts: tuple[PlannedScript, ...]
    messages: GeneratedCode  # the message, service and action classes (under Messages/)


_Spec = TypeVar("_Spec", MessageSpec, ServiceSpec)


def _resolve(registry: Registry, item: Topic | Service, kind: type[_Spec]) -> _Spec:
    where = item.locations.of("type")
    with located_at(where):
        found = registry.get(item.type)
    if not isinstance(found, kind):
        wanted = "a message" if kind is MessageSpec else "a service"
        raise LocatedError.at(
            where,
            f"'{item.type}' is a {found.kind.value}, not {wanted}",
            expected=f"{wanted} type such as "
            + ("geometry_msgs/Twist" if kind is MessageSpec else "std_srvs/Trigger"),
        )
    return found


_Entry = tuple[Topic | Service, MessageSpec | ServiceSpec]

# ROS 1 std_msgs types whose ROS# class is a hand-written time primitive of another shape.
_MISSHAPEN_IN_ROSSHARP = ("std_msgs/Time", "std_msgs/Duration")


def _check_time_messages(manifest: Manifest, registry: Registry, entries: list[_Entry]) -> None:
    """Refuse an entry whose type uses ROS 1's std_msgs/Time or std_msgs/Duration while ROS#'s
    classes are in use: ROS#'s Std.Time/Std.Duration, which stand for them, are the bare time
    primitive ({secs, nsecs}), while these messages hold it in a field 'data'. rosbridge refuses
    what such a class sends and the value it receives is lost (seen with rosbridge 0.11)."""
    if manifest.ros is not Dialect.ROS1 or manifest.namespace is not None:
        return
    for item, spec in entries:
        used = {m.full_name for m in registry.closure([spec])}
        for name in _MISSHAPEN_IN_ROSSHARP:
            if name in used:
                short = name.split("/")[1]
                raise LocatedError.at(
                    item.locations.of("type"),
                    f"{name} cannot be sent or received with ROS#'s class for it: "
                    f"Std.{short} is the bare {short.lower()} primitive {{secs, nsecs}}, while "
                    f"{name} holds it in a field 'data' (rosbridge refuses what it sends)",
                    hint="choose a root namespace with the manifest key `namespace:` "
                    f"(then a {name} class of the right shape is generated), or use a "
                    f"message with a {short.lower()} field",
                )


def _generate(manifest: Manifest, registry: Registry, entries: list[_Entry]) -> GeneratedCode:
    """The C# for every entry's type; a problem is shown at the entry that brings it in."""
    options = Options(manifest.ros, manifest.include_shipped, manifest.namespace)
    specs = [spec for _, spec in entries]
    try:
        return generate(registry, specs, options)
    except LocatedError:
        raise  # it points into the interface file at fault
    except UserError as error:
        failure, where = error, None
    # Codegen knows types, not manifest entries: point at the first entry whose types, with those
    # of the entries before it, make generation fail (a clash can take two entries).
    for count, (item, _) in enumerate(entries, start=1):
        try:
            generate(registry, specs[:count], options)
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


def _view(
    manifest: Manifest,
    item: Topic | Service,
    spec: MessageSpec | ServiceSpec,
    messages: GeneratedCode,
) -> Script:
    common = {
        "class_name": item.class_name,
        "ros_type": spec.full_name,
        "manifest": manifest.path.name,
    }
    if isinstance(item, Topic):
        message = messages.message_class(spec.full_name).qualified
        if item.direction is Direction.PUBLISH:
            return PublisherScript(
                **common, topic=item.name, message_type=message, rate=item.rate or 0.0
            )
        return SubscriberScript(
            **common,
            topic=item.name,
            message_type=message,
            throttle=item.throttle or 0,
            queue=item.queue or 1,
        )
    classes = messages.classes[f"{spec.package}/srv/{spec.name}"]
    kind = ServiceClientScript if item.role is Role.CLIENT else ServiceServerScript
    return kind(
        **common,
        service=item.name,
        request_type=classes[ClassRole.REQUEST].qualified,
        response_type=classes[ClassRole.RESPONSE].qualified,
    )


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


def _script_guid(manifest: Manifest, path: Path, salt: str, moves: Moves | None) -> str:
    meta = path.with_name(path.name + ".meta")
    if moves is not None and not meta.exists():
        moved = moves.guid(path.name)
        if moved is not None:
            return moved
    return meta_guid(meta, salt, manifest.asset_path(path))


def _check_class_names(
    manifest: Manifest, scripts: dict[str, ScriptInfo], moves: Moves | None
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
    items: tuple[Topic | Service, ...] = (*manifest.topics, *manifest.services)
    for item in items:
        clash = (
            "ROS#'s stock script"
            if item.class_name in RESERVED_NAMES
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
    """Everything the manifest's topics and services need in C#, as desired files; a script
    moved from an earlier output folder keeps its GUIDs (``moves``)."""
    _check_class_names(manifest, scripts, moves)
    items: list[tuple[Topic | Service, MessageSpec | ServiceSpec]] = []
    items += [(t, _resolve(registry, t, MessageSpec)) for t in manifest.topics]
    items += [(s, _resolve(registry, s, ServiceSpec)) for s in manifest.services]
    _check_time_messages(manifest, registry, items)
    messages = _generate(manifest, registry, items)
    messages_dir = manifest.output_dir / "Messages"
    scripts_dir = manifest.output_dir / "Scripts"
    generated: list[DesiredFile] = []
    created_once: list[DesiredFile] = []
    for file in output_files(messages, messages_dir):
        (created_once if file.create_only else generated).append(file)
    planned: list[PlannedScript] = []
    for item, spec in items:
        view = _view(manifest, item, spec, messages)
        rendered = render_script(view)
        path, user_path = scripts_dir / rendered.plumbing_name, scripts_dir / rendered.user_name
        guid = _script_guid(manifest, path, salt, moves)
        user_guid = _script_guid(manifest, user_path, salt, moves)
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
        kind = "topic" if isinstance(item, Topic) else "service"
        planned.append(PlannedScript(f"{kind} {item.name}", view, path, user_path, guid, item))
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
