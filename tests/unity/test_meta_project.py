"""``.meta`` files and the project index: deterministic GUIDs, Unity layouts, script lookup."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from unityscaffold.errors import UserError
from unityscaffold.unity.meta import (
    folder_meta,
    guid_for,
    meta_guid,
    monoscript_meta,
    read_meta_guid,
)
from unityscaffold.unity.project import (
    FALLBACK_SALT,
    find_project_root,
    project_salt,
    script_index,
    script_ref_for_file,
)


def test_guids_are_md5_of_salt_and_posix_path() -> None:
    import hashlib

    expected = hashlib.md5(b"salt:Assets/Scripts/Foo.cs").hexdigest()
    assert guid_for("salt", "Assets/Scripts/Foo.cs") == expected
    assert guid_for("salt", "Assets\\Scripts\\Foo.cs") == expected


def test_guids_differ_by_salt_and_path() -> None:
    guids = {guid_for(s, p) for s in ("a", "b") for p in ("Assets/A.cs", "Assets/B.cs")}
    assert len(guids) == 4


@pytest.mark.parametrize("path", ["/abs/Assets/A.cs", "C:/proj/Assets/A.cs", ""])
def test_a_guid_needs_a_project_relative_path(path: str) -> None:
    with pytest.raises(ValueError, match="relative"):
        guid_for("s", path)


def test_an_existing_meta_guid_always_wins(tmp_path: Path) -> None:
    meta = tmp_path / "Foo.cs.meta"
    assert meta_guid(meta, "s", "Assets/Foo.cs") == guid_for("s", "Assets/Foo.cs")
    meta.write_text(monoscript_meta("0123456789abcdef0123456789abcdef"))
    assert meta_guid(meta, "s", "Assets/Foo.cs") == "0123456789abcdef0123456789abcdef"


@pytest.mark.parametrize("render", [monoscript_meta, folder_meta])
def test_metas_use_unitys_layout_and_read_back(tmp_path: Path, render) -> None:  # type: ignore[no-untyped-def]
    text = render("4f1c2a9e7b3d48e6a05c9d21e7f36b80")
    assert text.startswith("fileFormatVersion: 2\nguid: 4f1c2a9e7b3d48e6a05c9d21e7f36b80\n")
    assert "  userData: \n" in text and "\r" not in text
    assert yaml.safe_load(text)["guid"] == "4f1c2a9e7b3d48e6a05c9d21e7f36b80"
    (tmp_path / "x.meta").write_text(text)
    assert read_meta_guid(tmp_path / "x.meta") == "4f1c2a9e7b3d48e6a05c9d21e7f36b80"


def test_a_two_line_meta_is_read(tmp_path: Path) -> None:
    (tmp_path / "x.meta").write_text(
        "fileFormatVersion: 2\nguid: ff98778ae051cfd40a6e4effdf851ebd\n"
    )
    assert read_meta_guid(tmp_path / "x.meta") == "ff98778ae051cfd40a6e4effdf851ebd"
    assert read_meta_guid(tmp_path / "missing.meta") is None


def _project(tmp_path: Path, product_guid: str | None = None) -> Path:
    root = tmp_path / "Proj"
    (root / "Assets" / "Scripts").mkdir(parents=True)
    (root / "ProjectSettings").mkdir()
    if product_guid:
        (root / "ProjectSettings" / "ProjectSettings.asset").write_text(
            f"%YAML 1.1\n--- !u!129 &1\nPlayerSettings:\n  productGUID: {product_guid}\n"
        )
    pkg = root / "Packages" / "com.siemens.ros-sharp" / "Runtime"
    pkg.mkdir(parents=True)
    (pkg / "RosConnector.cs").write_text("class RosConnector {}")
    (pkg / "RosConnector.cs.meta").write_text(monoscript_meta("ff98778ae051cfd40a6e4effdf851ebd"))
    (root / "Assets" / "Scripts" / "Mine.cs").write_text("class Mine {}")
    (root / "Assets" / "Scripts" / "Mine.cs.meta").write_text(monoscript_meta("a" * 32))
    return root


def test_the_project_root_is_found_from_anywhere_inside(tmp_path: Path) -> None:
    root = _project(tmp_path)
    assert find_project_root(root / "Assets" / "Scripts" / "Mine.cs") == root.resolve()
    assert find_project_root(tmp_path) is None


def test_the_salt_is_the_product_guid_or_the_fallback(tmp_path: Path) -> None:
    assert project_salt(_project(tmp_path / "a", "b" * 32)) == "b" * 32
    assert project_salt(_project(tmp_path / "b")) == FALLBACK_SALT


def test_scripts_are_indexed_in_assets_and_packages(tmp_path: Path) -> None:
    root = _project(tmp_path)
    index = script_index(root)
    assert sorted((s.class_name, s.guid) for s in index.values()) == [
        ("Mine", "a" * 32),
        ("RosConnector", "ff98778ae051cfd40a6e4effdf851ebd"),
    ]


def test_unitys_cache_is_not_indexed(tmp_path: Path) -> None:
    root = _project(tmp_path)
    cached = root / "Library" / "PackageCache" / "com.unity.ugui@1" / "Runtime" / "Image.cs"
    cached.parent.mkdir(parents=True)
    cached.write_text("class Image {}")
    (cached.parent / "Image.cs.meta").write_text(monoscript_meta("d" * 32))
    assert sorted(s.class_name for s in script_index(root).values()) == ["Mine", "RosConnector"]


def test_a_script_file_reference_comes_from_its_meta(tmp_path: Path) -> None:
    root = _project(tmp_path)
    ref = script_ref_for_file(root / "Assets" / "Scripts" / "Mine.cs")
    assert (ref.guid, ref.file_id, ref.class_name) == ("a" * 32, 11500000, "Mine")
    (root / "Assets" / "NoMeta.cs").write_text("")
    with pytest.raises(UserError, match=r"no \.meta"):
        script_ref_for_file(root / "Assets" / "NoMeta.cs")
