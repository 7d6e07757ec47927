"""The set of C# classes one ``generate`` call makes: units, names, paths, what ROS# ships."""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from functools import cache
from pathlib import PurePath

from unityscaffold.codegen._actions import ActionClasses, RuntimeTypes
from unityscaffold.codegen._build import FileContext
from unityscaffold.codegen._references import KnownClasses
from unityscaffold.codegen._shipped import ROS1_HANDWRITTEN, shipped_classes
from unityscaffold.codegen.naming import (
    ROSSHARP_MESSAGE,
    ROSSHARP_ROOT_NAMESPACE,
    ClassClash,
    CsClass,
    check_class_name,
    class_name,
    namespace_segment,
    rossharp_class,
    validate_namespace,
)
from unityscaffold.codegen.roles import ACTION_ROLES, CLASS_SUFFIX, ClassRole
from unityscaffold.errors import LocatedError, SourceLocation, UserError, located_at
from unityscaffold.interfaces.model import (
    ActionSpec,
    Dialect,
    Interface,
    MessageSpec,
    ServiceSpec,
)
from unityscaffold.interfaces.registry import Registry
from unityscaffold.interfaces.sources import package_name_location
from unityscaffold.interfaces.suffixes import ROS1_PART_SUFFIXES

__all__ = ["ClassEntry", "ClassSet", "collect_classes", "source_name", "unit_key"]

_WRAPPER_DEPENDENCIES = {
    Dialect.ROS1: ("std_msgs/Header", "actionlib_msgs/GoalID", "actionlib_msgs/GoalStatus"),
    Dialect.ROS2: ("std_msgs/msg/Header", "action_msgs/msg/GoalInfo", "action_msgs/msg/GoalStatus"),
}


@dataclass(frozen=True, slots=True)
class ClassEntry:
    """One C# class: the unit (message, service or action) it belongs to and its role there."""

    interface: Interface
    role: ClassRole
    spec: MessageSpec | None
    cs_class: CsClass
    ros_message_name: str
    path: str
    identity_of: Interface
    skip_reason: str | None = None


def source_name(interface: Interface) -> str:
    """``pkg/msg/Name.msg``: the definition file, relative to its package's parent."""
    source = interface.source
    if not source:
        return interface.full_name
    parts = source.split("/")
    if os.name == "nt" or "" in parts[1:] or "." in parts:
        # not a POSIX path in normal form (registry paths are): pathlib reads it
        path = PurePath(source)
        return f"{interface.package}/{path.parent.name}/{path.name}"
    return f"{interface.package}/{parts[-2] if len(parts) > 1 else ''}/{parts[-1]}"


def _generated_parts(interface: Interface) -> tuple[MessageSpec, ...]:
    if isinstance(interface, MessageSpec):
        return (interface,)
    if isinstance(interface, ServiceSpec):
        return (interface.request, interface.response)
    return (interface.goal, interface.result, interface.feedback)


def _owned_names(interface: Interface) -> set[str]:
    """Message names inside a service or action that have a class of their own."""
    names = {p.full_name for p in _generated_parts(interface)}
    if isinstance(interface, ActionSpec) and interface.dialect is Dialect.ROS1:
        names |= {d.full_name for d in interface.derived}
    return names


def _units(registry: Registry, roots: list[Interface], extra: tuple[str, ...]) -> list[Interface]:
    """Roots, the owners of service/action parts they use, and every free message used."""
    units: dict[str, Interface] = {}
    for root in roots:
        owner = _owner(registry, root) if isinstance(root, MessageSpec) else None
        units.setdefault(unit_key(owner or root), owner or root)
    while True:
        seeds = [p for u in units.values() for p in _generated_parts(u)]
        if any(isinstance(u, ActionSpec) for u in units.values()):
            seeds += [registry.message(name) for name in extra]
        closure = registry.closure(seeds)
        added = False
        for message in closure:
            owner = _owner(registry, message)
            if owner is None:
                units.setdefault(unit_key(message), message)
                continue
            if message.full_name not in _owned_names(owner) and message.owner is not None:
                where = SourceLocation(message.source or message.full_name)
                raise LocatedError.at(
                    where,
                    f"{message.full_name} is used as a field type, but it has no class of its own",
                    hint="use the service's or "
                    "action's own request, response, goal, result or feedback",
                )
            if unit_key(owner) not in units:
                units[unit_key(owner)] = owner
                added = True
        if not added:
            return [units[name] for name in sorted(units)]


def unit_key(interface: Interface) -> str:
    """``pkg/kind/Name``: unique even where ROS 1 has a service and an action of one name."""
    return f"{interface.package}/{interface.kind.value}/{interface.name}"


