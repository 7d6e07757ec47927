"""Every bad manifest in ``invalid/`` gives exactly its ``.expected`` message and writes nothing.

Each ``invalid/NAME.yaml`` is loaded as ``robot.yaml`` from a scratch folder; its full rendered
error is compared with ``invalid/NAME.expected``. After changing messages on purpose, rewrite the
snapshots and review their diff::

    UNITYSCAFFOLD_UPDATE=1 python3 -m pytest tests/manifest/test_manifest_invalid.py
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from helpers import UPDATE_HINT, text_diff, updating

from unityscaffold.errors import Exit, LocatedError, ScaffoldError, UserError
from unityscaffold.manifest import load_manifest

INVALID = Path(__file__).parent / "invalid"
CASES = sorted(INVALID.glob("*.yaml"))


def _tree(root: Path) -> list[tuple[str, int]]:
    return sorted((p.relative_to(root).as_posix(), p.stat().st_size) for p in root.rglob("*"))


@pytest.mark.parametrize("case", CASES, ids=[c.stem for c in CASES])
def test_invalid_manifest_gives_its_expected_message(
    case: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    shutil.copyfile(case, tmp_path / "robot.yaml")
    monkeypatch.chdir(tmp_path)
    before = _tree(tmp_path)
    with pytest.raises(ScaffoldError) as caught:
        load_manifest(Path("robot.yaml"))
    error = caught.value
    rendered = error.render() + "\n"
    assert isinstance(error, UserError) and error.exit_code is Exit.USER_ERROR
    assert "Traceback" not in rendered and "ruamel" not in rendered
    assert _tree(tmp_path) == before, "loading a manifest must write nothing"
    expected = case.with_suffix(".expected")
    if updating():
        expected.write_text(rendered, encoding="utf-8")
    assert expected.exists(), f"no snapshot {expected.name}; see this module's docstring"
    snapshot = expected.read_text(encoding="utf-8")
    assert rendered == snapshot, f"{UPDATE_HINT}\n" + text_diff(snapshot, rendered, expected.name)


@pytest.mark.parametrize("case", CASES, ids=[c.stem for c in CASES])
def test_invalid_manifest_diagnostics_are_located_and_sorted(case: Path) -> None:
    with pytest.raises(LocatedError) as caught:
        load_manifest(case)
    positions = [(d.location.line, d.location.col) for d in caught.value.diagnostics]
    assert positions == sorted(positions)
    for diagnostic in caught.value.diagnostics:
        assert diagnostic.location.path == str(case)


def test_every_snapshot_has_its_manifest() -> None:
    orphans = [e.name for e in INVALID.glob("*.expected") if not e.with_suffix(".yaml").exists()]
    assert orphans == []
