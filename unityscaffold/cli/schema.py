"""``scaffold schema``: the manifest's JSON Schema, for editors and validators."""

from __future__ import annotations

from pathlib import Path

import typer

from unityscaffold.fileout import write_if_changed
from unityscaffold.resources import schema_text


def register(app: typer.Typer) -> None:
    """Add ``schema`` to the root app."""

    @app.command("schema")
    def schema_command(
        output: Path | None = typer.Option(
            None,
            "--output",
            "-o",
            metavar="FILE",
            help="Write the schema to FILE (only if it differs) instead of printing it.",
        ),
    ) -> None:
        """Print the JSON Schema of robot.yaml (draft 2020-12).

        `scaffold init` writes a copy beside robot.yaml and points the manifest's first line
        (`# yaml-language-server: $schema=robot.schema.json`) at it, so editors with the YAML
        language server check and complete the manifest as you type.

        Examples:

          scaffold schema > robot.schema.json

          scaffold schema -o robot.schema.json      (refresh init's copy)
        """
        text = schema_text()
        if output is None:
            typer.echo(text, nl=False)
            return
        changed = write_if_changed(output, text)
        typer.echo(f"{'wrote' if changed else 'unchanged'} {output}")
