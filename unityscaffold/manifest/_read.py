"""Typed reads of Y-nodes that record a located diagnostic instead of failing.

Every reader returns None when the key is absent or its value is wrong; a wrong value has
already been reported to the sink, so callers may substitute defaults freely: the manifest is
never built while the sink holds errors.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Sequence

from unityscaffold.errors import Diagnostic, DiagnosticSink, SourceLocation
from unityscaffold.manifest._spec import FLOAT32_MAX, FLOAT32_TINY, INT32_MAX, Section
from unityscaffold.manifest._yaml import YEntry, YMap, YNode, YScalar, YSeq

__all__ = ["Reader", "describe", "one_of"]


def describe(node: YNode) -> str:
    """How a value is shown in a message: the scalar as written, else its kind."""
    if isinstance(node, YSeq):
        return "a list"
    if isinstance(node, YMap):
        return "a mapping"
    value = node.value
    if value is None:
        return "an empty value"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        # control characters (a tab, an escape sequence) shown escaped, not sent to the terminal
        return f"'{value}'" if value.isprintable() else repr(value)
    return str(value)


def one_of(choices: Sequence[str]) -> str:
    return "one of: " + ", ".join(choices)


def suggest(word: str, choices: Sequence[str]) -> str | None:
    close = difflib.get_close_matches(word, list(choices), n=1, cutoff=0.6)
    return f"did you mean '{close[0]}'?" if close else None


class Reader:
    """Reads keys of Y-mappings, reporting every problem to one sink."""

    def __init__(self, sink: DiagnosticSink) -> None:
        self.sink = sink

    def error(
        self,
        location: SourceLocation,
        message: str,
        *,
        expected: str | None = None,
        hint: str | None = None,
    ) -> None:
        self.sink.add(Diagnostic(location, message, expected=expected, hint=hint))

    def invalid(self, entry: YEntry, expected: str, hint: str | None = None) -> None:
        self.error(
            entry.value.location,
            f"invalid value for '{entry.key}': {describe(entry.value)}",
            expected=expected,
            hint=hint,
        )

    def mapping(self, node: YNode, section: Section) -> YMap | None:
        """``node`` as a mapping with only known keys and every required key, else None."""
        if not isinstance(node, YMap):
            self.error(
                node.location,
                f"this {section.label} is {describe(node)}, not a mapping",
                expected=f"a mapping with keys {', '.join(section.names)}",
            )
            return None
        meant: set[str] = set()
        for entry in node.entries:
            if entry.key not in section.names:
                hint = suggest(entry.key, section.names)
                if hint:
                    meant.add(hint.split("'")[1])
                hint = dict(section.foreign).get(entry.key, hint)
                self.error(
                    entry.key_location,
                    f"unknown key '{entry.key}' in {section.label}",
                    expected=one_of(sorted(section.names)),
                    hint=hint,
                )
        # A misspelt required key is reported once, as unknown, not also as missing.
        for name in section.required:
            if node.get(name) is None and name not in meant:
                doc = section.key(name).doc.replace("`", "")
                self.error(
                    node.location,
                    f"{section.label} is missing required key '{name}'",
                    hint=f"{name}: {doc}",
                )
        return node

    def scalar(
        self, m: YMap, key: str, types: tuple[type, ...], expected: str, hint: str | None = None
    ) -> object | None:
        entry = m.get(key)
        if entry is None:
            return None
        node = entry.value
        # bool is an int in Python, but never a number in a manifest
        ok = (
            isinstance(node, YScalar)
            and isinstance(node.value, types)
            and not (isinstance(node.value, bool) and bool not in types)
        )
        if not ok:
            self.invalid(entry, expected, hint)
            return None
        assert isinstance(node, YScalar)
        return node.value

    def text(
        self, m: YMap, key: str, expected: str, pattern: str | None = None, hint: str | None = None
    ) -> str | None:
        value = self.scalar(m, key, (str,), expected, _quote_hint(m, key) or hint)
        if not isinstance(value, str):
            return None
        if not value or (pattern and not re.search(pattern, value)):
            self.invalid(m.get(key), expected, hint)  # type: ignore[arg-type]
            return None
        return value

    def boolean(self, m: YMap, key: str) -> bool | None:
        value = self.scalar(
            m, key, (bool,), "true or false", hint="YAML 1.2 booleans are only true and false"
        )
        return value if isinstance(value, bool) else None

    def whole(self, m: YMap, key: str, expected: str) -> int | None:
        """A whole number; ``10.0`` counts as ``10``, as JSON Schema's ``integer`` has it."""
        value = self.scalar(m, key, (int, float), expected)
        if isinstance(value, float):
            if not value.is_integer():  # also false for inf and nan
                self.invalid(m.get(key), expected)  # type: ignore[arg-type]
                return None
            return int(value)
        return value if isinstance(value, int) else None

    def integer(self, m: YMap, key: str, minimum: int, unit: str = "") -> int | None:
        """A whole number from ``minimum`` up to what the C# ``int`` it is written to holds."""
        of = f" of {unit}" if unit else ""
        expected = f"a whole number{of} ≥ {minimum}"
        value = self.whole(m, key, expected)
        if value is None:
            return None
        if value < minimum:
            self.invalid(m.get(key), expected)  # type: ignore[arg-type]
            return None
        if value > INT32_MAX:
            self.invalid(
                m.get(key),  # type: ignore[arg-type]
                f"a whole number{of} from {minimum} to {INT32_MAX}",
                hint=f"'{key}' goes into a C# int field, which holds at most {INT32_MAX}",
            )
            return None
        return value

    def positive_number(self, m: YMap, key: str, unit: str) -> float | None:
        expected = f"a number of {unit} > 0"
        value = self.scalar(m, key, (int, float), expected)
        if not isinstance(value, (int, float)):
            return None
        if not value > 0 or value == float("inf"):
            self.invalid(m.get(key), expected)  # type: ignore[arg-type]
            return None
        if not FLOAT32_TINY <= value <= FLOAT32_MAX:
            self.invalid(
                m.get(key),  # type: ignore[arg-type]
                f"a number of {unit} from {FLOAT32_TINY:g} to {FLOAT32_MAX:g}",
                hint=f"'{key}' goes into a C# float field, which cannot hold it",
            )
            return None
        return float(value)

    def choice(self, m: YMap, key: str, choices: Sequence[str]) -> str | None:
        entry = m.get(key)
        if entry is None:
            return None
        node = entry.value
        if isinstance(node, YScalar) and isinstance(node.value, str) and node.value in choices:
            return node.value
        word = str(node.value) if isinstance(node, YScalar) else ""
        self.invalid(entry, one_of(choices), suggest(word, choices))
        return None

    def items(self, m: YMap, key: str) -> tuple[YNode, ...]:
        """A list value's items; an empty value counts as an empty list."""
        entry = m.get(key)
        if entry is None:
            return ()
        node = entry.value
        if isinstance(node, YSeq):
            return node.items
        if isinstance(node, YScalar) and node.value is None:
            return ()
        self.invalid(entry, "a list", hint=f"start each entry of '{key}' on its own line with '- '")
        return ()


def _quote_hint(m: YMap, key: str) -> str | None:
    """Suggest quoting when YAML turned something meant as text into a number or boolean."""
    entry = m.get(key)
    if entry is not None and isinstance(entry.value, YScalar):
        value = entry.value.value
        if isinstance(value, (bool, int, float)):
            return f"YAML read this as {type(value).__name__}; quote it to make it text"
    return None
