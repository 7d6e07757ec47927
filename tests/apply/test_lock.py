"""The lock file: deterministic JSON, read back unchanged, refusing what it cannot read."""

from __future__ import annotations

import pytest

from unityscaffold.apply.lock import LockComponent, LockFile, lock_path
from unityscaffold.errors import UserError


def test_lock_path_sits_beside_the_manifest(tmp_path):
    assert lock_path(tmp_path / "robot.yaml") == tmp_path / "robot.lock.json"


def test_render_is_sorted_and_reads_back(tmp_path):
    lock = LockFile(
        files={"Assets/b.cs": "2", "Assets/a.cs": "1"},
        user_files={"Assets/u.cs": "3"},
        components=(
            LockComponent("Assets/S.unity", "Z", "g2", "topic /z"),
            LockComponent("Assets/S.unity", "A", "g1", "topic /a"),
        ),
    )
    text = lock.render()
    assert text.index('"Assets/a.cs"') < text.index('"Assets/b.cs"')
    assert text.index('"A"') < text.index('"Z"')
    assert text.endswith("}\n")
    path = tmp_path / "robot.lock.json"
    path.write_text(text)
    again = LockFile.read(path)
    assert again.render() == text
    assert again.files == {"Assets/a.cs": "1", "Assets/b.cs": "2"}


def test_a_missing_lock_is_empty(tmp_path):
    assert LockFile.read(tmp_path / "none.lock.json") == LockFile()


@pytest.mark.parametrize("text", ["{", "[]", '{"version": 2}', '{"version": 1, "files": {}}'])
def test_an_unreadable_lock_is_a_user_error(tmp_path, text):
    path = tmp_path / "robot.lock.json"
    path.write_text(text)
    with pytest.raises(UserError, match="not a valid unityscaffold lock file"):
        LockFile.read(path)


@pytest.mark.parametrize(
    "entry",
    [
        '"files": {"../../victim.txt": "x"}, "user_files": {}, "components": []',
        '"files": {"/tmp/victim.txt": "x"}, "user_files": {}, "components": []',
        '"files": {"Assets/../../victim.txt": "x"}, "user_files": {}, "components": []',
        '"files": {"ProjectSettings/ProjectSettings.asset": "x"}, "user_files": {}, '
        '"components": []',
        '"files": {"Assets/a.cs": 1}, "user_files": {}, "components": []',
        '"files": {}, "user_files": {}, '
        '"components": [{"scene": "../evil.unity", "gameobject": "A", "script": "g"}]',
        '"files": {}, "user_files": {}, '
        '"components": [{"scene": "Assets/S.unity", "gameobject": 1, "script": "g"}]',
    ],
)
def test_a_lock_pointing_outside_the_assets_folder_is_refused(tmp_path, entry):
    """The lock decides what apply deletes and edits: a tampered one must not reach elsewhere."""
    path = tmp_path / "robot.lock.json"
    path.write_text('{"version": 1, ' + entry + "}")
    with pytest.raises(UserError, match="not a valid unityscaffold lock file"):
        LockFile.read(path)
