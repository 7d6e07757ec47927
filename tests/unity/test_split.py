"""Loading: documents rejoin to the exact input; anything else is refused with a clear message."""

from __future__ import annotations

from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError, UserError
from unityscaffold.unity.scene import SceneDocument


def test_every_corpus_file_rejoins_byte_for_byte(corpus_file: Path) -> None:
    data = corpus_file.read_bytes()
    scene = SceneDocument.load(corpus_file)
    assert scene.text().encode("utf-8") == data
    assert len(scene.documents()) == data.count(b"\n--- !u!")


def test_a_crlf_file_keeps_its_line_endings(corpus_file: Path) -> None:
    text = corpus_file.read_text(encoding="utf-8").replace("\n", "\r\n")
    scene = SceneDocument.parse(text, "crlf.unity")
    assert scene.text() == text
    assert all("\r" not in doc.text for doc in scene.documents())


def test_a_crlf_file_stays_crlf_after_an_edit(scene_2022: SceneDocument) -> None:
    crlf = SceneDocument.parse(scene_2022.text().replace("\n", "\r\n"), "crlf.unity")
    crlf.ensure_gameobject("New")
    out = crlf.text()
    assert out.count("\n") == out.count("\r\n") > scene_2022.text().count("\n")


def test_each_document_starts_with_its_header(corpus_file: Path) -> None:
    for doc in SceneDocument.load(corpus_file).documents():
        assert doc.header.startswith(f"--- !u!{doc.class_id} &{doc.file_id}")
        assert doc.header.endswith(" stripped") == doc.stripped


def _truncations(text: str) -> list[str]:
    return [text[: len(text) // 2], text[:-1], text[: text.rindex("{")]]


@pytest.mark.parametrize("cut", [0, 1, 2], ids=["half", "no-final-newline", "mid-flow-mapping"])
def test_a_truncated_file_is_refused(corpus_file: Path, cut: int) -> None:
    text = corpus_file.read_text(encoding="utf-8")
    with pytest.raises(LocatedError) as info:
        SceneDocument.parse(_truncations(text)[cut], "cut.unity")
    assert "cut.unity" in info.value.render()


@pytest.mark.parametrize(
    ("content", "message"),
    [
        (b"\x00\x00\x00\x00\x00\x01\x02binary", "binary-serialized"),
        (b"just: some yaml\n", "not a Unity YAML file"),
        (b"", "not a Unity YAML file"),
        (b"%YAML 1.1\n--- !u!1 &1\nGameObject:\n  m_Name: \xff\n", "not UTF-8"),
    ],
    ids=["binary", "plain-yaml", "empty", "not-utf8"],
)
def test_a_file_that_is_not_unity_text_is_refused(
    tmp_path: Path, content: bytes, message: str
) -> None:
    path = tmp_path / "bad.unity"
    path.write_bytes(content)
    with pytest.raises(UserError, match=message):
        SceneDocument.load(path)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n", "no '--- !u!"),
        ("%YAML 1.1\n--- !u!1 &x\nGameObject:\n  m_Name: a\n", "malformed document header"),
        ("%YAML 1.1\nhello\n--- !u!1 &1\nGameObject:\n  m_Name: a\n", "before the first"),
        ("%YAML 1.1\n--- !u!1 &1\n  m_Name: a\n", "no 'TypeName:' line"),
    ],
    ids=["no-documents", "bad-header", "junk-prolog", "no-type-line"],
)
def test_malformed_structure_is_refused_with_its_line(text: str, message: str) -> None:
    with pytest.raises(LocatedError, match=message) as info:
        SceneDocument.parse(text, "bad.unity")
    assert info.value.location.line >= 1


def test_a_missing_file_is_a_user_error(tmp_path: Path) -> None:
    with pytest.raises(UserError, match="cannot read"):
        SceneDocument.load(tmp_path / "nope.unity")


def test_a_document_with_no_fields_splits_alike_last_and_before_another() -> None:
    # Found by the mutated-scene property test: accepted as the last document, refused once
    # attach had added one after it, so an accepted edit could not be read back.
    head = "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n--- !u!29 &1\nOcclusionCullingSettings:\n"
    more = "--- !u!1 &5\nGameObject:\n  m_Name: a\n"
    for text, ids in ((head, [1]), (head + more, [1, 5])):
        scene = SceneDocument.parse(text, "s.unity")
        assert [d.file_id for d in scene.documents()] == ids
        assert scene.text() == text
