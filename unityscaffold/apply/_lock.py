"""The lock file next to the manifest: what the last ``apply`` generated.

It records every generated file with the sha256 of what apply wrote (so a hand edit can be told
from an outdated file), the user files apply created (so an untouched one can be removed with
its script), the scene components apply attached (so they can be pruned when the manifest
drops them), the fileIDs of those components and of the GameObjects apply made or adopted, and
the built-in components an object's ``primitive`` made (so a new shape can replace them).
The fileIDs are the objects' identity: a GameObject renamed or re-parented in Unity keeps its
fileID, so apply can tell it moved instead of creating a second one under the old name. Paths
are relative to the Unity project, so the lock survives moving the project.

A lock written before fileIDs were recorded (no ``gameobjects``, no ``file_id``) still reads:
such entries are matched by path, as they were then, and the next apply records the fileIDs.

``kept`` lists the files apply would have removed but kept because they were edited by hand; it
was told once, in the run that kept them, and is not told again while they stay. A lock from
before it was recorded has none, so such a file is told about once more.

``folders`` lists the asset folders apply gave a ``.meta`` for a robot's files, for as long as
they are on disk: one a user's file holds up when the robot goes is removed, with its ``.meta``,
by the first apply that finds it empty.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.apply._lock_read import LOCK_VERSION, Malformed, read_lock
from unityscaffold.apply._lock_records import (
    LockComponent,
    LockGameObject,
    LockPrimitive,
    LockRobot,
)
from unityscaffold.errors import UserError

__all__ = [
    "LOCK_VERSION",
    "LockComponent",
    "LockFile",
    "LockGameObject",
    "LockPrimitive",
    "LockRobot",
    "journal_path",
    "lock_path",
    "recorded",
    "sha256",
]


def sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def recorded(data: bytes, digest: str | None) -> bool:
    """Whether ``data`` is what apply wrote when it recorded ``digest``, also after a checkout
    turned its LF line endings into CRLF (apply writes LF)."""
    if digest is None:
        return False
    return sha256(data) == digest or sha256(data.replace(b"\r\n", b"\n")) == digest


def lock_path(manifest: Path) -> Path:
    """``robot.yaml`` -> ``robot.lock.json`` beside it."""
    return manifest.with_name(f"{manifest.stem}.lock.json")


def journal_path(manifest: Path) -> Path:
    """``robot.yaml`` -> ``robot.lock.pending.json``: the lock an apply is about to make true.

    It is written before the first file is replaced and removed after the lock; one left behind
    means that apply was interrupted, and the next run reads both (``LockFile.recovered``).
    """
    return manifest.with_name(f"{manifest.stem}.lock.pending.json")


@dataclass(frozen=True, slots=True)
class LockFile:
    files: dict[str, str] = field(default_factory=dict)
    user_files: dict[str, str] = field(default_factory=dict)
    components: tuple[LockComponent, ...] = ()
    gameobjects: tuple[LockGameObject, ...] = ()
    kept: frozenset[str] = frozenset()  # files kept as edited by hand, and told so
    robots: tuple[LockRobot, ...] = ()
    folders: frozenset[str] = frozenset()  # asset folders apply made for robots

    primitives: tuple[LockPrimitive, ...] = ()

    def primitives_in(self, scene: str) -> dict[str, LockPrimitive]:
        """Object path -> its primitive as apply last made it, in ``scene``."""
        return {p.gameobject: p for p in self.primitives if p.scene == scene}

    def robot_ids(self, scene: str, gameobject: str) -> frozenset[int]:
        """The fileIDs apply made for the robot at ``gameobject`` in ``scene``."""
        return frozenset(
            i
            for r in self.robots
            if (r.scene, r.gameobject) == (scene, gameobject)
            for i in r.file_ids
        )

    def robot_adopted(self, scene: str, gameobject: str) -> dict[str, int]:
        """The fileIDs apply took over from the robot at ``gameobject`` imported by hand, by
        slot (see ``LockRobot``)."""
        return {
            slot: i
            for r in self.robots
            if (r.scene, r.gameobject) == (scene, gameobject)
            for slot, i in r.adopted
        }

    def gameobjects_in(self, scene: str) -> dict[str, int]:
        """Path -> fileID of the GameObjects recorded in ``scene``."""
        return {g.path: g.file_id for g in self.gameobjects if g.scene == scene}

    @classmethod
    def read(cls, path: Path) -> LockFile:
        """The lock at ``path``; an empty one when there is none yet."""
        try:
            data = path.read_bytes()
        except FileNotFoundError:
            return cls()
        except OSError as exc:
            raise UserError(f"cannot read {path}: {exc.strerror}") from None
        try:
            return cls(**read_lock(data.decode("utf-8")))
        except UnicodeDecodeError:
            detail = "it is not UTF-8 text"
        except json.JSONDecodeError as exc:
            reason = exc.msg[:1].lower() + exc.msg[1:]
            detail = f"invalid JSON at line {exc.lineno}, column {exc.colno} ({reason})"
        except Malformed as exc:
            detail = exc.detail
        raise UserError(
            f"{path} is not a valid unityscaffold lock file: {detail}",
            hint="restore it from git, or delete it and run apply again to rebuild it "
            "(generated files that differ from the new output then count as hand edits)",
        )

    def recovered(self, journal: LockFile, root: Path) -> LockFile:
        """What is on disk after an apply that wrote ``journal`` was interrupted, somewhere
        between its first replaced file and its lock: every file and object either lock knows.

        A file known to both keeps the digest its content matches (the journal's when neither
        does: then it was edited by hand either way); components and GameObjects are the union,
        so the next run prunes what the interrupted one added and the manifest no longer wants;
        a primitive has the journal's shape and what either made.
        """

        def merge(old: dict[str, str], new: dict[str, str]) -> dict[str, str]:
            merged = {**old, **new}
            for relative in old.keys() & new.keys():
                if old[relative] != new[relative]:
                    try:
                        data = (root / relative).read_bytes()
                    except OSError:
                        continue
                    if recorded(data, old[relative]):
                        merged[relative] = old[relative]
            return merged

        newer = {(g.scene, g.path) for g in journal.gameobjects}
        return LockFile(
            merge(self.files, journal.files),
            merge(self.user_files, journal.user_files),
            tuple(sorted(set(self.components) | set(journal.components))),
            tuple(
                sorted(
                    {*journal.gameobjects}
                    | {g for g in self.gameobjects if (g.scene, g.path) not in newer}
                )
            ),
            self.kept | journal.kept,
            tuple(
                LockRobot(
                    scene,
                    path,
                    tuple(sorted(self.robot_ids(scene, path) | journal.robot_ids(scene, path))),
                    tuple(
                        sorted(
                            {
                                **self.robot_adopted(scene, path),
                                **journal.robot_adopted(scene, path),
                            }.items()
                        )
                    ),
                )
                for scene, path in sorted(
                    {(r.scene, r.gameobject) for r in (*self.robots, *journal.robots)}
                )
            ),
            self.folders | journal.folders,
            _merged_primitives(self.primitives, journal.primitives),
        )

    def render(self) -> str:
        """Deterministic JSON: sorted keys and entries, LF, final newline."""
        data = {
            "version": LOCK_VERSION,
            "generated_by": "unityscaffold",
            "files": dict(sorted(self.files.items())),
            "user_files": dict(sorted(self.user_files.items())),
            "components": [
                {
                    "scene": c.scene,
                    "gameobject": c.gameobject,
                    "script": c.script,
                    "entry": c.entry,
                    **({"file_id": c.file_id} if c.file_id else {}),
                }
                for c in sorted(set(self.components))
            ],
            "gameobjects": {
                scene: {g.path: g.file_id for g in sorted(self.gameobjects) if g.scene == scene}
                for scene in sorted({g.scene for g in self.gameobjects})
            },
            # only when there are any: locks without kept files read as they did before
            **({"kept": sorted(self.kept)} if self.kept else {}),
            **({"robots": robots} if (robots := self._rendered_robots()) else {}),
            **({"adopted": adopted} if (adopted := self._rendered_adopted()) else {}),
            **({"folders": sorted(self.folders)} if self.folders else {}),
            **({"primitives": made} if (made := self._rendered_primitives()) else {}),
        }
        return json.dumps(data, indent=2, sort_keys=False, ensure_ascii=False) + "\n"

    def _rendered_robots(self) -> dict[str, dict[str, list[int]]]:
        """Scene -> robot -> fileIDs; entries of one robot merged, empty ones left out."""
        found: dict[str, dict[str, list[int]]] = {}
        for scene, robot in sorted({(r.scene, r.gameobject) for r in self.robots}):
            ids = sorted(self.robot_ids(scene, robot))
            if ids:
                found.setdefault(scene, {})[robot] = ids
        return found

    def _rendered_adopted(self) -> dict[str, dict[str, dict[str, int]]]:
        """Scene -> robot -> slot -> fileID, for robots taken over from a hand import."""
        found: dict[str, dict[str, dict[str, int]]] = {}
        for scene, robot in sorted({(r.scene, r.gameobject) for r in self.robots}):
            slots = self.robot_adopted(scene, robot)
            if slots:
                found.setdefault(scene, {})[robot] = dict(sorted(slots.items()))
        return found

    def _rendered_primitives(self) -> dict[str, dict[str, dict[str, object]]]:
        """Scene -> object path -> shape and fileIDs; only when there are any, so locks without
        primitives read as they did before."""
        found: dict[str, dict[str, dict[str, object]]] = {}
        for p in sorted(set(self.primitives)):
            made: dict[str, object] = {"shape": p.shape, "file_ids": sorted(p.file_ids)}
            found.setdefault(p.scene, {})[p.gameobject] = made
        return found


def _merged_primitives(
    old: tuple[LockPrimitive, ...], new: tuple[LockPrimitive, ...]
) -> tuple[LockPrimitive, ...]:
    """The journal's primitives over the lock's: its shape, and the fileIDs of both (what the
    interrupted run made may or may not have reached the scene)."""
    merged = {(p.scene, p.gameobject): p for p in old}
    for p in new:
        before = merged.get((p.scene, p.gameobject))
        ids = set(p.file_ids) | set(before.file_ids if before else ())
        merged[(p.scene, p.gameobject)] = LockPrimitive(
            p.scene, p.gameobject, p.shape, tuple(sorted(ids))
        )
    return tuple(sorted(merged.values()))
