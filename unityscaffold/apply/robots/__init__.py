"""The manifest's ``robots:`` section in apply: each robot's URDF imported as ROS#'s importer
would (the ``urdf`` stage), its asset files planned, and its objects written into its scene.

- ``_plan``: the file half, one import per robot per plan and the asset files it makes;
- ``_place``: the scene half, the imported objects written by fileIDs kept in the lock;
- ``_models``: a mesh geometry's prefab or model instance;
- ``_adopt``: a robot imported by hand through ROS#'s editor window, taken over;
- ``_owned`` and ``_fields``: the fields the import enforces (kept as ``_editor.RobotFields``,
  which the scene's editor carries), and the ``objects:`` and ``components:`` entries refused
  for setting one.

The package sits above ``apply``'s scene plumbing (``_context``, ``_editor``, ``_lock``) and
below the modules that plan a scene and the project (``_objects``, ``_attach``, ``_scenes``,
``plan``), which use only the names below.
"""

from unityscaffold.apply.robots._fields import refuse_owned_fields
from unityscaffold.apply.robots._place import (
    place_robots,
    refuse_reshaped_robot_objects,
    remove_kept,
)
from unityscaffold.apply.robots._plan import PlannedRobot, plan_robots

__all__ = [
    "PlannedRobot",
    "place_robots",
    "plan_robots",
    "refuse_owned_fields",
    "refuse_reshaped_robot_objects",
    "remove_kept",
]
