"""Background servers for the tests that run real ROS processes (tests/live, tests/runtime):
a free loopback port, a process started in its own group with its output in a log, stopped with
its children, and a readiness poll that fails with the logs' last lines."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import time
from collections.abc import Callable
from pathlib import Path


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
