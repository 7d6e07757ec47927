"""The ``ROS2`` scripting define in ``ProjectSettings/ProjectSettings.asset``.

ROS#'s messages compile for ROS 1 or ROS 2 depending on this define, and ROS#'s RosConnector
inspector rewrites it from ``selectedRosVersion`` whenever it is shown; keeping both in line
with the manifest avoids a silent flip. The edit is a text edit of the
``scriptingDefineSymbols`` block, which Unity writes either empty (``{}``) or as one
``Group: A;B`` line per build target group.
"""

from __future__ import annotations

import re

__all__ = ["DEFINE", "with_ros_define"]

DEFINE = "ROS2"
_BLOCK = re.compile(
    r"^(?P<indent>[ ]+)scriptingDefineSymbols:(?P<rest>[^\n]*)\n"
    r"(?P<items>(?:(?P=indent)[ ]+[^\n]*\n)*)",
    re.M,
)


def _edit(symbols: str, want: bool) -> str:
    names = [s for s in symbols.split(";") if s and s != DEFINE]
    if want:
        names.append(DEFINE)
    return ";".join(names)


def with_ros_define(text: str, ros2: bool) -> str:
    """``text`` with ``ROS2`` defined in every build target group (ROS 2) or in none (ROS 1)."""
    match = _BLOCK.search(text)
    if match is None:
        if not ros2:
            return text
        anchor = re.search(r"^PlayerSettings:\n", text, re.M)
        if anchor is None:
            return text
        insert = f"  scriptingDefineSymbols:\n    Standalone: {DEFINE}\n"
        end = anchor.end()
        return text[:end] + insert + text[end:]
    indent, rest = match["indent"], match["rest"].strip()
    entries: list[tuple[str, str]] = []
    for line in match["items"].splitlines():
        key, _, value = line.strip().partition(":")
        entries.append((key, value.strip()))
    if rest not in ("", "{}"):
        return text  # an inline form Unity does not write; leave it to the user
    if ros2 and not entries:
        entries = [("Standalone", "")]
    edited = [(key, _edit(value, ros2)) for key, value in entries]
    kept = [(key, value) for key, value in edited if value]
    if not kept:
        block = f"{indent}scriptingDefineSymbols: {{}}\n"
    else:
        block = f"{indent}scriptingDefineSymbols:\n" + "".join(
            f"{indent}  {key}: {value}\n" for key, value in kept
        )
    return text[: match.start()] + block + text[match.end() :]
