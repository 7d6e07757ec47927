"""``scaffold msgs gen``: generate ROS# C# classes for types or whole packages."""

from __future__ import annotations

import typer


def register(app: typer.Typer) -> None:
    """Add the ``gen`` command to the ``msgs`` group."""
