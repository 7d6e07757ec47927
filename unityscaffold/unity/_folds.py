"""Long double-quoted strings folded over lines, read and written as Unity does.

Unity breaks a long double-quoted string at a space and keeps the spaces before the break: a
line ending in ``\\r\\n   `` followed by a fold is those three spaces plus the one the fold
stands for, where YAML (PyYAML, ruamel) drops trailing spaces and reads one. Reading a field
Unity's way matters wherever a value is compared (a value Unity refolded on save must equal the
same value on one line) and wherever it is written (apply's line must be Unity's, or its next
save refolds it: a diff nobody made).

The writing rule, read off every folded string in ROS#'s r2d2 scene (Unity 2022.3, the four
UrdfPlugin texts, 21 folds): once the text on a line reaches column 80, the line breaks at the
next space that is followed by something other than a space (so a run of spaces breaks at its
last one, the earlier ones kept at the end of the line), continuation lines indented two past
the key. A column-79 threshold fits those folds as well; 80 is the width of Unity's plain
folds.
"""

from __future__ import annotations

import re

import yaml

__all__ = ["FOLD_WIDTH", "fold_double_quoted", "keep_fold_spaces", "read_folds_unity_way"]

#: Unity folds plain and single-quoted strings once a line passes this column (as PyYAML does),
#: double-quoted ones once it reaches it.
FOLD_WIDTH = 80

_FOLD_RE = re.compile(r"(\\*)( +)\n")
_ESCAPED_SPACE = "\\x20"


def keep_fold_spaces(text: str) -> str:
    """A double-quoted scalar Unity folded over lines, made to read as Unity reads it.

    ``"a\\n   ⏎    b"`` is ``a``, a newline and four spaces, then ``b``: the spaces before a
    line break are written as ``\\x20`` escapes, which YAML keeps.
    """

    def escape(match: re.Match[str]) -> str:
        slashes, spaces = match.group(1), match.group(2)
        if len(slashes) % 2:  # the first space is already the escape "\\ "
            return slashes + " " + _ESCAPED_SPACE * (len(spaces) - 1) + "\n"
        return slashes + _ESCAPED_SPACE * len(spaces) + "\n"

    return _FOLD_RE.sub(escape, text)


_BaseLoader = getattr(yaml, "CBaseLoader", yaml.BaseLoader)


def read_folds_unity_way(text: str) -> str:
    """``text`` (YAML lines) with every double-quoted scalar that spans lines, wherever it is
    (a field's own value, a list item, a struct's field, a flow mapping), made to read as Unity
    reads it; everything else unchanged. Text YAML cannot scan is returned as it is."""
    if '"' not in text or text.count("\n") < 2:
        return text
    try:
        tokens = yaml.scan(text, Loader=_BaseLoader)
        quoted = [
            (token.start_mark.index, token.end_mark.index)
            for token in tokens
            if isinstance(token, yaml.ScalarToken)
            and token.style == '"'
            and token.start_mark.line != token.end_mark.line
        ]
    except yaml.YAMLError:
        return text
    pieces, last = [], 0
    for start, end in quoted:
        pieces += [text[last:start], keep_fold_spaces(text[start:end])]
        last = end
    return "".join(pieces) + text[last:]


def fold_double_quoted(escaped: str, column: int, indent: int) -> str:
    """``"escaped"`` (its escapes already applied) starting at ``column``, broken over lines
    as Unity breaks it, continuation lines indented by ``indent``."""
    out = ['"']
    column += 1
    pad = " " * indent
    last = len(escaped) - 1
    for index, ch in enumerate(escaped):
        if ch == " " and column >= FOLD_WIDTH and 0 < index < last and escaped[index + 1] != " ":
            out.append("\n" + pad)
            column = indent
            continue
        out.append(ch)
        column += 1
    out.append('"')
    return "".join(out)
