"""The committed table of ROS-TCP-Connector's own classes is exactly what its script derives.

``unityscaffold/codegen/rostcp/_shipped_data.py`` is written by ``scripts/update_tcp_shipped.py``
from the connector's Unity package (github.com/Unity-Technologies/ROS-TCP-Connector, tag
v0.7.0), found through ``UNITYSCAFFOLD_ROSTCP`` or beside the repository where CI puts it.
"""

from __future__ import annotations

import sys
from pathlib import Path

from processes import run

from tests.codegen.rostcp.tcp_helpers import PACKAGE_VARIABLE, connector_package
from unityscaffold.codegen.rostcp._shipped_data import CLASSES, FIELDS

REPO = Path(__file__).resolve().parents[3]
SCRIPT = REPO / "scripts" / "update_tcp_shipped.py"


def test_shipped_table_is_what_the_script_derives_from_the_connector() -> None:
    done = run([sys.executable, str(SCRIPT), str(connector_package()), "--check"], timeout=300)
    assert done.returncode == 0, done.stderr + f" (package from {PACKAGE_VARIABLE})"


def test_the_table_knows_the_hand_written_classes_per_ros_version() -> None:
    assert CLASSES[1]["BuiltinInterfaces/TimeMsg"] == ("std_msgs/Time", "Default")
    assert CLASSES[2]["BuiltinInterfaces/TimeMsg"] == ("builtin_interfaces/Time", "Default")
    assert FIELDS[1]["Std/HeaderMsg"] == ("seq:uint", "stamp:std_msgs/Time", "frame_id:string")
    assert FIELDS[2]["Std/HeaderMsg"] == ("stamp:builtin_interfaces/Time", "frame_id:string")
    assert FIELDS[2]["Sensor/CameraInfoMsg"][4] == "d:double[]"
    assert FIELDS[1]["Sensor/CameraInfoMsg"][5] == "K:double[9]"
