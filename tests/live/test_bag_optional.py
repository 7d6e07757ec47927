"""``rosbags`` is the optional ``bag`` extra: only ``discover --bag`` imports it, and without it
that command says what to install instead of failing with a traceback."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import processes

REPO = Path(__file__).resolve().parents[2]

# Runs the CLI in a fresh interpreter where ``import rosbags`` fails as if it were not installed
# (a None entry in sys.modules makes Python raise ModuleNotFoundError for it).
_PROGRAM = """
import json, sys
sys.modules["rosbags"] = None
from unityscaffold.cli import main
code = main(sys.argv[1:])
print(json.dumps({"code": code, "rosbags_imported": sys.modules.get("rosbags") is not None}))
"""


def _without_rosbags(cwd: Path, *args: str) -> tuple[dict[str, object], str]:
    env = {"PYTHONPATH": str(REPO), "PATH": "/usr/bin:/bin"}
    run = processes.run([sys.executable, "-c", _PROGRAM, *args], timeout=120, cwd=cwd, env=env)
    return json.loads(run.stdout.strip().splitlines()[-1]), run.stderr


def test_discover_bag_without_rosbags_says_which_extra_to_install(tmp_path):
    bag = tmp_path / "run.bag"
    bag.write_bytes(b"#ROSBAG V2.0\n")
    result, err = _without_rosbags(tmp_path, "discover", "--print", "--bag", str(bag))
    assert result["code"] == 2, err
    assert "error: reading a recording needs the Python package rosbags" in err
    assert "unityscaffold[bag]" in err
    assert "Traceback" not in err
    assert not (tmp_path / "ros_definitions").exists()


def test_discover_master_does_not_need_rosbags(tmp_path):
    result, err = _without_rosbags(
        tmp_path, "discover", "--print", "--master", "http://127.0.0.1:9", "--timeout", "0.5"
    )
    assert result["code"] == 2, err
    assert "127.0.0.1:9" in err  # nothing listens on port 9: a clean connection error
    assert "rosbags" not in err and "Traceback" not in err
    assert result["rosbags_imported"] is False
