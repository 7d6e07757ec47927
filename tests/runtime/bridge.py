"""A real rosbridge for ROS 1 for the runtime tests: rosmaster, rosbridge_websocket and rosapi_node
from rosbridge_suite's sources, all on loopback, all started by us and stopped by process id.

rosbridge_suite is not packaged by Debian; its unmodified ROS 1 sources (a checkout of
github.com/RobotWebTools/rosbridge_suite, branch ``ros1``) are found through
``UNITYSCAFFOLD_ROSBRIDGE`` or beside the repository where CI puts it. The
Python modules of its own messages and services (and of ``rosauth``'s one service, which
rosbridge_server imports) are generated here with genpy into the copied packages, as catkin's
devel space would place them.
"""

from __future__ import annotations

import os
import shutil
import socket
import subprocess
import xmlrpc.client
from dataclasses import dataclass, field
from pathlib import Path

from helpers import SYSTEM_PYTHON
from processes import free_port, start, stop, wait_for

REPO = Path(__file__).resolve().parents[2]
DATA = Path(__file__).parent / "data"
GENMSG_PY = Path("/usr/lib/genpy/genmsg_py.py")
GENSRV_PY = Path("/usr/lib/genpy/gensrv_py.py")
ROS1_SHARE = Path("/usr/share")


def vendor_folder(variable: str, name: str) -> Path | None:
    """A third-party checkout the tests use: ``$variable``, else beside the repo (as in CI)."""
    if os.environ.get(variable):
        return Path(os.environ[variable])
    candidate = REPO.parent / "shared" / "vendor" / name
    return candidate if candidate.is_dir() else None


def _generate(package: str, folder: Path, out: Path, kind: str) -> None:
    """genpy modules for ``folder``'s ``.msg`` or ``.srv`` files into ``out`` (a Python package)."""
    sources = sorted(folder.glob(f"*.{kind}"))
    if not sources:
        return
    script = GENMSG_PY if kind == "msg" else GENSRV_PY
    includes = [f"-I{package}:{folder.parent / 'msg'}", f"-Istd_msgs:{ROS1_SHARE / 'std_msgs/msg'}"]
    base = [str(SYSTEM_PYTHON), str(script), "-p", package, "-o", str(out), *includes]
    for source in sources:
        subprocess.run([*base, str(source)], check=True, capture_output=True, timeout=60)
    subprocess.run([*base, "--initpy"], check=True, capture_output=True, timeout=60)


def prepare_python_path(vendor: Path, root: Path) -> Path:
    """Copy rosbridge_suite's Python packages under ``root/python`` with their generated message
    modules inside, and its package folders under ``root/share`` (for ROS_PACKAGE_PATH)."""
    python = root / "python"
    python.mkdir(parents=True)
    for package, source in (
        ("rosapi", vendor / "rosapi" / "src" / "rosapi"),
        ("rosbridge_library", vendor / "rosbridge_library" / "src" / "rosbridge_library"),
        ("rosbridge_server", vendor / "rosbridge_server" / "src" / "rosbridge_server"),
    ):
        shutil.copytree(source, python / package)
    for package, folder in (
        ("rosapi", vendor / "rosapi"),
        ("rosbridge_msgs", vendor / "rosbridge_msgs"),
        ("rosauth", DATA / "rosauth"),
    ):
        (python / package).mkdir(exist_ok=True)
        init = python / package / "__init__.py"
        if not init.exists():
            init.write_text("")
        _generate(package, folder / "msg", python / package / "msg", "msg")
        _generate(package, folder / "srv", python / package / "srv", "srv")
    share = root / "share"
    share.mkdir()
    shutil.copytree(vendor / "rosapi", share / "rosapi")
    return python


def _listening(port: int) -> bool:
    with socket.socket() as sock:
        sock.settimeout(0.5)
        return sock.connect_ex(("127.0.0.1", port)) == 0


@dataclass
class Bridge:
    """A running rosmaster + rosbridge_websocket + rosapi_node, and how to reach them."""

    master_url: str
    url: str  # ws://127.0.0.1:PORT
    env: dict[str, str]
    home: Path
    processes: list[subprocess.Popen[bytes]] = field(default_factory=list)

    def master(self) -> xmlrpc.client.ServerProxy:
        return xmlrpc.client.ServerProxy(self.master_url)

    def system_state(self) -> tuple[dict[str, set[str]], dict[str, set[str]], dict[str, set[str]]]:
        """The master's publishers, subscribers and services: ``{name: {node, ...}}`` each."""
        state = self.master().getSystemState("/test")[2]
        publishers, subscribers, services = (
            {name: set(nodes) for name, nodes in part} for part in state
        )
        return publishers, subscribers, services

    def close(self) -> None:
        for process in reversed(self.processes):
            stop(process)


def start_bridge(
    vendor: Path, home: Path, *, extra_python_path: list[Path], packages: list[Path]
) -> Bridge:
    """rosmaster, then rosbridge_websocket (bound to loopback) and rosapi_node, on free ports.
    ``packages``: folders of extra ROS packages (their package.xml) for ROS_PACKAGE_PATH."""
    python = prepare_python_path(vendor, home)
    master_port, bridge_port = free_port(), free_port()
    master_url = f"http://127.0.0.1:{master_port}"
    env = {
        **os.environ,
        "ROS_MASTER_URI": master_url,
        "ROS_HOSTNAME": "127.0.0.1",
        "ROS_LOG_DIR": str(home / "log"),
        "ROS_HOME": str(home),
        "ROS_PACKAGE_PATH": os.pathsep.join(str(p) for p in [home / "share", *packages]),
        "PYTHONPATH": os.pathsep.join(str(p) for p in [python, *extra_python_path]),
    }
    env.pop("PYTHONHOME", None)
    bridge = Bridge(master_url, f"ws://127.0.0.1:{bridge_port}", env, home)
    logs = [home / "master.log", home / "rosbridge.log", home / "rosapi.log"]
    try:
        bridge.processes.append(
            start(
                [str(SYSTEM_PYTHON), "/usr/bin/rosmaster", "--core", "-p", str(master_port)],
                env,
                logs[0],
            )
        )
        wait_for("rosmaster", lambda: bridge.master().getPid("/test")[0] == 1, 20, logs)
        websocket = vendor / "rosbridge_server" / "scripts" / "rosbridge_websocket.py"
        bridge.processes.append(
            start(
                [
                    str(SYSTEM_PYTHON),
                    str(DATA / "bind_loopback.py"),
                    str(websocket),
                    "--port",
                    str(bridge_port),
                    "--address",
                    "127.0.0.1",
                ],
                env,
                logs[1],
            )
        )
        bridge.processes.append(
            start(
                [str(SYSTEM_PYTHON), str(vendor / "rosapi" / "scripts" / "rosapi_node")],
                env,
                logs[2],
            )
        )
        wait_for("rosbridge_websocket", lambda: _listening(bridge_port), 30, logs)
        wait_for("rosapi_node", lambda: "/rosapi/topics" in bridge.system_state()[2], 30, logs)
    except BaseException:
        bridge.close()
        raise
    return bridge
