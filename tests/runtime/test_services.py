"""Every ROS 1 service type Debian ships, and the sample's, both ways through a real rosbridge
and ROS#'s real client: ROS#'s client calls a rospy server, and a rospy client calls a service
the C# program advertises through ROS#. Random request and response values cross ROS#'s
serializer in both directions and are compared field by field (data/service_node.py).
Twice, as in test_roundtrip.py: with ROS#'s classes for the types it ships (std_srvs, nav_msgs'
GetMap...) and ours for the rest, and with ours for every type (``--include-shipped``) in a
client built without ROS#'s classes."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.runtime.bridge import Bridge
from tests.runtime.runtime_helpers import (
    build_echo,
    ros1_registry,
    service_round_trip,
    service_types,
)


@pytest.mark.parametrize("include_shipped", [False, True], ids=["rossharp-classes", "ours-only"])
def test_every_service_type_both_ways(
    bridge: Bridge,
    mcs: str,
    mono: str,
    rossharp_client: Path,
    ours_only_client: Path,
    tmp_path: Path,
    include_shipped: bool,
) -> None:
    registry = ros1_registry()
    services = service_types(registry)
    client = ours_only_client if include_shipped else rossharp_client
    echo = build_echo(
        mcs,
        client,
        registry,
        [],
        tmp_path / "Services",
        services=services,
        include_shipped=include_shipped,
    )
    names = [s.full_name for s in services]
    done = service_round_trip(
        bridge, mono, echo, names, tmp_path / "run", seed=31 + include_shipped
    )
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
