"""The set of connector classes one ``generate`` call makes: names, paths, registrations, and
which ones the connector already ships."""

from __future__ import annotations

from dataclasses import dataclass

from unityscaffold.codegen._classes import _units, unit_key
from unityscaffold.codegen.naming import (
    ClassClash,
    CsClass,
    check_class_name,
    class_name,
    namespace_segment,
    validate_namespace,
)
from unityscaffold.codegen.roles import ACTION_ROLES, CLASS_SUFFIX, ClassRole
from unityscaffold.codegen.rostcp._shipped import ROOT_NAMESPACE, ShippedClass, shipped_classes
from unityscaffold.errors import LocatedError, SourceLocation, UserError, located_at
from unityscaffold.interfaces.model import ActionSpec, Dialect, Interface, MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry
from unityscaffold.interfaces.sources import package_name_location

__all__ = ["TcpClass", "collect_classes"]

# What the generic action bases of the connector hold (ROS 1 actions only).
_WRAPPER_DEPENDENCIES = ("std_msgs/Header", "actionlib_msgs/GoalID", "actionlib_msgs/GoalStatus")
_TIME_CLASSES = {
    "time": CsClass(f"{ROOT_NAMESPACE}.BuiltinInterfaces", "TimeMsg"),
    "duration": CsClass(f"{ROOT_NAMESPACE}.BuiltinInterfaces", "DurationMsg"),
}


@dataclass(frozen=True, slots=True)
class TcpClass:
    """One class: its unit and role, name, ROS registration, file, and the shipped class that
    stands in for it (then it is not generated)."""

    interface: Interface
    role: ClassRole
    spec: MessageSpec | None
    cs_class: CsClass
    ros_name: str
    subtopic: str
    path: str
    identity_of: Interface
    shipped: ShippedClass | None = None


def _segment(unit: Interface) -> str:
    try:
        return namespace_segment(unit.package)
    except UserError as error:
        where = package_name_location(unit.source, unit.package)
        raise LocatedError.at(where, error.message, hint=error.hint) from None


def _parts(unit: Interface) -> list[tuple[ClassRole, MessageSpec | None, Interface]]:
    """(role, the message it holds, what its identity line describes) per class of ``unit``."""
    if isinstance(unit, MessageSpec):
        return [(ClassRole.MESSAGE, unit, unit)]
    if isinstance(unit, ServiceSpec):
        return [
            (ClassRole.REQUEST, unit.request, unit.request),
            (ClassRole.RESPONSE, unit.response, unit.response),
        ]
    held = {
        ClassRole.GOAL: unit.goal,
        ClassRole.RESULT: unit.result,
        ClassRole.FEEDBACK: unit.feedback,
    }
    derived = {d.name[len(unit.name) :]: d for d in unit.derived}
    return [
        (role, held.get(role), held.get(role) or derived.get(CLASS_SUFFIX[role]) or unit)
        for role in ACTION_ROLES
    ]


def _classes_of(unit: Interface, root: str, dialect: Dialect) -> list[TcpClass]:
    segment = _segment(unit)
    try:
        base = class_name(unit.name)
    except UserError:
        with located_at(SourceLocation(unit.source or unit.full_name)):
            raise
    shipped = shipped_classes(dialect)
    items = []
    for role, spec, identity in _parts(unit):
        suffix = "Msg" if role is ClassRole.MESSAGE else CLASS_SUFFIX[role]
        name = base + suffix
        with located_at(SourceLocation(unit.source or unit.full_name)):
            check_class_name(name)
        plain = role in (ClassRole.MESSAGE, ClassRole.REQUEST, ClassRole.RESPONSE)
        ros_name = f"{unit.package}/{unit.name}" + ("" if plain else CLASS_SUFFIX[role])
        definition = f"{unit.package}/{unit.name}" + (
            "" if role is ClassRole.MESSAGE else CLASS_SUFFIX[role]
        )
        found = shipped.get(definition)
        cls = found.cs_class if found else CsClass(f"{root}.{segment}", name)
        folder = unit.kind.value
        subtopic = "Response" if role is ClassRole.RESPONSE else "Default"
        path = f"{cls.namespace.rsplit('.', 1)[-1]}/{folder}/{cls.name}.cs"
        items.append(TcpClass(unit, role, spec, cls, ros_name, subtopic, path, identity, found))
    return items


