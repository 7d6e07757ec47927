"""Every ROS 1 service type Debian ships, and the sample's, both ways through a real rosbridge
and ROS#'s real client: ROS#'s client calls a rospy server, and a rospy client calls a service
the C# program advertises through ROS#. Random request and response values cross ROS#'s
serializer in both directions and are compared field by field (data/service_node.py)."""

from __future__ import annotations

from pathlib import Path

from tests.runtime.bridge import Bridge
from tests.runtime.runtime_helpers import (
    build_echo,
    ros1_registry,
    service_round_trip,
    service_types,
)


def test_every_service_type_both_ways(
    bridge: Bridge, mcs: str, mono: str, rossharp_client: Path, tmp_path: Path
) -> None:
    registry = ros1_registry()
    services = service_types(registry)
    echo = build_echo(mcs, rossharp_client, registry, [], tmp_path / "Services", services=services)
    names = [s.full_name for s in services]
    done = service_round_trip(bridge, mono, echo, names, tmp_path / "run")
    assert set(done.results) == set(names), done.node_output + done.echo_output
    failures = {
        f"{name} {half}": problem
        for name, halves in done.results.items()
        for half, problem in halves.items()
        if problem
    }
    report = "\n".join(f"{k}: {v}" for k, v in sorted(failures.items()))
    assert not failures, f"{report}\n{done.node_output}\n{done.echo_output}"
    assert {"std_srvs/Trigger", "std_srvs/SetBool", "nav_msgs/GetMap"} <= set(names)
    assert "diffbot_msgs/SetSpeedLimit" in names
    assert len(names) == 30
