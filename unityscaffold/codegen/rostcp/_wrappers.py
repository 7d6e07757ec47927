"""Views of a ROS 1 action's wrapper classes and its ``XAction`` class, on the connector's
hand-written generic bases (``ActionGoal<T>``, ``ActionResult<T>``, ``ActionFeedback<T>``,
``Action<…>``). Unlike the connector's shipped wrappers, ours register themselves, so a topic
of ``XActionGoal`` can be subscribed like any other."""

from __future__ import annotations

from unityscaffold.codegen import _literals
from unityscaffold.codegen.naming import CsClass
from unityscaffold.codegen.roles import ClassRole
from unityscaffold.codegen.rostcp._shipped import ROOT_NAMESPACE
from unityscaffold.codegen.rostcp._views import RUNTIME, ActionView, Header, WrapperView

__all__ = ["build_action", "build_wrapper"]

_HEADER = CsClass(f"{ROOT_NAMESPACE}.Std", "HeaderMsg").qualified
_GOAL_ID = CsClass(f"{ROOT_NAMESPACE}.Actionlib", "GoalIDMsg").qualified
_STATUS = CsClass(f"{ROOT_NAMESPACE}.Actionlib", "GoalStatusMsg").qualified
_WRAPPERS = {
    ClassRole.ACTION_GOAL: ("ActionGoal", ClassRole.GOAL, "goal", (("goal_id", _GOAL_ID),)),
    ClassRole.ACTION_RESULT: ("ActionResult", ClassRole.RESULT, "result", (("status", _STATUS),)),
    ClassRole.ACTION_FEEDBACK: (
        "ActionFeedback",
        ClassRole.FEEDBACK,
        "feedback",
        (("status", _STATUS),),
    ),
}


def build_wrapper(
    header: Header, role: ClassRole, classes: dict[ClassRole, CsClass], ros_name: str
) -> WrapperView:
    base, part_role, part_name, inherited = _WRAPPERS[role]
    part = classes[part_role].qualified
    return WrapperView(
        header=header,
        class_name=classes[role].name,
        base=f"{RUNTIME}.{base}<{part}>",
        ros_name=_literals.string_literal(ros_name),
        inherited=(("header", _HEADER), *inherited),
        part_name=part_name,
        part_class=part,
    )


def build_action(header: Header, classes: dict[ClassRole, CsClass], ros_name: str) -> ActionView:
    wrappers = (ClassRole.ACTION_GOAL, ClassRole.ACTION_RESULT, ClassRole.ACTION_FEEDBACK)
    parts = (ClassRole.GOAL, ClassRole.RESULT, ClassRole.FEEDBACK)
    arguments = ", ".join(classes[r].qualified for r in (*wrappers, *parts))
    return ActionView(
        header=header,
        class_name=classes[ClassRole.ACTION].name,
        base=f"{RUNTIME}.Action<{arguments}>",
        ros_name=_literals.string_literal(ros_name),
        parts=tuple(
            (name, classes[role].qualified)
            for name, role in zip(
                ("action_goal", "action_result", "action_feedback"), wrappers, strict=True
            )
        ),
    )
