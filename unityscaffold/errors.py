"""The one error family of unityscaffold.

Library code raises these and never prints or exits; only ``cli`` turns them into a message
and an exit status. Every error a user can cause is a ``UserError``; when it concerns a place
in a file it carries ``Diagnostic`` values that render as ``path:line:col: message``.
"""

from __future__ import annotations

import enum
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field

__all__ = [
    "Diagnostic",
    "Exit",
    "InternalError",
    "LocatedError",
    "ScaffoldError",
    "Severity",
    "SourceLocation",
    "UserError",
    "located_at",
]


class Exit(enum.IntEnum):
    """Exit statuses of the ``scaffold`` command."""

    OK = 0
    DRIFT = 1
    USER_ERROR = 2
    INTERNAL = 3


class Severity(enum.Enum):
    ERROR = "error"
    WARNING = "warning"


@dataclass(frozen=True, slots=True)
class SourceLocation:
    """A position in a text file; ``line`` and ``col`` count from 1."""

    path: str
    line: int = 0
    col: int = 0
    source_line: str | None = None

    @classmethod
    def at_byte(cls, path: str, raw: bytes, offset: int) -> SourceLocation:
        """Line and column (in characters) of the byte at ``offset`` of a file's ``raw``
        content, such as one that is not UTF-8; the line is shown with such bytes replaced."""
        start = raw.rfind(b"\n", 0, offset) + 1
        end = raw.find(b"\n", offset)
        before = raw[start:offset].decode("utf-8", "replace")
        source = raw[start : end if end >= 0 else len(raw)].decode("utf-8", "replace")
        return cls(path, raw.count(b"\n", 0, offset) + 1, len(before) + 1, source.rstrip("\r"))

    def __str__(self) -> str:
        if self.line <= 0:
            return self.path
        if self.col <= 0:
            return f"{self.path}:{self.line}"
        return f"{self.path}:{self.line}:{self.col}"


@dataclass(frozen=True, slots=True)
class Diagnostic:
    """One located finding: what is wrong, what was expected, and how to fix it."""

    location: SourceLocation
    message: str
    expected: str | None = None
    hint: str | None = None
    severity: Severity = Severity.ERROR

    def render(self) -> str:
        text = f"{self.location}: {self.severity.value}: {self.message}"
        if self.expected:
            text += f" (expected {self.expected})"
        src = self.location.source_line
        if src is not None:
            shown = src.replace("\t", " ")
            text += f"\n    {shown}"
            if self.location.col > 0:
                text += "\n    " + " " * (self.location.col - 1) + "^"
        if self.hint:
            text += f"\n  hint: {self.hint}"
        return text


class ScaffoldError(Exception):
    """Root of every error unityscaffold raises on purpose."""

    exit_code: Exit = Exit.INTERNAL

    def render(self) -> str:
        return str(self)


class UserError(ScaffoldError):
    """A mistake in the user's input or environment, reported as a message, never a traceback."""

    exit_code = Exit.USER_ERROR

    def __init__(self, message: str, *, hint: str | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.hint = hint

    def render(self) -> str:
        text = f"error: {self.message}"
        if self.hint:
            text += f"\n  hint: {self.hint}"
        return text


class LocatedError(UserError):
    """One or more diagnostics tied to places in files."""

    def __init__(self, diagnostics: Iterable[Diagnostic]) -> None:
        self.diagnostics: tuple[Diagnostic, ...] = tuple(diagnostics)
        if not self.diagnostics:
            raise ValueError("LocatedError needs at least one diagnostic")
        first = self.diagnostics[0]
        super().__init__(first.message, hint=first.hint)

    @classmethod
    def at(
        cls,
        location: SourceLocation,
        message: str,
        *,
        expected: str | None = None,
        hint: str | None = None,
    ) -> LocatedError:
        return cls([Diagnostic(location, message, expected=expected, hint=hint)])

    @property
    def location(self) -> SourceLocation:
        return self.diagnostics[0].location

    def __str__(self) -> str:
        return self.render()

    def render(self) -> str:
        return "\n".join(d.render() for d in self.diagnostics)


class InternalError(ScaffoldError):
    """A bug in unityscaffold itself: the CLI asks the user to report it."""


@contextmanager
def located_at(location: SourceLocation) -> Iterator[None]:
    """Report a ``UserError`` raised inside at ``location``, unless it already has a place.

    The one way a caller ties an error from a lower layer, which knows nothing of the file the
    user wrote, to the place in that file that led to it (a manifest key, an interface line).
    """
    try:
        yield
    except LocatedError:
        raise
    except UserError as error:
        raise LocatedError.at(location, error.message, hint=error.hint) from None


@dataclass(slots=True)
class DiagnosticSink:
    """Collects the diagnostics of one input so that every problem is reported before stopping.

    The one collector of the manifest reader and both interface grammars.
    """

    diagnostics: list[Diagnostic] = field(default_factory=list)

    def add(self, diagnostic: Diagnostic) -> None:
        self.diagnostics.append(diagnostic)

    def error(
        self,
        location: SourceLocation,
        message: str,
        *,
        expected: str | None = None,
        hint: str | None = None,
    ) -> None:
        self.add(Diagnostic(location, message, expected=expected, hint=hint))

    @property
    def errors(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity is Severity.ERROR]

    def raise_if_errors(self) -> None:
        """Stop with every error collected so far, in the order they were found."""
        if self.errors:
            raise LocatedError(self.errors)