def _refuse_ros2_actions(units: list[Interface]) -> None:
    for unit in units:
        if isinstance(unit, ActionSpec) and unit.dialect is Dialect.ROS2:
            raise UserError(
                f"{unit.full_name} is a ROS 2 action, which ROS-TCP-Connector cannot carry",
                hint="its ROS 2 endpoint (ROS-TCP-Endpoint ROS2v0.7.0) resolves only "
                "pkg.msg and pkg.srv types and has no action support; use ROS# "
                "(runtime: ros-sharp) for ROS 2 actions, or services and topics",
            )


def _check_unique(items: list[TcpClass], dialect: Dialect, custom_root: bool) -> None:
    """No generated class named like a shipped one, no two classes for one registration."""
    shipped = shipped_classes(dialect)
    registered = {(s.ros_name, s.subtopic): s.cs_class for s in shipped.values()}
    names = {s.cs_class: definition for definition, s in shipped.items()}
    for item in items:
        if item.shipped is not None:
            continue
        if not custom_root and item.cs_class in names:
            raise ClassClash(
                f"{item.interface.full_name} would become {item.cs_class.full_name}, a class "
                f"ROS-TCP-Connector already ships for {names[item.cs_class]}",
                with_shipped=True,
            )
        key = (item.ros_name, item.subtopic)
        other = registered.setdefault(key, item.cs_class)
        if other != item.cs_class:
            raise UserError(
                f"{item.cs_class.full_name} and {other.full_name} would both register as "
                f"{item.ros_name} ({item.subtopic})",
                hint="ROS-TCP-Connector decodes by ROS name, one class per name: rename one "
                "of the types",
            )
        names[item.cs_class] = item.ros_name


def collect_classes(
    registry: Registry,
    roots: list[Interface],
    dialect: Dialect,
    include_shipped: bool,
    namespace: str | None,
) -> list[TcpClass]:
    """Every class ``roots`` need, generated or shipped; raises UserError on bad input."""
    if include_shipped:
        raise UserError(
            "ROS-TCP-Connector's own message classes cannot be generated again",
            hint="it decodes by ROS name with one class per name, so a second class for a "
            "name it ships would race its own; leave include_shipped off",
        )
    root = validate_namespace(namespace) if namespace is not None else ROOT_NAMESPACE
    _refuse_ros2_actions(roots)
    extra = _WRAPPER_DEPENDENCIES if dialect is Dialect.ROS1 else ()
    units = _units(registry, roots, extra)
    _refuse_ros2_actions(units)
    items = [item for unit in units for item in _classes_of(unit, root, dialect)]
    _check_unique(items, dialect, namespace is not None)
    return items


def class_resolver(items: list[TcpClass]) -> dict[str, CsClass]:
    """Message full name (as field types spell it) -> its class, ROS 1 time and duration
    included; derived ROS 1 action messages map to their wrapper classes."""
    by_ros: dict[str, CsClass] = dict(_TIME_CLASSES)
    roles: dict[tuple[str, ClassRole], CsClass] = {}
    for item in items:
        roles[(unit_key(item.interface), item.role)] = item.cs_class
        if item.spec is not None:
            by_ros[item.spec.full_name] = item.cs_class
    for item in items:
        if isinstance(item.interface, ActionSpec) and item.role is ClassRole.ACTION:
            for derived in item.interface.derived:
                suffix = derived.name[len(item.interface.name) :]
                role = next(r for r in ACTION_ROLES if CLASS_SUFFIX[r] == suffix)
                by_ros[derived.full_name] = roles[(unit_key(item.interface), role)]
    return by_ros
