"""Interfaces -> generated C# files for ROS#: pure, no writing.

``generate(registry, roots, options)`` takes the types asked for, adds their whole dependency
closure, decides for every class whether ROS# already ships it, and renders the rest.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

from unityscaffold.codegen._actions import build_action, build_wrapper
from unityscaffold.codegen._build import FileContext, build_message
from unityscaffold.codegen._classes import ClassEntry, ClassSet, collect_classes, source_name
from unityscaffold.codegen._identity import Identities
from unityscaffold.codegen._shipped import shipped_fields
from unityscaffold.codegen._views import View
from unityscaffold.codegen.naming import CsClass
from unityscaffold.codegen.roles import MESSAGE_ROLES, ClassRole
from unityscaffold.interfaces.model import Dialect, Interface
from unityscaffold.interfaces.registry import Registry
from unityscaffold.resources import template_environment

__all__ = ["GeneratedCode", "GeneratedFile", "Options", "SkippedClass", "generate"]


@dataclass(frozen=True, slots=True)
class Options:
    """How to generate: the ROS version, and the ROS#-shipped/namespace policy.

    ``namespace`` replaces ROS#'s root ``RosSharp.RosBridgeClient.MessageTypes``; then every
    type is generated (nothing can clash with ROS#'s classes).
    """

    dialect: Dialect
    include_shipped: bool = False
    namespace: str | None = None


@dataclass(frozen=True, slots=True)
class GeneratedFile:
    """One C# file: ``path`` is relative to the output folder (``Geometry/msg/Pose.cs``)."""

    path: str
    text: str
    ros_type: str
    role: ClassRole
    cs_class: CsClass


@dataclass(frozen=True, slots=True)
class SkippedClass:
    """A class not generated, and why (ROS# ships it, or hand-writes it)."""

    path: str
    ros_type: str
    role: ClassRole
    cs_class: CsClass
    reason: str
    #: Set when the class ROS# ships has other fields than this definition: messages would
    #: lose or lack fields on the wire. Says how to generate ours instead.
    warning: str | None = None
    #: The message whose shipped class differs only in the values a new instance starts with
    #: (the warning's whole finding): that matters only where Unity constructs one to send.
    default_of: str | None = None


@dataclass(frozen=True, slots=True)
class GeneratedCode:
    """What one run produces, and which C# class each ROS type maps to.

    ``classes`` maps ``pkg/msg/Name``, ``pkg/srv/Name`` and ``pkg/action/Name`` (both ROS
    versions) to their classes by ``ClassRole``. Every message full name as field types spell
    it (ROS 1 ``pkg/Name``, ``pkg/NameRequest``; ROS 2 ``pkg/srv/Name_Request``…) maps to
    ``{ClassRole.MESSAGE: class}`` too, shipped and skipped types included.
    """

    files: tuple[GeneratedFile, ...]
    skipped: tuple[SkippedClass, ...]
    classes: dict[str, dict[ClassRole, CsClass]] = field(default_factory=dict)

    def message_class(self, name: str) -> CsClass:
        """The class of a message type (as users or field types name it)."""
        return self.classes[name][ClassRole.MESSAGE]


def _render(view: View) -> str:
    return template_environment().get_template(view.template).render(view=view)


def _view(class_set: ClassSet, ctx: FileContext, ids: Identities, item: ClassEntry) -> View:
    source = source_name(item.interface)
    if item.role in MESSAGE_ROLES:
        assert item.spec is not None
        return build_message(
            ctx,
            item.spec,
            item.cs_class,
            item.ros_message_name,
            source,
            ids.label(item.identity_of),
        )
    classes = class_set.action_classes(item.interface)
    if item.role is ClassRole.ACTION:
        identity = ids.label(item.identity_of)
        return build_action(ctx, classes, item.ros_message_name, source, identity)
    return build_wrapper(
        ctx,
        classes,
        item.role,
        class_set.runtime,
        item.ros_message_name,
        source,
        ids.label(item.identity_of),
    )


def _differs_from_shipped(item: ClassEntry, dialect: Dialect, ids: Identities) -> str | None:
    """A warning when ROS#'s class for ``item`` declares other fields than its definition."""
    if item.spec is None or not item.skip_reason or not item.skip_reason.startswith("ROS# ships"):
        return None
    key = (item.cs_class.namespace.rsplit(".", 1)[-1], item.cs_class.name)
    theirs = shipped_fields(dialect).get(key, ())
    ours = tuple(f.name for f in item.spec.fields)
    if not theirs or theirs == ours:
        return None
    missing = [n for n in ours if n not in theirs]
    extra = [n for n in theirs if n not in ours]
    parts = [f"lacks {', '.join(missing)}"] if missing else []
    parts += [f"has {', '.join(extra)}, which this definition does not"] if extra else []
    if not parts:
        parts = ["declares the same fields in another order"]
    return (
        f"ROS#'s {item.cs_class.full_name} does not match {item.ros_message_name} as defined "
        f"here ({ids.label(item.identity_of)}): it {'; '.join(parts)}; to generate ours "
        "instead, set a `namespace:` of your own in the manifest (msgs gen --namespace)"
    )


def generate(registry: Registry, roots: Iterable[Interface], options: Options) -> GeneratedCode:
    """C# for ``roots`` and every type they use; raises ``UserError`` on bad input."""
    class_set = collect_classes(
        registry, list(roots), options.dialect, options.include_shipped, options.namespace
    )
    ctx = class_set.file_context()
    ids = Identities(registry, options.dialect)
    files: list[GeneratedFile] = []
    for item in class_set.generated:
        text = _render(_view(class_set, ctx, ids, item))
        files.append(
            GeneratedFile(item.path, text, item.interface.full_name, item.role, item.cs_class)
        )
    skipped = [
        SkippedClass(
            i.path,
            i.interface.full_name,
            i.role,
            i.cs_class,
            i.skip_reason or "",
            _differs_from_shipped(i, options.dialect, ids),
        )
        for i in class_set.skipped
    ]
    return GeneratedCode(
        tuple(sorted(files, key=lambda f: f.path)),
        tuple(sorted(skipped, key=lambda s: s.path)),
        class_set.class_map(),
    )
