"""The lock file next to the manifest: what the last ``apply`` generated.

It records every generated file with the sha256 of what apply wrote (so a hand edit can be told
from an outdated file), the user files apply created (so an untouched one can be removed with
its script), and the scene components apply attached (so they can be pruned when the manifest
drops them). Paths are relative to the Unity project, so the lock survives moving the project.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

from unityscaffold.errors import UserError

__all__ = ["LOCK_VERSION", "LockComponent", "LockFile", "lock_path", "sha256"]

LOCK_VERSION = 1


def sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def lock_path(manifest: Path) -> Path:
    """``robot.yaml`` -> ``robot.lock.json`` beside it."""
    return manifest.with_name(f"{manifest.stem}.lock.json")


@dataclass(frozen=True, slots=True, order=True)
class LockComponent:
    """A component apply attached: scene, GameObject path and script GUID identify it."""

    scene: str
    gameobject: str
    script: str
    source: str = ""  # what in the manifest asked for it, e.g. "topic /odom"


def asset_path(value: object) -> str:
    """A project-relative path from the lock, refused unless it stays inside ``Assets/``.

    The lock decides what apply deletes and which scenes it edits, so a lock edited by hand
    (or by a bad merge) must not be able to point anywhere else.
    """
    if not isinstance(value, str):
        raise TypeError(f"expected a path, found {value!r}")
    parts = PurePosixPath(value).parts
    if (
        not parts
        or parts[0] != "Assets"
        or ".." in parts
        or "\\" in value
        or PurePosixPath(value).is_absolute()
    ):
        raise ValueError(f"{value!r} is not a path inside the project's Assets/ folder")
    return value


def _asset_map(data: dict[object, object]) -> dict[str, str]:
    found = {}
    for key, value in data.items():
        if not isinstance(value, str):
            raise TypeError(f"expected a sha256 for {key!r}, found {value!r}")
        found[asset_path(key)] = value
    return found


def _component(data: dict[str, object]) -> LockComponent:
    values = {key: data[key] for key in ("scene", "gameobject", "script")}
    values["source"] = data.get("source", "")
    if not all(isinstance(v, str) for v in values.values()):
        raise TypeError(f"component entries hold strings, found {data!r}")
    asset_path(values["scene"])
    return LockComponent(**values)  # type: ignore[arg-type]


@dataclass(frozen=True, slots=True)
class LockFile:
    files: dict[str, str] = field(default_factory=dict)
    user_files: dict[str, str] = field(default_factory=dict)
    components: tuple[LockComponent, ...] = ()

    @classmethod
    def read(cls, path: Path) -> LockFile:
        """The lock at ``path``; an empty one when there is none yet."""
        try:
            text = path.read_text(encoding="utf-8")
        except FileNotFoundError:
            return cls()
        except OSError as exc:
            raise UserError(f"cannot read {path}: {exc.strerror}") from None
        try:
            data = json.loads(text)
            if data.get("version") != LOCK_VERSION:
                raise ValueError(f"unsupported lock version {data.get('version')!r}")
            return cls(
                files=_asset_map(data["files"]),
                user_files=_asset_map(data["user_files"]),
                components=tuple(_component(c) for c in data["components"]),
            )
        except (ValueError, KeyError, TypeError, AttributeError) as exc:
            raise UserError(
                f"{path} is not a valid unityscaffold lock file: {exc}",
                hint="restore it from git, or delete it to start over (apply will "
                "then treat existing generated files as hand-made)",
            ) from None

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
                    "source": c.source,
                }
                for c in sorted(set(self.components))
            ],
        }
        return json.dumps(data, indent=2, sort_keys=False, ensure_ascii=False) + "\n"
