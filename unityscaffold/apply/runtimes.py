"""Each runtime's message-class generator, for commands that generate classes without a
manifest (``msgs gen --runtime``); apply itself asks ``_target.target_for``."""

from __future__ import annotations

from collections.abc import Sequence

from unityscaffold.apply._target import target_of
from unityscaffold.codegen import GeneratedCode, Options
from unityscaffold.interfaces.model import Interface
from unityscaffold.interfaces.registry import Registry
from unityscaffold.manifest.runtime import Runtime

__all__ = ["generate_classes"]


def generate_classes(
    runtime: Runtime, registry: Registry, roots: Sequence[Interface], options: Options
) -> GeneratedCode:
    """The message, service and action classes ``runtime`` needs for ``roots``."""
    return target_of(runtime).classes(registry, roots, options)
