"""Attacks on the no-op record: every way a record could be replayed for a project that differs
from the one it was made for. ``--check`` is what CI trusts, so each case asks that a recorded
project, changed, gets the answer it gets without the record (and that it is not "matches")."""

from __future__ import annotations

import mmap
import os
import random
import shutil
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from tests.cli.noop_support import (
    GENERATED,
    SCRIPT,
    copy_sample,
    records,
    scaffold,
    settle,
    unrecorded,
)
from unityscaffold.cli import _noop, _recorder

CHECK = ("apply", "--check")


def _flip_a_byte(root: Path) -> None:
    """The same size, one letter other (what a hand edit of one character looks like)."""
    path = root / SCRIPT
    data = path.read_bytes()
    path.write_bytes(data.replace(b"Scan", b"Scam", 1))


def _leftover_temporary_file(root: Path) -> None:
    # what a killed apply leaves: --check reports it until an apply removes it
    (root / GENERATED / "Scripts" / ".ScanSubscriber.cs.999-0.tmp").write_text(
        "x\n", encoding="utf-8"
    )


def _field_added(root: Path) -> None:
    with open(root / "ros_ws/src/diffbot_msgs/msg/WheelState.msg", "a", encoding="utf-8") as msg:
        msg.write("float64 extra\n")


def _topic_renamed(root: Path) -> None:
    manifest = root / "robot.yaml"
    manifest.write_text(
        manifest.read_text(encoding="utf-8").replace("/scan", "/scan2", 1), encoding="utf-8"
    )


DRIFT: dict[str, Callable[[Path], None]] = {
    "a script edited, same size": _flip_a_byte,
    "a leftover temporary file": _leftover_temporary_file,
    "a field added to a message": _field_added,
    "the manifest's topic renamed": _topic_renamed,
}


class AttributeCache:
    """A FUSE mount's kernel attribute cache (bindfs, sshfs, network file systems): the ``stat``
    of a path under ``root`` as first asked is served again, whatever happened to the file
    since. Reads and folder listings go to the file system as usual."""

    def __init__(self, root: Path) -> None:
        self.root = str(root) + os.sep
        self.kept: dict[tuple[str, bool], os.stat_result] = {}

    def _cached(self, real: Callable[..., os.stat_result], path: Any, follow: bool) -> Any:
        if isinstance(path, int):
            return real(path)
        name = os.path.abspath(os.fsdecode(os.fspath(path)))
        if not name.startswith(self.root):
            return real(path, follow_symlinks=follow)
        if (name, follow) not in self.kept:
            self.kept[(name, follow)] = real(path, follow_symlinks=follow)
        return self.kept[(name, follow)]

    def install(self, monkeypatch: pytest.MonkeyPatch) -> None:
        real = os.stat

        def stat(path: Any, *, dir_fd: Any = None, follow_symlinks: bool = True) -> Any:
            if dir_fd is not None:
                return real(path, dir_fd=dir_fd, follow_symlinks=follow_symlinks)
            return self._cached(real, path, follow_symlinks)

        def lstat(path: Any, *, dir_fd: Any = None) -> Any:
            return stat(path, dir_fd=dir_fd, follow_symlinks=False)

        # the program's os.stat, and the one the record compares with (taken at import)
        for module in (os, _noop, _recorder):
            prefix = "" if module is os else "_real_"
            monkeypatch.setattr(module, f"{prefix}stat", stat)
            monkeypatch.setattr(module, f"{prefix}lstat", lstat)


@pytest.mark.parametrize("what", sorted(DRIFT))
def test_drift_behind_a_stale_attribute_cache_is_not_replayed_as_matching(
    sample: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    monkeypatch: pytest.MonkeyPatch,
    what: str,
) -> None:
    AttributeCache(sample).install(monkeypatch)
    settle()
    assert scaffold(capsysbinary, *CHECK)[0] == 0
    assert len(records(sample.parent / "cache")) == 1
    DRIFT[what](sample)
    after = scaffold(capsysbinary, *CHECK)
    assert after[0] == 1 and b"matches the manifest" not in after[1]
    assert after == unrecorded(capsysbinary, monkeypatch, *CHECK)


def test_an_edit_through_a_shared_mapping_is_seen_though_the_stat_is_unchanged(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes]
) -> None:
    script = sample / SCRIPT
    data = script.read_bytes()
    at = data.index(b"Scan") + 3
    with open(script, "r+b") as handle, mmap.mmap(handle.fileno(), 0) as mapping:
        # The first write to a page makes the kernel stamp the file's times; later writes to
        # the page, already dirty, are not stamped until it is written back (seconds later).
        mapping[at] = data[at]
        settle()
        assert scaffold(capsysbinary, *CHECK)[0] == 0
        assert len(records(sample.parent / "cache")) == 1
        before = script.stat()
        mapping[at] = ord("m")
        after = script.stat()
        assert (after.st_size, after.st_mtime_ns, after.st_ctime_ns) == (
            before.st_size,
            before.st_mtime_ns,
            before.st_ctime_ns,
        ), "the premise: a write through a dirty mapped page leaves the stat as it was"
        assert script.read_bytes() != data
        code, out, _ = scaffold(capsysbinary, *CHECK)
    assert code == 1 and b"edited by hand" in out


