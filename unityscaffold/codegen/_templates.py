"""The one jinja2 environment for all targets' templates.

Templates live in the top-level ``templates/`` folder, which the wheel ships as
``unityscaffold/templates``; an editable install finds it beside the package.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import jinja2

import unityscaffold
from unityscaffold.errors import InternalError

__all__ = ["environment", "templates_dir"]


def templates_dir() -> Path:
    """``unityscaffold/templates`` in an installed wheel, else the repository's ``templates``."""
    package = Path(unityscaffold.__file__).resolve().parent
    for candidate in (package / "templates", package.parent / "templates"):
        if candidate.is_dir():
            return candidate
    raise InternalError(f"templates folder not found beside {package}")


@cache
def environment() -> jinja2.Environment:
    return jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(templates_dir())),
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        autoescape=False,
    )
