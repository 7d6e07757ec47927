"""The rule every write obeys: nothing is written or deleted outside the Unity project.

The manifest's paths are checked when it loads, but a symbolic link inside the project (an
``Assets/`` made a link, a link created later in the output folder, or a stale lock) could still
lead elsewhere; ``apply`` and ``init`` both check each folder they touch, once.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

from unityscaffold.errors import UserError
from unityscaffold.fileout import real_path

__all__ = ["check_inside"]


def check_inside(project: Path, paths: Iterable[Path]) -> None:
    """Refuse any write or deletion whose folder resolves outside ``project``."""
    root = real_path(project)
    inside = str(root).rstrip(os.sep) + os.sep
    resolved: dict[Path, str] = {}
    for path in paths:
        folder = resolved.get(path.parent)
        if folder is None:
            folder = resolved[path.parent] = str(real_path(path.parent))
        if not (folder + os.sep).startswith(inside):
            real = Path(folder) / path.name
            raise UserError(
                f"refusing to touch {path}: it resolves to {real}, outside the "
                f"Unity project {root}",
                hint="a folder on the way is a symbolic link; replace it with a real "
                "folder inside the project",
            )
