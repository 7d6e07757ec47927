"""Where unityscaffold keeps what it may reuse between commands: the user's cache folder.

``$XDG_CACHE_HOME`` or ``~/.cache`` (``%LOCALAPPDATA%`` on Windows), under ``unityscaffold/``.
Nothing kept there is ever needed: a missing, unreadable or unwritable folder only means a
command does the work again. ``UNITYSCAFFOLD_NO_CACHE`` (any non-empty value) turns every use
of it off. Kept free of imports beyond the standard library's ``os``: the CLI asks for it
before anything else is loaded.

Each use has a folder of its own there, named here so that the no-op record knows which files
in the cache are the scaffold's own rather than inputs.
"""

from __future__ import annotations

import os

__all__ = ["cache_root", "record_cache_folder", "template_cache_folder"]


def cache_root() -> str | None:
    """The absolute ``.../unityscaffold`` cache folder, or None when caching is off."""
    if os.environ.get("UNITYSCAFFOLD_NO_CACHE"):
        return None
    base = os.environ.get("XDG_CACHE_HOME") or (
        os.environ.get("LOCALAPPDATA") if os.name == "nt" else None
    )
    if not base:
        home = os.path.expanduser("~")
        if home == "~":
            return None
        base = os.path.join(home, ".cache")
    if not os.path.isabs(base):
        return None
    return os.path.join(base, "unityscaffold")


def template_cache_folder(root: str, version: str) -> str:
    """Where jinja keeps the compiled templates of ``version`` of the scaffold."""
    return os.path.join(root, f"{version}-templates")


def record_cache_folder(root: str) -> str:
    """Where the no-op record keeps its records (``cli/_noop.py``)."""
    return os.path.join(root, "noop")
