"""Scalars exactly as Unity writes them: float32 digits, integers, and string quoting/folding.

See ``docs/unity-yaml.md#scalars``. Everything here is a pure function of the value (plus,
for strings, the column where the scalar starts), so it can be property-tested against a YAML
reader.
"""

from __future__ import annotations

import math
import struct

from unityscaffold.unity._folds import FOLD_WIDTH, fold_double_quoted, keep_fold_spaces

__all__ = [
    "FOLD_WIDTH",
    "PLAIN_EXPONENTS",
    "format_float",
    "format_string",
    "keep_fold_spaces",
    "to_float32",
]


#: Decimal exponents written in plain notation. −9 and the switch to e-notation below it are
#: observed; above, 3 is observed plain and 11 in e-notation, 9 is our choice in between.
PLAIN_EXPONENTS = range(-9, 10)

_INDICATORS = frozenset("-?:,[]{}#&*!|>'\"%@`")
_NAMED_ESCAPES = {
    "\0": "0",
    "\x07": "a",
    "\x08": "b",
    "\t": "t",
    "\n": "n",
    "\x0b": "v",
    "\x0c": "f",
    "\r": "r",
    "\x1b": "e",
    '"': '"',
    "\\": "\\",
}


def to_float32(value: float) -> float:
    """Round ``value`` to the nearest float32; raise ``ValueError`` when it does not fit."""
    try:
        result: float = struct.unpack("<f", struct.pack("<f", value))[0]
    except OverflowError:
        raise ValueError(f"{value!r} is outside the float32 range") from None
    return result


def _shortest_digits(value: float) -> tuple[str, int]:
    """Shortest significant digits that read back as the same float32, and the exponent."""
    for precision in range(1, 10):
        text = f"{value:.{precision - 1}e}"
        try:
            if to_float32(float(text)) == value:
                break
        except ValueError:  # rounded up past the float32 maximum: cannot match
            continue
    mantissa, exponent = text.split("e")
    digits = mantissa.lstrip("-").replace(".", "").rstrip("0") or "0"
    return digits, int(exponent)


def format_float(value: float) -> str:
    """Unity's text for a float field: shortest float32 digits, plain or e-notation."""
    value = to_float32(value)
    if math.isnan(value):
        return "NaN"
    if math.isinf(value):
        return "Infinity" if value > 0 else "-Infinity"
    sign = "-" if math.copysign(1.0, value) < 0 else ""
    if value == 0:
        return f"{sign}0"
    digits, exponent = _shortest_digits(abs(value))
    if exponent in PLAIN_EXPONENTS:
        return sign + _plain_notation(digits, exponent)
    mantissa = digits[0] + ("." + digits[1:] if len(digits) > 1 else "")
    return f"{sign}{mantissa}e{'+' if exponent >= 0 else '-'}{abs(exponent):02d}"


def _plain_notation(digits: str, exponent: int) -> str:
    if exponent < 0:
        return "0." + "0" * (-exponent - 1) + digits
    whole = exponent + 1
    if len(digits) <= whole:
        return digits + "0" * (whole - len(digits))
    return digits[:whole] + "." + digits[whole:]


def _needs_double_quotes(text: str) -> bool:
    # Unity decodes UTF-8 only inside double quotes, so anything outside printable ASCII
    # (and CR, which a single-quoted scalar cannot keep) goes there as an escape.
    if any(not (" " <= ch <= "~") and ch != "\n" for ch in text):
        return True
    # A multi-line single-quoted scalar loses the spaces around each line break when read.
    return "\n" in text and any(
        line != line.strip(" ") for line in text.split("\n")[:-1] + text.split("\n")[1:]
    )


def _plain_allowed(text: str, quote_trailing_bracket: bool) -> bool:
    if "\n" in text or text[0] in _INDICATORS or text[0] == " " or text[-1] == " ":
        return False
    if text.startswith(("---", "...")) or ": " in text or " #" in text or text.endswith(":"):
        return False
    return not (quote_trailing_bracket and text.endswith("]"))


def format_string(
    text: str, *, column: int = 0, indent: int = 4, quote_trailing_bracket: bool = False
) -> str:
    """Unity's text for a string value that starts at ``column``.

    Plain when YAML allows it, single-quoted for indicators and line breaks (``'`` doubled, each
    ``\\n`` written as an empty line), double-quoted with ``\\u`` escapes for anything outside
    printable ASCII. Plain and single-quoted text folds at a single space past column 80, with
    continuation lines indented by ``indent``; double-quoted text folds as Unity folds it
    (``_folds``). Files from 6000.x single-quote a trailing ``]``.
    """
    if text == "":
        return ""
    if _needs_double_quotes(text):
        return fold_double_quoted(_escaped(text), column, indent)
    if _plain_allowed(text, quote_trailing_bracket):
        return _folded(text, column, indent, quoted=False)
    return _folded(text, column, indent, quoted=True)


def _escaped(text: str) -> str:
    out = []
    for ch in text:
        if ch in _NAMED_ESCAPES:
            out.append("\\" + _NAMED_ESCAPES[ch])
        elif " " <= ch <= "~":
            out.append(ch)
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\x{ord(ch):02X}")
        elif ord(ch) <= 0xFFFF:
            out.append(f"\\u{ord(ch):04X}")
        else:
            out.append(f"\\U{ord(ch):08X}")
    return "".join(out)


def _folded(text: str, column: int, indent: int, *, quoted: bool) -> str:
    """PyYAML's plain/single-quoted writer: break at a lone space once past FOLD_WIDTH."""
    out: list[str] = []
    if quoted:
        out.append("'")
        column += 1
    pad = " " * indent
    words = _split_runs(text)
    for index, run in enumerate(words):
        if run == " " and column > FOLD_WIDTH and 0 < index < len(words) - 1:
            out.append("\n" + pad)
            column = indent
        elif run.startswith("\n"):
            # a single-quoted scalar keeps n line breaks as n+1 breaks (n empty lines)
            out.append("\n" * (len(run) + 1) + pad)
            column = indent
        else:
            piece = run.replace("'", "''") if quoted else run
            out.append(piece)
            column += len(piece)
    if quoted:
        out.append("'")
    return "".join(out)


def _split_runs(text: str) -> list[str]:
    """Split into runs of spaces, runs of line breaks, and everything else."""
    runs: list[str] = []
    start = 0
    for end in range(1, len(text) + 1):
        if end == len(text) or _kind(text[end]) != _kind(text[start]):
            runs.append(text[start:end])
            start = end
    return runs


def _kind(ch: str) -> int:
    return 1 if ch == " " else 2 if ch == "\n" else 0
