"""Live and recorded ROS systems as interface sources: what ``scaffold discover`` reads.

Four sources feed one result model (``Discovery``): a ROS 1 master with TCPROS probes of its
nodes (``master``), a rosbridge's rosapi (``rosbridge``), bag files (``bag``), and the ROS 2
graph itself through rclpy (``_ros2``, an optional extra).
``definitions`` turns the full definition texts they report back into ``.msg`` files in a
definitions cache, verifying ROS 1 md5sums on the way.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live._actions import group_actions
from unityscaffold.interfaces.live._installed import local_types, with_installed_files
from unityscaffold.interfaces.live._optional import optional_extra
from unityscaffold.interfaces.live.model import (
    Direction,
    DiscoveredAction,
    DiscoveredService,
    DiscoveredTopic,
    Discovery,
    NameFilter,
    Progress,
)
from unityscaffold.interfaces.model import Dialect

__all__ = [
    "Direction",
    "DiscoveredAction",
    "DiscoveredService",
    "DiscoveredTopic",
    "Discovery",
    "NameFilter",
    "Progress",
    "discover",
    "list_live_types",
]


def list_live_types(url: str, *, timeout: float) -> list[tuple[str, str]]:
    """``(topic, type)`` of the active topics: ``http://`` is a ROS 1 master, ``ws://`` or
    ``wss://`` a rosbridge."""
    from unityscaffold.interfaces.live import _master, _rosbridge

    if url.startswith("http://"):
        return _master.list_master_types(url, timeout=timeout)
    if url.startswith(("ws://", "wss://")):
        return _rosbridge.list_rosbridge_types(url, timeout=timeout)
    raise UserError(
        f"not a live ROS URL: {url!r}",
        hint="use http://HOST:11311 (ROS 1 master) or ws://HOST:9090 (rosbridge)",
    )


def discover(
    *,
    master_url: str | None = None,
    rosbridge_url: str | None = None,
    bag: Path | None = None,
    ros2: bool = False,
    timeout: float = 2.0,
    wait: float = 5.0,
    names: NameFilter | None = None,
    dialect: Dialect | None = None,
    progress: Progress | None = None,
    search_paths: Sequence[Path] = (),
) -> Discovery:
    """Read one source; exactly one of ``master_url``, ``rosbridge_url``, ``bag`` and ``ros2``.

    In ROS 1, each complete set of actionlib topics comes back as one action, not as topics.
    ``wait`` bounds the ROS 2 graph's discovery; ``search_paths`` (with the environment) are
    where ROS 2 types need no description from the nodes.
    """
    from unityscaffold.interfaces.live import _master, _rosbridge

    chosen = [s for s in (master_url, rosbridge_url, bag) if s is not None] + [ros2] * ros2
    if len(chosen) != 1:
        raise UserError("give exactly one of --master, --rosbridge, --bag and --ros2")
    names = names or NameFilter()
    if ros2:
        return _discover_graph(wait, timeout, names, search_paths, progress)
    if master_url is not None:
        found = _master.discover_master(master_url, timeout=timeout, names=names, progress=progress)
    elif rosbridge_url is not None:
        found = _rosbridge.discover_rosbridge(
            rosbridge_url,
            timeout=timeout,
            names=names,
            dialect=dialect,
            progress=progress,
            known=lambda found: local_types(found, search_paths),
        )
    else:
        assert bag is not None
        found = _discover_bag(Path(bag), names)
    return group_actions(found)


def _discover_graph(
    wait: float,
    timeout: float,
    names: NameFilter,
    search_paths: Sequence[Path],
    progress: Progress | None,
) -> Discovery:
    from unityscaffold.interfaces.live._ros2 import discover_graph

    known = local_types(Dialect.ROS2, search_paths)
    found = discover_graph(wait=wait, timeout=timeout, names=names, known=known, progress=progress)
    return with_installed_files(found, search_paths)


def _discover_bag(bag: Path, names: NameFilter) -> Discovery:
    """The bag reader; it needs ``rosbags``, an optional extra, so it is imported only here."""
    with optional_extra(
        ("rosbags",),
        "reading a recording needs the Python package rosbags, which is not installed",
        hint="install unityscaffold with its `bag` extra: "
        "python3 -m pip install 'unityscaffold[bag]' (from a checkout: '.[bag]')",
    ):
        from unityscaffold.interfaces.live import _bag
    return _bag.discover_bag(bag, names=names)
