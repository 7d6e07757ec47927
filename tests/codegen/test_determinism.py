"""Output is byte-identical whatever Python's hash seed: sorted iteration, no timestamps."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from codegen_helpers import DATA


def _run(seed: str, out: Path) -> dict[str, bytes]:
    env = {**os.environ, "PYTHONHASHSEED": seed}
    code = "from unityscaffold.cli import main; import sys; sys.exit(main(sys.argv[1:]))"
    subprocess.run(
        [
            sys.executable,
            "-c",
            code,
            "msgs",
            "gen",
            "--ros",
            "2",
            "--path",
            str(DATA / "ros2"),
            "--include-shipped",
            "--out",
            str(out),
            "scaffold_test_msgs",
            "std_msgs",
            "geometry_msgs",
        ],
        env=env,
        check=True,
        capture_output=True,
    )
    return {p.relative_to(out).as_posix(): p.read_bytes() for p in out.rglob("*") if p.is_file()}


def test_generation_is_identical_under_different_hash_seeds(tmp_path: Path) -> None:
    first = _run("1", tmp_path / "a" / "out")
    second = _run("4242", tmp_path / "b" / "out")
    assert len(first) > 100
    assert first == second
    texts = [data for name, data in first.items() if name.endswith(".cs")]
    assert all(b"\r\n" not in t and not t.startswith(b"\xef\xbb\xbf") for t in texts)
