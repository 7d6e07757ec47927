"""The typer application behind ``scaffold``: its commands, and how errors become exit statuses."""

from __future__ import annotations

import importlib
import os
from typing import Any

import typer

from unityscaffold import __version__
from unityscaffold.cli._text import one_line_paragraphs
from unityscaffold.errors import Exit, ScaffoldError, UserError

__all__ = ["build_app", "run_cli"]

# Command name -> the module that defines it. A module is imported only when its command runs
# (or for the full help), so `scaffold apply` does not pay for discovery's network stack.
_COMMANDS = {
    "apply": "apply",
    "plan": "apply",
    "init": "apply",
    "msgs": "msgs",
    "scene": "scene",
    "discover": "discover",
    "schema": "schema",
}
_GROUPS = ("msgs", "scene")


def _wanted(argv: list[str]) -> list[str]:
    """The command modules needed for ``argv``: one for a known command, else all."""
    first = next((arg for arg in argv if not arg.startswith("-")), None)
    if first in _COMMANDS:
        return [_COMMANDS[first]]
    return sorted(set(_COMMANDS.values()))


def build_app(argv: list[str]) -> typer.Typer:
    app = typer.Typer(
        name="scaffold",
        help=_root.__doc__,
        no_args_is_help=True,
        add_completion=True,  # --install-completion / --show-completion for bash, zsh, fish, pwsh
        pretty_exceptions_enable=False,
    )
    app.callback()(_root)
    for name in _wanted(argv):
        module = importlib.import_module(f"unityscaffold.cli.{name}")
        if name in _GROUPS:
            app.add_typer(module.app, name=name)
        else:
            module.register(app)
    return app


def _indent_kept(text: str) -> str:
    """``text`` with a blank line more after its first paragraph, so typer keeps the examples'
    indentation.

    typer dedents the paragraphs after the first as one block with ``inspect.cleandoc``, whose
    first line does not count towards the common indentation: when only examples followed an
    ``Examples:`` line, they lost their indentation (and differed from one command to the next).
    An empty first line counts for nothing and is dropped, so the block keeps its margins.
    """
    first, _, rest = text.partition("\n\n")
    return f"{first}\n\n\n{rest}" if rest else text


def _reflow_help(command: Any) -> None:
    """Every command's help as ``one_line_paragraphs`` (the click tree typer builds)."""
    if command.help:
        command.help = _indent_kept(one_line_paragraphs(command.help))
    for sub in getattr(command, "commands", {}).values():
        _reflow_help(sub)


def _version(value: bool) -> None:
    if value:
        typer.echo(f"scaffold {__version__}")
        raise typer.Exit()


def _root(
    version: bool = typer.Option(
        False, "--version", callback=_version, is_eager=True, help="Print the version and exit."
    ),
) -> None:
    """Generate ROS# message classes, ROS components and scene wiring for Unity.

    Examples:

      scaffold init my_robot --ros 2

      scaffold apply my_robot/robot.yaml

      scaffold apply --check        (robot.yaml here or in a folder above)

      scaffold msgs show sensor_msgs/msg/Imu

    Each command's --help has its own examples.
    """


def _usage_errors() -> tuple[type[BaseException], ...]:
    """Click's usage-error class, wherever it lives: typer 0.26+ bundles its own click."""
    found = []
    for module in ("typer._click.exceptions", "click.exceptions"):
        try:
            found.append(importlib.import_module(module).ClickException)
        except ImportError:
            continue
    return tuple(found)


def run_cli(args: list[str]) -> int:
    """Run the CLI; user errors become a message on stderr and exit status 2, never a traceback."""
    try:
        # Without standalone mode click returns a command's exit status instead of exiting.
        # prog_name fixed: also `python -m unityscaffold` completes and shows usage as `scaffold`
        command = typer.main.get_command(build_app(args))
        _reflow_help(command)
        status = command(args=args, prog_name="scaffold", standalone_mode=False)
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
    except Exception as exc:  # a usage error or a bug
        if isinstance(exc, _usage_errors()):
            exc.show()  # type: ignore[attr-defined]
            return int(Exit.USER_ERROR)
        if isinstance(exc, OSError) and _folder_gone():
            gone = UserError(
                "the current folder no longer exists",
                hint="cd to a folder that does and run the command again",
            )
            typer.echo(gone.render(), err=True)
            return int(Exit.USER_ERROR)
        import traceback

        typer.echo(
            "internal error: unityscaffold hit a bug; please report it with this "
            "output:\n" + traceback.format_exc(),
            err=True,
        )
        return int(Exit.INTERNAL)
    return status if isinstance(status, int) else int(Exit.OK)


def _folder_gone() -> bool:
    """Whether the current folder was deleted (every relative path, the manifest's too, fails)."""
    try:
        os.getcwd()
    except OSError:
        return True
    return False
