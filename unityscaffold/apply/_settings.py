"""The ``ROS2`` scripting define in ``ProjectSettings/ProjectSettings.asset``.

ROS#'s messages compile for ROS 1 or ROS 2 depending on this define, and ROS#'s RosConnector
inspector rewrites it from ``selectedRosVersion`` whenever it is shown; keeping both in line
with the manifest avoids a silent flip. The edit is a text edit of the
``scriptingDefineSymbols`` block, which Unity writes either empty (``{}``) or as one
``Group: A;B`` line per build target group.

Unity keeps defines per build target group, and ROS# reads the define of the group being
built, so for ROS 2 every group Unity 2022.3 can build for without a console SDK gets it
(``GROUPS``, under the names Unity writes), plus any other group the file already lists.
A file checked out with CRLF line endings keeps them.
"""

from __future__ import annotations

import re

__all__ = ["DEFINE", "with_ros_define"]

DEFINE = "ROS2"
#: Build target groups as ProjectSettings.asset names them (``iPhone`` is iOS, ``Windows Store
#: Apps`` is UWP); Unity lists them in this (ordinal) order.
GROUPS = (
    "Android",
    "EmbeddedLinux",
    "LinuxHeadlessSimulation",
    "QNX",
    "Server",
    "Standalone",
    "VisionOS",
    "WebGL",
    "Windows Store Apps",
    "iPhone",
    "tvOS",
)
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
    if "\r\n" in text:
        lf = text.replace("\r\n", "\n")
        edited = _with_ros_define(lf, ros2)
        return text if edited == lf else edited.replace("\n", "\r\n")
    return _with_ros_define(text, ros2)


def _block(indent: str, entries: list[tuple[str, str]]) -> str:
    if not entries:
        return f"{indent}scriptingDefineSymbols: {{}}\n"
    return f"{indent}scriptingDefineSymbols:\n" + "".join(
        f"{indent}  {key}: {value}\n" for key, value in entries
    )


def _with_ros_define(text: str, ros2: bool) -> str:
    match = _BLOCK.search(text)
    if match is None:
        if not ros2:
            return text
        anchor = re.search(r"^PlayerSettings:\n", text, re.M)
        if anchor is None:
            return text
        end = anchor.end()
        return text[:end] + _block("  ", [(group, DEFINE) for group in GROUPS]) + text[end:]
    indent, rest = match["indent"], match["rest"].strip()
    entries: list[tuple[str, str]] = []
    for line in match["items"].splitlines():
        key, _, value = line.strip().partition(":")
        entries.append((key, value.strip()))
    if rest not in ("", "{}"):
        return text  # an inline form Unity does not write; leave it to the user
    if ros2:
        listed = {key for key, _ in entries}
        entries += [(group, "") for group in GROUPS if group not in listed]
        entries.sort(key=lambda entry: entry[0])
    edited = [(key, _edit(value, ros2)) for key, value in entries]
    kept = [(key, value) for key, value in edited if value]
    return text[: match.start()] + _block(indent, kept) + text[match.end() :]
