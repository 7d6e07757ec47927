"""The manifest's ``# yaml-language-server: $schema=…`` first line, and whether the schema copy
it names still matches this version's schema.

``scaffold init`` copies the schema beside robot.yaml; after an upgrade that adds keys, the
editor would check the manifest against the old copy and flag the new keys. ``stale_schema``
lets the CLI say so, with the command that refreshes it.
"""

from __future__ import annotations

import re
from pathlib import Path

from unityscaffold.resources import schema_text

__all__ = ["schema_reference", "stale_schema"]

_MODELINE = re.compile(r"\A\ufeff?# yaml-language-server: \$schema=(\S+)")


def schema_reference(text: str) -> str | None:
    """The schema a manifest's first line points editors at, if it has that line."""
    match = _MODELINE.match(text)
    return match[1] if match else None


def stale_schema(manifest: Path) -> Path | None:
    """The local schema file the manifest names, when it is missing or differs from the
    shipped schema (line endings aside); None when it is current, a URL, or not named."""
    try:
        with manifest.open(encoding="utf-8", errors="replace") as handle:
            first = handle.readline()
    except OSError:
        return None
    reference = schema_reference(first)
    if reference is None or "://" in reference:
        return None
    path = Path(reference) if Path(reference).is_absolute() else manifest.parent / reference
    try:
        current = path.read_text(encoding="utf-8").replace("\r\n", "\n")
    except (OSError, UnicodeDecodeError):
        return path
    return None if current == schema_text() else path
