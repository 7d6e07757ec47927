"""Refresh the built-in interface definitions shipped with unityscaffold.

The built-in set lets the standard interfaces resolve on a machine with no ROS installed. It is
copied verbatim (definitions are data; their texts decide md5sums) from:
  ROS 1 Noetic: Debian's ros-*-msgs packages under /usr/share (see .ci/run for the list);
  ROS 2 Jazzy: the PyPI ros-jazzy-* interface wheels installed in this Python's prefix.
Run: python3 scripts/update_builtin.py, then review `git diff --stat`.
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TARGET = ROOT / "unityscaffold" / "interfaces" / "builtin"
ROS1_PACKAGES = (
    "actionlib_msgs diagnostic_msgs geometry_msgs map_msgs move_base_msgs nav_msgs pcl_msgs "
    "roscpp rosgraph_msgs sensor_msgs shape_msgs std_msgs std_srvs stereo_msgs tf2_msgs "
    "topic_tools trajectory_msgs visualization_msgs"
).split()
ROS2_EXCLUDED = {"test_msgs"}  # a grammar torture set, not something robots use
# ... except its Fibonacci action: no PyPI wheel brings a standard action package (Jazzy's
# example_interfaces, action_tutorials_interfaces and nav2_msgs have none), and the built-in
# set needs one action so that a fresh ROS 2 project can try `actions:`. It is the action of
# ROS 2's tutorials (example_interfaces/action/Fibonacci has the same three fields).
ROS2_FROM_EXCLUDED = {"test_msgs": ("action/Fibonacci.action",)}
# Jazzy's tf2_msgs has no PyPI wheel, and /tf needs its TFMessage. That file's text is the same
# in ROS 1 and ROS 2 (geometry2's tf2_msgs/msg/TFMessage.msg, one line), so it is copied from
# Debian's ROS 1 package. The package's other files differ between the two (TF2Error's
# constants were renamed in ROS 2) and are left out.
ROS2_FROM_ROS1 = {"tf2_msgs": ("msg/TFMessage.msg",)}


def copy_package(source: Path, target: Path) -> int:
    count = 0
    for kind in ("msg", "srv", "action"):
        files = sorted((source / kind).glob(f"*.{kind}")) if (source / kind).is_dir() else []
        for file in files:
            dest = target / kind / file.name
            dest.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(file, dest)
            count += 1
    return count


def main() -> int:
    for dialect in ("ros1", "ros2"):
        shutil.rmtree(TARGET / dialect, ignore_errors=True)
    total = 0
    for name in ROS1_PACKAGES:
        source = Path("/usr/share") / name
        if not source.is_dir():
            print(f"missing ROS 1 package {source}", file=sys.stderr)
            return 1
        total += copy_package(source, TARGET / "ros1" / name)
    share = Path(sys.prefix) / "share"
    for source in sorted(share.iterdir()):
        if source.name in ROS2_EXCLUDED or not (source / "package.xml").is_file():
            continue
        if any((source / kind).is_dir() for kind in ("msg", "srv", "action")):
            total += copy_package(source, TARGET / "ros2" / source.name)
    for package, files in ROS2_FROM_EXCLUDED.items():
        for relative in files:
            dest = TARGET / "ros2" / package / relative
            dest.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(share / package / relative, dest)
            total += 1
    for package, files in ROS2_FROM_ROS1.items():
        if (TARGET / "ros2" / package).exists():
            continue  # a wheel brought the package itself
        for relative in files:
            dest = TARGET / "ros2" / package / relative
            dest.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(Path("/usr/share") / package / relative, dest)
            total += 1
    print(f"copied {total} definition files into {TARGET}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
