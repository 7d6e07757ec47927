"""The ``scaffold`` command: a thin typer layer. Only this package prints or exits."""

from __future__ import annotations

import sys

import typer

from unityscaffold import __version__
from unityscaffold.cli import apply, discover, msgs, scene
from unityscaffold.errors import Exit, ScaffoldError

__all__ = ["app", "main"]

app = typer.Typer(
    name="scaffold",
    help="Generate ROS# message classes, ROS components and scene wiring for Unity.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)
app.add_typer(msgs.app, name="msgs")
app.add_typer(scene.app, name="scene")
apply.register(app)
discover.register(app)


def _version(value: bool) -> None:
    if value:
        typer.echo(f"scaffold {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: bool = typer.Option(
        False, "--version", callback=_version, is_eager=True, help="Print the version and exit."
    ),
) -> None:
    """Generate ROS# message classes, ROS components and scene wiring for Unity."""


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; user errors become a message on stderr and exit status 2, never a traceback."""
    try:
        # Without standalone mode click returns a command's exit status instead of exiting.
        status = app(args=argv, standalone_mode=False)
    except ScaffoldError as exc:
        typer.echo(exc.render(), err=True)
        return int(exc.exit_code)
    except typer.Exit as exc:
        return int(exc.exit_code or 0)
    except typer.Abort:
        typer.echo("aborted", err=True)
        return int(Exit.USER_ERROR)
    except KeyboardInterrupt:
        typer.echo("interrupted", err=True)
        return 130
    except Exception as exc:  # a click usage error or a bug
        import click

        if isinstance(exc, click.ClickException):
            exc.show()
            return int(Exit.USER_ERROR)
        raise
    return status if isinstance(status, int) else int(Exit.OK)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
