"""A real ROS 2 Jazzy for the tests and CI: rclpy and its interface packages from PyPI's Jazzy
wheels in a virtual environment of their own, rosbridge_suite's ``ros2`` branch (2.x) on top, and
the interface packages PyPI does not carry built with those wheels' rosidl generators (cmake, g++).

    python3 scripts/ros2_stack.py            # build the stack if needed, print its folder
    python3 scripts/ros2_stack.py --python   # ... print its Python instead

What is built, in the stack folder (``ROOT``):

- ``ROOT/venv``: a venv of Debian's ``/usr/bin/python3`` (its headers, ``python3-dev``, are
  needed to build interface packages) with every wheel pinned in ``scripts/ros2_requirements.txt``
  (``ros-jazzy-rclpy``, ``ros-jazzy-rmw-fastrtps-cpp``, ``ros-jazzy-rcl-action``, the common
  interface packages, ``ros-jazzy-test-msgs``, the rosidl generators, ``ament_cmake``, and
  rosbridge's own Python dependencies). The venv is also the install prefix of what is built
  here, so ``ROOT/venv/bin/python`` imports all of it.
- built into that prefix: rosbridge_suite's ``rosbridge_msgs`` (rosbridge_server imports it) and
  ``rosapi_msgs`` (rosapi), and the sample robot's ``diffbot_msgs`` for ROS 2
  (``sample_project/ros2_ws/src/diffbot_msgs``).

rosbridge_suite's pure-Python packages are not copied: ``environment()`` puts their sources on
``PYTHONPATH``. They come from ``UNITYSCAFFOLD_ROSBRIDGE2`` (a checkout of
github.com/RobotWebTools/rosbridge_suite, branch ``ros2``), ``UNITYSCAFFOLD_ROS2CLI`` (github.com/
ros2/ros2cli, branch ``jazzy``) and ``UNITYSCAFFOLD_ROSIDL_RUNTIME_PY`` (github.com/ros2/
rosidl_runtime_py, branch ``jazzy``), or from ``../shared/vendor`` beside the repository, where CI
puts them.

The stack is cached: ``ROOT`` is ``ros2-jazzy-<key>`` under ``UNITYSCAFFOLD_ROS2_CACHE`` (default
``~/.cache/unityscaffold``), ``<key>`` a digest of everything the build reads and does (its steps'
source in this script, the pinned requirements, the built packages' files, the Python's version). A
change to any of them builds a new stack; nothing is reused on trust. A build that stopped half-way
has no ``.complete`` marker and is built again; a lock file keeps two builds of one key from
running at once. On a fresh machine the build takes several minutes (the pip downloads and three
CMake builds); cached, it is a digest and a check. Each use touches the stack's marker; a new build
removes the other stacks (about 350 MB each) that nothing has used for ``STALE_DAYS``, so a machine
that builds many keys does not keep them all.

Everything talks on loopback only: ``environment()`` sets ``ROS_AUTOMATIC_DISCOVERY_RANGE=
LOCALHOST`` and the ``ROS_DOMAIN_ID`` it is given (pick one at random per test session, so
sessions on one machine do not meet).
"""

from __future__ import annotations

import argparse
import fcntl
import hashlib
import inspect
import os
import shutil
import subprocess
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
REQUIREMENTS = Path(__file__).with_name("ros2_requirements.txt")
# The sample robot's interfaces as a ROS 2 package (its ROS 1 one is sample_project/ros_ws).
SAMPLE_INTERFACES = REPO / "sample_project" / "ros2_ws" / "src" / "diffbot_msgs"
VENV_PYTHON = Path("/usr/bin/python3")
# The folders the exported CMake files of PyPI's Jazzy wheels name: those of the machine that
# built them. They must be this venv's, or CMake refuses the imported targets.
BUILT_PYTHON_INCLUDE = "/opt/python/cp311-cp311/include/python3.11"
BUILT_NUMPY_INCLUDE = "/opt/python/cp311-cp311/lib/python3.11/site-packages/numpy/_core/include"
# The tools the build needs beside the venv's Python (Debian: cmake, g++, make, python3-dev,
# python3-venv).
BUILD_TOOLS = ("cmake", "make", "gcc", "g++")
# Another key's stack unused for this long is removed when a new one is built.
STALE_DAYS = 14

# rosbridge_suite's Python packages (sources on PYTHONPATH) and the ros2cli parts rosapi imports.
ROSBRIDGE_SOURCES = ("rosbridge_library/src", "rosbridge_server/src", "rosapi/src")
ROS2CLI_PARTS = ("ros2cli", "ros2node", "ros2service", "ros2topic", "ros2param", "ros2action")
BUILT_PACKAGES = ("rosbridge_msgs", "rosapi_msgs")


class StackError(Exception):
    """The stack cannot be built here: what is missing and how to get it."""


