"""Property: real scenes, mutated at random, are edited cleanly or refused cleanly.

Each example takes a real Unity file (``tests/data/unity``, see ``conftest.corpus_files``), mutates
its lines (drop, duplicate, move, point one ``{fileID}`` at another object of the file, which makes
dangling links and cycles, cut the file short, garble a line) and runs ``scene ls`` and ``scene
attach --create`` through the real entry point:

- the exit status is 0 or 2, never 3 (an internal error), and no traceback is printed;
- each command ends within a bound (a walk of a corrupt hierarchy must end);
- a refused file is byte-identical afterwards, with no temporary file beside it;
- an accepted edit re-parses, passes validation, and removes no original line except the ones
  an attach rewrites (an empty ``m_Children``/``m_Roots``/``m_Component`` list that gains its
  first item).
"""

from __future__ import annotations

import contextlib
import difflib
import re
import shutil
from pathlib import Path

import pytest
from helpers import deadline, run_cli
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from unityscaffold.unity.scene import SceneDocument

from .conftest import CORPUS, CORPUS_IDS

SECONDS = 30
GUID = "0123456789abcdef0123456789abcdef"
_REF = re.compile(r"\{fileID: (-?\d+)\}")
# The lines an attach may rewrite in place: an empty list gaining its first item.
_REWRITTEN = re.compile(r"^  (m_Children|m_Roots|m_Component): \[\]\n$")

mutation = st.tuples(
    st.sampled_from(["drop", "duplicate", "move", "relink", "truncate", "garble"]),
    st.integers(0, 10**6),
    st.integers(0, 10**6),
)


def mutate(text: str, steps: list[tuple[str, int, int]]) -> str:
    lines = text.splitlines(keepends=True)
    ids = [m.group(1) for m in _REF.finditer(text) if m.group(1) != "0"]
    for kind, a, b in steps:
        if len(lines) < 3:
            break
        i, j = 2 + a % (len(lines) - 2), 2 + b % (len(lines) - 2)  # keep the %YAML header
        if kind == "drop":
            del lines[i]
        elif kind == "duplicate":
            lines.insert(j, lines[i])
        elif kind == "move":
            lines.insert(j, lines.pop(i))
        elif kind == "relink" and ids:
            found = [k for k, line in enumerate(lines) if _REF.search(line)]
            if found:
                k = found[a % len(found)]
                target = ids[b % len(ids)]
                lines[k] = _REF.sub(f"{{fileID: {target}}}", lines[k], count=1)
        elif kind == "truncate":
            lines = lines[:i]
        elif kind == "garble":
            line = lines[i]
            cut = b % max(len(line), 1)
            lines[i] = line[:cut] + "{[:'\n"[a % 5] + line[cut:]
    return "".join(lines)


def _run(*args: str) -> tuple[int, str]:
    with deadline(SECONDS, "a command does not end"):
        run = run_cli(*args)
    assert "Traceback" not in run.err, run.err
    assert run.code in (0, 2), f"exit {run.code}:\n{run.out}{run.err}"
    return run.code, run.err


def _assert_only_expected_lines_removed(before: str, after: str) -> None:
    old, new = before.splitlines(keepends=True), after.splitlines(keepends=True)
    matcher = difflib.SequenceMatcher(None, old, new, autojunk=False)
    for op, i1, i2, _j1, _j2 in matcher.get_opcodes():
        if op in ("replace", "delete"):
            for line in old[i1:i2]:
                assert _REWRITTEN.match(line), f"an original line was lost: {line!r}"


@pytest.mark.parametrize("source", CORPUS, ids=CORPUS_IDS)
@settings(
    max_examples=12,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
@given(steps=st.lists(mutation, min_size=1, max_size=4))
def test_a_mutated_real_scene_is_edited_or_refused_cleanly(
    source: Path, tmp_path: Path, steps: list[tuple[str, int, int]]
) -> None:
    folder = tmp_path / "case"
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir()
    path = folder / source.name
    text = mutate(source.read_text(encoding="utf-8"), steps)
    path.write_bytes(text.encode("utf-8"))

    _run("scene", "ls", str(path))
    assert path.read_bytes() == text.encode("utf-8")
    target = "Scaffold/Probe"
    if source.suffix == ".prefab":
        with contextlib.suppress(Exception):
            scene = SceneDocument.parse(text, str(path))
            target = f"{scene.roots()[0].name}/Probe"
    code, err = _run(
        "scene", "attach", str(path), "-g", target, "--create", "--guid", GUID, "--set", "Topic=x"
    )
    assert sorted(p.name for p in folder.iterdir()) == [path.name], "a temporary file was left"
    after = path.read_text(encoding="utf-8")
    if code == 2:
        assert after == text, f"a refused file was changed:\n{err}"
        return
    edited = SceneDocument.parse(after, str(path))
    assert edited.validate() == []
    assert SceneDocument.parse(after, str(path)).text() == after
    _assert_only_expected_lines_removed(text, after)
