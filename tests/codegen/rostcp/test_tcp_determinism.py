"""The connector's classes are byte-identical whatever Python's hash seed."""

from __future__ import annotations

import os
import sys

import pytest
from processes import run

from unityscaffold.interfaces.model import Dialect

# Every type of one ROS version through the connector's generator, as one digest of each
# file's path and text and each skipped class's warning.
_PROGRAM = """
import hashlib, sys
from unityscaffold.codegen import Options
from unityscaffold.codegen.rostcp import generate
from unityscaffold.interfaces.model import Dialect, MessageSpec
from unityscaffold.interfaces.registry import Registry
dialect = Dialect(int(sys.argv[1]))
registry = Registry.load(dialect)
interfaces, _ = registry.parse_all()
roots = interfaces if dialect is Dialect.ROS1 else [
    i for i in interfaces
    if isinstance(i, MessageSpec) and not any(
        f.type.base == "wstring" for m in [i, *registry.closure([i])] for f in m.fields
    )
]
code = generate(registry, roots, Options(dialect))
digest = hashlib.sha256()
for file in code.files:
    digest.update(f"{file.path}\\0{file.text}\\0".encode())
for skipped in code.skipped:
    digest.update(f"{skipped.path}\\0{skipped.warning}\\0".encode())
print(len(code.files), digest.hexdigest())
"""


def _digest(dialect: Dialect, seed: str) -> str:
    env = {**os.environ, "PYTHONHASHSEED": seed}
    done = run(
        [sys.executable, "-c", _PROGRAM, str(int(dialect))], timeout=600, check=True, env=env
    )
    return done.stdout


@pytest.mark.parametrize("dialect", [Dialect.ROS1, Dialect.ROS2], ids=["ros1", "ros2"])
def test_connector_classes_are_identical_under_different_hash_seeds(
    dialect: Dialect, request: pytest.FixtureRequest
) -> None:
    request.getfixturevalue("ros1_share" if dialect is Dialect.ROS1 else "ros2_share")
    first = _digest(dialect, "1")
    assert int(first.split()[0]) > 30
    assert first == _digest(dialect, "4242")
