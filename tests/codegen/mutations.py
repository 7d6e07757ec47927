"""Mutated real interface definitions for the property tests: what a fuzzer would try.

A mutation takes one real ``.msg`` or ``.srv`` text and changes a few of its lines: names that
C# may not hold (too long, keywords, members every class inherits), comments with XML's special
characters, constant values at and past their type's range, array sizes and defaults. The texts
stay close to real ones, so most are still accepted and reach the C# generator.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from hypothesis import strategies as st

from unityscaffold.interfaces.model import Dialect

INHERITED = ("Equals", "GetHashCode", "GetType", "ToString", "MemberwiseClone", "Finalize")
KEYWORDS = ("class", "object", "string", "value", "base", "this", "params", "__arglist")
# Boundary values for every integer type, and a few that no type holds.
NUMBERS = (
    "0",
    "-1",
    "127",
    "-128",
    "128",
    "255",
    "256",
    "32767",
    "-32768",
    "65535",
    "2147483647",
    "-2147483648",
    "2147483648",
    "4294967295",
    "4294967296",
    "9223372036854775807",
    "-9223372036854775808",
    "18446744073709551615",
    "0x7f",
    "1e39",
    "-1e39",
    "3.4028235e38",
    "1e-50",
    "nan",
    "-inf",
    "True",
    "1_000",
)
COMMENT_PIECES = [
    *"<>&]\"'\\/*abc x\x01\x0b\r\u0085\u2028\u2029\ufffe",
    "]]>",
    "<!--",
    "-->",
    "&amp;",
    "\u00e9",
    "\U0001f600",
]
COMMENT_TEXT = st.lists(st.sampled_from(COMMENT_PIECES), max_size=8).map("".join)
SIZES = ("0", "1", "3", "64", "65", "1000", "2147483647", "<=2", "<=65", "")


@dataclass(frozen=True)
class Mutant:
    """A mutated definition: where it goes (``pkg/msg/Name.msg``) and its text."""

    package: str
    kind: str
    name: str
    text: str
    origin: str

    @property
    def relative(self) -> str:
        return f"{self.package}/{self.kind}/{self.name}.{self.kind}"

    def write(self, root: Path) -> Path:
        path = root / self.relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(self.text.encode("utf-8"))
        return path


def real_definitions(share: Path, dialect: Dialect, count: int) -> list[Path]:
    """``count`` real .msg and .srv files spread over ``share``'s packages (a fixed choice)."""
    files = sorted(share.glob("*/msg/*.msg")) + sorted(share.glob("*/srv/*.srv"))
    if dialect is Dialect.ROS2:
        files = [f for f in files if f.parent.parent.name not in ("test_msgs",)]
    step = max(1, len(files) // count)
    return files[::step][:count]


def _names(dialect: Dialect) -> st.SearchStrategy[str]:
    # Names the grammar may accept but C# may not take as they are.
    if dialect is Dialect.ROS1:
        long_name = st.integers(500, 520).map(lambda n: "a" * n)
        plain = st.from_regex(r"\A[A-Za-z][A-Za-z0-9_]{0,8}\Z")
        special = st.sampled_from(INHERITED + KEYWORDS + ("RosMessageName", "Fuzz"))
    else:
        long_name = st.integers(500, 520).map(lambda n: "a" * n)
        plain = st.from_regex(r"\A[a-z](?:[a-z0-9]|_(?=[a-z0-9])){0,8}\Z")
        special = st.sampled_from(("class", "object", "string", "value", "base", "this"))
    return st.one_of(long_name, plain, special)


_DECL = re.compile(r"^(?P<type>\S+) +(?P<name>[^\s=#]+)(?P<rest>.*)$")


@st.composite
def _mutate_line(draw: st.DrawFn, line: str, dialect: Dialect) -> str:
    match = _DECL.match(line)
    choice = draw(st.sampled_from(("name", "comment", "value", "size", "keep", "drop", "twice")))
    if choice == "comment":
        return f"{line}  # {draw(COMMENT_TEXT)}"
    if choice == "drop":
        return ""
    if choice == "twice":
        return f"{line}\n{line}"
    if match is None or choice == "keep":
        return line
    type_, name, rest = match["type"], match["name"], match["rest"]
    if choice == "name":
        new = draw(_names(dialect))
        if "=" in rest and dialect is Dialect.ROS2:
            new = new.upper()
        return f"{type_} {new}{rest}"
    if choice == "value":
        if "=" in rest:
            return f"{type_} {name}={draw(st.sampled_from(NUMBERS))}"
        if dialect is Dialect.ROS2 and "/" not in type_ and "[" not in type_:
            return f"{type_} {name} {draw(st.sampled_from(NUMBERS))}"
        return line
    base = type_.split("[", 1)[0]
    size = draw(st.sampled_from(SIZES))
    if dialect is Dialect.ROS1 and size.startswith("<="):
        size = size[2:]
    return f"{base}[{size}] {name}{rest}"


@st.composite
def mutants(draw: st.DrawFn, sources: list[Path], dialect: Dialect, index: int) -> Mutant:
    """One mutant of one of ``sources``, named ``Fuzz<index>`` in the source's package."""
    source = draw(st.sampled_from(sources))
    lines = source.read_text(encoding="utf-8").split("\n")
    # A few lines change; the rest stays as the real file has it.
    for _ in range(draw(st.integers(1, 3))):
        at = draw(st.integers(0, max(0, len(lines) - 1)))
        lines[at] = draw(_mutate_line(lines[at], dialect))
    if draw(st.booleans()):
        lines.insert(0, f"# {draw(COMMENT_TEXT)}")
    kind = source.suffix[1:]
    return Mutant(source.parent.parent.name, kind, f"Fuzz{index}", "\n".join(lines), str(source))
