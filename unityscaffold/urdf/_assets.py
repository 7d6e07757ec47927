"""What a file of the import that needs other assets' GUIDs looks like to the writer: the STL
prefabs and copied models (``urdf.models``), the copied textures (``urdf.textures``), the
textured materials (``urdf.materials``). Apply gives each a GUID first, then writes them."""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

__all__ = ["GuidOf", "PlannedAsset"]

#: The GUID of a path in the robot's asset folder.
GuidOf = Callable[[str], str]


class PlannedAsset(Protocol):
    """A file at ``path`` in the robot's asset folder, with its ``.meta``."""

    @property
    def path(self) -> str: ...

    def content(self, guid_of: GuidOf) -> bytes:
        """The file's bytes; ``guid_of`` gives the GUID of another asset of the robot."""
        ...

    def meta(self, guid: str) -> str:
        """The text of the file's ``.meta`` with ``guid``."""
        ...
