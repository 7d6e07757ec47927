"""GameObjects known by identity (their fileID), not by name.

The lock records the fileID of every GameObject apply made or adopted. Unity keeps an object's
fileID when it is renamed or re-parented, so a recorded fileID found under another path means the
object moved in Unity since the last apply. Looking it up by its old name would find nothing and
create a second one (and a second copy of each of its components), so apply stops instead and
names the manifest lines to change; with ``--follow-renames`` it uses the object where it is now
and rewrites those lines itself, which keeps the manifest the one source of truth.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import PurePosixPath
from typing import Protocol

from unityscaffold.errors import Diagnostic, LocatedError, SourceLocation, UserError
from unityscaffold.unity import SceneDocument

__all__ = [
    "Moved",
    "Named",
    "follow_in_manifest",
    "followed_notes",
    "moved_objects",
    "now_at",
    "report_moves",
]

_FOLLOW = "apply --follow-renames"


@dataclass(frozen=True, slots=True)
class Named:
    """A GameObject path the manifest names: an entry's ``gameobject`` or an ``@Path`` value."""

    path: str
    location: SourceLocation
    reference: bool = False


@dataclass(frozen=True, slots=True)
class Moved:
    """A manifest path whose GameObject (or a parent of it) Unity renamed or moved."""

    named: Named
    now: str


def moved_objects(doc: SceneDocument, recorded: Mapping[str, int]) -> dict[str, str]:
    """Recorded path -> the path the same GameObject has now, for each one that moved.

    A recorded path that names a GameObject again (one made in Unity after the rename) is left
    out, with the recorded paths under it: the manifest's path then means that object, and what
    apply had attached to the moved one is pruned by fileID like any component the manifest no
    longer asks for.
    """
    paths = doc.hierarchy.paths
    moved = {
        old: paths[file_id]
        for old, file_id in recorded.items()
        if file_id in paths and paths[file_id] != old
    }
    taken = set(paths.values())
    replaced = [old for old in moved if old in taken]
    return {
        old: new
        for old, new in moved.items()
        if not any(old == r or old.startswith(r + "/") for r in replaced)
    }


def now_at(path: str, moves: Mapping[str, str]) -> str | None:
    """Where the object the manifest calls ``path`` is now, when it or a parent moved."""
    names = path.strip("/").split("/")
    for level in range(len(names), 0, -1):
        found = moves.get("/".join(names[:level]))
        if found is not None:
            return "/".join([found, *names[level:]])
    return None


def report_moves(scene: str, moved: list[Moved]) -> LocatedError:
    """One diagnostic per renamed object, naming every manifest line that still has the old name."""
    groups: dict[tuple[str, str], list[Named]] = {}
    for item in sorted(moved, key=lambda m: (m.named.location.line, m.named.location.col)):
        groups.setdefault((item.named.path, item.now), []).append(item.named)
    problems = []
    for (old, new), named in groups.items():
        lines = ", ".join(sorted({_line(n.location) for n in named}, key=_line_key))
        problems.append(
            Diagnostic(
                named[0].location,
                f"`{old}` is now `{new}` in {PurePosixPath(scene).name} (renamed or moved in "
                f"Unity since the last apply); rename it at {lines}",
                hint=f"change the manifest to `{new}`, or run {_FOLLOW} to have apply "
                f"do it; apply never creates a second `{old}` beside the one it made",
            )
        )
    return LocatedError(problems)


def followed_notes(scenes: Iterable[HasFollowed]) -> list[str]:
    """One line per GameObject followed to its new path, with the manifest lines that take it.
    Worded for the plan as much as for the run, since --dry-run prints it too."""
    notes = []
    for scene in scenes:
        groups: dict[tuple[str, str], set[str]] = {}
        for item in scene.followed:
            groups.setdefault((item.named.path, item.now), set()).add(_line(item.named.location))
        for (old, new), lines in groups.items():
            shown = ", ".join(sorted(lines, key=_line_key))
            notes.append(
                f"`{old}` is now `{new}` in {PurePosixPath(scene.relative).name}: followed; "
                f"{shown} take the new path"
            )
    return notes


class HasFollowed(Protocol):
    relative: str
    followed: list[Moved]


def _line(location: SourceLocation) -> str:
    return f"{PurePosixPath(location.path).name}:{location.line}"


def _line_key(text: str) -> tuple[str, int]:
    name, _, line = text.rpartition(":")
    return name, int(line)


# A plain YAML scalar that stays the same string: no indicator first, no ": " or " #" inside.
_PLAIN = re.compile(r"[A-Za-z0-9_.()\[\]-][^:#\"'\\]*")
_UNSAFE = re.compile(r"[\"'\\\x00-\x1f]")


def follow_in_manifest(text: str, moved: Iterable[Moved]) -> str:
    """The manifest with each moved path rewritten where it is named, all else byte for byte."""
    lines = text.splitlines(keepends=True)
    for item in sorted(moved, key=lambda m: (m.named.location.line, -m.named.location.col)):
        where = item.named.location
        index = where.line - 1
        if not 0 <= index < len(lines) or _UNSAFE.search(item.now):
            raise _cannot_follow(item)
        line = lines[index]
        start = max(where.col - 1, 0)
        head, tail = line[:start], line[start:]
        if item.named.reference:
            new_tail = _follow_reference(tail, item)
        else:
            new_tail = _follow_value(tail, item)
        if new_tail is None:
            raise _cannot_follow(item)
        lines[index] = head + new_tail
    return "".join(lines)


def _follow_value(tail: str, item: Moved) -> str | None:
    old, new = item.named.path, item.now
    if tail[:1] in ("'", '"') and tail[1:].startswith(old + tail[0]):
        return tail[0] + new + tail[1 + len(old) :]
    if tail.startswith(old) and not _continues(tail[len(old) :]):
        shown = new if _PLAIN.fullmatch(new) and new == new.strip() else json.dumps(new)
        return shown + tail[len(old) :]
    return None


def _continues(rest: str) -> bool:
    """Whether a plain scalar goes on after a prefix (``Robot`` in ``Robot/Lidar``)."""
    return bool(rest) and rest[0] not in " \t\r\n,}]#"


def _follow_reference(tail: str, item: Moved) -> str | None:
    """``"@Old"``, ``"@Old:Class"`` and every such item of a list on the line."""
    pattern = re.compile(re.escape("@" + item.named.path) + r"(?=[\"':,\]} \t\r\n]|$)")
    replaced, count = pattern.subn(lambda _: "@" + item.now, tail)
    return replaced if count else None


def _cannot_follow(item: Moved) -> UserError:
    return LocatedError.at(
        item.named.location,
        f"`{item.named.path}` is now `{item.now}`, and {_FOLLOW} cannot rewrite this line "
        "by itself",
        hint=f"change it to `{item.now}` by hand",
    )
