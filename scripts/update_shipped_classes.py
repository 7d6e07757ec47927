"""Regenerate ``unityscaffold/codegen/_shipped_data.py``: the message classes ROS# ships.

Generated C# must not define a class ROS# already has under the same full name (the project would
not compile), so the generator needs the list of ROS#'s own message classes. This script reads it
from a checkout of ROS#'s Unity package (``com.siemens.ros-sharp`` at a release tag): every
``.cs`` file under ``Runtime/Libraries/RosBridgeClient/MessageTypes/ROS1`` and ``ROS2`` declares
one class, its namespace and its ``RosMessageName``.

Run:
    python3 scripts/update_shipped_classes.py PATH/TO/com.siemens.ros-sharp [--tag 2.2.1]
or set ``UNITYSCAFFOLD_ROSSHARP`` to that folder. ``--check`` compares instead of writing
(exit 1 when the committed module differs). Review the result with ``git diff``.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TARGET = ROOT / "unityscaffold" / "codegen" / "_shipped_data.py"
ENV_VAR = "UNITYSCAFFOLD_ROSSHARP"
MESSAGE_TYPES = Path("Runtime/Libraries/RosBridgeClient/MessageTypes")
NAMESPACE_ROOT = "RosSharp.RosBridgeClient.MessageTypes"
DEFAULT_TAG = "2.2.1"  # the ROS# release `scaffold init` pins (apply/_rossharp.py DEFAULT_VERSION)
WIDTH = 99  # entries are packed onto lines up to this many characters

_NAMESPACE_RE = re.compile(rf"^namespace {re.escape(NAMESPACE_ROOT)}\.(\w+)\s*$", re.M)
_CLASS_RE = re.compile(r"^\s*public class (\w+)\b", re.M)
_ROS_NAME_RE = re.compile(r'^\s*public const string RosMessageName = "([^"]+)";', re.M)
_GUARD_RE = re.compile(r"^#if (!?)ROS2\s*$", re.M)
_PROPERTY_RE = re.compile(r"^\s*public [\w.\[\]<>, ]+? (\w+) \{ get; set; \}", re.M)

HEADER = '''\
"""Message classes ROS# {tag} ships, as data. Generated: do not edit by hand.

Written by ``scripts/update_shipped_classes.py`` from siemens/ros-sharp at tag {tag}
(``com.siemens.ros-sharp/{folder}/ROS1`` and ``ROS2``).

