"""A real ROS 2 Jazzy for the tests: the stack ``scripts/ros2_stack.py`` builds (PyPI's Jazzy
wheels in a venv of their own, rosbridge_suite 2.x's interface packages and the sample's built
into it; cached), a ROS domain of this test session's own, rosbridge 2.x's websocket server and
rosapi on loopback, and rclpy node scripts run in the stack's venv.

Each session claims a free ``ROS_DOMAIN_ID`` (a lock file per id under the temp folder, held
until the session ends) and talks on loopback only (``ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST``),
so parallel sessions on one machine never see each other's nodes.
"""

from __future__ import annotations

import contextlib
import fcntl
import importlib.util
import json
import random
import socket
import subprocess
import tempfile
from collections.abc import Collection, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType
from typing import IO, Any

from helpers import require
from processes import free_port, start, stop, wait_for
from websockets.exceptions import WebSocketException
from websockets.sync.client import connect

from tests.runtime.lines import Lines

REPO = Path(__file__).resolve().parents[2]
STACK_SCRIPT = REPO / "scripts" / "ros2_stack.py"
# Domain ids a session may claim: 0 is everyone's default, and past 101 the port numbers
# DDS derives from the id run into the ephemeral range on Linux.
DOMAIN_IDS = range(1, 101)
# A request field no service type has (Rosbridge2.knows_services).
PROBE_FIELD = "unityscaffold_probe"


def stack_module() -> ModuleType:
    """``scripts/ros2_stack.py`` as a module (it is a script, not part of the package)."""
    spec = importlib.util.spec_from_file_location("ros2_stack", STACK_SCRIPT)
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@dataclass
class Ros2:
    """The built stack and this session's domain: ``env`` runs a process in it."""

    root: Path
    python: Path  # the venv's, with rclpy and every interface package
    domain_id: int
    home: Path
    env: dict[str, str]
    _claim: IO[str] | None = field(default=None, repr=False)

    def run_node(self, script: Path, *args: str) -> Lines:
        """An rclpy node script (``python script args``) in this domain, its output as lines."""
        process = subprocess.Popen(
            [str(self.python), str(script), *args],
            env=self.env,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
        )
        return Lines(process)

    def close(self) -> None:
        if self._claim:
            self._claim.close()  # releases the domain id's lock


def _claim_domain() -> tuple[int, IO[str]]:
    ids = list(DOMAIN_IDS)
    random.SystemRandom().shuffle(ids)
    for domain_id in ids:
        handle = (Path(tempfile.gettempdir()) / f"unityscaffold-ros-domain-{domain_id}.lock").open(
            "w"
        )
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            handle.close()
            continue
        return domain_id, handle
    raise RuntimeError(f"every ROS domain id in {DOMAIN_IDS} is taken by another session")


def open_ros2(home: Path) -> Ros2:
    """The stack (built first if this machine has none for these inputs) and a domain of this
    session's own. A stack that cannot be built is a skip locally, a failure under CI=true."""
    module = stack_module()
    try:
        root = module.ensure()
    except module.StackError as error:
        require(False, f"ROS 2 Jazzy ({error})")
    domain_id, claim = _claim_domain()
    env = module.environment(root, domain_id, home)
    return Ros2(root, module.venv_python(root), domain_id, home, env, claim)


def _listening(port: int) -> bool:
    with socket.socket() as sock:
        sock.settimeout(0.5)
        return sock.connect_ex(("127.0.0.1", port)) == 0


@dataclass
class Rosbridge2:
    """A running rosbridge 2.x websocket server (and rosapi), and how to reach it."""

    url: str  # ws://127.0.0.1:PORT
    ros2: Ros2
    logs: list[Path]
    processes: list[subprocess.Popen[bytes]] = field(default_factory=list)

    def call(self, service: str, args: dict[str, Any] | None = None) -> dict[str, Any]:
        """One ``call_service`` through a plain JSON websocket client: the answer's message."""
        with connect(self.url, open_timeout=10) as socket_:
            request = {"op": "call_service", "service": service, "id": "probe"}
            socket_.send(json.dumps({**request, "args": args or {}}))
            answer: dict[str, Any] = json.loads(socket_.recv(timeout=30))
            return answer

    def knows_services(self, services: Collection[str]) -> bool:
        """Whether rosbridge's own node has discovered every one of ``services``. rosbridge
        refuses a call to a service its node has not seen ("Service ... does not exist"), and
        rosapi, a node of its own, may list a service before it does. Each is asked with a call
        carrying a field no request has: rosbridge refuses that only once it has found the
        service, and before calling it, so no server ever sees it."""
        answers: dict[str, str] = {}
        with connect(self.url, open_timeout=10, max_size=None) as socket_:
            for name in services:
                args = {PROBE_FIELD: 0}
                socket_.send(
                    json.dumps({"op": "call_service", "service": name, "id": name, "args": args})
                )
            while len(answers) < len(services):
                message = json.loads(socket_.recv(timeout=30))
                if message.get("op") == "service_response":
                    answers[str(message.get("id"))] = str(message.get("values"))
        return all(f"does not have a field {PROBE_FIELD}" in answers[name] for name in services)

    def log_text(self) -> str:
        return "\n".join(p.read_text(errors="replace") for p in self.logs if p.exists())

    def close(self) -> None:
        # rosbridge 2.1.0 ignores SIGTERM; stop() ends it with SIGKILL after its grace period.
        for process in reversed(self.processes):
            stop(process)


def start_rosbridge2(
    ros2: Ros2, *, rosapi: bool = True, parameters: dict[str, str] | None = None
) -> Rosbridge2:
    """rosbridge_websocket on a free loopback port (``parameters``: its ROS parameters, e.g.
    ``{"send_action_goals_in_new_thread": "true"}``) and, with ``rosapi``, rosapi_node; returns
    once rosbridge answers a call to one of rosapi's services (or, without rosapi, listens)."""
    rosbridge = stack_module().rosbridge_folder()
    port = free_port()
    logs = [ros2.home / f"rosbridge-{port}.log", ros2.home / f"rosapi-{port}.log"]
    settings = {"port": str(port), "address": "127.0.0.1", **(parameters or {})}
    arguments = [a for name, value in settings.items() for a in ("-p", f"{name}:={value}")]
    script = rosbridge / "rosbridge_server" / "scripts" / "rosbridge_websocket.py"
    bridge = Rosbridge2(f"ws://127.0.0.1:{port}", ros2, logs)
    try:
        bridge.processes.append(
            start([str(ros2.python), str(script), "--ros-args", *arguments], ros2.env, logs[0])
        )
        if rosapi:
            node = rosbridge / "rosapi" / "scripts" / "rosapi_node"
            bridge.processes.append(start([str(ros2.python), str(node)], ros2.env, logs[1]))
        wait_for("rosbridge_websocket (ROS 2)", lambda: _listening(port), 60, logs)
        if rosapi:
            wait_for("rosapi (ROS 2)", lambda: _rosapi_answers(bridge), 60, logs)
    except BaseException:
        bridge.close()
        raise
    return bridge


def _rosapi_answers(bridge: Rosbridge2) -> bool:
    with contextlib.suppress(TimeoutError, WebSocketException):
        return bool(bridge.call("/rosapi/services").get("result"))
    return False


@contextlib.contextmanager
def running_rosbridge2(ros2: Ros2, **options: Any) -> Iterator[Rosbridge2]:
    """``start_rosbridge2`` for the length of a ``with`` block (a test's own bridge)."""
    bridge = start_rosbridge2(ros2, **options)
    try:
        yield bridge
    finally:
        bridge.close()
