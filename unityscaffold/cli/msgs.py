"""``scaffold msgs``: list, show and generate ROS interface types."""

from __future__ import annotations

import typer

app = typer.Typer(help="List, show and generate ROS message, service and action types.",
                  no_args_is_help=True)

from unityscaffold.cli import msgs_gen  # noqa: E402

msgs_gen.register(app)
