"""A robot entry whose GameObject is already in the scene, and not as apply made it.

The common case is a team moving to this tool with a robot imported by hand through ROS#'s
editor window: a second root of the same name would make every later ``@r2d2/...`` path
ambiguous, so the entry is refused, saying what is there, before anything is written.
"""

from __future__ import annotations

from collections.abc import Mapping

from unityscaffold.apply._robot_plan import PlannedRobot
from unityscaffold.errors import LocatedError
from unityscaffold.unity import SceneDocument
from unityscaffold.unity.setvalue import component_label

__all__ = ["refuse_foreign_robot"]


def refuse_foreign_robot(
    doc: SceneDocument,
    robot: PlannedRobot,
    parent: int | None,
    ours: int,
    script_names: Mapping[str, str],
) -> None:
    """Refuse ``robot`` when a GameObject other than ``ours`` (the fileID apply gives the
    robot's root, which an earlier apply made) has its name under ``parent`` (a GameObject's
    fileID; None: the scene's roots)."""
    name = robot.gameobject.rpartition("/")[2]
    found = [i for i in doc.hierarchy.children_named(parent, name) if i != ours]
    if not found:
        return
    go = doc.gameobject(found[0])
    where = robot.entry.locations.of("gameobject")
    scene = robot.entry.scene
    if go.is_prefab_instance:
        raise LocatedError.at(
            where,
            f"{scene} already has '{go.path}', an instance of a prefab, where this robot goes",
            hint="apply imports a robot as GameObjects of the scene itself: delete or rename "
            "the instance in Unity, or give this entry another `gameobject`",
        )
    kinds = [component_label(c, script_names) for c in doc.components_of(go)]
    if "UrdfRobot" in kinds:
        raise LocatedError.at(
            where,
            f"{scene} already has a GameObject '{go.path}' with a UrdfRobot component, "
            "imported by hand (apply did not make it)",
            hint="apply does not take over a robot imported in Unity's editor: delete it in "
            "Unity and apply again to import it from the URDF, or give this entry another "
            "`gameobject` to import a second one",
        )
    raise LocatedError.at(
        where,
        f"{scene} already has a GameObject '{go.path}' ({', '.join(kinds)}), which is not a "
        "robot, where this robot goes",
        hint="rename or move that GameObject in Unity, or give this entry another `gameobject`",
    )
