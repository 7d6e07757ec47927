"""``runtime:`` and ROS-TCP-Connector's ``connector:`` keys read into the model."""

from __future__ import annotations

from pathlib import Path

from unityscaffold.manifest import parse_manifest
from unityscaffold.manifest.runtime import Runtime, TcpConnection


def test_a_manifest_without_runtime_targets_ros_sharp_with_no_connection_settings() -> None:
    m = parse_manifest("version: 1\nros: 1\nscene: Assets/M.unity\n", Path("robot.yaml"))
    assert m.runtime is Runtime.ROS_SHARP
    assert m.connector.tcp is None and m.connector.gameobject == "RosConnector"


def test_the_connector_runtime_reads_every_rosconnection_setting() -> None:
    text = """\
version: 1
ros: 1
runtime: ros-tcp-connector
scene: Assets/M.unity
connector: {host: robot.local, port: 10001, connect_on_start: false, keepalive: 2.5,
            network_timeout: 3, sleep: 0.02, show_hud: false, tf_topics: [/tf, /tf_static],
            listen_for_tf: false}
topics:
  - {name: /cmd_vel, type: geometry_msgs/Twist, direction: publish, queue: 1, latch: true}
"""
    m = parse_manifest(text, Path("robot.yaml"))
    assert m.runtime is Runtime.TCP_CONNECTOR
    assert m.connector.gameobject == "ROSConnection"
    assert m.connector.tcp == TcpConnection(
        host="robot.local",
        port=10001,
        connect_on_start=False,
        keepalive=2.5,
        network_timeout=3.0,
        sleep=0.02,
        show_hud=False,
        tf_topics=("/tf", "/tf_static"),
        listen_for_tf=False,
    )
    (topic,) = m.topics
    assert (topic.queue, topic.latch, topic.throttle) == (1, True, None)


def test_the_connector_runtime_defaults_are_rosconnections_own() -> None:
    text = "version: 1\nros: 2\nruntime: ros-tcp-connector\nscene: Assets/M.unity\n"
    assert parse_manifest(text, Path("robot.yaml")).connector.tcp == TcpConnection()
