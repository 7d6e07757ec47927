"""The bounded waits of the tests that run real processes (tests/processes.py,
tests/runtime/lines.py): a process that hangs or dies fails its test with what it printed, it
never stops the suite."""

from __future__ import annotations

import sys

import pytest
from processes import run

from tests.runtime.lines import start

# Prints a line, then hangs with SIGTERM ignored (as rosbridge_websocket 2.1.0 does).
HANGS = (
    "import signal, sys, time; signal.signal(signal.SIGTERM, signal.SIG_IGN);"
    " print('started', flush=True); sys.stdin.close(); time.sleep(60)"
)


def test_a_command_that_hangs_fails_with_what_it_printed() -> None:
    hangs = ["sh", "-c", "trap '' TERM; echo started; exec sleep 60"]
    with pytest.raises(AssertionError, match=r"did not end within 3 s:\nstarted"):
        run(hangs, timeout=3)


def test_a_command_that_fails_fails_under_check_with_its_output() -> None:
    program = "import sys; print('out'); sys.exit('err')"
    with pytest.raises(AssertionError, match=r"exited 1:\nout\nerr"):
        run([sys.executable, "-c", program], timeout=60, check=True)
    assert run([sys.executable, "-c", program], timeout=60).returncode == 1


def test_a_child_that_hangs_is_killed_and_its_output_says_so() -> None:
    lines = start([sys.executable, "-c", HANGS])
    assert lines.wait_for(lambda line: line == "started", 30)
    assert lines.finish(timeout=0.5) == "started\n(killed after 0.5 s)"
    assert lines.finish() == "started\n(killed after 0.5 s)"  # a second call changes nothing


def test_a_child_that_aborts_at_shutdown_says_so() -> None:
    program = "import os; print('done', flush=True); os.abort()"
    assert start([sys.executable, "-c", program]).finish() == "done\n(ended by SIGABRT)"
