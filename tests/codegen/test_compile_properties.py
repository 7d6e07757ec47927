"""Property: whatever the grammar accepts, the generator turns into C# that mcs compiles, or it
refuses at the definition's file and line.

Each example is a batch of mutated real definitions (``mutations.py``), generated together and
compiled with one mcs call. The budget is fixed (``BATCHES`` batches of ``BATCH`` definitions
per ROS version, about 15 s in all); ``UNITYSCAFFOLD_FUZZ_BATCHES`` raises it for a longer run.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from codegen_helpers import STUB_NEEDS
from csharp import ROSSHARP_STUB, compile_cs
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from mutations import Mutant, mutants, real_definitions

from unityscaffold.codegen import Options, generate
from unityscaffold.errors import LocatedError
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry

BATCH = 40
BATCHES = int(os.environ.get("UNITYSCAFFOLD_FUZZ_BATCHES", "5"))


def _check_batch(mcs: str, root: Path, dialect: Dialect, batch: list[Mutant]) -> int:
    """Check one batch; return how many of its mutants were accepted (and so compiled)."""
    folder = root / "defs"
    for mutant in batch:
        mutant.write(folder)
    registry = Registry.load(dialect, [folder])
    accepted = []
    for mutant in batch:
        full = (
            f"{mutant.package}/{mutant.name}"
            if dialect is Dialect.ROS1
            else f"{mutant.package}/{mutant.kind}/{mutant.name}"
        )
        try:
            interface = registry.get(full)
            generate(registry, [interface], Options(dialect, include_shipped=True))
        except LocatedError as refused:
            for diagnostic in refused.diagnostics:
                assert diagnostic.location.path.endswith(mutant.relative), refused.render()
                assert diagnostic.location.line >= 1, refused.render()
            continue
        accepted.append((mutant, interface))
    if not accepted:
        return 0
    roots = [i for _, i in accepted]
    roots += [registry.get(n) for n in STUB_NEEDS[dialect]]
    code = generate(registry, roots, Options(dialect, include_shipped=True))
    sources = [ROSSHARP_STUB]
    for file in code.files:
        path = root / "src" / file.path
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(file.text, encoding="utf-8")
        sources.append(path)
    compiled = compile_cs(mcs, sources, root / "Fuzz.dll", ros2=dialect is Dialect.ROS2)
    shown = "\n\n".join(f"{m.origin} -> {m.relative}:\n{m.text}" for m, _ in accepted)
    assert compiled.returncode == 0 and "warning" not in compiled.output, (
        compiled.output[-3000:] + "\n" + shown[-6000:]
    )
    return len(accepted)


def _batches(sources: list[Path], dialect: Dialect) -> st.SearchStrategy[list[Mutant]]:
    return st.tuples(*(mutants(sources, dialect, i) for i in range(BATCH))).map(list)


@pytest.mark.parametrize("dialect", [Dialect.ROS1, Dialect.ROS2], ids=["ros1", "ros2"])
def test_accepted_mutants_compile_or_are_refused_at_their_line(
    dialect: Dialect,
    mcs: str,
    ros1_share: Path,
    ros2_share: Path,
    tmp_path_factory: pytest.TempPathFactory,
) -> None:
    share = ros1_share if dialect is Dialect.ROS1 else ros2_share
    sources = real_definitions(share, dialect, 60)

    @given(_batches(sources, dialect))
    @settings(
        max_examples=BATCHES,
        deadline=None,
        database=None,
        suppress_health_check=list(HealthCheck),
    )
    def check(batch: list[Mutant]) -> None:
        _check_batch(mcs, tmp_path_factory.mktemp("fuzz"), dialect, batch)

    check()
