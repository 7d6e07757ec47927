"""Fixtures for the URDF stage: the real files ROS#'s importer and Unity wrote.

They are read from the vendored snapshots beside the repository (``../shared/vendor``, or the
folder in ``UNITYSCAFFOLD_VENDOR``): ROS#'s r2d2 sample (the URDF and the scene Unity 2022.3
saved after ROS#'s importer built the robot from it) and Unity-Robotics-Hub's Niryo gripper
(STL files and the Mesh assets Unity wrote from them). Without them a test skips locally and
fails under CI=true.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import require
from robot_helpers import NIRYO, R2D2


@pytest.fixture(scope="session")
def r2d2_urdf() -> Path:
    path = R2D2 / "custom_r2d2.urdf"
    require(path.is_file(), f"ROS#'s r2d2 sample ({R2D2})")
    return path


@pytest.fixture(scope="session")
def r2d2_scene() -> Path:
    path = R2D2 / "Scenes" / "Completed" / "gazebo_simulation_scene_ROS2_1_Camera_COMPLETED.unity"
    require(path.is_file(), f"ROS#'s r2d2 sample scene ({R2D2})")
    return path


@pytest.fixture(scope="session")
def niryo() -> Path:
    require((NIRYO / "G1_Rod.STL").is_file(), f"the Niryo gripper's STL and Mesh assets ({NIRYO})")
    return NIRYO
