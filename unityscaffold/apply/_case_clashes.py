"""Paths apply would write that name one file, or one folder, on a disk that ignores letter
case: Windows' and macOS' default file systems, where most Unity projects live. On Linux they
are two, so a project generated here would lose one of them in a checkout there."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path, PurePosixPath

from unityscaffold.errors import UserError

__all__ = ["check_case_clashes"]


def check_case_clashes(root: Path, paths: Iterable[Path]) -> None:
    """Refuse two spellings of one file or folder under ``root``, told apart only by case."""
    seen: dict[str, str] = {}
    for path in sorted(paths):
        try:
            relative = path.relative_to(root).as_posix()
        except ValueError:  # beside the project (the lock): not part of a checkout's Assets
            continue
        parts = PurePosixPath(relative).parts
        for end in range(1, len(parts) + 1):
            spelled = "/".join(parts[:end])
            first = seen.setdefault(spelled.casefold(), spelled)
            if first != spelled:
                raise _clash(first, spelled, folder=end < len(parts))


def _clash(first: str, second: str, *, folder: bool) -> UserError:
    kind = "folders" if folder else "files"
    return UserError(
        f"apply would write {kind} {first} and {second}, whose names differ only in letter case: "
        "on Windows and macOS they are one",
        hint="rename what one of them comes from (a URDF material or mesh file, a message "
        "type, an output folder in the manifest) so the names differ in more than case",
    )
