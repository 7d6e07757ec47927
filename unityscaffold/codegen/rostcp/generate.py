"""Interfaces -> C# classes for ROS-TCP-Connector: pure, no writing."""

from __future__ import annotations

from collections.abc import Iterable

from unityscaffold.codegen._classes import source_name, unit_key
from unityscaffold.codegen._identity import Identities
from unityscaffold.codegen.generate import GeneratedCode, GeneratedFile, Options, SkippedClass
from unityscaffold.codegen.naming import CsClass
from unityscaffold.codegen.roles import ClassRole
from unityscaffold.codegen.rostcp._build import MessageContext, build_message
from unityscaffold.codegen.rostcp._classes import TcpClass, class_resolver, collect_classes
from unityscaffold.codegen.rostcp._stale import stale_warnings
from unityscaffold.codegen.rostcp._views import RUNTIME, Header, View
from unityscaffold.codegen.rostcp._wrappers import build_action, build_wrapper
from unityscaffold.errors import LocatedError, SourceLocation
from unityscaffold.interfaces.model import Dialect, Interface
from unityscaffold.interfaces.registry import Registry
from unityscaffold.resources import template_environment

__all__ = ["generate"]


def _render(view: View) -> str:
    return template_environment().get_template(view.template).render(view=view)


def _view(
    item: TcpClass, ctx: MessageContext, ids: Identities, roles: dict[ClassRole, CsClass]
) -> View:
    define = "ROS2" if ctx.dialect is Dialect.ROS2 else "!ROS2"
    header = Header(
        source_name(item.interface), ids.label(item.identity_of), define, item.cs_class.namespace
    )
    if item.spec is not None:
        register = f", {RUNTIME}.MessageSubtopic.Response" if item.subtopic == "Response" else ""
        provenance = (header.source, header.identity)
        return build_message(ctx, item.spec, item.cs_class, item.ros_name, register, provenance)
    if item.role is ClassRole.ACTION:
        return build_action(header, roles, item.ros_name)
    return build_wrapper(header, item.role, roles, item.ros_name)


def _class_map(
    items: list[TcpClass], by_ros: dict[str, CsClass]
) -> dict[str, dict[ClassRole, CsClass]]:
    result: dict[str, dict[ClassRole, CsClass]] = {}
    for item in items:
        result.setdefault(unit_key(item.interface), {})[item.role] = item.cs_class
    for name in sorted(by_ros):
        if "/" in name:
            result.setdefault(name, {ClassRole.MESSAGE: by_ros[name]})
    return dict(sorted(result.items()))


def generate(registry: Registry, roots: Iterable[Interface], options: Options) -> GeneratedCode:
    """Connector classes for ``roots`` and every type they use; raises ``UserError`` on bad
    input (a ROS 2 action, ``include_shipped``, a clash) and writes nothing."""
    items = collect_classes(
        registry, list(roots), options.dialect, options.include_shipped, options.namespace
    )
    by_ros = class_resolver(items)

    def class_of(name: str, used_at: SourceLocation | None) -> CsClass:
        try:
            return by_ros[name]
        except KeyError:
            where = used_at or SourceLocation(name)
            raise LocatedError.at(where, f"no C# class for {name}") from None

    ctx = MessageContext(options.dialect, class_of)
    ids = Identities(registry, options.dialect)
    roles: dict[str, dict[ClassRole, CsClass]] = {}
    for item in items:
        roles.setdefault(unit_key(item.interface), {})[item.role] = item.cs_class
    warnings, defaults = stale_warnings(items, options.dialect, ids)
    files, skipped = [], []
    for item in items:
        role_map = roles[unit_key(item.interface)]
        if item.shipped is None:
            text = _render(_view(item, ctx, ids, role_map))
            full_name = item.interface.full_name
            files.append(GeneratedFile(item.path, text, full_name, item.role, item.cs_class))
            continue
        reason = f"ROS-TCP-Connector ships {item.cs_class.full_name}"
        name = item.cs_class.full_name
        skipped.append(
            SkippedClass(
                item.path,
                item.interface.full_name,
                item.role,
                item.cs_class,
                reason,
                warnings.get(name),
                defaults.get(name),
            )
        )
    return GeneratedCode(
        tuple(sorted(files, key=lambda f: f.path)),
        tuple(sorted(skipped, key=lambda s: s.path)),
        _class_map(items, by_ros),
    )
