"""Shell completion is on: typer's --show-completion prints a script for the shell, and the
completion protocol it uses (run with ``_SCAFFOLD_COMPLETE`` set) completes commands and options,
also when started as ``python -m unityscaffold``."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from helpers import run_cli


@pytest.mark.parametrize(
    ("shell", "registration"),
    [
        ("bash", "complete -o default -F _scaffold_completion scaffold"),
        ("zsh", "compdef _scaffold_completion scaffold"),
        ("fish", "complete --command scaffold"),
    ],
)
def test_show_completion_prints_a_script_for_scaffold(shell: str, registration: str) -> None:
    # With shellingham installed typer detects the shell from the process tree and ignores the
    # name given; its own switch for tests makes the named shell count, so each is checked.
    env = {**os.environ, "_TYPER_COMPLETE_TEST_DISABLE_SHELL_DETECTION": "1"}
    done = subprocess.run(
        [sys.executable, "-m", "unityscaffold", "--show-completion", shell],
        env=env,
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    assert "_SCAFFOLD_COMPLETE" in done.stdout
    assert registration in done.stdout


def test_help_lists_install_completion() -> None:
    assert "--install-completion" in run_cli("--help").out


@pytest.mark.parametrize(
    ("words", "expected"),
    [
        ("scaffold ms", ["msgs"]),
        ("scaffold msgs g", ["gen"]),
        ("scaffold sch", ["schema"]),
        ("scaffold apply --ch", ["--check"]),
    ],
)
def test_bash_completion_completes_commands_and_options(words: str, expected: list[str]) -> None:
    env = {
        **os.environ,
        "_SCAFFOLD_COMPLETE": "complete_bash",
        "COMP_WORDS": words,
        "COMP_CWORD": str(len(words.split()) - 1),
    }
    done = subprocess.run(
        [sys.executable, "-m", "unityscaffold"], env=env, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == expected
