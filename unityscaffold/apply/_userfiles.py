"""The user halves of generated scripts (``<Class>.User.cs``): created once, then the user's.

The lock records the digest of what apply created. While a user half still has exactly that
content, the user never touched it: apply may refresh it when the generated half's signature
changes (a topic's type changed, say) and may remove it with its script. Once edited, it is
never rewritten or removed; apply only says when it was made for an earlier signature.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.apply._code import CodePlan, PlannedScript
from unityscaffold.apply._lock import LockFile, recorded, sha256
from unityscaffold.apply._moves import Moves
from unityscaffold.fileout import DesiredFile, same_text
from unityscaffold.manifest.model import Manifest

__all__ = ["UserFiles", "plan_user_files"]


@dataclass(slots=True)
class UserFiles:
    desired: list[DesiredFile] = field(default_factory=list)
    digests: dict[str, str] = field(default_factory=dict)  # for the new lock
    notes: list[str] = field(default_factory=list)
    moved: set[str] = field(default_factory=set)  # old user halves whose content moved here


def _regenerates(path: Path, code: CodePlan) -> bool:
    """Whether this plan changes the generated half at ``path`` (so its signature may move)."""
    wanted = next(d.content for d in code.generated if d.path == path)
    try:
        return not same_text(path.read_bytes(), wanted)
    except OSError:
        return True


def plan_user_files(
    manifest: Manifest, code: CodePlan, lock: LockFile, moves: Moves | None = None
) -> UserFiles:
    """User halves to create; one moved from an earlier output folder (``moves``) keeps the
    content it has there, your code included, and the old copy goes (``UserFiles.moved``)."""
    result = UserFiles()
    initial = {d.path: d.content for d in code.created_once}
    for script in code.scripts:
        relative = manifest.asset_path(script.user_path)
        fresh = initial[script.user_path]
        digest = lock.user_files.get(relative)
        try:
            current = script.user_path.read_bytes()
        except FileNotFoundError:
            current = None
        source = moves.sources.get(script.user_path.name) if moves is not None else None
        if current is None and source is not None:
            try:
                old = (manifest.project_root / source).read_bytes()
            except OSError:
                old = None
            if old is not None:
                result.moved.add(source)
                if recorded(old, lock.user_files[source]):
                    # never edited: made afresh, for what the generated half is now (its
                    # type may have changed in the same run)
                    result.desired.append(DesiredFile(script.user_path, fresh, create_only=True))
                    result.digests[relative] = sha256(fresh)
                else:
                    result.desired.append(DesiredFile(script.user_path, old, create_only=True))
                    result.digests[relative] = lock.user_files[source]
                    if lock.user_files[source] != sha256(fresh):
                        result.notes.append(_earlier(relative, script))
                continue
        if current is None or digest is None or same_text(current, fresh):
            # New, unknown to the lock (kept as it is), or already as apply would create it.
            result.desired.append(DesiredFile(script.user_path, fresh, create_only=True))
            result.digests[relative] = sha256(fresh)
        elif recorded(current, digest):
            # Untouched since apply created it, but made for an earlier generated half.
            result.desired.append(DesiredFile(script.user_path, fresh))
            result.digests[relative] = sha256(fresh)
        else:
            result.digests[relative] = digest
            if digest != sha256(fresh) and _regenerates(script.path, code):
                result.notes.append(_earlier(relative, script))
    return result


def _earlier(relative: str, script: PlannedScript) -> str:
    # Says what the class is generated for now, so that after a rename it cannot read as if
    # the new topic were the earlier version.
    return (
        f"{relative} was written for an earlier version of {script.view.class_name}, which is "
        f"now generated for {script.entry}; check that its methods still match {script.path.name}"
    )
