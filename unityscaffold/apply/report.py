"""Words for a plan: the summary, the unified diff, and the JSON form for scripts."""

from __future__ import annotations

import difflib
import os
from typing import Any

from unityscaffold.apply.plan import Plan
from unityscaffold.fileout import ChangeKind

__all__ = ["plan_diff", "plan_json", "plan_summary"]


def plan_summary(plan: Plan, *, verbose: bool = True, manifest_as: str | None = None) -> str:
    """The plan in words; its header names the manifest ``manifest_as`` (as the user typed it),
    by default relative to the current folder."""
    counts = {kind: 0 for kind in ChangeKind}
    for change in plan.changes:
        counts[change.kind] += 1
    m = plan.manifest
    unchanged = counts[ChangeKind.UNCHANGED] + counts[ChangeKind.SKIP]
    lines = [
        f"{manifest_as or os.path.relpath(m.path)}: Unity project {m.project_root} "
        f"(ROS {int(m.ros)})",
        f"files: {counts[ChangeKind.CREATE]} to create, {counts[ChangeKind.UPDATE]} to update, "
        f"{len(plan.deletions)} to remove, {unchanged} unchanged",
    ]
    if verbose:
        for change in plan.changes:
            if change.writes:
                lines.append(f"  {change.kind.value:<7} {plan.relative(change.path)}")
        lines += [f"  remove  {plan.relative(path)}" for path in plan.deletions]
    for scene in plan.scenes:
        if scene.edits:
            lines.append(f"scene {scene.relative}:")
            lines += [f"  {edit}" for edit in scene.edits]
    lines += [f"note: {note}" for note in plan.notes]
    lines += [
        f"edited by hand (apply will stop; apply --force overwrites): {c}" for c in plan.conflicts
    ]
    if plan.in_sync and not plan.conflicts:
        lines.append("the project matches the manifest")
    return "\n".join(lines)


def _text(data: bytes) -> list[str]:
    # CRLF is read as LF, as when planning: a Windows checkout is not a change on every line.
    text = data.decode("utf-8", errors="replace").replace("\r\n", "\n")
    return text.splitlines(keepends=True)


def plan_diff(plan: Plan) -> str:
    """Unified diffs of updated and removed files (new files are listed in the summary)."""
    parts: list[str] = []
    for change in plan.changes:
        if change.kind is not ChangeKind.UPDATE:
            continue
        name = plan.relative(change.path)
        before = _text(change.path.read_bytes())
        parts += difflib.unified_diff(before, _text(change.content), f"a/{name}", f"b/{name}")
    for path in plan.deletions:
        if path.is_dir():
            continue  # an empty folder: nothing to show
        name = plan.relative(path)
        parts += difflib.unified_diff(_text(path.read_bytes()), [], f"a/{name}", "/dev/null")
    return "".join(parts)


def plan_json(plan: Plan) -> dict[str, Any]:
    return {
        "manifest": str(plan.manifest.path),
        "project": str(plan.manifest.project_root),
        "in_sync": plan.in_sync and not plan.conflicts,
        "files": [
            {"path": plan.relative(c.path), "action": c.kind.value}
            for c in plan.changes
            if c.writes
        ],
        "removed": [plan.relative(p) for p in plan.deletions],
        "scenes": [{"path": s.relative, "actions": s.edits} for s in plan.scenes if s.edits],
        "conflicts": plan.conflicts,
        "notes": plan.notes,
    }
