"""The ROS-TCP-Connector runtime for apply: its classes, its scripts' views (``scripts_tcp``)
and its ``ROSConnection`` in the scene."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from unityscaffold.apply import _tcpconnector as package
from unityscaffold.apply._rossharp import RESERVED_NAMES as ROSSHARP_NAMES
from unityscaffold.apply._rossharp import RosSharp
from unityscaffold.apply._script_views import action_script, script_names
from unityscaffold.codegen import ClassRole, GeneratedCode, Options, rostcp
from unityscaffold.codegen.scripts import Script
from unityscaffold.codegen.scripts_tcp import (
    CONNECTION_FIELD,
    DEFAULT_QUEUE,
    TcpActionClientScript,
    TcpActionServerScript,
    TcpPublisherScript,
    TcpServiceClientScript,
    TcpServiceServerScript,
    TcpSubscriberScript,
)
from unityscaffold.interfaces.model import Dialect, Interface, MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry
from unityscaffold.manifest.model import Action, Direction, Manifest, Role, Service, Topic
from unityscaffold.manifest.runtime import TcpConnection
from unityscaffold.unity import ScriptRef
from unityscaffold.unity.values import FieldValue

__all__ = ["TcpConnectorTarget"]

Entry = Topic | Service | Action


class TcpConnectorTarget:
    """Unity's ROS-TCP-Connector: ``ROSConnection`` and the ``tcpconnector/`` templates."""

    label = "ROS-TCP-Connector"
    connection_field = CONNECTION_FIELD
    connection_class = "ROSConnection"
    # ROS#'s names stay taken: a project may hold both packages, and its scenes ROS#'s scripts
    reserved_names = package.RESERVED_NAMES | ROSSHARP_NAMES

    def classes(
        self, registry: Registry, roots: Sequence[Interface], options: Options
    ) -> GeneratedCode:
        return rostcp.generate(registry, roots, options)

    def check(
        self, manifest: Manifest, registry: Registry, entries: Sequence[tuple[Entry, Interface]]
    ) -> None:
        """Nothing beyond the manifest's own checks (ROS 2 actions are refused there)."""

    def script_view(
        self, manifest: Manifest, item: Entry, spec: Interface, messages: GeneratedCode
    ) -> Script:
        if isinstance(item, Action):
            action = TcpActionClientScript if item.role is Role.CLIENT else TcpActionServerScript
            return action_script(action, manifest, item, spec, messages)
        common = script_names(manifest, item, spec)
        ros2 = manifest.ros is Dialect.ROS2
        if isinstance(item, Topic):
            message = messages.message_class(spec.full_name).qualified
            if item.direction is Direction.PUBLISH:
                assert isinstance(spec, MessageSpec)
                return TcpPublisherScript(
                    **common,
                    topic=item.name,
                    message_type=message,
                    rate=item.rate or 0.0,
                    queue=item.queue or DEFAULT_QUEUE,
                    latch=bool(item.latch),
                    empty_cdr=ros2 and not spec.fields,
                )
            return TcpSubscriberScript(**common, topic=item.name, message_type=message)
        assert isinstance(spec, ServiceSpec)
        classes = messages.classes[f"{spec.package}/srv/{spec.name}"]
        client = item.role is Role.CLIENT
        kind = TcpServiceClientScript if client else TcpServiceServerScript
        sent = spec.request if client else spec.response
        return kind(
            **common,
            service=item.name,
            request_type=classes[ClassRole.REQUEST].qualified,
            response_type=classes[ClassRole.RESPONSE].qualified,
            empty_cdr=ros2 and not sent.fields,
        )

    def connection_fields(self, manifest: Manifest) -> list[tuple[str, FieldValue]]:
        """ROSConnection's serialized fields, in its declaration order (v0.7)."""
        c = manifest.connector.tcp or TcpConnection()
        return [
            ("m_RosIPAddress", c.host),
            ("m_RosPort", int(c.port)),
            ("m_ConnectOnStart", bool(c.connect_on_start)),
            ("m_KeepaliveTime", float(c.keepalive)),
            ("m_NetworkTimeoutSeconds", float(c.network_timeout)),
            ("m_SleepTimeSeconds", float(c.sleep)),
            ("m_ShowHUD", bool(c.show_hud)),
            ("m_TFTopics", tuple(c.tf_topics)),
            ("listenForTFMessages", bool(c.listen_for_tf)),
        ]

    def connection_script(self, rossharp: RosSharp, project: Path) -> ScriptRef:
        return package.connection_script(project)

    def notes(self, project: Path, rossharp: RosSharp) -> tuple[str, ...]:
        return package.pin_notes(project)
