"""GameObjects known by identity (their fileID), not by name.

The lock records the fileID of every GameObject apply made or adopted. Unity keeps an object's
fileID when it is renamed or re-parented, so a recorded fileID found under another path means the
object moved in Unity since the last apply, whatever now sits at the old path (a re-imported
robot, a new empty object): the recorded object wins. Looking it up by its old name would create
a second one, or take the newcomer, and move the components apply attached (with the settings the
user gave them) from one GameObject to another, so apply stops instead and names the manifest
lines to change; with ``--follow-renames`` it uses the object where it is now and rewrites those
lines itself, which keeps the manifest the one source of truth. The same records tell apart two
same-named siblings: the one apply made is the one meant (``recorded_now``).
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import PurePosixPath
from typing import Literal, Protocol

from unityscaffold.errors import Diagnostic, LocatedError, SourceLocation, UserError
from unityscaffold.unity import SceneDocument

__all__ = [
    "Implied",
    "Moved",
    "Named",
    "follow_in_manifest",
    "followed_notes",
    "moved_objects",
    "now_at",
    "recorded_now",
    "report_moves",
]

_FOLLOW = "apply --follow-renames"


#: Where a path the manifest does not write comes from: the RosConnector's default with no
#: ``connector:`` section, or with one that has no ``gameobject``; an entry without ``gameobject``
#: (the RosConnector's, in a scene other than the RosConnector's).
Implied = Literal["", "section", "connector", "entry"]


@dataclass(frozen=True, slots=True)
class Named:
    """A GameObject path the manifest names: an entry's ``gameobject`` or an ``@Path`` value,
    or one it implies by leaving ``gameobject`` out (``implied`` says which way)."""

    path: str
    location: SourceLocation
    reference: bool = False
    implied: Implied = ""


@dataclass(frozen=True, slots=True)
class Moved:
    """A manifest path whose GameObject (or a parent of it) Unity renamed or moved."""

    named: Named
    now: str
    replaced: bool = False  # the old path names another GameObject now


def moved_objects(doc: SceneDocument, recorded: Mapping[str, int]) -> dict[str, str]:
    """Recorded path -> the path the same GameObject has now, for each one that moved.

    A GameObject made in Unity at the old path does not change that: the recorded one is still
    the one the manifest's path meant.
    """
    paths = doc.hierarchy.paths
    return {
        old: paths[file_id]
        for old, file_id in recorded.items()
        if file_id in paths and paths[file_id] != old
    }


def recorded_now(doc: SceneDocument, recorded: Mapping[str, int]) -> dict[str, int]:
    """Where each recorded GameObject is now -> its fileID: the one meant by that path when
    same-named siblings make it ambiguous. A path two recorded objects share now is left out."""
    paths = doc.hierarchy.paths
    found: dict[str, list[int]] = {}
    for file_id in sorted(set(recorded.values())):
        if file_id in paths:
            found.setdefault(paths[file_id], []).append(file_id)
    return {path: ids[0] for path, ids in found.items() if len(ids) == 1}


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
    groups: dict[tuple[str, str, Implied], list[Moved]] = {}
    for item in sorted(moved, key=lambda m: (m.named.location.line, m.named.location.col)):
        groups.setdefault((item.named.path, item.now, item.named.implied), []).append(item)
    problems = []
    for (old, new, implied), items in groups.items():
        where = items[0].named.location
        what = f"`{old}` is now `{new}` in {PurePosixPath(scene).name} (renamed or moved in Unity "
        if implied:
            problems.append(
                Diagnostic(
                    where,
                    what
                    + f"since the last apply); {_IMPLIED[implied]} `{old}`: "
                    + _addition(implied, new),
                    hint=(
                        "write it by hand" if implied == "entry" else f"{_FOLLOW} adds it for you"
                    )
                    + f"; apply never creates a second `{old}` beside the one it made",
                )
            )
            continue
        lines = ", ".join(sorted({_line(m.named.location) for m in items}, key=_line_key))
        replaced = any(m.replaced for m in items)
        taken = f"; another GameObject is at `{old}` now" if replaced else ""
        problems.append(
            Diagnostic(
                where,
                what + f"since the last apply{taken}); rename it at {lines}",
                hint=_replaced_hint(old, new) if replaced else _moved_hint(old, new),
            )
        )
    return LocatedError(problems)


_IMPLIED: dict[Implied, str] = {
    "section": "the manifest has no `connector:` section, so the RosConnector is looked for at "
    "its default",
    "connector": "`connector:` has no `gameobject`, so the RosConnector is looked for at its "
    "default",
    "entry": "this entry has no `gameobject`, so it takes the RosConnector's,",
}


def _addition(implied: Implied, new: str) -> str:
    """What to write into the manifest so that it names ``new``."""
    if implied == "section":
        return f"add `connector: {{gameobject: {_scalar(new)}}}` to the manifest"
    if implied == "connector":
        return f"add `gameobject: {_scalar(new)}` under `connector:`"
    return f"add `gameobject: {_scalar(new)}` to this entry"


def _moved_hint(old: str, new: str) -> str:
    return (
        f"change the manifest to `{new}`, or run {_FOLLOW} to have apply do it; apply never "
        f"creates a second `{old}` beside the one it made"
    )


def _replaced_hint(old: str, new: str) -> str:
    return (
        f"change the manifest to `{new}`, or run {_FOLLOW} to have apply do it; to use the "
        f"new `{old}` instead, follow first, then change the manifest back to `{old}`: apply "
        "never moves a component from one GameObject to another unless the manifest says so"
    )


def followed_notes(scenes: Iterable[HasFollowed]) -> list[str]:
    """One line per GameObject followed to its new path, with the manifest lines that take it.
    Worded for the plan as much as for the run, since --dry-run prints it too."""
    notes = []
    for scene in scenes:
        groups: dict[tuple[str, str], set[str]] = {}
        for item in scene.followed:
            if item.named.implied:
                taken = _addition(item.named.implied, item.now).replace("add ", "added ", 1)
            else:
                taken = _line(item.named.location)
            groups.setdefault((item.named.path, item.now), set()).add(taken)
        for (old, new), lines in groups.items():
            lines_taken = sorted(t for t in lines if not t.startswith("added "))
            shown = ", ".join(sorted(lines_taken, key=_line_key))
            said = [f"{shown} take the new path"] if shown else []
            said += sorted(t for t in lines if t.startswith("added "))
            notes.append(
                f"`{old}` is now `{new}` in {PurePosixPath(scene.relative).name}: followed; "
                + "; ".join(said)
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


# A plain YAML scalar that stays the same string, in block and flow context alike: no indicator
# first, no ": " or " #" inside, no flow indicator.
_PLAIN = re.compile(r"[A-Za-z0-9_.()-][^:#\"'\\,\[\]{}]*")
_UNSAFE = re.compile(r"[\"'\\\x00-\x1f]")
_HEADER = re.compile(r"(version|ros|project|output|scene|namespace)\s*:")


def _scalar(path: str) -> str:
    """``path`` as a YAML value: plain where it can be, else double-quoted."""
    return path if _PLAIN.fullmatch(path) and path == path.strip() else json.dumps(path)


def follow_in_manifest(text: str, moved: Iterable[Moved]) -> str:
    """The manifest with each moved path rewritten where it is named, all else byte for byte;
    a RosConnector left at its default gets the ``gameobject`` it now has written out."""
    lines = text.splitlines(keepends=True)
    implied: dict[Implied, Moved] = {}
    for item in sorted(moved, key=lambda m: (m.named.location.line, -m.named.location.col)):
        if item.named.implied:
            implied.setdefault(item.named.implied, item)
            continue
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
    for item in implied.values():
        _write_connector(lines, item)
    return "".join(lines)


def _write_connector(lines: list[str], item: Moved) -> None:
    """``connector: {gameobject: NEW}`` after the header keys, or ``gameobject: NEW`` added to
    a ``connector:`` written without it; an entry's own ``gameobject`` is left to the user."""
    eol = "\r\n" if lines and lines[0].endswith("\r\n") else "\n"
    value = _scalar(item.now)
    if lines and not lines[-1].endswith("\n"):
        lines[-1] += eol
    if item.named.implied == "section":
        header = [i for i, line in enumerate(lines) if _HEADER.match(line)]
        at = header[-1] + 1 if header else len(lines)
        while at < len(lines) and lines[at][:1] in (" ", "\t") and lines[at].strip():
            at += 1  # a header value that goes on over more lines
        lines.insert(at, f"connector: {{gameobject: {value}}}{eol}")
        return
    found = [i for i, line in enumerate(lines) if re.match(r"connector\s*:", line)]
    if item.named.implied == "connector" and len(found) == 1:
        index = found[0]
        rest = lines[index].split(":", 1)[1].split(" #", 1)[0].strip()
        if not rest:  # a block mapping: the next line's indentation, else two spaces
            below = [
                ln for ln in lines[index + 1 :] if ln.strip() and not ln.lstrip().startswith("#")
            ]
            indent = len(below[0]) - len(below[0].lstrip()) if below else 0
            lines.insert(index + 1, f"{' ' * (indent or 2)}gameobject: {value}{eol}")
            return
        if rest.startswith("{"):
            head, _, tail = lines[index].partition("{")
            gap = "" if tail.lstrip().startswith("}") else ", "
            lines[index] = f"{head}{{gameobject: {value}{gap}{tail}"
            return
    raise _cannot_follow(item)


def _follow_value(tail: str, item: Moved) -> str | None:
    old, new = item.named.path, item.now
    if tail[:1] in ("'", '"') and tail[1:].startswith(old + tail[0]):
        return tail[0] + new + tail[1 + len(old) :]
    if tail.startswith(old) and not _continues(tail[len(old) :]):
        return _scalar(new) + tail[len(old) :]
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
    if item.named.implied:
        addition = _addition(item.named.implied, item.now)
        return LocatedError.at(
            item.named.location,
            f"`{item.named.path}` is now `{item.now}`, and {_FOLLOW} cannot {addition} by itself",
            hint="write it by hand",
        )
    return LocatedError.at(
        item.named.location,
        f"`{item.named.path}` is now `{item.now}`, and {_FOLLOW} cannot rewrite this line "
        "by itself",
        hint=f"change it to `{item.now}` by hand",
    )
