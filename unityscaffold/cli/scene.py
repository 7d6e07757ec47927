"""``scaffold scene``: inspect a scene and attach components by hand."""

from __future__ import annotations

import typer

app = typer.Typer(help="Inspect Unity scenes and attach components.", no_args_is_help=True)
