"""Views of the four action classes ROS# builds on its generic bases.

ROS 1 (``ActionGoal<T>``: header, goal_id, goal; ``ActionResult<T>``/``ActionFeedback<T>``:
header, status, result/feedback) and ROS 2 as ROS# 2.2.1 models it (``ActionGoal<T>``: header,
goalInfo, args…; ``ActionResult<T>``: header, action, values, status, result, id;
``ActionFeedback<T>``: header, values, id, action). ROS#'s own ROS 2 feedback class passes
``(header, id, action)`` to a base constructor declared ``(header, action, id)``; these pass
the arguments in the declared order.
"""

from __future__ import annotations

from dataclasses import dataclass

from unityscaffold.codegen import _literals
from unityscaffold.codegen._build import FileContext
from unityscaffold.codegen._references import References
from unityscaffold.codegen._views import ActionView, ActionWrapperView, FileHeader
from unityscaffold.codegen.naming import CsClass
from unityscaffold.codegen.roles import WRAPPER_PAYLOAD, ClassRole
from unityscaffold.interfaces.model import Dialect

__all__ = ["ActionClasses", "RuntimeTypes", "build_action", "build_wrapper"]

_RUNTIME = "global::RosSharp.RosBridgeClient."


@dataclass(frozen=True, slots=True)
class RuntimeTypes:
    """The message classes ROS#'s action bases use (Header, GoalID/GoalStatus or GoalInfo)."""

    header: CsClass
    goal_id: CsClass | None = None
    goal_status: CsClass | None = None
    goal_info: CsClass | None = None


@dataclass(frozen=True, slots=True)
class ActionClasses:
    goal: CsClass
    result: CsClass
    feedback: CsClass
    action_goal: CsClass
    action_result: CsClass
    action_feedback: CsClass
    action: CsClass


# role -> (ROS#'s base class, payload member, runtime parameters (type key or C# type, name))
_Wrapper = tuple[str, str, tuple[tuple[str, str], ...]]
_WRAPPERS: dict[Dialect, dict[ClassRole, _Wrapper]] = {
    Dialect.ROS1: {
        ClassRole.ACTION_GOAL: (
            "ActionGoal",
            "goal",
            (("header", "header"), ("goal_id", "goal_id")),
        ),
        ClassRole.ACTION_RESULT: (
            "ActionResult",
            "result",
            (("header", "header"), ("goal_status", "status")),
        ),
        ClassRole.ACTION_FEEDBACK: (
            "ActionFeedback",
            "feedback",
            (("header", "header"), ("goal_status", "status")),
        ),
    },
    Dialect.ROS2: {
        ClassRole.ACTION_GOAL: (
            "ActionGoal",
            "args",
            (("header", "header"), ("goal_info", "goalInfo")),
        ),
        ClassRole.ACTION_RESULT: (
            "ActionResult",
            "values",
            (
                ("header", "header"),
                ("string", "action"),
                ("sbyte", "status"),
                ("bool", "result"),
                ("string", "id"),
            ),
        ),
        ClassRole.ACTION_FEEDBACK: (
            "ActionFeedback",
            "values",
            (("header", "header"), ("string", "action"), ("string", "id")),
        ),
    },
}


def _base(ctx: FileContext, name: str) -> str:
    return (_RUNTIME if ctx.qualify_runtime else "") + name


def build_wrapper(
    ctx: FileContext,
    classes: ActionClasses,
    role: ClassRole,
    runtime: RuntimeTypes,
    ros_name: str,
    source: str,
    identity: str,
) -> ActionWrapperView:
    cls: CsClass = getattr(classes, role.value)
    payload_cls: CsClass = getattr(classes, WRAPPER_PAYLOAD[role].value)
    base, payload, params = _WRAPPERS[ctx.dialect][role]
    runtime_classes: dict[str, CsClass] = {
        key: getattr(runtime, key) for key, _ in params if hasattr(runtime, key)
    }
    wanted = [(payload_cls, False), *((c, ctx.qualify_runtime) for c in runtime_classes.values())]
    refs = References(cls.namespace, ctx.known, wanted)
    typed = [
        (
            refs.name(runtime_classes[key], qualified=ctx.qualify_runtime)
            if key in runtime_classes
            else key,
            name,
        )
        for key, name in params
    ]
    payload_type = refs.name(payload_cls)
    parameters = [*(f"{t} {n}" for t, n in typed), f"{payload_type} {payload}"]
    return ActionWrapperView(
        header=FileHeader(source, identity, ctx.define, cls.namespace, refs.usings),
        class_name=cls.name,
        base=f"{_base(ctx, base)}<{payload_type}>",
        ros_name=_literals.string_literal(ros_name),
        doc=(),
        payload=payload,
        payload_type=payload_type,
        parameters=", ".join(parameters),
        base_arguments=", ".join(n for _, n in typed),
    )


def build_action(
    ctx: FileContext, classes: ActionClasses, ros_name: str, source: str, identity: str
) -> ActionView:
    cls = classes.action
    order = (
        classes.action_goal,
        classes.action_result,
        classes.action_feedback,
        classes.goal,
        classes.result,
        classes.feedback,
    )
    refs = References(cls.namespace, ctx.known, [(c, False) for c in order])
    names = [refs.name(c) for c in order]
    # The constructor's parameters are named after the ROS 1 Action message's fields.
    fields = ("action_goal", "action_result", "action_feedback")
    parts = tuple(zip(names[:3], fields, strict=True))
    return ActionView(
        header=FileHeader(source, identity, ctx.define, cls.namespace, refs.usings),
        class_name=cls.name,
        base=f"{_base(ctx, 'Action')}<{', '.join(names)}>",
        ros_name=_literals.string_literal(ros_name),
        doc=(),
        parts=parts,
        parameters=", ".join(f"{t} {n}" for t, n in parts),
        base_arguments=", ".join(n for _, n in parts),
    )
