"""`scaffold apply` loads what its manifest needs: a robot's apply no template engine and no
script views, a project without robots no URDF reader, a ROS# project no ROS-TCP-Connector
code (each is a share of the command's start; bench/bench_startup.py measures it)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

from tests.cli.noop_support import REPO, SAMPLE

URDF = """<robot name="bot">
  <link name="base"><visual><geometry><box size="1 2 3"/></geometry></visual></link>
</robot>
"""
# the CLI in a fresh interpreter, then the names of the modules it loaded
_LOADED = (
    "import sys; from unityscaffold.cli import main; status = main(sys.argv[1:]); "
    "print(status, *sorted(sys.modules))"
)


def _env(cache: Path) -> dict[str, str]:
    env = {**os.environ, "XDG_CACHE_HOME": str(cache), "UNITYSCAFFOLD_NO_REPLAY": "1"}
    env["PYTHONPATH"] = os.pathsep.join([str(REPO), env.get("PYTHONPATH", "")])
    return env


def _apply_modules(manifest: Path, cache: Path) -> set[str]:
    """The modules a fresh `scaffold apply` process loads (it plans: no no-op record)."""
    command = [sys.executable, "-c", _LOADED, "apply", "--quiet", str(manifest)]
    done = subprocess.run(command, env=_env(cache), capture_output=True, text=True, check=True)
    status, *loaded = done.stdout.split()
    assert status == "0", done.stderr
    return set(loaded)


def test_a_robots_apply_loads_neither_jinja_nor_script_views_nor_the_other_runtime(
    tmp_path: Path,
) -> None:
    project = tmp_path / "p"
    init = [sys.executable, "-m", "unityscaffold", "init", "--ros", "2", str(project)]
    subprocess.run(init, env=_env(tmp_path / "cache"), check=True, capture_output=True)
    (project / "bot.urdf").write_text(URDF, encoding="utf-8")
    manifest = project / "robot.yaml"
    text = manifest.read_text(encoding="utf-8")
    manifest.write_text(text.replace("\nrobots:\n", "\nrobots:\n  - urdf: bot.urdf\n", 1))
    loaded = _apply_modules(manifest, tmp_path / "cache")
    assert "unityscaffold.urdf._import" in loaded  # the robot was imported
    assert "jinja2" not in loaded
    assert "unityscaffold.codegen.scripts" not in loaded
    assert "unityscaffold.apply._target_tcp" not in loaded
    assert "m_Name: bot\n" in (project / "Assets/Scenes/Main.unity").read_text(encoding="utf-8")


def test_an_apply_without_robots_loads_no_urdf_reader(tmp_path: Path) -> None:
    project = tmp_path / "sample_project"
    shutil.copytree(SAMPLE, project)
    loaded = _apply_modules(project / "robot.yaml", tmp_path / "cache")
    assert "unityscaffold.codegen.scripts" in loaded  # its topics' scripts were planned
    assert "unityscaffold.urdf._import" not in loaded
    assert "unityscaffold.urdf._load" not in loaded
    assert "unityscaffold.apply._target_tcp" not in loaded
