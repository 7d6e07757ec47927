"""What both runtimes' script views share: an entry's names, and an action's six classes."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, TypedDict

from unityscaffold.codegen import ClassRole, GeneratedCode
from unityscaffold.interfaces.model import Interface
from unityscaffold.manifest.model import Action, Manifest, Service, Topic

if TYPE_CHECKING:  # the views themselves load with the first script (see _target_rossharp)
    from unityscaffold.codegen.scripts import Script

__all__ = ["ScriptNames", "action_script", "script_names"]


class ScriptNames(TypedDict):
    """The names every topic's and service's script view takes (as keyword arguments)."""

    class_name: str
    ros_type: str
    manifest: str


def script_names(manifest: Manifest, item: Topic | Service, spec: Interface) -> ScriptNames:
    """``item``'s class name, its ROS type and the manifest's file name."""
    return ScriptNames(
        class_name=item.class_name, ros_type=spec.full_name, manifest=manifest.path.name
    )


def action_script(
    kind: Callable[..., Script],
    manifest: Manifest,
    item: Action,
    spec: Interface,
    messages: GeneratedCode,
    **extra: object,
) -> Script:
    """``kind``'s view of ``item`` (``extra`` for what only one runtime's scripts take)."""
    ros_type = f"{spec.package}/action/{spec.name}"
    classes = messages.classes[ros_type]
    return kind(
        class_name=item.class_name,
        ros_type=ros_type,
        manifest=manifest.path.name,
        action=item.name,
        goal_type=classes[ClassRole.GOAL].qualified,
        result_type=classes[ClassRole.RESULT].qualified,
        feedback_type=classes[ClassRole.FEEDBACK].qualified,
        action_goal_type=classes[ClassRole.ACTION_GOAL].qualified,
        action_result_type=classes[ClassRole.ACTION_RESULT].qualified,
        action_feedback_type=classes[ClassRole.ACTION_FEEDBACK].qualified,
        **extra,
    )
