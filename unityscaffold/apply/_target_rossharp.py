"""The ROS# runtime for apply: its classes (codegen's ROS# target), its scripts' views, the
check that only ROS# needs, and its RosConnector in the scene."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from unityscaffold.apply._rossharp import RESERVED_NAMES, RosSharp
from unityscaffold.apply._script_views import action_script, script_names
from unityscaffold.codegen import ClassRole, GeneratedCode, Options, generate
from unityscaffold.errors import LocatedError
from unityscaffold.interfaces.model import Dialect, Interface
from unityscaffold.interfaces.registry import Registry
from unityscaffold.manifest.model import Action, Direction, Manifest, Role, Service, Topic
from unityscaffold.unity import Enum, ScriptRef
from unityscaffold.unity.values import FieldValue

if TYPE_CHECKING:
    from unityscaffold.codegen.scripts import Script

__all__ = ["RosSharpTarget"]

Entry = Topic | Service | Action

# ROS 1 std_msgs types whose ROS# class is a hand-written time primitive of another shape.
_MISSHAPEN_IN_ROSSHARP = ("std_msgs/Time", "std_msgs/Duration")


class RosSharpTarget:
    """Siemens' ROS# over rosbridge: ``RosConnector`` and the ``rossharp/`` templates."""

    label = "ROS#"
    connection_field = "Connector"
    connection_class = "RosConnector"
    reserved_names = RESERVED_NAMES

    def classes(
        self, registry: Registry, roots: Sequence[Interface], options: Options
    ) -> GeneratedCode:
        return generate(registry, roots, options)

    def check(
        self, manifest: Manifest, registry: Registry, entries: Sequence[tuple[Entry, Interface]]
    ) -> None:
        """Refuse an entry whose type uses ROS 1's std_msgs/Time or std_msgs/Duration while
        ROS#'s classes are in use: ROS#'s Std.Time/Std.Duration, which stand for them, are the
        bare time primitive ({secs, nsecs}), while these messages hold it in a field 'data'.
        rosbridge refuses what such a class sends and the value it receives is lost (seen with
        rosbridge 0.11)."""
        if manifest.ros is not Dialect.ROS1 or manifest.namespace is not None:
            return
        for item, spec in entries:
            used = {m.full_name for m in registry.closure([spec])}
            for name in _MISSHAPEN_IN_ROSSHARP:
                if name in used:
                    short = name.split("/")[1]
                    raise LocatedError.at(
                        item.locations.of("type"),
                        f"{name} cannot be sent or received with ROS#'s class for it: "
                        f"Std.{short} is the bare {short.lower()} primitive {{secs, nsecs}}, "
                        f"while {name} holds it in a field 'data' (rosbridge refuses what it "
                        "sends)",
                        hint="choose a root namespace with the manifest key `namespace:` "
                        f"(then a {name} class of the right shape is generated), or use a "
                        f"message with a {short.lower()} field",
                    )

    def script_view(
        self, manifest: Manifest, item: Entry, spec: Interface, messages: GeneratedCode
    ) -> Script:
        # the scripts' views load with the first script: a manifest of robots only needs none
        from unityscaffold.codegen.scripts import (
            ActionClientScript,
            ActionServerScript,
            PublisherScript,
            ServiceClientScript,
            ServiceServerScript,
            SubscriberScript,
        )

        if isinstance(item, Action):
            action = ActionClientScript if item.role is Role.CLIENT else ActionServerScript
            ros2 = manifest.ros is Dialect.ROS2
            return action_script(action, manifest, item, spec, messages, ros2=ros2)
        common = script_names(manifest, item, spec)
        if isinstance(item, Topic):
            message = messages.message_class(spec.full_name).qualified
            if item.direction is Direction.PUBLISH:
                return PublisherScript(
                    **common, topic=item.name, message_type=message, rate=item.rate or 0.0
                )
            return SubscriberScript(
                **common,
                topic=item.name,
                message_type=message,
                throttle=item.throttle or 0,
                queue=item.queue or 1,
            )
        classes = messages.classes[f"{spec.package}/srv/{spec.name}"]
        kind = ServiceClientScript if item.role is Role.CLIENT else ServiceServerScript
        return kind(
            **common,
            service=item.name,
            request_type=classes[ClassRole.REQUEST].qualified,
            response_type=classes[ClassRole.RESPONSE].qualified,
        )

    def connection_fields(self, manifest: Manifest) -> list[tuple[str, FieldValue]]:
        """The RosConnector's serialized fields."""
        c = manifest.connector
        return [
            ("selectedRosVersion", Enum(int(manifest.ros) - 1)),
            ("SecondsTimeout", int(c.timeout)),
            ("Serializer", Enum(int(c.serializer))),
            ("protocol", Enum(int(c.protocol))),
            ("RosBridgeServerUrl", c.url),
        ]

    def connection_script(self, rossharp: RosSharp, project: Path) -> ScriptRef:
        return rossharp.script(self.connection_class)

    def notes(self, project: Path, rossharp: RosSharp) -> tuple[str, ...]:
        return rossharp.notes
