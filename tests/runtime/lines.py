"""A child process's output read line by line in the background, so that a test can wait for
a given line with a timeout that only guards against a hang (the test fails on the output,
never on how long it took)."""

from __future__ import annotations

import contextlib
import queue
import signal
import subprocess
import threading
import time
from collections.abc import Callable


class Lines:
    """Every line ``process`` prints (stdout, with stderr merged by the caller), kept in order."""

    def __init__(self, process: subprocess.Popen[str]) -> None:
        assert process.stdout
        self.process = process
        self.seen: list[str] = []
        self._finished = False
        self._queue: queue.Queue[str | None] = queue.Queue()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.process.stdout
        for line in self.process.stdout:
            self._queue.put(line.rstrip("\n"))
        self._queue.put(None)

    def wait_for(self, wanted: Callable[[str], bool], timeout: float) -> bool:
        """True once a line for which ``wanted`` holds has been printed (now or before); False
        if the process ended or ``timeout`` passed first."""
        if any(wanted(line) for line in self.seen):
            return True
        deadline = time.monotonic() + timeout
        while (left := deadline - time.monotonic()) > 0:
            try:
                line = self._queue.get(timeout=left)
            except queue.Empty:
                return False
            if line is None:
                self._queue.put(None)  # stays ended for later calls
                return False
            self.seen.append(line)
            if wanted(line):
                return True
        return False

    def finish(self, timeout: float = 30) -> str:
        """Close stdin, wait for the end (kill after ``timeout``), return everything printed,
        with a last line saying so if the process was killed or ended by a signal."""
        if self._finished:
            return "\n".join(self.seen)
        if self.process.stdin and not self.process.stdin.closed:
            with contextlib.suppress(BrokenPipeError):
                self.process.stdin.close()
        ending = ""
        try:
            self.process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.process.kill()
            ending = f"(killed after {timeout} s)"
            # A process in uninterruptible sleep outlives SIGKILL: the test fails on its output
            # rather than waiting for it.
            with contextlib.suppress(subprocess.TimeoutExpired):
                self.process.wait(timeout=10)
        # A child that inherited the pipe can hold it open after the process ended.
        self._reader.join(10)
        while not self._queue.empty():
            line = self._queue.get()
            if line is not None:
                self.seen.append(line)
        code = self.process.returncode
        if not ending and code is not None and code < 0:
            ending = f"(ended by {signal.Signals(-code).name})"
        if ending:
            self.seen.append(ending)
        self._finished = True
        return "\n".join(self.seen)


def start(argv: list[str], env: dict[str, str] | None = None) -> Lines:
    """``argv`` with a stdin pipe, stdout and stderr read together."""
    process = subprocess.Popen(
        argv,
        env=env,
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    return Lines(process)
