"""``scaffold msgs list --live URL``: the types of the active topics of a running ROS 1 system."""

from __future__ import annotations

import json

from helpers import run_cli


def test_msgs_list_live_lists_the_active_topics_of_a_real_master(ros1_system):
    run = run_cli("msgs", "list", "--live", ros1_system.url, "--json", "--timeout", "5")
    assert run.code == 0, run.err
    listed = {entry["topic"]: entry["type"] for entry in json.loads(run.out)}
    assert listed["/chatter"] == "std_msgs/String"
    assert listed["/imu"] == "sensor_msgs/Imu"


def test_msgs_list_live_on_an_unreachable_master_is_a_clear_error():
    run = run_cli("msgs", "list", "--live", "http://127.0.0.1:1", "--timeout", "1")
    assert run.code == 2
    assert "no ROS master at http://127.0.0.1:1" in run.err
    assert "Traceback" not in run.err