Per ROS version: C# namespace (the last segment under ``{root}``)
-> entries ``ros_name`` (class = last segment of the name) or ``ros_name>Class`` (a service's
``Request``/``Response`` class, which carries the service's name).
"""

from __future__ import annotations

# fmt: off
SHIPPED: dict[int, dict[str, tuple[str, ...]]] = {{
'''
FOOTER = "}\n# fmt: on\n"
FIELDS_HEADER = """
#: Per ROS version: ``namespace/Class`` -> its serialized fields in order, to tell when a
#: distro's definition has fields ROS#'s class lacks (or the other way round).
# fmt: off
FIELDS: dict[int, dict[str, tuple[str, ...]]] = {
"""


class SourceError(Exception):
    """The checkout does not look like ROS#'s message classes."""


def _one(pattern: re.Pattern[str], text: str, what: str, path: Path) -> re.Match[str]:
    found = list(pattern.finditer(text))
    if len(found) != 1:
        raise SourceError(f"{path}: expected one {what}, found {len(found)}")
    return found[0]


def read_fields(path: Path) -> list[str]:
    """The serialized fields of one ROS# message class, in declaration order."""
    return _PROPERTY_RE.findall(path.read_text(encoding="utf-8-sig"))


def read_entry(path: Path, version: int) -> tuple[str, str]:
    """(namespace segment, entry) for one ROS# message class file."""
    text = path.read_text(encoding="utf-8-sig")
    guard = _one(_GUARD_RE, text, "'#if ROS2' or '#if !ROS2' line", path)
    if (guard.group(1) == "") != (version == 2):
        raise SourceError(f"{path}: its #if guard does not match its ROS{version} folder")
    namespace = _one(_NAMESPACE_RE, text, f"namespace under {NAMESPACE_ROOT}", path).group(1)
    class_name = _one(_CLASS_RE, text, "public class", path).group(1)
    ros_name = _one(_ROS_NAME_RE, text, "RosMessageName", path).group(1)
    if ros_name.rsplit("/", 1)[-1] == class_name:
        return namespace, ros_name
    return namespace, f"{ros_name}>{class_name}"


def shipped_classes(
    package: Path, fields: dict[int, dict[str, list[str]]] | None = None
) -> dict[int, dict[str, list[str]]]:
    """Per ROS version, namespace segment -> sorted entries; ``fields`` gets, per ROS version,
    ``namespace/Class`` -> the class's serialized fields."""
    table: dict[int, dict[str, list[str]]] = {}
    for version in (1, 2):
        folder = package / MESSAGE_TYPES / f"ROS{version}"
        files = sorted(folder.rglob("*.cs"))
        if not files:
            raise SourceError(f"no .cs files under {folder}: is this com.siemens.ros-sharp?")
        by_namespace: dict[str, list[str]] = defaultdict(list)
        for path in files:
            namespace, entry = read_entry(path, version)
            by_namespace[namespace].append(entry)
            if fields is not None:
                name = entry.partition(">")[2] or entry.rsplit("/", 1)[-1]
                fields.setdefault(version, {})[f"{namespace}/{name}"] = read_fields(path)
        table[version] = {ns: sorted(entries) for ns, entries in sorted(by_namespace.items())}
    return table


def _packed(entries: list[str], indent: str) -> list[str]:
    """Quoted entries, as many to a line as fit in WIDTH (a longer one gets a line alone)."""
    lines: list[str] = []
    current = ""
    for entry in entries:
        item = f'"{entry}",'
        candidate = f"{current} {item}" if current else indent + item
        if current and len(candidate) > WIDTH:
            lines.append(current)
            candidate = indent + item
        current = candidate
    lines.append(current)
    return lines


def render(
    table: dict[int, dict[str, list[str]]],
    tag: str,
    fields: dict[int, dict[str, list[str]]] | None = None,
) -> str:
    """The text of ``_shipped_data.py``."""
    out = [HEADER.format(tag=tag, folder=MESSAGE_TYPES.as_posix(), root=NAMESPACE_ROOT)]
    for version, namespaces in table.items():
        out.append(f"    {version}: {{\n")
        for namespace, entries in namespaces.items():
            out.append(f'        "{namespace}": (\n')
            out += [line + "\n" for line in _packed(entries, " " * 12)]
            out.append("        ),\n")
        out.append("    },\n")
    out.append(FOOTER)
    out.append(FIELDS_HEADER)
    for version, classes in sorted((fields or {}).items()):
        out.append(f"    {version}: {{\n")
        for name, names in sorted(classes.items()):
            quoted = ", ".join(f'"{n}"' for n in names) + ("," if len(names) == 1 else "")
            one_line = f'        "{name}": ({quoted}),'
            if len(one_line) <= WIDTH:
                out.append(one_line + "\n")
                continue
            out.append(f'        "{name}": (\n')
            out += [line + "\n" for line in _packed(names, " " * 12)]
            out.append("        ),\n")
        out.append("    },\n")
    out.append(FOOTER)
    return "".join(out)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument(
        "package",
        nargs="?",
        type=Path,
        default=os.environ.get(ENV_VAR),
        help=f"ROS#'s com.siemens.ros-sharp folder (default: ${ENV_VAR})",
    )
    parser.add_argument("--tag", default=DEFAULT_TAG, help="the ROS# tag of that checkout")
    parser.add_argument("--output", type=Path, default=TARGET, help="the module to write")
    parser.add_argument("--check", action="store_true", help="compare instead of writing")
    args = parser.parse_args(argv)
    if args.package is None:
        parser.error(f"give the com.siemens.ros-sharp folder or set {ENV_VAR}")
    try:
        fields: dict[int, dict[str, list[str]]] = {}
        table = shipped_classes(Path(args.package), fields)
    except (SourceError, OSError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    text = render(table, args.tag, fields)
    output: Path = args.output
    if args.check:
        current = output.read_text(encoding="utf-8") if output.is_file() else ""
        if current != text:
            print(f"{output} is out of date: run {Path(__file__).name}", file=sys.stderr)
            return 1
        return 0
    output.write_text(text, encoding="utf-8", newline="\n")
    count = sum(len(entries) for version in table.values() for entries in version.values())
    print(f"wrote {count} classes to {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
