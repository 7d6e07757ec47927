"""The lock file: deterministic JSON, read back to the same content, refusing what it cannot read."""

from __future__ import annotations

import pytest

from unityscaffold.apply.lock import LockComponent, LockFile, lock_path
from unityscaffold.errors import UserError


def test_lock_path_sits_beside_the_manifest(tmp_path):
    assert lock_path(tmp_path / "robot.yaml") == tmp_path / "robot.lock.json"


def test_render_is_sorted_and_reads_back(tmp_path):
    lock = LockFile(files={"b.cs": "2", "a.cs": "1"}, user_files={"u.cs": "3"},
                    components=(LockComponent("S.unity", "Z", "g2", "topic /z"),
                                LockComponent("S.unity", "A", "g1", "topic /a")))
    text = lock.render()
    assert text.index('"a.cs"') < text.index('"b.cs"')
    assert text.index('"A"') < text.index('"Z"')
    assert text.endswith("}\n")
    path = tmp_path / "robot.lock.json"
    path.write_text(text)
    again = LockFile.read(path)
    assert again.render() == text
    assert again.files == {"a.cs": "1", "b.cs": "2"}


def test_a_missing_lock_is_empty(tmp_path):
    assert LockFile.read(tmp_path / "none.lock.json") == LockFile()


@pytest.mark.parametrize("text", ["{", "[]", '{"version": 2}', '{"version": 1, "files": {}}'])
def test_an_unreadable_lock_is_a_user_error(tmp_path, text):
    path = tmp_path / "robot.lock.json"
    path.write_text(text)
    with pytest.raises(UserError, match="not a valid unityscaffold lock file"):
        LockFile.read(path)
