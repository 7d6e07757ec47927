"""Every ROS 2 service type the stack's Jazzy wheels carry (std_srvs, rcl_interfaces, test_msgs,
rosapi's own, the sample's diffbot_msgs, ...) both ways through the real rosbridge 2.x and ROS#'s
real client with our generated classes: ROS#'s client calls an rclpy server, and an rclpy client
calls a service the C# program advertises (data/ros2/service_node.py, csharp/ServiceEcho.cs).
Random request and response values cross ROS#'s serializer both ways, compared field by field.

The plan runs first through a plain JSON websocket client (data/ros2/json_echo.py): the types
that fail there fail in rosbridge itself, and must be exactly those with a field rosbridge 2.x
cannot carry. ROS#'s client then runs every other type, and every one must pass (the C# program
calls one service after the other from the previous answer's handler, and ROS# never answers a
failed call: a type rosbridge fails would stop the rest, so it is shown by the JSON client)."""

from __future__ import annotations

from pathlib import Path

from tests.runtime.ros2 import Ros2, Rosbridge2
from tests.runtime.ros2_roundtrip import (
    build_ros2_echo,
    identity_classes,
    json_client,
    ros2_registry,
    ros2_service_types,
    service_round_trip,
)
from unityscaffold.interfaces.rosbridge2 import uncarried_fields

SEED = 31


def _failures(results: dict[str, dict[str, str | None]]) -> dict[str, str]:
    return {
        f"{name} {half}": problem
        for name, halves in results.items()
        for half, problem in halves.items()
        if problem
    }


def test_every_jazzy_service_type_both_ways_through_rossharp_unless_rosbridge_drops_it(
    ros2: Ros2,
    rosbridge2: Rosbridge2,
    mcs: str,
    mono: str,
    rossharp_ros2_client: Path,
    tmp_path: Path,
) -> None:
    registry = ros2_registry(ros2.root / "venv" / "share")
    services = ros2_service_types(registry)
    names = [s.full_name for s in services]
    plain = service_round_trip(
        rosbridge2,
        json_client("services"),
        identity_classes(names),
        names,
        tmp_path / "json",
        seed=SEED,
    )
    assert set(plain.results) == set(names), plain.node_output + plain.client_output
    dropped = {name for name, halves in plain.results.items() if any(halves.values())}
    expected = {
        s.full_name
        for s in services
        if uncarried_fields(registry, s.request) or uncarried_fields(registry, s.response)
    }
    report = "\n".join(f"{k}: {v}" for k, v in sorted(_failures(plain.results).items()))
    assert dropped == expected, f"{sorted(dropped ^ expected)}\n{report}"

    carried = [s for s in services if s.full_name not in dropped]
    echo = build_ros2_echo(
        mcs, rossharp_ros2_client, registry, [], tmp_path / "Services2", services=carried
    )
    ours = service_round_trip(
        rosbridge2,
        [mono, str(echo.exe)],
        echo.classes,
        [s.full_name for s in carried],
        tmp_path / "cs",
        seed=SEED,
    )
    failures = _failures(ours.results)
    report = "\n".join(f"{k}: {v}" for k, v in sorted(failures.items()))
    assert set(ours.results) == {s.full_name for s in carried}, ours.node_output
    assert not failures, f"{report}\n{ours.node_output}\n{ours.client_output[-3000:]}"
    assert {"std_srvs/srv/SetBool", "diffbot_msgs/srv/SetSpeedLimit"} <= set(names)
    assert (len(names), len(carried)) == (53, 48)
