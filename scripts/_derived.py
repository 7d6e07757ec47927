"""The ending every ``scripts/update_*.py`` that derives a committed data file shares: write the
file, or with ``--check`` say whether the committed one is out of date."""

from __future__ import annotations

import sys
from pathlib import Path


def write_or_check(output: Path, text: str, check: bool) -> int:
    """Exit status: 0 written or up to date, 1 out of date (``check`` only)."""
    if check:
        current = output.read_text(encoding="utf-8") if output.exists() else ""
        if current != text:
            print(f"{output} is out of date; run without --check", file=sys.stderr)
            return 1
        return 0
    output.write_text(text, encoding="utf-8")
    print(f"wrote {output}")
    return 0
