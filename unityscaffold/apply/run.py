"""Running a plan: show it, check it, or write it. The only place ``apply`` writes."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.apply._lock import lock_path
from unityscaffold.apply.plan import Plan, make_plan
from unityscaffold.errors import LocatedError, UserError
from unityscaffold.fileout import write_files
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
            hint="move your code into the matching .User.cs file (it is never rewritten), "
            "or run apply --force to overwrite these files",
        )
    # The lock is written last: if a deletion fails, the old lock still lists the file and the
    # next run tries again instead of forgetting it.
    lock = lock_path(plan.manifest.path)
    outcome.written = write_files([c for c in plan.changes if c.path != lock])
    for path in plan.deletions:
        try:
            path.unlink(missing_ok=True)
        except OSError as exc:
            raise UserError(
                f"cannot remove {path}: {exc.strerror}; the other changes were written",
                hint="fix the cause and run apply again to finish the clean-up",
            ) from None
        outcome.deleted.append(path)
    outcome.written += write_files([c for c in plan.changes if c.path == lock])
    return outcome
