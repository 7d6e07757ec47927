"""The identity a generated file's header records: ROS 1 md5sum or ROS 2 type hash."""

from __future__ import annotations

from unityscaffold.interfaces.identity_ros1 import Ros1Identity
from unityscaffold.interfaces.identity_ros2 import Ros2Identity
from unityscaffold.interfaces.model import ActionSpec, Dialect, Interface
from unityscaffold.interfaces.registry import Registry

__all__ = ["Identities"]


class Identities:
    """Header lines such as ``ROS 1 md5sum of std_msgs/Header: 2176…``, each computed once."""

    def __init__(self, registry: Registry, dialect: Dialect) -> None:
        self.dialect = dialect
        self._ros1 = Ros1Identity(registry) if dialect is Dialect.ROS1 else None
        self._ros2 = Ros2Identity(registry) if dialect is Dialect.ROS2 else None
        self._cache: dict[str, str] = {}

    def label(self, interface: Interface) -> str:
        key = interface.full_name
        if key not in self._cache:
            self._cache[key] = self._compute(interface)
        return self._cache[key]

    def _compute(self, interface: Interface) -> str:
        if self._ros1 is not None:
            assert not isinstance(interface, ActionSpec), "ROS 1 actions have no md5sum"
            return f"ROS 1 md5sum of {interface.full_name}: {self._ros1.md5sum(interface)}"
        assert self._ros2 is not None
        return f"ROS 2 type hash of {interface.full_name}: {self._ros2.type_hash(interface)}"