def _pycache_prefix_above(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    # PYTHONPYCACHEPREFIX=<a folder above the project>: bytecode is written there, mirroring
    # the source folders; the project's own files are inputs all the same
    monkeypatch.setattr(sys, "pycache_prefix", str(tmp_path))
    return copy_sample(tmp_path / "work" / "sample_project", tmp_path / "cache", monkeypatch)


def _cache_folder_above(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    # a project kept inside the cache folder (XDG_CACHE_HOME=~ and a project in ~/unityscaffold)
    cache = tmp_path / "cache"
    return copy_sample(cache / "unityscaffold" / "sample_project", cache, monkeypatch)


@pytest.mark.parametrize("what", sorted(DRIFT))
@pytest.mark.parametrize("enclosed", [_pycache_prefix_above, _cache_folder_above])
def test_drift_in_a_project_inside_a_cache_folder_is_not_replayed_as_matching(
    tmp_path: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    monkeypatch: pytest.MonkeyPatch,
    enclosed: Callable[[Path, pytest.MonkeyPatch], Path],
    what: str,
) -> None:
    project = enclosed(tmp_path, monkeypatch)
    settle()
    assert scaffold(capsysbinary, *CHECK)[0] == 0
    assert len(records(tmp_path / "cache")) == 1
    DRIFT[what](project)
    after = scaffold(capsysbinary, *CHECK)
    assert after[0] == 1 and b"matches the manifest" not in after[1]
    assert after == unrecorded(capsysbinary, monkeypatch, *CHECK)


def _damaged_positions(data: bytes, *landmarks: bytes) -> list[int]:
    """Where to damage a record: its head and tail, around each landmark, and anywhere."""
    positions = {*range(48), *range(len(data) - 32, len(data))}
    for landmark in landmarks:
        start = data.index(landmark)
        positions.update(range(start, start + len(landmark) + 24))
    positions.update(random.Random(19).sample(range(len(data)), 150))
    return sorted(p for p in positions if 0 <= p < len(data))


def test_a_damaged_record_is_no_record(
    sample: Path, capsysbinary: pytest.CaptureFixture[bytes], planned: list[list[str]]
) -> None:
    settle()
    first = scaffold(capsysbinary, *CHECK)
    [record] = records(sample.parent / "cache")
    data = record.read_bytes()
    # the key (whatever follows it: the status, the output's length) and the printed text
    landmarks = (_noop._key(list(CHECK)).encode("ascii"), b"the project matches the manifest")
    damaged = [
        data[:position] + bytes([data[position] ^ mask]) + data[position + 1 :]
        for position in _damaged_positions(data, *landmarks)
        for mask in (0x01, 0x7F)
    ]
    damaged += [data[:cut] for cut in (0, 1, 8, 40, len(data) // 2, len(data) - 1)]
    damaged.append(data + b"\0")
    for bad in damaged:
        record.write_bytes(bad)
        assert _noop.replay(list(CHECK)) is None
        assert capsysbinary.readouterr() == (b"", b""), "a damaged record printed"
    record.write_bytes(data)
    assert scaffold(capsysbinary, *CHECK) == first
    assert planned == [list(CHECK)]  # the record as written is replayed


def test_a_symlink_pointed_at_an_identical_copy_is_seen(
    tmp_path: Path,
    capsysbinary: pytest.CaptureFixture[bytes],
    planned: list[list[str]],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # every byte read is the same, but the project is another one (its real path is shown):
    # what a symlink points at is compared, not only what is read through it
    first = copy_sample(tmp_path / "robot-a", tmp_path / "cache", monkeypatch)
    shutil.copytree(first, tmp_path / "robot-b", symlinks=True)
    monkeypatch.chdir(tmp_path)
    (tmp_path / "robot").symlink_to("robot-a")
    args = (*CHECK, "robot/robot.yaml")
    before = scaffold(capsysbinary, *args)
    assert before[0] == 0 and b"robot-a" in before[1]
    assert len(records(tmp_path / "cache")) == 1
    (tmp_path / "robot").unlink()
    (tmp_path / "robot").symlink_to("robot-b")
    after = scaffold(capsysbinary, *args)
    assert b"robot-b" in after[1] and b"robot-a" not in after[1]
    assert after == unrecorded(capsysbinary, monkeypatch, *args)
    assert len(planned) == 3