def _ros1_generated_owner(registry: Registry, message: MessageSpec) -> Interface | None:
    """The .srv/.action whose generated .msg copy ``message`` is (Debian installs those)."""
    for kind, suffix in ROS1_PART_SUFFIXES:
        if message.name.endswith(suffix) and len(message.name) > len(suffix):
            base = message.name[: -len(suffix)]
            owner = registry.find(f"{message.package}/{kind.value}/{base}")
            if owner is not None and not isinstance(owner, MessageSpec):
                return owner
    return None


def _owner(registry: Registry, part: MessageSpec) -> Interface | None:
    """The service or action that defines ``part``, or None for a free message."""
    if part.owner is None:
        if part.dialect is Dialect.ROS1:
            return _ros1_generated_owner(registry, part)
        return None
    if part.dialect is Dialect.ROS1:
        package, name = part.owner.split("/")
        return registry.get(f"{package}/{part.subfolder}/{name}")
    return registry.get(part.owner)


@cache
def _shipped_names(dialect: Dialect) -> dict[str, frozenset[str]]:
    """The classes ROS# ships, as names by full namespace: hundreds of them, known to every
    ``generate`` call."""
    names: dict[str, set[str]] = {}
    for segment, name in shipped_classes(dialect):
        names.setdefault(rossharp_class(segment, name).namespace, set()).add(name)
    return {namespace: frozenset(found) for namespace, found in names.items()}


class ClassSet:
    """Every class of one ``generate`` call, named, placed, and marked generated or skipped."""

    def __init__(
        self, dialect: Dialect, root: str, custom_namespace: bool, items: list[ClassEntry]
    ) -> None:
        self.dialect = dialect
        self.root = root
        self.custom_namespace = custom_namespace
        self.items = items
        self.known = KnownClasses()
        self.known.add(i.cs_class for i in items)
        if not custom_namespace:
            for namespace, names in _shipped_names(dialect).items():
                self.known.add_names(namespace, names)
        if dialect is Dialect.ROS1:
            self.known.add(rossharp_class(ns, cls) for ns, cls in ROS1_HANDWRITTEN)
        self.by_ros: dict[str, CsClass] = {}
        self._roles: dict[str, dict[ClassRole, CsClass]] = {}
        for item in items:
            self._roles.setdefault(unit_key(item.interface), {})[item.role] = item.cs_class
            if item.spec is not None:
                self.by_ros[item.spec.full_name] = item.cs_class
        for item in items:
            if isinstance(item.interface, ActionSpec) and dialect is Dialect.ROS1:
                for derived in item.interface.derived:
                    role = _role_of_derived(item.interface, derived)
                    self.by_ros[derived.full_name] = self._roles[unit_key(item.interface)][role]
        if dialect is Dialect.ROS1:
            self.runtime = RuntimeTypes(
                rossharp_class("Std", "Header"),
                goal_id=rossharp_class("Actionlib", "GoalID"),
                goal_status=rossharp_class("Actionlib", "GoalStatus"),
            )
        else:
            self.runtime = RuntimeTypes(
                rossharp_class("Std", "Header"), goal_info=rossharp_class("Action", "GoalInfo")
            )

    @property
    def generated(self) -> list[ClassEntry]:
        return [i for i in self.items if i.skip_reason is None]

    @property
    def skipped(self) -> list[ClassEntry]:
        return [i for i in self.items if i.skip_reason is not None]

    def class_of(self, full_name: str, used_at: SourceLocation | None) -> CsClass:
        try:
            return self.by_ros[full_name]
        except KeyError:
            raise LocatedError.at(
                used_at or SourceLocation(full_name), f"no C# class for {full_name}"
            ) from None

    def action_classes(self, interface: Interface) -> ActionClasses:
        roles = self._roles[unit_key(interface)]
        return ActionClasses(**{role.value: roles[role] for role in ACTION_ROLES})

    def class_map(self) -> dict[str, dict[ClassRole, CsClass]]:
        result = {name: dict(roles) for name, roles in sorted(self._roles.items())}
        for name, cls in sorted(self.by_ros.items()):
            result.setdefault(name, {ClassRole.MESSAGE: cls})
        return result

    def file_context(self) -> FileContext:
        return FileContext(
            dialect=self.dialect,
            known=self.known,
            message_base=ROSSHARP_MESSAGE,
            qualify_runtime=self.custom_namespace,
            class_of=self.class_of,
            time_class=lambda base: rossharp_class("Std", base.capitalize()),
        )


def _role_of_derived(action: ActionSpec, derived: MessageSpec) -> ClassRole:
    suffix = derived.name[len(action.name) :]
    return next(role for role in ACTION_ROLES if CLASS_SUFFIX[role] == suffix)


