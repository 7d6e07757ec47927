"""Split Unity YAML text into a prolog and documents whose concatenation is the input.

Each document keeps its exact text (header line included). CRLF files are handled as LF inside
and converted back on output, so every offset and regex here can assume ``\\n``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import yaml

from unityscaffold.errors import LocatedError, SourceLocation

__all__ = ["Doc", "SplitFile", "split_text"]

HEADER_RE = re.compile(r"^--- !u!(\d+) &(-?\d+)( stripped)?$", re.M)
_ANY_HEADER_RE = re.compile(r"^---", re.M)
_TYPE_LINE_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_]*:\n")
_BaseLoader = getattr(yaml, "CBaseLoader", yaml.BaseLoader)


@dataclass(slots=True, eq=False)
class Doc:
    """One ``--- !u!<class> &<fileID>`` document; ``text`` runs from its header to the next."""

    class_id: int
    file_id: int
    stripped: bool
    text: str
    cache: dict[str, object] = field(default_factory=dict)

    @property
    def header(self) -> str:
        return self.text[: self.text.index("\n")]

    @property
    def type_name(self) -> str:
        start = self.text.index("\n") + 1
        return self.text[start : self.text.index(":", start)]


@dataclass(frozen=True, slots=True)
class SplitFile:
    prolog: str
    docs: list[Doc]
    crlf: bool


def _error(path: str, text: str, offset: int, message: str, hint: str | None = None) -> LocatedError:
    line = text.count("\n", 0, offset) + 1
    start = text.rfind("\n", 0, offset) + 1
    end = text.find("\n", offset)
    source = text[start : end if end >= 0 else len(text)]
    return LocatedError.at(SourceLocation(path, line, 1, source), message, hint=hint)


def detect_crlf(text: str) -> bool:
    """True when every line break is CRLF (git may convert a whole file); mixed files stay LF."""
    crlf = text.count("\r\n")
    return crlf > 0 and crlf == text.count("\n")


def split_text(text: str, path: str) -> SplitFile:
    """Split ``text``; raise ``LocatedError`` for anything that is not complete Unity YAML text."""
    crlf = detect_crlf(text)
    if crlf:
        text = text.replace("\r\n", "\n")
    if not text.startswith("%YAML"):
        raise _error(
            path, text, 0, "not a Unity YAML file: it does not start with '%YAML'",
            hint="Unity writes text scenes only with Asset Serialization Mode 'Force Text'",
        )
    headers = list(HEADER_RE.finditer(text))
    _check_headers(text, path, headers)
    docs = [_make_doc(text, path, m, headers[i + 1].start() if i + 1 < len(headers) else len(text))
            for i, m in enumerate(headers)]
    _check_complete(text, path, headers, docs)
    return SplitFile(text[: headers[0].start()], docs, crlf)


def _check_headers(text: str, path: str, headers: list[re.Match[str]]) -> None:
    if len(headers) != len(_ANY_HEADER_RE.findall(text)):
        good = {m.start() for m in headers}
        bad = next(m.start() for m in _ANY_HEADER_RE.finditer(text) if m.start() not in good)
        raise _error(path, text, bad, "malformed document header",
                     hint="expected '--- !u!<classID> &<fileID>' optionally followed by ' stripped'")
    if not headers:
        raise _error(path, text, len(text), "no '--- !u!<class> &<fileID>' document in the file")
    prolog = text[: headers[0].start()]
    if any(line and not line.startswith("%") for line in prolog.split("\n")):
        raise _error(path, text, 0, "unexpected text before the first document",
                     hint="only %YAML/%TAG directives may precede the first '--- !u!' header")


def _make_doc(text: str, path: str, match: re.Match[str], end: int) -> Doc:
    body_start = match.end() + 1
    if not _TYPE_LINE_RE.match(text, body_start):
        raise _error(path, text, min(body_start, len(text) - 1),
                     f"document {match.group(0)} has no 'TypeName:' line",
                     hint="the file may be truncated or edited by hand")
    return Doc(int(match.group(1)), int(match.group(2)), bool(match.group(3)), text[match.start():end])


def _check_complete(text: str, path: str, headers: list[re.Match[str]], docs: list[Doc]) -> None:
    truncated_hint = "the file looks truncated; restore it from version control"
    if not text.endswith("\n"):
        raise _error(path, text, len(text) - 1, "the file does not end with a line break",
                     hint=truncated_hint)
    last = docs[-1]
    try:
        yaml.load(last.text[last.text.index("\n") + 1 :], Loader=_BaseLoader)
    except yaml.YAMLError as exc:
        raise _error(path, text, headers[-1].start(),
                     f"the last document {last.header} is not valid YAML ({_first_line(exc)})",
                     hint=truncated_hint) from None


def _first_line(exc: Exception) -> str:
    return str(exc).strip().split("\n")[0]
