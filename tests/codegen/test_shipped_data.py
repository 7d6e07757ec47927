"""The committed list of ROS#'s own message classes is exactly what its generator derives.

``unityscaffold/codegen/_shipped_data.py`` is written by ``scripts/update_shipped_classes.py``
from ROS#'s Unity package. This runs the script on a checkout of ROS# 2.2.1's
``com.siemens.ros-sharp`` (github.com/siemens/ros-sharp, tag 2.2.1), found through
``UNITYSCAFFOLD_ROSSHARP`` or beside the repository where CI puts it, and compares its output
with the committed module byte for byte.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from helpers import require, text_diff

REPO = Path(__file__).resolve().parents[2]
SCRIPT = REPO / "scripts" / "update_shipped_classes.py"
COMMITTED = REPO / "unityscaffold" / "codegen" / "_shipped_data.py"
VENDORED = REPO.parent / "shared" / "vendor" / "ros-sharp" / "2.2.1" / "com.siemens.ros-sharp"


def _checkout() -> Path:
    configured = os.environ.get("UNITYSCAFFOLD_ROSSHARP")
    path = Path(configured) if configured else VENDORED
    require(
        (path / "Runtime").is_dir(),
        f"ROS# 2.2.1's com.siemens.ros-sharp (set UNITYSCAFFOLD_ROSSHARP; default {VENDORED})",
    )
    return path


def test_shipped_data_is_what_the_script_derives_from_rossharp(tmp_path: Path) -> None:
    out = tmp_path / "_shipped_data.py"
    result = subprocess.run(
        [sys.executable, str(SCRIPT), str(_checkout()), "--output", str(out)],
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, result.stderr
    expected, actual = COMMITTED.read_bytes(), out.read_bytes()
    assert actual == expected, text_diff(expected, actual, "unityscaffold/codegen/_shipped_data.py")