def _classes_of(unit: Interface, root: str) -> list[ClassEntry]:
    # Both placed only when they fail, as in entry() below.
    try:
        segment = namespace_segment(unit.package)
    except UserError as error:
        where = package_name_location(unit.source, unit.package)
        raise LocatedError.at(where, error.message, hint=error.hint) from None
    namespace = f"{root}.{segment}"
    folder = unit.kind.value
    try:
        base = class_name(unit.name)
    except UserError:
        with located_at(SourceLocation(unit.source or unit.full_name)):  # its file's name
            raise

    def entry(
        role: ClassRole,
        spec: MessageSpec | None,
        name: str,
        ros_name: str,
        identity: Interface,
    ) -> ClassEntry:
        try:
            check_class_name(name)
        except UserError:
            # placed only when it fails: a context manager per class is a cost each one pays
            with located_at(SourceLocation(unit.source or unit.full_name)):
                raise
        return ClassEntry(
            unit,
            role,
            spec,
            CsClass(namespace, name),
            ros_name,
            f"{segment}/{folder}/{name}.cs",
            identity,
        )

    if isinstance(unit, MessageSpec):
        return [entry(ClassRole.MESSAGE, unit, base, unit.full_name, unit)]
    if isinstance(unit, ServiceSpec):
        return [
            entry(role, half, base + CLASS_SUFFIX[role], unit.full_name, half)
            for role, half in (
                (ClassRole.REQUEST, unit.request),
                (ClassRole.RESPONSE, unit.response),
            )
        ]
    prefix = f"{unit.package}/" if unit.dialect is Dialect.ROS1 else f"{unit.package}/action/"
    parts = {
        ClassRole.GOAL: unit.goal,
        ClassRole.RESULT: unit.result,
        ClassRole.FEEDBACK: unit.feedback,
    }
    derived = {d.name[len(unit.name) :]: d for d in unit.derived}
    items = []
    for role in ACTION_ROLES:
        suffix = CLASS_SUFFIX[role]
        identity: Interface = parts.get(role) or (
            derived.get(suffix) or unit if unit.dialect is Dialect.ROS1 else unit
        )
        items.append(
            entry(role, parts.get(role), base + suffix, f"{prefix}{unit.name}{suffix}", identity)
        )
    return items


def _skip_reason(item: ClassEntry, dialect: Dialect, include_shipped: bool) -> str | None:
    key = (item.cs_class.namespace.rsplit(".", 1)[-1], item.cs_class.name)
    if dialect is Dialect.ROS1 and ROS1_HANDWRITTEN.get(key) == item.ros_message_name:
        return (
            f"ROS# hand-writes {item.cs_class.full_name} (never generated); it is the bare time "
            f"primitive, not {item.ros_message_name} (whose value is in a field 'data'), so "
            f"it does not work as a {item.ros_message_name} message; another root namespace "
            "gives one of the right shape"
        )
    if include_shipped:
        return None
    shipped = shipped_classes(dialect).get(key)
    if shipped is None:
        return None
    if shipped != item.ros_message_name:
        raise ClassClash(
            f"{item.interface.full_name} would become {item.cs_class.full_name}, "
            f"a class ROS# already ships for {shipped}",
            with_shipped=True,
        )
    return f"ROS# ships {item.cs_class.full_name}"


def _check_unique(items: list[ClassEntry]) -> None:
    seen: dict[CsClass, ClassEntry] = {}
    for item in items:
        other = seen.setdefault(item.cs_class, item)
        if other is not item:
            both = f"{other.interface.full_name} and {item.interface.full_name}"
            raise ClassClash(
                f"{both} would both become C# class {item.cs_class.full_name}",
                with_shipped=False,
            )


def collect_classes(
    registry: Registry,
    roots: list[Interface],
    dialect: Dialect,
    include_shipped: bool,
    namespace: str | None,
) -> ClassSet:
    if namespace is not None:
        validate_namespace(namespace)
    extra = _WRAPPER_DEPENDENCIES[dialect] if namespace is None else ()
    items: list[ClassEntry] = []
    for unit in _units(registry, roots, extra):
        items += _classes_of(unit, namespace or ROSSHARP_ROOT_NAMESPACE)
    _check_unique(items)
    if namespace is None:
        reasons = [_skip_reason(i, dialect, include_shipped) for i in items]
        # a new entry only for a class that is skipped: most are generated
        items = [
            i if reason is None else replace(i, skip_reason=reason)
            for i, reason in zip(items, reasons, strict=True)
        ]
    return ClassSet(dialect, namespace or ROSSHARP_ROOT_NAMESPACE, namespace is not None, items)
