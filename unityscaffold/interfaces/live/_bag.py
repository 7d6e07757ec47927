"""Recordings: the topics, types and embedded definitions of a ROS 1 ``.bag`` or a ROS 2 bag.

Read with rosbags' low-level readers, which only parse the bag's index and connection records;
its high-level reader would also parse every definition with rosbags' own grammar, which is
not the one ROS uses. Every recorded topic was published by the system, so Unity subscribes.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from rosbags.interfaces import Connection, MessageDefinitionFormat
from rosbags.rosbag1 import Reader as Reader1
from rosbags.rosbag1 import ReaderError as ReaderError1
from rosbags.rosbag2 import Reader as Reader2
from rosbags.rosbag2.errors import ReaderError as ReaderError2

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live.model import Direction, DiscoveredTopic, Discovery, NameFilter
from unityscaffold.interfaces.model import Dialect

__all__ = ["discover_bag"]

_ROS2_SUFFIXES = (".db3", ".mcap")


def _reader(path: Path) -> tuple[Dialect, Any]:
    if not path.exists():
        raise UserError(f"bag not found: {path}")
    if path.suffix == ".bag":
        return Dialect.ROS1, Reader1(path)
    if path.suffix in _ROS2_SUFFIXES or (path.is_dir() and (path / "metadata.yaml").is_file()):
        return Dialect.ROS2, Reader2(path)
    raise UserError(
        f"{path} is not a bag",
        hint="give a ROS 1 .bag file, a ROS 2 .db3 or .mcap file, or a rosbag2 folder",
    )


def _connections(path: Path) -> tuple[Dialect, list[Connection]]:
    dialect, reader = _reader(path)
    try:
        with reader:
            return dialect, list(reader.connections)
    except (ReaderError1, ReaderError2) as exc:
        raise UserError(f"cannot read bag {path}: {exc}") from None
    except OSError as exc:
        raise UserError(
            f"cannot read bag {path}: {exc.strerror or 'corrupt or truncated'}"
        ) from None
    except (ValueError, KeyError, IndexError):
        # rosbags lets some corruptions through as plain Python errors, whose text means
        # nothing to the user.
        raise UserError(f"cannot read bag {path}: corrupt or truncated") from None
    except Exception as exc:
        # The storage plugins (sqlite3, mcap) raise their own error families.
        if type(exc).__module__.startswith(("sqlite3", "rosbags")):
            raise UserError(f"cannot read bag {path}: {exc}") from None
        raise


def _topic(connection: Connection, dialect: Dialect) -> DiscoveredTopic:
    definition = None
    if connection.msgdef.format is MessageDefinitionFormat.MSG and connection.msgdef.data:
        definition = connection.msgdef.data
    elif connection.msgdef.format is MessageDefinitionFormat.IDL:
        definition = connection.msgdef.data  # refused with a clear message when split
    kind, md5 = connection.msgtype, None
    if dialect is Dialect.ROS1:
        # rosbags names every type pkg/msg/Type; a ROS 1 bag stores pkg/Type.
        kind, md5 = kind.replace("/msg/", "/", 1), connection.digest or None
    return DiscoveredTopic(connection.topic, kind, Direction.SUBSCRIBE, md5, definition)


def discover_bag(path: Path, *, names: NameFilter) -> Discovery:
    """The recorded topics (one per name, the first connection winning)."""
    dialect, connections = _connections(path)
    topics: dict[str, DiscoveredTopic] = {}
    warnings: list[str] = []
    for connection in connections:
        if not names.accepts(connection.topic):
            continue
        topic = _topic(connection, dialect)
        known = topics.setdefault(topic.name, topic)
        if known.type != topic.type:
            warnings.append(
                f"{topic.name} was recorded with two types, {known.type} and "
                f"{topic.type}; keeping {known.type}"
            )
        elif topic.definition is None:
            warnings.append(f"{topic.name} has no embedded definition of {topic.type}")
    return Discovery(dialect, str(path), tuple(topics.values()), (), tuple(sorted(set(warnings))))
