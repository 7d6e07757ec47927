"""Validation before writing: corrupt files are refused and nothing is written."""

from __future__ import annotations

from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError
from unityscaffold.unity import _textops
from unityscaffold.unity._documents import Documents
from unityscaffold.unity._links import Links
from unityscaffold.unity._split import Doc, split_text
from unityscaffold.unity._validate import check_docs, validate_docs
from unityscaffold.unity.scene import SceneDocument
from unityscaffold.unity.textdiff import diff
from unityscaffold.unity.values import ScriptRef

DATA = Path(__file__).resolve().parents[1] / "data" / "unity"
SOURCE = DATA / "ros-sharp" / "ROSVersionSwitch.unity"
SCRIPT = ScriptRef("ff98778ae051cfd40a6e4effdf851ebd")

CORRUPTIONS = {
    "duplicate-file-id": (
        ("--- !u!114 &1259760941", "--- !u!114 &1259760939"),
        "more than one object",
    ),
    "dangling-reference": (
        (
            "m_Father: {fileID: 0}\n  m_LocalEulerAnglesHint: {x: 50",
            "m_Father: {fileID: 42}\n  m_LocalEulerAnglesHint: {x: 50",
        ),
        "refers to fileID 42",
    ),
    "component-not-listed": (("  - component: {fileID: 1259760941}\n", ""), "does not list it"),
    "scene-roots-mismatch": (
        ("  - {fileID: 705507995}\n", ""),
        "m_Roots: does not match the scene's roots: omits root &705507995",
    ),
}


def test_every_corpus_file_passes_validation(corpus_file: Path) -> None:
    assert SceneDocument.load(corpus_file).validate() == []


@pytest.mark.parametrize("case", sorted(CORRUPTIONS))
def test_a_corrupt_scene_is_refused_and_nothing_is_written(tmp_path: Path, case: str) -> None:
    (old, new), message = CORRUPTIONS[case]
    text = SOURCE.read_text(encoding="utf-8")
    assert old in text
    path = tmp_path / "Scene.unity"
    path.write_text(text.replace(old, new, 1), encoding="utf-8")
    before = path.read_bytes()
    scene = SceneDocument.load(path)
    scene.ensure_component("Main Camera", SCRIPT, {"SecondsTimeout": 3})
    with pytest.raises(LocatedError, match=message) as info:
        scene.write()
    assert path.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["Scene.unity"]  # no temp file left
    rendered = info.value.render()
    assert f"{path}:" in rendered and "--- !u!" in rendered


def test_a_diagnostic_names_the_document_key_and_line(tmp_path: Path) -> None:
    (old, new), _ = CORRUPTIONS["dangling-reference"]
    scene = SceneDocument.parse(SOURCE.read_text().replace(old, new), "s.unity")
    problem = scene.validate()[0]
    assert (
        problem.message
        == "--- !u!4 &705507995: m_Father: refers to fileID 42, which is not in the file"
    )
    assert problem.location.source_line == "  m_Father: {fileID: 42}"
    assert scene.text().splitlines()[problem.location.line - 1] == problem.location.source_line


def test_an_edited_document_that_is_not_yaml_is_caught() -> None:
    # No public edit writes broken YAML, so break a document the way a faulty edit would.
    split = split_text(SOURCE.read_text(), "s.unity")
    docs = Documents("s.unity", split.prolog, split.docs, split.crlf)
    doc = docs.require(1259760941)
    _textops.set_text(doc, doc.text.replace("Topic: test", "Topic: [unclosed"))
    docs.touch(doc)
    problems = validate_docs(docs.path, docs.prolog, docs.in_order, docs.changed)
    assert any("not valid YAML" in d.message for d in problems)


def test_write_rewrites_only_when_bytes_change(tmp_path: Path) -> None:
    path = tmp_path / "Scene.unity"
    path.write_bytes(SOURCE.read_bytes())
    path.chmod(0o640)
    scene = SceneDocument.load(path)
    assert scene.write() is False
    scene.ensure_component("Main Camera", SCRIPT)
    assert scene.write() is True
    assert path.read_text() == scene.text() and (path.stat().st_mode & 0o777) == 0o640
    assert SceneDocument.load(path).write() is False


def test_the_diff_of_a_large_file_keeps_real_line_numbers() -> None:
    old = "".join(f"line {i}\n" for i in range(1000))
    new = old.replace("line 500\n", "line 500 changed\n")
    text = diff(old, new, "/abs/Scene.unity")
    assert text.splitlines()[:3] == [
        "--- a/abs/Scene.unity",
        "+++ b/abs/Scene.unity",
        "@@ -498,7 +498,7 @@",
    ]
    assert "-line 500\n+line 500 changed\n" in text
    assert diff(old, old, "x") == ""


def _edit(docs: Documents, file_id: int, old: str, new: str) -> None:
    doc = docs.require(file_id)
    assert old in doc.text
    _textops.set_text(doc, doc.text.replace(old, new, 1))
    docs.touch(doc)


# Breakage after a clean check, as a faulty edit would leave it (public edits keep files sound).
BREAKAGE = {
    "dangling": lambda d: _edit(d, 705507995, "m_Father: {fileID: 0}", "m_Father: {fileID: 42}"),
    "own-parent": lambda d: _edit(
        d, 705507995, "m_Father: {fileID: 0}", "m_Father: {fileID: 705507995}"
    ),
    "unlisted-component": lambda d: _edit(
        d, 1259760938, "  - component: {fileID: 1259760941}\n", ""
    ),
    "roots": lambda d: _edit(d, 9223372036854775807, "  - {fileID: 705507995}\n", ""),
    "not-yaml": lambda d: _edit(d, 1259760941, "Topic: test", "Topic: [unclosed"),
    # the GameObject that still lists it is not edited: only a removal shows it dangles
    "removed": lambda d: d.remove(d.require(1259760941)),
    "duplicate": lambda d: d.insert(Doc(114, 1259760939, False, d.require(1259760941).text)),
}


@pytest.mark.parametrize("case", sorted(BREAKAGE))
def test_a_check_after_a_clean_one_finds_what_a_full_check_finds(case: str) -> None:
    split = split_text(SOURCE.read_text(), "s.unity")
    docs = Documents("s.unity", split.prolog, split.docs, split.crlf)
    clean, checked = check_docs("s.unity", docs.prolog, docs.in_order, docs.changed)
    assert clean == [] and checked is not None
    BREAKAGE[case](docs)
    again, kept = check_docs(
        "s.unity", docs.prolog, docs.in_order, docs.changed, checked, docs.take_recent()
    )
    assert again and kept is None
    assert again == validate_docs("s.unity", docs.prolog, docs.in_order, docs.changed)


def test_a_validation_after_a_clean_one_rereads_only_the_edited_documents(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    reads: list[int] = []
    full_read = Links.read.__func__  # type: ignore[attr-defined]
    monkeypatch.setattr(
        Links,
        "read",
        classmethod(lambda cls, docs: reads.append(len(docs)) or full_read(cls, docs)),
    )
    scene = SceneDocument.load(SOURCE)
    assert scene.validate() == [] and reads == [16]
    scene.ensure_component("Main Camera", SCRIPT, {"SecondsTimeout": 3})
    scene.ensure_gameobject("Robot/base_link/camera")
    assert scene.validate() == [] and reads == [16]
    # a removal is checked in full: something unchanged may still refer to what went
    scene.remove_component(scene.find_component("Main Camera", SCRIPT.guid))  # type: ignore[arg-type]
    assert scene.validate() == [] and reads == [16, 22]
    assert SceneDocument.parse(scene.text(), "s.unity").validate() == []
