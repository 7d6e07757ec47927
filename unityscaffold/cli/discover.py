"""``scaffold discover``: topics, services and definitions from a live ROS system or a bag."""

from __future__ import annotations

import typer


def register(app: typer.Typer) -> None:
    """Add the ``discover`` command to the root app."""
