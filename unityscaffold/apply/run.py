"""Running a plan: show it, check it, or write it. The only place ``apply`` writes."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.apply._lock import journal_path, lock_path
from unityscaffold.apply.plan import Plan, make_plan
from unityscaffold.errors import LocatedError, UserError
from unityscaffold.fileout import write_files, write_if_changed
from unityscaffold.interfaces.registry import Registry
from unityscaffold.manifest import load_manifest
from unityscaffold.manifest.model import Manifest

__all__ = ["Mode", "Outcome", "load_registry", "run"]


class Mode(enum.Enum):
    PLAN = "plan"
    CHECK = "check"
    APPLY = "apply"


@dataclass(slots=True)
class Outcome:
    mode: Mode
    plan: Plan
    written: list[Path] = field(default_factory=list)
    deleted: list[Path] = field(default_factory=list)


def load_registry(manifest: Manifest, *, use_environment: bool) -> Registry:
    """The manifest's interface folders, then (if asked) the ROS environment, then built-ins.

    Without the environment, a run reads only files in the repository and the built-in
    standard definitions, so its output is the same on every machine.
    """
    for folder in manifest.interfaces:
        if not folder.is_dir():
            raise LocatedError.at(
                manifest.locations.of("interfaces"),
                f"interface folder {folder} does not exist",
                hint="paths in `interfaces` are relative to the manifest",
            )
    return Registry.load(manifest.ros, list(manifest.interfaces), use_environment=use_environment)


def run(
    manifest_path: Path,
    mode: Mode,
    *,
    force: bool = False,
    use_environment: bool = False,
    follow_renames: bool = False,
) -> Outcome:
    """Plan the manifest's project, then show (PLAN), compare (CHECK) or write (APPLY) it."""
    manifest = load_manifest(manifest_path)
    plan = make_plan(
        manifest,
        load_registry(manifest, use_environment=use_environment),
        force=force,
        follow_renames=follow_renames,
    )
    outcome = Outcome(mode, plan)
    if mode is not Mode.APPLY:
        return outcome
    if plan.conflicts:
        listed = "\n  ".join(plan.conflicts)
        raise UserError(
            f"generated files were edited by hand, so apply stopped and wrote nothing:\n  {listed}",
            hint=_conflict_hint(plan),
        )
    # Order matters for a run that is interrupted (Ctrl-C, SIGKILL): the journal (the new
    # lock) is on disk before the first file is replaced, the lock is written after the last
    # deletion, and the journal is removed after the lock. The next run reads the journal if
    # it is still there (make_plan), so the lock never forgets a file or a component.
    lock = lock_path(plan.manifest.path)
    journal = journal_path(plan.manifest.path)
    lock_changes = [c for c in plan.changes if c.path == lock]
    work = [c for c in plan.changes if c.path != lock]
    removals = [p for p in plan.deletions if p != journal]

    def record() -> None:
        if any(c.writes for c in work) or removals:
            if plan.recovered_lock is not None:
                # an earlier journal is about to be replaced: keep what it knew in the lock
                write_if_changed(lock, plan.recovered_lock)
            write_if_changed(journal, lock_changes[0].content)

    outcome.written = write_files(work, before_replace=record)
    for path in removals:
        _remove(path)
        outcome.deleted.append(path)
    # compared again, not as planned: record() may have put the recovered lock there since
    if write_if_changed(lock, lock_changes[0].content):
        outcome.written.append(lock)
    if journal.exists():
        _remove(journal)
        if journal in plan.deletions:
            outcome.deleted.append(journal)
    return outcome


def _remove(path: Path) -> None:
    """Remove a file, or a folder the plan found empty."""
    try:
        if path.is_dir() and not path.is_symlink():
            path.rmdir()
        else:
            path.unlink(missing_ok=True)
    except OSError as exc:
        raise UserError(
            f"cannot remove {path}: {exc.strerror}; the other changes were written",
            hint="fix the cause and run apply again to finish the clean-up",
        ) from None


def _conflict_hint(plan: Plan) -> str:
    """What to do instead, for scripts (a user half exists) and message classes (none does)."""
    scripts = plan.manifest.output + "/Scripts/"
    ways = []
    if any(c.startswith(scripts) for c in plan.conflicts):
        ways.append("move your code into the matching .User.cs file (it is never rewritten)")
    if any(not c.startswith(scripts) for c in plan.conflicts):
        ways.append(
            "change a message class through its .msg/.srv/.action definition (the class is "
            "regenerated from it), or keep your code in a file of your own"
        )
    return "; ".join(ways) + "; or run apply --force to overwrite these files"
