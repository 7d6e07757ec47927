"""The ``scaffold`` command: a thin typer layer. Only this package prints or exits.

``main`` first asks the no-op record (``_noop``) whether this exact command already verified
this unchanged project; only if not does it load typer and the commands (``_app``), watched
by ``_recorder``.
"""

from __future__ import annotations

import sys

from unityscaffold.cli._text import one_line_paragraphs

TYPE_CHECKING = False  # typing itself is not loaded for a replayed no-op
if TYPE_CHECKING:
    from typing import Any

    import typer

__all__ = ["build_app", "main", "one_line_paragraphs"]


def build_app(argv: list[str]) -> typer.Typer:
    """The typer app with the commands ``argv`` needs (all of them for the root's help)."""
    from unityscaffold.cli._app import build_app as build

    return build(argv)


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; user errors become a message on stderr and exit status 2, never a traceback."""
    from unityscaffold.cli import _noop

    args = sys.argv[1:] if argv is None else list(argv)
    replayed = _noop.replay(args)
    if replayed is not None:
        return replayed
    from unityscaffold.cli._recorder import Recorder

    recorder = Recorder.start(args)
    status: Any = None
    try:
        from unityscaffold.cli._app import run_cli

        status = run_cli(args)
    finally:
        if recorder is not None:
            recorder.finish(status)
    return int(status)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
