"""``unityscaffold.fileout``: compare before writing, create-only metas, all-or-nothing writes,
and the single-file ``write_if_changed`` on the same path."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from unityscaffold import fileout
from unityscaffold.errors import UserError
from unityscaffold.fileout import (
    ChangeKind,
    DesiredFile,
    FileChange,
    plan_files,
    write_chunks_if_changed,
    write_files,
    write_if_changed,
)


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
    assert [(c.path.name, c.kind) for c in changes] == [
        ("kept.meta", ChangeKind.SKIP),
        ("new.cs", ChangeKind.CREATE),
        ("old.cs", ChangeKind.UPDATE),
        ("same.cs", ChangeKind.UNCHANGED),
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
    real = fileout._write_temp
    calls = []

    def flaky(change: FileChange, durable: bool, chunks: fileout.Chunks | None = None) -> str:
        calls.append(change.path)
        if len(calls) == 3:
            raise OSError(28, "No space left on device", str(change.path))
        return real(change, durable, chunks)

    monkeypatch.setattr(fileout, "_write_temp", flaky)
    changes = plan_files(
        [
            DesiredFile(tmp_path / "old.cs", b"new"),
            DesiredFile(tmp_path / "pkg" / "a.cs", b"a"),
            DesiredFile(tmp_path / "pkg" / "sub" / "b.cs", b"b"),
        ]
    )
    with pytest.raises(UserError, match=r"cannot write .*b\.cs: No space left"):
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


def test_a_failed_rename_removes_the_temporary_files_and_says_how_far_it_got(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    real = os.replace

    def refuse_b(source: str | Path, target: str | Path) -> None:
        if Path(target).name == "b.cs":
            raise OSError(13, "Permission denied", str(target))
        real(source, target)

    monkeypatch.setattr(os, "replace", refuse_b)
    changes = plan_files([DesiredFile(tmp_path / n, n.encode()) for n in ("a.cs", "b.cs", "c.cs")])
    with pytest.raises(UserError, match=r"cannot replace .*b\.cs: Permission denied; 1 of 3"):
        write_files(changes)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.cs"]


def test_an_updated_file_keeps_its_permission_bits(tmp_path: Path) -> None:
    path = tmp_path / "run.sh"
    path.write_bytes(b"old")
    path.chmod(0o751)
    write_files(plan_files([DesiredFile(path, b"new")]))
    assert path.read_bytes() == b"new" and path.stat().st_mode & 0o7777 == 0o751


def test_write_if_changed_creates_replaces_and_skips(tmp_path: Path) -> None:
    target = tmp_path / "f.txt"
    assert write_if_changed(target, "a\n") is True
    before = target.stat().st_mtime_ns
    assert write_if_changed(str(target), b"a\n") is False
    assert target.stat().st_mtime_ns == before
    assert write_if_changed(target, "b\r\n") is True
    assert target.read_bytes() == b"b\r\n"
    assert target.stat().st_mode & 0o644 == 0o644
    assert [p.name for p in tmp_path.iterdir()] == ["f.txt"]


def test_write_if_changed_keeps_permissions_and_reports_failures_as_user_errors(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    target = tmp_path / "robot.yaml"
    target.write_text("old")
    target.chmod(0o640)
    assert write_if_changed(target, "new")
    assert target.stat().st_mode & 0o7777 == 0o640

    def refuse(source: str | Path, target: str | Path) -> None:
        raise OSError(16, "Device or resource busy", str(target))

    monkeypatch.setattr(os, "replace", refuse)
    with pytest.raises(
        UserError, match=r"robot\.yaml: Device or resource busy; it was left as it was"
    ):
        write_if_changed(target, "newer")
    assert target.read_text() == "new"
    assert [p.name for p in tmp_path.iterdir()] == ["robot.yaml"]


def test_write_if_changed_refuses_a_folder_in_the_way(tmp_path: Path) -> None:
    (tmp_path / "Scene.unity").mkdir()
    with pytest.raises(UserError, match="a folder of that name exists"):
        write_if_changed(tmp_path / "Scene.unity", "x")


def test_write_chunks_if_changed_compares_piece_by_piece_and_writes_only_a_difference(
    tmp_path: Path,
) -> None:
    target = tmp_path / "Big.unity"
    pieces = [b"%YAML 1.1\n", b"--- !u!1 &1\n" * 3, b"GameObject:\n"]
    assert write_chunks_if_changed(target, lambda: iter(pieces)) is True
    assert target.read_bytes() == b"".join(pieces)
    target.chmod(0o640)
    before = target.stat().st_mtime_ns
    assert write_chunks_if_changed(target, lambda: iter(pieces)) is False
    assert target.stat().st_mtime_ns == before
    for changed in ([*pieces, b"x"], pieces[:-1], [pieces[0], b"-" * len(pieces[1]), pieces[2]]):
        assert write_chunks_if_changed(target, lambda c=changed: iter(c)) is True
        assert target.read_bytes() == b"".join(changed)
    assert target.stat().st_mode & 0o7777 == 0o640
    assert [p.name for p in tmp_path.iterdir()] == ["Big.unity"]


def test_write_chunks_if_changed_refuses_a_folder_in_the_way(tmp_path: Path) -> None:
    (tmp_path / "Scene.unity").mkdir()
    with pytest.raises(UserError, match="a folder of that name exists"):
        write_chunks_if_changed(tmp_path / "Scene.unity", lambda: iter([b"x"]))


def test_a_file_differing_only_in_crlf_line_endings_is_unchanged_and_kept(tmp_path: Path) -> None:
    path = tmp_path / "A.cs"
    path.write_bytes(b"class A\r\n{\r\n}\r\n")
    [same] = plan_files([DesiredFile(path, b"class A\n{\n}\n")])
    assert same.kind is ChangeKind.UNCHANGED
    [changed] = plan_files([DesiredFile(path, b"class B\n{\n}\n")])
    assert changed.kind is ChangeKind.UPDATE
    write_files([changed])
    assert path.read_bytes() == b"class B\n{\n}\n"  # written with LF
    assert fileout.same_text(b"a\r\nb", b"a\nb")
    assert not fileout.same_text(b"a\rb", b"a\nb")


def test_a_name_longer_than_file_systems_take_is_refused_before_anything_is_touched(
    tmp_path: Path,
) -> None:
    fits = tmp_path / ("é" * 127 + "a")  # 255 bytes of UTF-8
    too_long = tmp_path / "Messages" / ("é" * 128)  # 256 bytes
    fileout.check_name_lengths([fits])
    with pytest.raises(UserError, match="the name 'éééééééééééééééééééééééé…' is 256 bytes long"):
        fileout.check_name_lengths([fits, too_long])
    assert fileout.name_too_long("Assets/" + "a" * 250, len(".meta")) is None
    assert fileout.name_too_long("Assets/" + "a" * 251, len(".meta")) == "a" * 251
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name", ["a" * 255, "é" * 127 + "a", "a" * 240 + ".meta"])
def test_a_name_as_long_as_file_systems_take_is_written_through_a_shorter_temporary_name(
    tmp_path: Path, name: str
) -> None:
    """Its temporary file (``.<name>.<pid>-<n>.tmp``) would be too long to create."""
    target = tmp_path / "Assets" / name
    write_files(plan_files([DesiredFile(target, b"x")]))
    assert target.read_bytes() == b"x"
    assert [p.name for p in target.parent.iterdir()] == [name]


def test_relative_paths_are_planned_and_written_from_the_working_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    Path("kept.cs").write_bytes(b"same")
    desired = [
        DesiredFile(Path("kept.cs"), b"same"),
        DesiredFile(Path("top.cs"), b"top"),
        DesiredFile(Path("new") / "deeper" / "a.cs", b"a"),
    ]
    changes = plan_files(desired)
    assert [(c.path.as_posix(), c.kind) for c in changes] == [
        ("kept.cs", ChangeKind.UNCHANGED),
        ("new/deeper/a.cs", ChangeKind.CREATE),
        ("top.cs", ChangeKind.CREATE),
    ]
    assert write_files(changes) == [Path("new/deeper/a.cs"), Path("top.cs")]
    assert (tmp_path / "new" / "deeper" / "a.cs").read_bytes() == b"a"
    assert (tmp_path / "top.cs").read_bytes() == b"top"


def test_every_file_in_a_missing_folder_is_a_create_and_a_file_in_the_way_is_still_reported(
    tmp_path: Path,
) -> None:
    (tmp_path / "blocker").write_text("a file")
    inside_missing = [DesiredFile(tmp_path / "gone" / n, b"x") for n in ("a.cs", "b.cs")]
    assert {c.kind for c in plan_files(inside_missing)} == {ChangeKind.CREATE}
    with pytest.raises(UserError, match="blocker exists and is not a folder"):
        plan_files([DesiredFile(tmp_path / "blocker" / "sub" / "a.cs", b"x")])
