"""Reading the lock's JSON: each part checked for its shape, and a part with the wrong one told
by its JSON path, so the user sees which line of the file to mend."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import PurePosixPath
from typing import TypedDict

from unityscaffold.apply._lock_records import (
    LockComponent,
    LockGameObject,
    LockPrimitive,
    LockRobot,
)

__all__ = ["LOCK_VERSION", "LockFields", "Malformed", "read_lock"]

LOCK_VERSION = 1


class LockFields(TypedDict):
    """What a lock file holds, by ``LockFile``'s field names."""

    files: dict[str, str]
    user_files: dict[str, str]
    components: tuple[LockComponent, ...]
    gameobjects: tuple[LockGameObject, ...]
    kept: frozenset[str]
    robots: tuple[LockRobot, ...]
    folders: frozenset[str]
    primitives: tuple[LockPrimitive, ...]


class Malformed(Exception):
    """A part of the lock with the wrong shape, told by its JSON path.

    Such as ``files["Assets/a.cs"] should be a sha256 string, found the number 1``.
    """

    def __init__(self, detail: str) -> None:
        super().__init__(detail)
        self.detail = detail


_MISSING = object()  # a key the lock does not have


def _wrong(where: str, expected: str, value: object) -> Malformed:
    return Malformed(f"{where} should be {expected}, found {_describe(value)}")


def _describe(value: object) -> str:
    """A JSON value in the user's words, short enough for one line."""
    if value is _MISSING:
        return "nothing"
    if value is None or isinstance(value, bool):
        return json.dumps(value)
    if isinstance(value, int | float):
        return f"the number {value}"
    if isinstance(value, str):
        return "the string " + json.dumps(value, ensure_ascii=False)
    return "a list" if isinstance(value, list) else "an object"


def _object(value: object, where: str) -> dict[str, object]:
    if not isinstance(value, dict):
        raise _wrong(where, "an object", value)
    return value


def _string(value: object, where: str, expected: str = "a string") -> str:
    if not isinstance(value, str):
        raise _wrong(where, expected, value)
    return value


_INSIDE_ASSETS = "a path inside the project's Assets/ folder"


def _inside_assets(path: str) -> bool:
    """The lock decides what apply deletes and which scenes it edits, so a lock edited by hand
    (or by a bad merge) must not be able to point outside ``Assets/``."""
    parts = PurePosixPath(path).parts
    return bool(parts) and parts[0] == "Assets" and ".." not in parts and "\\" not in path


def _asset_map(data: dict[str, object], key: str) -> dict[str, str]:
    entries = _object(data.get(key, _MISSING), key)
    found = {}
    for path, digest in entries.items():
        shown = json.dumps(path, ensure_ascii=False)
        if not _inside_assets(path):
            raise Malformed(f"{key} has the key {shown}, which is not {_INSIDE_ASSETS}")
        found[path] = _string(digest, f"{key}[{shown}]", "a sha256 string")
    return found


def _file_id(value: object, where: str) -> int:
    if type(value) is not int or not 0 < value < 1 << 63:
        raise _wrong(where, "a fileID (a positive 64-bit integer)", value)
    return value


def _per_scene(data: dict[str, object], key: str) -> Iterator[tuple[str, str, object, str]]:
    """``(scene, path, value, where)`` for each entry of ``key``, a map of scene paths to maps
    of GameObject paths."""
    for scene, entries in _object(data.get(key, {}), key).items():
        shown = json.dumps(scene, ensure_ascii=False)
        if not _inside_assets(scene):
            raise Malformed(f"{key} has the key {shown}, which is not {_INSIDE_ASSETS}")
        for path, value in _object(entries, f"{key}[{shown}]").items():
            yield scene, path, value, f"{key}[{shown}][{json.dumps(path, ensure_ascii=False)}]"


def _file_ids(value: object, where: str) -> tuple[int, ...]:
    if not isinstance(value, list):
        raise _wrong(where, "a list of fileIDs", value)
    return tuple(_file_id(i, f"{where}[{n}]") for n, i in enumerate(value))


def _gameobjects(data: dict[str, object]) -> tuple[LockGameObject, ...]:
    return tuple(
        LockGameObject(scene, path, _file_id(file_id, where))
        for scene, path, file_id, where in _per_scene(data, "gameobjects")
    )


def _components(data: dict[str, object]) -> tuple[LockComponent, ...]:
    entries = data.get("components", _MISSING)
    if not isinstance(entries, list):
        raise _wrong("components", "a list", entries)
    found = []
    for index, entry in enumerate(entries):
        where = f"components[{index}]"
        item = _object(entry, where)
        scene, gameobject, script = (
            _string(item.get(key, _MISSING), f"{where}.{key}")
            for key in ("scene", "gameobject", "script")
        )
        entry_name = _string(item.get("entry", ""), f"{where}.entry")
        file_id = _file_id(item["file_id"], f"{where}.file_id") if "file_id" in item else 0
        if not _inside_assets(scene):
            raise _wrong(f"{where}.scene", _INSIDE_ASSETS, scene)
        found.append(LockComponent(scene, gameobject, script, entry_name, file_id))
    return tuple(found)


def _robots(data: dict[str, object]) -> tuple[LockRobot, ...]:
    adopted = _adopted(data)
    return tuple(
        LockRobot(scene, path, _file_ids(ids, where), adopted.get((scene, path), ()))
        for scene, path, ids, where in _per_scene(data, "robots")
    )


def _adopted(data: dict[str, object]) -> dict[tuple[str, str], tuple[tuple[str, int], ...]]:
    return {
        (scene, path): tuple(
            (slot, _file_id(i, f"{where}[{json.dumps(slot)}]"))
            for slot, i in sorted(_object(slots, where).items())
        )
        for scene, path, slots, where in _per_scene(data, "adopted")
    }


def _primitives(data: dict[str, object]) -> tuple[LockPrimitive, ...]:
    found = []
    for scene, path, made, where in _per_scene(data, "primitives"):
        item = _object(made, where)
        shape = _string(item.get("shape", _MISSING), f"{where}.shape")
        file_ids = _file_ids(item.get("file_ids", _MISSING), f"{where}.file_ids")
        found.append(LockPrimitive(scene, path, shape, file_ids))
    return tuple(found)


def _asset_paths(data: dict[str, object], key: str) -> frozenset[str]:
    entries = data.get(key, [])
    if not isinstance(entries, list):
        raise _wrong(key, "a list", entries)
    for index, path in enumerate(entries):
        if not _inside_assets(_string(path, f"{key}[{index}]")):
            raise _wrong(f"{key}[{index}]", _INSIDE_ASSETS, path)
    return frozenset(entries)


def read_lock(text: str) -> LockFields:
    """The fields of the lock in ``text``; raises ``Malformed`` or ``ValueError``."""
    data = _object(json.loads(text), "the whole file")
    version = data.get("version", _MISSING)
    if type(version) is not int or version != LOCK_VERSION:
        raise _wrong("version", str(LOCK_VERSION), version)
    return LockFields(
        files=_asset_map(data, "files"),
        user_files=_asset_map(data, "user_files"),
        components=_components(data),
        gameobjects=_gameobjects(data),
        kept=_asset_paths(data, "kept"),
        robots=_robots(data),
        folders=_asset_paths(data, "folders"),
        primitives=_primitives(data),
    )
