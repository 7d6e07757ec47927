"""Every ROS 1 message type Debian ships, and the sample's own, through a real rosbridge and
ROS#'s real client: rospy publishes random values, a C# program receives and republishes each
object unchanged, rospy compares field by field (runtime_helpers.round_trip). Twice: with ROS#'s
classes for the types it ships and ours for the rest (what apply sets up), and with ours for
every type (``--include-shipped``) in a client built without ROS#'s classes.

Serializer: Newtonsoft_JSON. ROS#'s default, System.Text.Json, cannot run here (see client.py);
test_stj_contract.py checks our classes against its contract instead."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.runtime.bridge import Bridge
from tests.runtime.runtime_helpers import (
    TIME_PRIMITIVES,
    build_echo,
    message_types,
    ros1_registry,
    round_trip,
)


@pytest.mark.parametrize("include_shipped", [False, True], ids=["rossharp-classes", "ours-only"])
def test_every_message_type_round_trips_with_newtonsoft(
    bridge: Bridge,
    mcs: str,
    mono: str,
    rossharp_client: Path,
    ours_only_client: Path,
    tmp_path: Path,
    include_shipped: bool,
) -> None:
    registry = ros1_registry()
    roots = [s for s in message_types(registry) if s.full_name not in TIME_PRIMITIVES]
    client = ours_only_client if include_shipped else rossharp_client
    echo = build_echo(
        mcs, client, registry, roots, tmp_path / "Echo", include_shipped=include_shipped
    )
    names = [s.full_name for s in roots]
    done = round_trip(bridge, mono, echo, names, tmp_path / "run", seed=1 + include_shipped)
    failures = {name: problem for name, problem in done.results.items() if problem}
    assert set(done.results) == set(names), done.node_output + done.echo_output
    assert not failures, "\n".join(f"{k}: {v}" for k, v in sorted(failures.items()))
    # Debian's 16 packages with messages and the sample's package (messages and its action's).
    assert len({n.split("/")[0] for n in names}) == 17
    assert {"diffbot_msgs/BaseStatus", "diffbot_msgs/DockActionFeedback"} <= set(names)
    assert len(names) == 161
