"""Processes for the tests that run real tools and ROS processes (tests/live, tests/runtime, ...):
a command run to its end within a time limit, a free loopback port, a background server started
in its own group with its output in a log, stopped with its children, and a readiness poll that
fails with the logs' last lines. Every wait is bounded: a hang fails the test with what the
process printed, it never stops the suite."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any


def run(
    argv: list[str], *, timeout: float, check: bool = False, **options: Any
) -> subprocess.CompletedProcess[str]:
    """``argv`` to its end, its output captured as text; killed after ``timeout`` seconds, and
    the test then fails with what it printed by then. ``check``: a non-zero exit fails too."""
    try:
        done = subprocess.run(argv, capture_output=True, text=True, timeout=timeout, **options)
    except subprocess.TimeoutExpired as error:
        printed = "".join(_text(part) for part in (error.stdout, error.stderr))
        raise AssertionError(f"{argv} did not end within {timeout} s:\n{printed}") from None
    if check and done.returncode != 0:
        raise AssertionError(f"{argv} exited {done.returncode}:\n{done.stdout}{done.stderr}")
    return done


def _text(output: str | bytes | None) -> str:
    # subprocess's timeout keeps the output read so far as bytes, whatever ``text`` says.
    if isinstance(output, bytes):
        return output.decode(errors="replace")
    return output or ""


def free_port() -> int:
    """A TCP port on loopback that nothing listens on right now."""
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def start(argv: list[str], env: dict[str, str], log: Path) -> subprocess.Popen[bytes]:
    """``argv`` in a new session (so ``stop`` reaches its children), output to ``log``."""
    with log.open("wb") as out:
        return subprocess.Popen(
            argv, env=env, stdout=out, stderr=subprocess.STDOUT, start_new_session=True
        )


def stop(process: subprocess.Popen[bytes]) -> None:
    """Stop a process ``start`` made, and its children, by its process group id."""
    if process.poll() is not None:
        return
    os.killpg(process.pid, signal.SIGTERM)
    try:
        process.wait(timeout=5)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait(timeout=5)


def wait_for(what: str, check: Callable[[], bool], timeout: float, logs: list[Path]) -> None:
    """Poll ``check`` until it is true; fail with the last lines of ``logs`` after ``timeout``."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            if check():
                return
        except OSError:  # a server that is not listening yet
            pass
        time.sleep(0.1)
    text = "\n".join(p.read_text(errors="replace")[-3000:] for p in logs if p.exists())
    raise RuntimeError(f"{what} did not come up within {timeout} s\n{text}")
