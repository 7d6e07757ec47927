"""Regenerate ``unityscaffold/codegen/rostcp/_shipped_data.py``: ROS-TCP-Connector's own classes.

The connector decodes every incoming message with the class registered under its ROS name, so
the generator must reference the classes the package already has instead of generating a second
one, and must tell when one of them no longer matches a distro's definition. This script reads
the package's ``Runtime/Messages`` folder (``com.unity.robotics.ros-tcp-connector`` at a release
tag): per class its namespace, name, ``k_RosMessageName``, the subtopic it registers under, and
its fields as its deserializing constructor reads them (the wire order), per ROS version (the
hand-written classes differ under ``#if ROS2``).

Run:
    python3 scripts/update_tcp_shipped.py PATH/TO/com.unity.robotics.ros-tcp-connector
or set ``UNITYSCAFFOLD_ROSTCP`` to that folder. ``--check`` compares instead of writing
(exit 1 when the committed module differs). Review the result with ``git diff``.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

from _derived import write_or_check

ROOT = Path(__file__).resolve().parent.parent
TARGET = ROOT / "unityscaffold" / "codegen" / "rostcp" / "_shipped_data.py"
ENV_VAR = "UNITYSCAFFOLD_ROSTCP"
DEFAULT_TAG = "v0.7.0"
SKIPPED = ("MessageBackwardsCompat.cs", "HandwrittenMessages/action/")
DIALECTS = (1, 2)
WIDTH = 99

_NAMESPACE = re.compile(r"^namespace RosMessageTypes\.(\w+)")
_CLASS = re.compile(r"^\s*public class (\w+) : (\w+)")
_ROS_NAME = re.compile(r'k_RosMessageName = "([^"]+)"')
_SUBTOPIC = re.compile(
    r"MessageRegistry\.Register\(k_RosMessageName, Deserialize(?:, MessageSubtopic\.(\w+))?\)"
)
_FIELD = re.compile(r"^\s*public ([\w.\[\]]+) (\w+)(?: = ([^;]+))?;")
_READ = re.compile(r"deserializer\.Read\(out this\.(\w+)(?:, (.+))?\);")
_NESTED = re.compile(r"this\.(\w+) = ([\w.]+)\.Deserialize\(deserializer\);")
_COUNT = re.compile(
    r"(?:sizeof\((\w+)\), |([\w.]+)\.Deserialize, )?(\d+|deserializer\.ReadLength\(\))$"
)
# The connector's hand-written action bases read these before the subclass's own field.
_BASE_FIELDS = {
    "ActionGoal": (("header", "Std.HeaderMsg"), ("goal_id", "Actionlib.GoalIDMsg")),
    "ActionResult": (("header", "Std.HeaderMsg"), ("status", "Actionlib.GoalStatusMsg")),
    "ActionFeedback": (("header", "Std.HeaderMsg"), ("status", "Actionlib.GoalStatusMsg")),
}


@dataclass
class _Class:
    namespace: str
    name: str
    base: str
    ros_names: dict[int, str] = field(default_factory=dict)
    subtopic: str = "-"
    types: dict[int, dict[str, tuple[str, str | None]]] = field(default_factory=dict)
    reads: dict[int, list[tuple[str, str | None, str | None]]] = field(default_factory=dict)


def _branches(lines: list[str]) -> list[tuple[str, tuple[int, ...]]]:
    """Each line with the ROS versions it is compiled for (``#if ROS2`` / ``#if !ROS2``)."""
    stack: list[tuple[int, ...]] = []
    out = []
    for line in lines:
        text = line.strip()
        if text.startswith("#if"):
            stack.append((2,) if text == "#if ROS2" else (1,) if text == "#if !ROS2" else DIALECTS)
        elif text == "#else":
            stack[-1] = tuple(d for d in DIALECTS if d not in stack[-1]) or DIALECTS
        elif text == "#endif":
            stack.pop()
        else:
            active = [d for d in DIALECTS if all(d in s for s in stack)]
            out.append((line, tuple(active)))
    return out


def _parse(path: Path) -> _Class | None:
    found: _Class | None = None
    namespace = ""
    for line, dialects in _branches(path.read_text(encoding="utf-8-sig").splitlines()):
        if match := _NAMESPACE.match(line):
            namespace = match[1]
        elif match := _CLASS.match(line):
            found = _Class(namespace, match[1], match[2])
            found.types = {d: {} for d in DIALECTS}
            found.reads = {d: [] for d in DIALECTS}
        if found is None:
            continue
        for dialect in dialects:
            _read_line(found, line, dialect)
    return found


def _read_line(found: _Class, line: str, dialect: int) -> None:
    if (match := _ROS_NAME.search(line)) and "const" in line:
        found.ros_names[dialect] = match[1]
    elif match := _SUBTOPIC.search(line):
        found.subtopic = match[1] or "Default"
    elif (match := _FIELD.match(line)) and " const " not in line:
        found.types[dialect][match[2]] = (match[1], match[3])
    elif ": base(deserializer)" in line:
        for name, cls in _BASE_FIELDS.get(found.base, ()):
            found.reads[dialect].append((name, cls, None))
    elif match := _READ.search(line):
        count = None
        element = None
        if match[2]:
            parts = _COUNT.match(match[2])
            assert parts, line
            element = parts[2]
            count = "" if parts[3].startswith("deserializer") else parts[3]
        found.reads[dialect].append((match[1], element, count))
    elif match := _NESTED.search(line):
        found.reads[dialect].append((match[1], match[2], None))


def definition_name(cls: _Class, dialect: int) -> str:
    """The ROS type ``cls`` stands for, as ROS 1 names it: a service half or an action part
    registers its service's or action's name with a subtopic."""
    ros_name = cls.ros_names[dialect]
    if cls.subtopic in ("Response", "Goal", "Result", "Feedback"):
        return ros_name + cls.subtopic
    if cls.name == ros_name.rsplit("/", 1)[-1] + "Request":
        return ros_name + "Request"
    return ros_name


def _ros_name_of(classes: dict[tuple[str, str], _Class], own: str, ref: str, dialect: int) -> str:
    namespace, _, name = ref.rpartition(".")
    found = classes.get((namespace or own, name))
    if found is None and not namespace:  # named through a `using RosMessageTypes.X;`
        (found,) = [c for (_, n), c in classes.items() if n == name]
    assert found is not None, ref
    return definition_name(found, dialect)


def _field_entries(
    classes: dict[tuple[str, str], _Class], cls: _Class, dialect: int
) -> tuple[str, ...]:
    entries = []
    for name, element, count in cls.reads[dialect]:
        declared, default = cls.types[dialect].get(name, (element or "", None))
        if element is None and declared.endswith("[]"):
            element = declared[:-2]
        base = element or declared
        if base and base[0].isupper():
            base = _ros_name_of(classes, cls.namespace, base, dialect)
        suffix = "" if count is None else f"[{count}]"
        text = f"{name}:{base}{suffix}"
        if default is not None and default not in ("0", '""', "false"):
            text += f"={default}"
        entries.append(text)
    return tuple(entries)


HEADER = '''\
"""Message classes ROS-TCP-Connector {tag} ships, as data. Generated: do not edit by hand.

Written by ``scripts/update_tcp_shipped.py`` from Unity-Technologies/ROS-TCP-Connector at tag
{tag} (``com.unity.robotics.ros-tcp-connector/Runtime/Messages``).

``CLASSES``: per ROS version, ``Namespace/Class`` (under ``RosMessageTypes``) -> (the ROS name
it registers, its ``MessageSubtopic``, ``-`` for a class that never registers).
``FIELDS``: per ROS version, ``Namespace/Class`` -> its fields in wire order, each
``name:type`` with ``type`` a C# primitive or a ROS message name, ``[N]`` for a fixed array,
``[]`` for one with a length, and ``=value`` for an initializer other than zero.
"""

from __future__ import annotations

# fmt: off
'''


def _packed(start: str, items: list[str], end: str) -> str:
    """``start`` + items + ``end`` on one line if it fits, else the items packed onto lines."""
    body = " ".join(items)
    one = start + (body if len(items) == 1 else body.rstrip(",")) + end
    if len(one) <= WIDTH:
        return one + "\n"
    lines, line = [start], "           "
    for item in items:
        if len(line) + 1 + len(item) > WIDTH:
            lines.append(line)
            line = "           "
        line += " " + item
    lines += [line, "        " + end]
    return "\n".join(lines) + "\n"


def render(classes: dict[tuple[str, str], _Class], tag: str) -> str:
    out = [HEADER.format(tag=tag)]
    out.append("CLASSES: dict[int, dict[str, tuple[str, str]]] = {\n")
    for dialect in DIALECTS:
        out.append(f"    {dialect}: {{\n")
        for key in sorted(classes):
            cls = classes[key]
            value = [f'"{cls.ros_names[dialect]}",', f'"{cls.subtopic}",']
            out.append(_packed(f'        "{key[0]}/{key[1]}": (', value, "),"))
        out.append("    },\n")
    out.append("}\n\nFIELDS: dict[int, dict[str, tuple[str, ...]]] = {\n")
    for dialect in DIALECTS:
        out.append(f"    {dialect}: {{\n")
        for key in sorted(classes):
            entries = [f'"{e}",' for e in _field_entries(classes, classes[key], dialect)]
            out.append(_packed(f'        "{key[0]}/{key[1]}": (', entries, "),"))
        out.append("    },\n")
    out.append("}\n# fmt: on\n")
    return "".join(out)


def read_package(package: Path) -> dict[tuple[str, str], _Class]:
    classes = {}
    folder = package / "Runtime" / "Messages"
    for path in sorted(folder.rglob("*.cs")):
        relative = path.relative_to(folder).as_posix()
        if any(relative.startswith(s) or relative == s for s in SKIPPED):
            continue
        found = _parse(path)
        if found is None or not found.ros_names:
            raise SystemExit(f"{path}: no message class found")
        classes[(found.namespace, found.name)] = found
    return classes


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("package", nargs="?", default=os.environ.get(ENV_VAR))
    parser.add_argument("--tag", default=DEFAULT_TAG)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    if not args.package:
        parser.error(f"give the package folder or set {ENV_VAR}")
    text = render(read_package(Path(args.package)), args.tag)
    return write_or_check(TARGET, text, args.check)


if __name__ == "__main__":
    sys.exit(main())
