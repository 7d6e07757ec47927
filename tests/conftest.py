"""Shared fixtures: the real tools and data the tests run against.

A missing tool or data set skips a test on a developer machine, and fails it in CI
(``CI=true``), where ``.ci/run`` must have installed everything.
"""

from __future__ import annotations

import shutil
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from helpers import IN_CI, SYSTEM_PYTHON, require
from hypothesis import settings
from processes import run

# Speed is measured by bench/, never asserted by tests: no per-example time limit, which on a
# loaded machine turned one slow first call into a "Flaky" failure. In CI (CI=true) the examples
# are derandomized, the same on every run: CI's verdict on a commit never depends on the draw,
# while a developer's runs go on exploring new examples.
settings.register_profile("unityscaffold", deadline=None)
settings.register_profile("unityscaffold-ci", deadline=None, derandomize=True)
settings.load_profile("unityscaffold-ci" if IN_CI else "unityscaffold")

REPO = Path(__file__).resolve().parent.parent
ROS1_SHARE = Path("/usr/share")
ROS2_SHARE = Path(sys.prefix) / "share"


@pytest.fixture(scope="session")
def mcs() -> str:
    path = shutil.which("mcs")
    require(path, "Mono's C# compiler mcs (Debian package mono-mcs)")
    assert path
    return path


@pytest.fixture(scope="session")
def mono() -> str:
    path = shutil.which("mono")
    require(path, "Mono's runtime (Debian package mono-runtime)")
    require(Path("/usr/lib/mono/4.5/Facades/netstandard.dll").exists(), "Debian's mono-devel")
    assert path
    return path


@pytest.fixture(scope="session")
def ros1_share() -> Path:
    require(
        (ROS1_SHARE / "std_msgs" / "msg").is_dir() and (ROS1_SHARE / "std_srvs" / "srv").is_dir(),
        "Debian's ROS 1 interface packages (ros-*-msgs, ros-std-srvs)",
    )
    return ROS1_SHARE


@pytest.fixture(scope="session")
def ros2_share() -> Path:
    require(
        (ROS2_SHARE / "test_msgs" / "msg").is_dir() and (ROS2_SHARE / "std_msgs" / "msg").is_dir(),
        "the ROS 2 Jazzy interface wheels (ros-jazzy-common-interfaces, ros-jazzy-test-msgs)",
    )
    return ROS2_SHARE


@pytest.fixture(scope="session")
def genmsg_python() -> Path:
    works = (
        SYSTEM_PYTHON.exists()
        and run([str(SYSTEM_PYTHON), "-c", "import genmsg"], timeout=60).returncode == 0
    )
    require(works, "Debian's python3-genmsg under /usr/bin/python3")
    return SYSTEM_PYTHON


@pytest.fixture(scope="session", autouse=True)
def _own_cache_folder(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """Caches (compiled templates, no-op records) in a folder of the session's, not the user's;
    commands run in-process and as child processes alike."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("XDG_CACHE_HOME", str(tmp_path_factory.mktemp("cache")))
        yield
