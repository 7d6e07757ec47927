"""The commented ``robot.yaml`` that ``scaffold init`` writes into a new project."""

from __future__ import annotations

import string

from unityscaffold.errors import UserError
from unityscaffold.manifest.model import MANIFEST_VERSION
from unityscaffold.manifest.runtime import Runtime

__all__ = ["starter_manifest"]

_TEMPLATE = string.Template("""\
${modeline}# unityscaffold manifest: run `scaffold apply robot.yaml` after editing.
# Every key is described in unityscaffold's docs/manifest.md and by `scaffold schema`.
version: ${version}
ros: ${ros}                 # ROS version of the robot: 1 or 2
${runtime}project: .              # the Unity project root, relative to this file
output: Assets/RosGenerated
scene: ${scene}

# Extra folders with .msg/.srv/.action files (relative to this file):
# interfaces:
#   - ../robot_ws/src

${connector}
topics:
#  - {name: /cmd_vel, type: geometry_msgs/Twist, direction: publish, rate: 10}
${topic_example}
# Each entry: name, type, role (client: Unity calls it; server: Unity provides it).
services:
#  - {name: /reset, type: std_srvs/Trigger, role: client}

${actions}
# Existing MonoBehaviours (yours, ${packages} or uGUI's) with field values; "@Path/To/Object"
# refers to a GameObject in the same scene. Add `id:` to have two of one script on one object.
components:
${component_example}

# GameObjects created if missing and kept as written: position, rotation (Euler degrees),
# scale, active, tag, layer, ui (RectTransform), primitive (cube, sphere, capsule, cylinder,
# plane, quad: as Unity's GameObject > 3D Object menu makes it) and built-in components
# (Camera, Light, Rigidbody, Box/Sphere/Capsule/MeshCollider, MeshFilter, MeshRenderer,
# Canvas, CanvasRenderer, AudioListener).
objects:
#  - path: Robot/base_link
#    position: [0, 0.1, 0]
#    rotation: [0, 90, 0]
#    components: [Rigidbody, {type: BoxCollider, fields: {m_Size: [0.5, 0.2, 0.8]}}]
#  - path: Robot/base_link/Screen
#    primitive: plane
#    components: [{type: MeshRenderer, fields: {m_Materials: [Default-Material]}}]

# Robots imported from their URDF as ROS#'s importer does it (links, joints, colliders,
# materials), kept as the URDF says; `objects` and `components` can then add to the links.
robots:
#  - urdf: ros/my_robot.urdf
#    packages: {my_robot_description: ros/my_robot_description}
#    position: [0, 0.5, 0]
#    kinematic: true
#    gravity: false
""")


# ROS 1's definitions built into unityscaffold include a robot's action (move_base_msgs); ROS 2's
# standard interfaces have none, so its example is the tutorials' Fibonacci (built in from
# test_msgs), and a robot's own action needs its package in `interfaces`.
_ACTIONS = {
    1: """\
# Each entry: name, type (pkg/action/Name), role (client: Unity sends goals; server: Unity
# carries them out), gameobject, scene.
actions:
#  - {name: /move_base, type: move_base_msgs/action/MoveBase, role: client}
""",
    2: """\
# Each entry: name, type (pkg/action/Name), role (client: Unity sends goals; server: Unity
# carries them out), gameobject, scene. A robot's action needs its package in `interfaces`,
# e.g. for {name: /navigate_to_pose, type: nav2_msgs/action/NavigateToPose, role: client}.
actions:
#  - {name: /fibonacci, type: test_msgs/action/Fibonacci, role: client}
""",
}


_CONNECTOR = {
    Runtime.ROS_SHARP: """\
connector:              # ROS#'s RosConnector, created if missing
  gameobject: RosConnector
  url: ws://localhost:9090
  timeout: 10           # seconds
  serializer: microsoft # or newtonsoft
  protocol: websocket-sharp  # or websocket-net

# Each entry: name, type, direction (publish: Unity sends; subscribe: Unity receives),
# optional rate (Hz, publish), throttle (ms) and queue (subscribe), gameobject, scene.""",
    Runtime.TCP_CONNECTOR: """\
connector:              # ROS-TCP-Connector's ROSConnection, created if missing
  gameobject: ROSConnection
  host: 127.0.0.1       # where ROS-TCP-Endpoint runs (ros_tcp_endpoint's tcp_ip)
  port: 10000
  show_hud: true

# Each entry: name, type, direction (publish: Unity sends; subscribe: Unity receives),
# optional rate (Hz), queue (the ROS publisher's queue size) and latch (publish),
# gameobject, scene.""",
}
_TOPIC_EXAMPLE = {
    Runtime.ROS_SHARP: """\
#  - {name: /odom, type: nav_msgs/Odometry, direction: subscribe, throttle: 100,
#    gameobject: Robot/base_link}
""",
    Runtime.TCP_CONNECTOR: """\
#  - {name: /odom, type: nav_msgs/Odometry, direction: subscribe, gameobject: Robot/base_link}
""",
}
_COMPONENT_EXAMPLE = {
    Runtime.ROS_SHARP: """\
#  - script: TwistSubscriber
#    gameobject: RosConnector
#    fields: {Topic: /cmd_vel_unity, SubscribedTransform: "@Robot/base_link"}""",
    Runtime.TCP_CONNECTOR: """\
#  - script: Assets/Scripts/Lidar.cs
#    gameobject: Robot/base_link
#    fields: {Range: 12.5, Target: "@Robot/Target"}""",
}
_NO_ACTIONS = """\
# ROS 2 actions cannot pass through ROS-TCP-Endpoint (it carries messages and services
# only); use runtime: ros-sharp for them.
"""


def starter_manifest(
    ros: int, scene: str, *, schema: str | None = None, runtime: Runtime = Runtime.ROS_SHARP
) -> str:
    """A small, valid, commented manifest for a robot on ROS ``ros`` with one ``scene``.

    ``scene`` is the project-relative scene file, e.g. ``Assets/Scenes/Main.unity``. With
    ``schema`` (a URL or a path relative to the manifest) the first line tells editors running
    the YAML language server where ``robot.schema.json`` is.
    """
    if ros not in (1, 2):
        raise UserError(f"unknown ROS version ${ros}", hint="choose 1 or 2")
    if not scene.endswith(".unity") or any(c in scene for c in "\n#:\"'"):
        raise UserError(
            f"invalid scene path '${scene}'",
            hint="give a project-relative .unity file, e.g. Assets/Scenes/Main.unity",
        )
    modeline = (
        f"# yaml-language-server: $schema={schema}\n"
        f"# ({schema} lets editors check this file; after upgrading unityscaffold refresh it\n"
        f"# with `scaffold schema -o {schema}`.)\n"
        if schema
        else ""
    )
    tcp = runtime is Runtime.TCP_CONNECTOR
    return _TEMPLATE.substitute(
        version=MANIFEST_VERSION,
        ros=ros,
        runtime=f"runtime: {runtime.value}  # or ros-sharp\n" if tcp else "",
        scene=scene,
        modeline=modeline,
        connector=_CONNECTOR[runtime],
        topic_example=_TOPIC_EXAMPLE[runtime],
        component_example=_COMPONENT_EXAMPLE[runtime],
        packages="a package's" if tcp else "ROS#'s",
        actions=_NO_ACTIONS if tcp and ros == 2 else _ACTIONS[ros],
    )
