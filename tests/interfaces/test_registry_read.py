"""The registry reads an interface file exactly as text mode with UTF-8 does."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from unityscaffold.errors import LocatedError
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry, _read_text
from unityscaffold.interfaces.sources import SearchRoot


def _same_as_text_mode(path: Path) -> None:
    """The same text, or for text that is not UTF-8 an error that names its first bad byte in
    the whole file (text mode counts from the chunk it was decoding)."""
    data = path.read_bytes()
    try:
        expected = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        with pytest.raises(UnicodeDecodeError) as raised:
            _read_text(path)
        assert raised.value.object == data
        start = raised.value.start
        data[:start].decode("utf-8")  # all before it decodes (this raises otherwise)
        with pytest.raises(UnicodeDecodeError):
            data[start : start + 4].decode("utf-8")
    else:
        assert _read_text(path) == expected


@settings(max_examples=300, deadline=None)
@given(
    st.lists(st.sampled_from([b"a", b"\r", b"\n", b"\r\n", b"\xef\xbb\xbf", b"\xc3\xa9", b"\xff"]))
)
def test_any_bytes_read_as_text_mode_reads_them(tmp_path_factory, parts):
    path = tmp_path_factory.mktemp("read") / "T.msg"
    path.write_bytes(b"".join(parts))
    _same_as_text_mode(path)


def test_a_bad_byte_past_the_first_chunk_is_found_where_it_is(tmp_path):
    path = tmp_path / "T.msg"
    path.write_bytes(b"int32 a\r\n" * 2000 + b"\xff")
    _same_as_text_mode(path)


def test_crlf_and_lone_cr_files_parse_like_lf(tmp_path):
    texts = {"lf": b"# doc\nint32 a # x\nstring B=hi\n", "crlf": b"", "cr": b""}
    texts["crlf"] = texts["lf"].replace(b"\n", b"\r\n")
    texts["cr"] = texts["lf"].replace(b"\n", b"\r")
    parsed = {}
    for kind, data in texts.items():
        folder = tmp_path / kind / "pkg" / "msg"
        folder.mkdir(parents=True)
        (folder.parent / "package.xml").write_text("<package><name>pkg</name></package>")
        (folder / "T.msg").write_bytes(data)
        registry = Registry(Dialect.ROS1, [SearchRoot(tmp_path / kind, kind, recursive=False)])
        parsed[kind] = replace(registry.parse(registry.files()[0]), source="")
    assert parsed["crlf"] == parsed["lf"] == parsed["cr"]
    assert parsed["lf"].text == texts["lf"].decode()


def test_a_file_that_is_not_utf8_is_a_located_error(tmp_path):
    folder = tmp_path / "pkg" / "msg"
    folder.mkdir(parents=True)
    (folder.parent / "package.xml").write_text("<package><name>pkg</name></package>")
    (folder / "T.msg").write_bytes(b"int32 a\r\n# caf\xe9\r\n")
    registry = Registry(Dialect.ROS1, [SearchRoot(tmp_path, "t", recursive=False)])
    with pytest.raises(LocatedError) as caught:
        registry.parse(registry.files()[0])
    assert caught.value.render() == (
        f"{folder / 'T.msg'}:2:6: error: the file is not UTF-8 text (byte 0xe9)\n"
        "    # caf\ufffd\n"
        "         ^\n"
        "  hint: save it as UTF-8"
    )
