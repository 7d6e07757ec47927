"""What an earlier apply made that the manifest no longer asks for, and what must stay.

Files are removed only if they still have the content apply wrote (the lock's digest). A user
half the user edited stays, and so does its generated half: a partial method's body without
its declaration would not compile.
"""

from __future__ import annotations

from collections.abc import Set
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.apply._lock import LockFile, recorded
from unityscaffold.manifest.model import Manifest

__all__ = ["Pruning", "plan_pruning"]

_USER_SUFFIX = ".User.cs"


@dataclass(slots=True)
class Pruning:
    deletions: list[Path] = field(default_factory=list)
    kept_files: dict[str, str] = field(default_factory=dict)  # still tracked by the new lock
    kept_user_files: dict[str, str] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)


def _untouched(path: Path, digest: str, relative: str, notes: list[str]) -> bool | None:
    """Whether the file still has the content apply wrote; None when it is gone."""
    try:
        return recorded(path.read_bytes(), digest)
    except FileNotFoundError:
        return None
    except OSError as exc:
        notes.append(f"kept {relative}: cannot read it ({exc.strerror})")
        return False


def plan_pruning(
    manifest: Manifest,
    lock: LockFile,
    wanted: set[str],
    moved: Set[str] = frozenset(),
) -> Pruning:
    """``moved`` user halves were copied to the new output folder, so they go even if edited."""
    result = Pruning()
    root = manifest.project_root
    for relative, digest in sorted(lock.user_files.items()):
        if relative in wanted:
            continue
        if relative in moved:
            result.deletions.append(root / relative)
            continue
        state = _untouched(root / relative, digest, relative, result.notes)
        if state is False:
            result.kept_user_files[relative] = digest
            if relative not in lock.kept:  # said once, in the run that keeps it
                result.notes.append(
                    f"kept {relative} (you edited it) and its generated half; delete "
                    "both when you no longer need them"
                )
        elif state:
            result.deletions.append(root / relative)
    kept_plumbing = {r[: -len(_USER_SUFFIX)] + ".cs" for r in result.kept_user_files}
    for relative, digest in sorted(lock.files.items()):
        if relative in wanted:
            continue
        if relative in kept_plumbing:
            result.kept_files[relative] = digest
            continue
        state = _untouched(root / relative, digest, relative, result.notes)
        if state is False:
            result.kept_files[relative] = digest
            if relative not in lock.kept:
                result.notes.append(
                    f"kept {relative}: edited since apply made it; delete it yourself if unused"
                )
        elif state:
            result.deletions.append(root / relative)
    metas = [p.with_name(p.name + ".meta") for p in result.deletions]
    result.deletions += [m for m in metas if m.exists()]
    return result
