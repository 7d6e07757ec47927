"""A whole plan: what ``apply`` would write, update and delete to make the project match.

Pure: reads the manifest, the interfaces, the Unity project and the lock, and returns file
changes and scene edits; nothing is written here (see ``apply.run``).
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.apply._case_clashes import check_case_clashes
from unityscaffold.apply._class_notes import class_notes
from unityscaffold.apply._code import CodePlan, plan_code
from unityscaffold.apply._identity import follow_in_manifest, followed_notes
from unityscaffold.apply._inside import check_inside
from unityscaffold.apply._leftovers import plan_leftovers, temp_leftovers_of
from unityscaffold.apply._lock import (
    LockFile,
    LockGameObject,
    journal_path,
    lock_path,
    recorded,
    sha256,
)
from unityscaffold.apply._moves import find_moves
from unityscaffold.apply._prune import Pruning, plan_pruning
from unityscaffold.apply._rosbridge2 import rosbridge2_notes
from unityscaffold.apply._rossharp import RosSharp
from unityscaffold.apply._scenes import ScenePlan, plan_scenes
from unityscaffold.apply._scriptmetas import plan_script_metas
from unityscaffold.apply._settings import with_ros_define
from unityscaffold.apply._target import target_for
from unityscaffold.apply._userfiles import UserFiles, plan_user_files
from unityscaffold.apply.robots import PlannedRobot, plan_robots
from unityscaffold.errors import LocatedError, UserError
from unityscaffold.fileout import (
    DesiredFile,
    FileChange,
    check_name_lengths,
    plan_files,
    same_text,
)
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry
from unityscaffold.manifest.model import Manifest
from unityscaffold.unity.project import project_salt, script_index

__all__ = ["Plan", "make_plan"]

_SETTINGS = Path("ProjectSettings") / "ProjectSettings.asset"


@dataclass(slots=True)
class Plan:
    manifest: Manifest
    changes: list[FileChange]
    deletions: list[Path]
    scenes: list[ScenePlan]
    conflicts: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    skipped_types: int = 0
    #: The lock as recovered from an interrupted run's journal, to be made the lock before a
    #: new journal replaces that one (None when no run was interrupted).
    recovered_lock: bytes | None = None

    @property
    def writes(self) -> list[FileChange]:
        return [c for c in self.changes if c.writes]

    @property
    def in_sync(self) -> bool:
        return not self.writes and not self.deletions

    def relative(self, path: Path) -> str:
        """``path`` for people: inside the project relative to it, else to the manifest."""
        # A manifest named from a subfolder (../robot.yaml) keeps its '..' in the planned
        # paths; folded here, the lock beside it reads robot.lock.json, not Assets/../...
        path = Path(os.path.normpath(path))
        for base in (self.manifest.project_root, self.manifest.path.parent):
            try:
                return path.relative_to(Path(os.path.normpath(base))).as_posix()
            except ValueError:
                continue
        return str(path)


def _settings_change(manifest: Manifest) -> list[DesiredFile]:
    path = manifest.project_root / _SETTINGS
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        return []
    except (OSError, UnicodeDecodeError):
        text = ""
    if not text.startswith("%YAML"):
        raise UserError(
            f"{path} is not a text (YAML) settings file",
            hint="set Edit > Project Settings > Editor > Asset Serialization Mode to "
            "'Force Text'; apply keeps the ROS2 define there in line with `ros`",
        )
    wanted = with_ros_define(text, manifest.ros is Dialect.ROS2)
    return [DesiredFile(path, wanted.encode("utf-8"))] if wanted != text else []


def _conflicts(manifest: Manifest, generated: list[DesiredFile], lock: LockFile) -> list[str]:
    """Generated files someone edited by hand since apply last wrote them."""
    found = []
    for want in generated:
        try:
            current = want.path.read_bytes()
        except FileNotFoundError:
            continue
        if same_text(current, want.content):
            continue
        if not recorded(current, lock.files.get(manifest.asset_path(want.path))):
            found.append(manifest.asset_path(want.path))
    return found


def _followed_manifest(manifest: Manifest, scenes: list[ScenePlan]) -> list[DesiredFile]:
    """The manifest with the paths of GameObjects renamed in Unity rewritten (--follow-renames)."""
    moved = [m for s in scenes for m in s.followed]
    if not moved:
        return []
    text = manifest.path.read_text(encoding="utf-8")
    return [DesiredFile(manifest.path, follow_in_manifest(text, moved).encode("utf-8"))]


def make_plan(
    manifest: Manifest, registry: Registry, *, force: bool = False, follow_renames: bool = False
) -> Plan:
    """Compute everything ``apply`` would do; raises ``UserError`` for bad input."""
    project = manifest.project_root
    if not (project / "Assets").is_dir():
        raise LocatedError.at(
            manifest.locations.of("project"),
            f"{project} is not a Unity project (no Assets/ folder)",
            hint="set `project:` in the manifest, or create one with scaffold init",
        )
    journal = journal_path(manifest.path)
    lock, recovered = _last_lock(manifest, journal)
    salt = project_salt(project)
    metas = plan_script_metas(manifest, script_index(project), salt)
    scripts = metas.scripts
    moves = find_moves(manifest, lock)
    code: CodePlan = plan_code(manifest, registry, salt, scripts, moves)
    rossharp = RosSharp.of(project, scripts)
    robots = tuple(plan_robots(manifest, salt))
    scenes = plan_scenes(
        manifest, code, rossharp, scripts, lock, follow_renames=follow_renames, robots=robots
    )

    generated = list(code.generated) + [f for r in robots for f in r.files]
    check_name_lengths(d.path for d in (*generated, *code.created_once))
    conflicts = [] if force else _conflicts(manifest, generated, lock)
    user = plan_user_files(manifest, code, lock, moves)
    user_paths = {d.path for d in user.desired}
    desired = generated + [d for d in code.created_once if d.path not in user_paths]
    desired += [meta for r in robots for meta in r.metas]
    desired += user.desired + metas.desired + _settings_change(manifest)
    desired += [DesiredFile(s.path, s.after.encode("utf-8")) for s in scenes if s.changed]

    check_case_clashes(project, [d.path for d in desired])
    wanted = {manifest.asset_path(d.path) for d in desired}
    pruning = plan_pruning(manifest, lock, wanted, user.moved)
    deletions = pruning.deletions
    # Temporary files may sit beside any file apply writes: scenes, settings, generated files.
    beside = [manifest.scene_path(s) for s in manifest.scenes] + [project / _SETTINGS]
    made = [project / folder for folder in lock.folders]
    deletions += plan_leftovers(manifest, [d.path for d in desired], deletions, beside, made)
    target_notes = target_for(manifest).notes(project, rossharp)
    folders = _robot_folders(robots, lock, project, deletions)
    new_lock = _new_lock(manifest, generated, user, pruning, scenes, folders)
    check_inside(project, [d.path for d in desired] + deletions)
    # Beside the manifest, outside the project: the lock's and the journal's temporary files,
    # then the journal itself, removed last (apply.run).
    deletions += temp_leftovers_of([lock_path(manifest.path), journal])
    if journal.exists():
        deletions.append(journal)
    desired += _followed_manifest(manifest, scenes)
    desired.append(DesiredFile(lock_path(manifest.path), new_lock.render().encode("utf-8")))
    changes = plan_files(desired)
    notes = [*target_notes, *user.notes, *pruning.notes, *followed_notes(scenes)]
    notes += class_notes(code, registry, {c.path for c in changes if c.writes})
    notes += rosbridge2_notes(manifest, registry)
    notes += [note for robot in robots for note in robot.notes()]
    return Plan(
        manifest,
        changes,
        deletions,
        scenes,
        conflicts,
        notes,
        skipped_types=len(code.messages.skipped),
        recovered_lock=recovered,
    )


def _last_lock(manifest: Manifest, journal: Path) -> tuple[LockFile, bytes | None]:
    """The lock the last apply left, and, when that apply was interrupted (its journal is still
    there), the lock recovered from both, rendered: what it may have done counts as done."""
    lock = LockFile.read(lock_path(manifest.path))
    if not journal.exists():
        return lock, None
    lock = lock.recovered(LockFile.read(journal), manifest.project_root)
    return lock, lock.render().encode("utf-8")


def _new_lock(
    manifest: Manifest,
    generated: list[DesiredFile],
    user: UserFiles,
    pruning: Pruning,
    scenes: Sequence[ScenePlan],
    folders: frozenset[str],
) -> LockFile:
    """The lock this apply leaves: what it generated, and what the scenes hold of its making."""
    return LockFile(
        files={
            **pruning.kept_files,
            **{manifest.asset_path(d.path): sha256(d.content) for d in generated},
        },
        user_files={**pruning.kept_user_files, **user.digests},
        components=tuple(sorted({c for s in scenes for c in s.components})),
        gameobjects=tuple(
            LockGameObject(s.relative, path, file_id)
            for s in scenes
            for path, file_id in sorted(s.gameobjects.items())
        ),
        kept=frozenset(pruning.kept_files) | frozenset(pruning.kept_user_files),
        robots=tuple(sorted(r for s in scenes for r in s.robots)),
        folders=folders,
        primitives=tuple(sorted(p for s in scenes for p in s.primitives)),
    )


def _robot_folders(
    robots: Iterable[PlannedRobot], lock: LockFile, project: Path, deletions: list[Path]
) -> frozenset[str]:
    """The robots' asset folders, and the ones an earlier apply made that are still there."""
    gone = set(deletions)
    kept = {f for f in lock.folders if (project / f) not in gone and (project / f).is_dir()}
    return frozenset(f for r in robots for f in r.folders) | kept
