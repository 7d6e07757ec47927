"""ROS 2 definition files this machine has and the Unity project may not: copied into the cache.

``discover --ros2`` names types; their files come from the interface packages installed where
it runs (``AMENT_PREFIX_PATH``, the Python prefix of PyPI's wheels). A type defined neither by
the manifest's interfaces nor by the tool's built-in set would be missing wherever ``apply``
runs next (a Unity workstation with no ROS), so its file and every file it uses that is just
as local go to the definitions cache, byte for byte, as ROS 1's rebuilt texts do.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Sequence
from pathlib import Path

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live.model import Discovery
from unityscaffold.interfaces.model import Dialect, Interface
from unityscaffold.interfaces.registry import Registry

__all__ = ["local_types", "with_installed_files"]


def local_types(dialect: Dialect, search_paths: Sequence[Path]) -> Callable[[str], bool]:
    """Whether a type is defined by the manifest's folders, the environment or the built-in
    set: such a type needs no definition from the system."""
    local = Registry.load(dialect, search_paths)

    def known(type_name: str) -> bool:
        try:
            return local.find(type_name) is not None
        except UserError:  # a local file that does not parse: ask the system instead
            return False

    return known


def with_installed_files(discovery: Discovery, search_paths: Sequence[Path]) -> Discovery:
    """``discovery`` with ``files`` holding each local-only definition file it depends on."""
    portable = Registry.load(Dialect.ROS2, search_paths, use_environment=False)
    local = Registry.load(Dialect.ROS2, search_paths)
    names = [
        *(t.type for t in discovery.topics if not t.definition),
        *(s.type for s in discovery.services),
        *(a.type for a in discovery.actions),
    ]
    roots: list[Interface] = []
    for name in names:
        try:
            found = local.find(name)
        except UserError:
            continue  # a broken local file: the staging step reports it at its line
        if found is not None:
            roots.append(found)
    try:
        used: list[Interface] = [*roots, *local.closure(roots)]
    except UserError:
        used = roots  # an unknown or broken dependency: reported when the cache is verified
    files: dict[str, str] = dict(discovery.files)
    for interface in used:
        file = local.file_of(interface)
        if file is None or _portable(portable, interface):
            continue
        relative = f"{file.package}/{file.kind.value}/{file.name}.{file.kind.value}"
        files.setdefault(relative, file.path.read_text(encoding="utf-8"))
    return dataclasses.replace(discovery, files=tuple(sorted(files.items())))


def _portable(portable: Registry, interface: Interface) -> bool:
    """Whether the manifest's folders or the built-in set define ``interface``'s file."""
    try:
        return portable.file_of(interface) is not None
    except UserError:
        return False
