"""``apply.files``: compare before writing, create-only metas, all-or-nothing writes.

(Kept here with the generator's tests, its first user.)
"""

from __future__ import annotations

from pathlib import Path

import pytest

from unityscaffold.apply import files
from unityscaffold.apply.files import Action, DesiredFile, plan_files, write_files
from unityscaffold.errors import UserError


def test_plan_says_create_update_unchanged_and_skip(tmp_path: Path) -> None:
    (tmp_path / "same.cs").write_bytes(b"same")
    (tmp_path / "old.cs").write_bytes(b"old")
    (tmp_path / "kept.meta").write_bytes(b"guid: mine")
    changes = plan_files(
        [
            DesiredFile(tmp_path / "new.cs", b"new"),
            DesiredFile(tmp_path / "same.cs", b"same"),
            DesiredFile(tmp_path / "old.cs", b"new"),
            DesiredFile(tmp_path / "kept.meta", b"guid: ours", create_only=True),
        ]
    )
    assert [(c.path.name, c.action) for c in changes] == [
        ("kept.meta", Action.SKIP),
        ("new.cs", Action.CREATE),
        ("old.cs", Action.UPDATE),
        ("same.cs", Action.UNCHANGED),
    ]


def test_writes_only_changed_files_and_keeps_existing_metas(tmp_path: Path) -> None:
    (tmp_path / "kept.meta").write_bytes(b"guid: mine")
    (tmp_path / "same.cs").write_bytes(b"same")
    before = (tmp_path / "same.cs").stat().st_mtime_ns
    written = write_files(
        plan_files(
            [
                DesiredFile(tmp_path / "a" / "b" / "new.cs", b"new"),
                DesiredFile(tmp_path / "same.cs", b"same"),
                DesiredFile(tmp_path / "kept.meta", b"guid: ours", create_only=True),
            ]
        )
    )
    assert written == [tmp_path / "a" / "b" / "new.cs"]
    assert (tmp_path / "a" / "b" / "new.cs").read_bytes() == b"new"
    assert (tmp_path / "kept.meta").read_bytes() == b"guid: mine"
    assert (tmp_path / "same.cs").stat().st_mtime_ns == before
    assert not list(tmp_path.rglob("*.tmp"))


def test_a_failure_while_writing_leaves_nothing_behind(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "old.cs").write_bytes(b"old")
    real = files._write_temp
    calls = []

    def flaky(change: files.FileChange, mode: int) -> Path:
        calls.append(change.path)
        if len(calls) == 3:
            raise OSError(28, "No space left on device", str(change.path))
        return real(change, mode)

    monkeypatch.setattr(files, "_write_temp", flaky)
    changes = plan_files(
        [
            DesiredFile(tmp_path / "old.cs", b"new"),
            DesiredFile(tmp_path / "pkg" / "a.cs", b"a"),
            DesiredFile(tmp_path / "pkg" / "sub" / "b.cs", b"b"),
        ]
    )
    with pytest.raises(UserError, match="No space left"):
        write_files(changes)
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["old.cs"]
    assert (tmp_path / "old.cs").read_bytes() == b"old"


def test_a_file_where_a_folder_must_go_is_reported_before_writing(tmp_path: Path) -> None:
    (tmp_path / "pkg").write_text("a file")
    with pytest.raises(UserError, match="is not a folder"):
        plan_files(
            [DesiredFile(tmp_path / "ok.cs", b"x"), DesiredFile(tmp_path / "pkg" / "a.cs", b"a")]
        )
    assert not (tmp_path / "ok.cs").exists()


def test_new_files_get_normal_permissions(tmp_path: Path) -> None:
    write_files(plan_files([DesiredFile(tmp_path / "a.cs", b"a")]))
    assert (tmp_path / "a.cs").stat().st_mode & 0o644 == 0o644