def vendor_folder(variable: str, name: str) -> Path:
    """A third-party checkout: ``$variable``, else ``../shared/vendor/name`` beside the repo."""
    folder = Path(os.environ[variable]) if os.environ.get(variable) else None
    folder = folder or REPO.parent / "shared" / "vendor" / name
    if not folder.is_dir():
        raise StackError(f"{name} not found: set {variable} to a checkout of it")
    return folder


def rosbridge_folder() -> Path:
    return vendor_folder("UNITYSCAFFOLD_ROSBRIDGE2", "rosbridge_suite-ros2")


def _files_digest(digest: hashlib._Hash, folder: Path) -> None:
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        digest.update(path.relative_to(folder).as_posix().encode() + b"\0")
        digest.update(path.read_bytes() + b"\0")


def stack_key() -> str:
    """A digest of everything the build reads and does: a change to any of it means another
    stack. The build steps count by their source, so editing this script's text elsewhere
    (its docs, the test-side helpers) keeps the cache."""
    digest = hashlib.sha256()
    for step in (_build, _point_cmake_at_this_python, _cmake_install, _run):
        digest.update(inspect.getsource(step).encode())
    facts = (BUILT_PYTHON_INCLUDE, BUILT_NUMPY_INCLUDE, str(VENV_PYTHON), *BUILT_PACKAGES)
    digest.update("\0".join(facts).encode())
    digest.update(REQUIREMENTS.read_bytes())
    version = subprocess.run(
        [str(VENV_PYTHON), "-c", "import sys; print(sys.version)"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    digest.update(version.encode())
    rosbridge = rosbridge_folder()
    for package in BUILT_PACKAGES:
        _files_digest(digest, rosbridge / package)
    _files_digest(digest, SAMPLE_INTERFACES)
    return digest.hexdigest()[:16]


def cache_folder() -> Path:
    """``UNITYSCAFFOLD_ROS2_CACHE``, else ``~/.cache/unityscaffold``; not ``$XDG_CACHE_HOME``,
    which the test suite points at a folder of each session's own."""
    if os.environ.get("UNITYSCAFFOLD_ROS2_CACHE"):
        return Path(os.environ["UNITYSCAFFOLD_ROS2_CACHE"])
    return Path.home() / ".cache" / "unityscaffold"


def stack_root() -> Path:
    """Where the stack of this checkout's inputs lives (built or not)."""
    return cache_folder() / f"ros2-jazzy-{stack_key()}"


def venv_python(root: Path) -> Path:
    return root / "venv" / "bin" / "python"


def python_path() -> list[Path]:
    """rosbridge_suite's Python packages and the pure-Python parts rosapi imports."""
    rosbridge = rosbridge_folder()
    ros2cli = vendor_folder("UNITYSCAFFOLD_ROS2CLI", "ros2cli-jazzy")
    runtime_py = vendor_folder("UNITYSCAFFOLD_ROSIDL_RUNTIME_PY", "rosidl_runtime_py-jazzy")
    return [
        *(rosbridge / s for s in ROSBRIDGE_SOURCES),
        *(ros2cli / p for p in ROS2CLI_PARTS),
        runtime_py,
    ]


def environment(root: Path, domain_id: int, home: Path) -> dict[str, str]:
    """The environment for the stack's processes (rclpy nodes, rosbridge, rosapi): on loopback
    only, in ``domain_id``, with logs under ``home``."""
    prefix = root / "venv"
    env = {
        **os.environ,
        "PATH": os.pathsep.join([str(prefix / "bin"), os.environ.get("PATH", "")]),
        "AMENT_PREFIX_PATH": str(prefix),
        "LD_LIBRARY_PATH": str(prefix / "lib"),
        "PYTHONPATH": os.pathsep.join(str(p) for p in python_path()),
        "RMW_IMPLEMENTATION": "rmw_fastrtps_cpp",
        "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
        "ROS_DOMAIN_ID": str(domain_id),
        "ROS_LOG_DIR": str(home / "log"),
        "ROS_HOME": str(home),
        "PYTHONDONTWRITEBYTECODE": "1",
    }
    for name in ("PYTHONHOME", "VIRTUAL_ENV", "ROS_DISTRO", "ROS_LOCALHOST_ONLY"):
        env.pop(name, None)
    return env


def ensure() -> Path:
    """The stack's folder, built first unless a complete one of the same key is there."""
    root = stack_root()
    marker = root / ".complete"
    if marker.exists():
        marker.touch()  # last used now: see _prune_stale
        return root
    root.parent.mkdir(parents=True, exist_ok=True)
    with _locked(root.with_name(root.name + ".lock")):
        if marker.exists():  # built by another process while this one waited
            return root
        missing = [tool for tool in BUILD_TOOLS if not shutil.which(tool)]
        if missing or not VENV_PYTHON.exists():
            raise StackError(
                f"cannot build ROS 2 Jazzy: missing {', '.join(missing) or VENV_PYTHON}"
                " (Debian: apt-get install cmake make g++ python3-dev python3-venv)"
            )
        if root.exists():
            shutil.rmtree(root)  # an earlier build stopped half-way
        root.mkdir()
        _build(root)
        marker.write_text(root.name + "\n")
    _prune_stale(root)
    return root


def _prune_stale(kept: Path) -> None:
    """Remove the other stacks beside ``kept`` whose marker nothing has touched for
    ``STALE_DAYS`` (and that no build holds the lock of): a stack in use is touched at each use."""
    cutoff = time.time() - STALE_DAYS * 86400
    for other in sorted(kept.parent.glob("ros2-jazzy-*")):
        if other == kept or not other.is_dir():
            continue
        marker = other / ".complete"
        if marker.exists() and marker.stat().st_mtime > cutoff:
            continue
        lock = other.with_name(other.name + ".lock")
        with lock.open("w") as handle:
            try:
                fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:  # being built right now
                continue
            shutil.rmtree(other, ignore_errors=True)
        lock.unlink(missing_ok=True)
        print(f"ros2_stack: removed {other}, unused for {STALE_DAYS} days", file=sys.stderr)


@contextmanager
def _locked(path: Path) -> Iterator[None]:
    with path.open("w") as handle:
        fcntl.flock(handle, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def _run(argv: list[str], log: Path, env: dict[str, str] | None = None) -> None:
    with log.open("a") as out:
        out.write("+ " + " ".join(argv) + "\n")
        out.flush()
        done = subprocess.run(argv, stdout=out, stderr=subprocess.STDOUT, env=env, check=False)
    if done.returncode != 0:
        tail = log.read_text(errors="replace")[-4000:]
        raise StackError(f"{argv[0]} failed (exit {done.returncode}); {log}:\n{tail}")


def _build(root: Path) -> None:
    log = root / "build.log"
    prefix = root / "venv"
    _run([str(VENV_PYTHON), "-m", "venv", str(prefix)], log)
    pip = [str(prefix / "bin" / "python"), "-m", "pip", "--disable-pip-version-check"]
    _run([*pip, "install", "-q", "-r", str(REQUIREMENTS)], log)
    _point_cmake_at_this_python(prefix)
    rosbridge = rosbridge_folder()
    sources = [*(rosbridge / package for package in BUILT_PACKAGES), SAMPLE_INTERFACES]
    for source in sources:
        _cmake_install(source, root / "build" / source.name, prefix, log)
    shutil.rmtree(root / "build")


def _point_cmake_at_this_python(prefix: Path) -> None:
    """Rewrite the include folders the wheels' CMake exports name to this venv's."""
    python = str(prefix / "bin" / "python")
    include, numpy = subprocess.run(
        [
            python,
            "-c",
            "import sysconfig, numpy; print(sysconfig.get_paths()['include']);"
            " print(numpy.get_include())",
        ],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    if not (Path(include) / "Python.h").exists():
        raise StackError(f"no Python.h in {include} (Debian: apt-get install python3-dev)")
    for path in sorted((prefix / "share").glob("*/cmake/*.cmake")):
        text = path.read_text()
        if BUILT_PYTHON_INCLUDE in text or BUILT_NUMPY_INCLUDE in text:
            text = text.replace(BUILT_NUMPY_INCLUDE, numpy).replace(BUILT_PYTHON_INCLUDE, include)
            path.write_text(text)


def _cmake_install(source: Path, build: Path, prefix: Path, log: Path) -> None:
    env = {**os.environ, "PATH": os.pathsep.join([str(prefix / "bin"), os.environ["PATH"]])}
    env["AMENT_PREFIX_PATH"] = str(prefix)
    env.pop("PYTHONPATH", None)
    configure = [
        "cmake",
        "-S",
        str(source),
        "-B",
        str(build),
        f"-DCMAKE_PREFIX_PATH={prefix}",
        f"-DCMAKE_INSTALL_PREFIX={prefix}",
        f"-DPython3_EXECUTABLE={prefix / 'bin' / 'python'}",
        "-DBUILD_TESTING=OFF",
    ]
    _run(configure, log, env=env)
    _run(["cmake", "--build", str(build), f"-j{os.cpu_count() or 2}"], log, env=env)
    _run(["cmake", "--install", str(build)], log, env=env)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--python", action="store_true", help="print the venv's Python instead")
    args = parser.parse_args()
    try:
        root = ensure()
    except StackError as error:
        print(f"ros2_stack: {error}", file=sys.stderr)
        return 1
    print(venv_python(root) if args.python else root)
    return 0


if __name__ == "__main__":
    sys.exit(main())
