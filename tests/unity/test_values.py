"""Script references: MD4 per RFC 1320 and Unity's fileIDs for classes inside DLLs."""

from __future__ import annotations

import pytest

from unityscaffold.unity._md4 import md4
from unityscaffold.unity.values import AssetRef, ScriptRef, script_file_id_for_dll_class


@pytest.mark.parametrize(
    ("message", "digest"),
    [  # RFC 1320, appendix A.5
        (b"", "31d6cfe0d16ae931b73c59d7e0c089c0"),
        (b"a", "bde52cb31de33e46245e05fbdbd6fb24"),
        (b"abc", "a448017aaf21d8525fc10ae87aa6729d"),
        (b"message digest", "d9130a8164549fe818874806e1c7014b"),
        (b"abcdefghijklmnopqrstuvwxyz", "d79e1c308aa5bbcdeea8ed63df412da9"),
        (
            b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789",
            "043f8582f241db351ce627e153e7f0e4",
        ),
        (b"1234567890" * 8, "e33b4ddc9c38f2199c3e7b164fcc0536"),
    ],
)
def test_md4_matches_the_rfc_1320_test_suite(message: bytes, digest: str) -> None:
    assert md4(message).hex() == digest


@pytest.mark.parametrize(
    ("namespace", "name", "file_id"),
    [
        ("UnityEngine.UI", "Text", 708705254),
        ("UnityEngine.UI", "Image", -765806418),
        ("UnityEngine.EventSystems", "EventSystem", -619905303),
    ],
)
def test_dll_class_file_ids_match_those_unity_wrote(
    namespace: str, name: str, file_id: int
) -> None:
    assert script_file_id_for_dll_class(namespace, name) == file_id
    ref = ScriptRef.for_dll_class("f70555f144d8491a825f0804e09c671c", namespace, name)
    assert ref.file_id == file_id and ref.type == 3


@pytest.mark.parametrize("guid", ["", "ABCDEF0123456789abcdef0123456789", "xyz", "0" * 31])
def test_a_malformed_guid_is_refused(guid: str) -> None:
    with pytest.raises(ValueError, match="GUID"):
        ScriptRef(guid)
    with pytest.raises(ValueError, match="GUID"):
        AssetRef(0, guid)
