"""The message classes ROS# 2.2.1 already ships, per ROS version.

Generated code refers to these instead of generating them: a second class with the same full
name in the user's project does not compile (CS0433). ROS 1's ``Std.Time`` and ``Std.Duration``
are hand-written in ROS# and exist in every ROS# install.
"""

from __future__ import annotations

from functools import cache

from unityscaffold.codegen._shipped_data import FIELDS, SHIPPED
from unityscaffold.interfaces.model import Dialect

__all__ = ["ROS1_HANDWRITTEN", "shipped_classes", "shipped_fields"]

ROS1_HANDWRITTEN: dict[tuple[str, str], str] = {
    ("Std", "Time"): "std_msgs/Time",
    ("Std", "Duration"): "std_msgs/Duration",
}
"""ROS 1 classes ROS# writes by hand: (namespace, class) -> the std_msgs type they stand for."""


@cache
def shipped_classes(dialect: Dialect) -> dict[tuple[str, str], str]:
    """(namespace segment, class name) -> the RosMessageName of ROS#'s class."""
    table: dict[tuple[str, str], str] = {}
    for namespace, entries in SHIPPED[int(dialect)].items():
        for entry in entries:
            ros_name, _, explicit = entry.partition(">")
            table[(namespace, explicit or ros_name.rsplit("/", 1)[-1])] = ros_name
    return table


@cache
def shipped_fields(dialect: Dialect) -> dict[tuple[str, str], tuple[str, ...]]:
    """(namespace segment, class name) -> the fields ROS#'s class declares, in order. Empty
    for a class whose fields are inherited (ROS#'s action wrappers): nothing to compare."""
    table: dict[tuple[str, str], tuple[str, ...]] = {}
    for key, names in FIELDS[int(dialect)].items():
        namespace, _, name = key.partition("/")
        table[(namespace, name)] = names
    return table
