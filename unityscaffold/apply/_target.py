"""The one place apply chooses its runtime: ``target_for(manifest)`` gives the object that
knows the manifest's runtime (ROS# or ROS-TCP-Connector): its message classes, its scripts'
views, its connection component and field, and the notes about its package. Everything
else in apply is the same for both."""

from __future__ import annotations

from collections.abc import Sequence
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

from unityscaffold.apply._rossharp import RosSharp
from unityscaffold.codegen import GeneratedCode, Options
from unityscaffold.interfaces.model import Interface
from unityscaffold.interfaces.registry import Registry
from unityscaffold.manifest.model import Action, Manifest, Service, Topic
from unityscaffold.manifest.runtime import Runtime
from unityscaffold.unity import ScriptRef
from unityscaffold.unity.values import FieldValue

if TYPE_CHECKING:
    from unityscaffold.codegen.scripts import Script

__all__ = ["RuntimeTarget", "target_for", "target_of"]

Entry = Topic | Service | Action


class RuntimeTarget(Protocol):
    label: str  # how messages name the runtime
    connection_field: str  # the generated scripts' field that holds the connection
    connection_class: str  # the connection component's class
    reserved_names: frozenset[str]  # classes a generated script must not be named like

    def classes(
        self, registry: Registry, roots: Sequence[Interface], options: Options
    ) -> GeneratedCode: ...

    def check(
        self, manifest: Manifest, registry: Registry, entries: Sequence[tuple[Entry, Interface]]
    ) -> None: ...

    def script_view(
        self, manifest: Manifest, item: Entry, spec: Interface, messages: GeneratedCode
    ) -> Script: ...

    def connection_fields(self, manifest: Manifest) -> list[tuple[str, FieldValue]]: ...

    def connection_script(self, rossharp: RosSharp, project: Path) -> ScriptRef: ...

    def notes(self, project: Path, rossharp: RosSharp) -> tuple[str, ...]: ...


def target_for(manifest: Manifest) -> RuntimeTarget:
    return target_of(manifest.runtime)


@cache
def target_of(runtime: Runtime) -> RuntimeTarget:
    """The runtime's target, its module imported on first use: a command loads the code
    generator of its own runtime only (the other's modules are 5% of an apply's imports)."""
    if runtime is Runtime.TCP_CONNECTOR:
        from unityscaffold.apply._target_tcp import TcpConnectorTarget

        return TcpConnectorTarget()
    from unityscaffold.apply._target_rossharp import RosSharpTarget

    return RosSharpTarget()
