"""Unified diffs of scene text, cheap even for very large files with few changes."""

from __future__ import annotations

import difflib

__all__ = ["diff"]


def diff(original_text: str, new_text: str, path: str, *, context: int = 3) -> str:
    """A unified diff (``a/path`` → ``b/path``); empty when the texts are equal.

    The common head and tail are cut off before ``difflib`` runs, so the cost follows the
    changed region rather than the file size.
    """
    if original_text == new_text:
        return ""
    old = original_text.splitlines(keepends=True)
    new = new_text.splitlines(keepends=True)
    head = 0
    limit = min(len(old), len(new))
    while head < limit and old[head] == new[head]:
        head += 1
    tail = 0
    while tail < limit - head and old[-1 - tail] == new[-1 - tail]:
        tail += 1
    start = max(0, head - context)
    old_mid = old[start : len(old) - max(0, tail - context)]
    new_mid = new[start : len(new) - max(0, tail - context)]
    label = path.replace("\\", "/").lstrip("/")
    lines = list(difflib.unified_diff(old_mid, new_mid, f"a/{label}", f"b/{label}", n=context))
    return "".join(_shift(line, start) for line in lines)


def _shift(line: str, offset: int) -> str:
    """Renumber a hunk header of a diff computed on a slice starting after ``offset`` lines."""
    if line.startswith("@@") and offset:
        old, new = line.split(" ")[1:3]
        return f"@@ {_moved(old, offset)} {_moved(new, offset)} @@\n"
    if not line.endswith("\n"):
        return line + "\n\\ No newline at end of file\n"
    return line


def _moved(spec: str, offset: int) -> str:
    first, comma, count = spec[1:].partition(",")
    return f"{spec[0]}{int(first) + offset}{comma}{count}"
