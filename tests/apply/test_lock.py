"""The lock file: deterministic JSON, read back unchanged, refusing what it cannot read."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from helpers import run_cli, snapshot

from unityscaffold.apply._lock import LockComponent, LockFile, LockPrimitive, LockRobot, lock_path
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


def test_kept_files_are_listed_only_when_there_are_some_and_read_back(tmp_path):
    """A lock from before kept files were recorded has no ``kept`` key, and reads as none."""
    path = tmp_path / "robot.lock.json"
    plain = LockFile(files={"Assets/a.cs": "1"})
    assert '"kept"' not in plain.render()
    path.write_text(plain.render())
    assert LockFile.read(path) == plain
    kept = LockFile(files={"Assets/a.cs": "1"}, kept=frozenset({"Assets/b.cs", "Assets/a.cs"}))
    assert '"kept": [\n    "Assets/a.cs",\n    "Assets/b.cs"\n  ]' in kept.render()
    path.write_text(kept.render())
    assert LockFile.read(path) == kept


def test_robot_folders_are_listed_only_when_there_are_some_and_read_back(tmp_path):
    path = tmp_path / "robot.lock.json"
    assert '"folders"' not in LockFile().render()
    lock = LockFile(folders=frozenset({"Assets/Urdf/bot", "Assets/Urdf"}))
    assert '"folders": [\n    "Assets/Urdf",\n    "Assets/Urdf/bot"\n  ]' in lock.render()
    path.write_text(lock.render())
    assert LockFile.read(path) == lock


def test_robots_are_listed_only_when_there_are_some_merged_and_read_back(tmp_path):
    path = tmp_path / "robot.lock.json"
    assert '"robots"' not in LockFile().render()
    made = LockRobot("Assets/S.unity", "r2d2", (9, 3))
    kept = LockRobot("Assets/S.unity", "r2d2", (4,))
    lock = LockFile(robots=(made, kept, LockRobot("Assets/S.unity", "gone", ())))
    assert '"robots": {\n    "Assets/S.unity": {\n      "r2d2": [\n        3,' in lock.render()
    path.write_text(lock.render())
    assert LockFile.read(path).robot_ids("Assets/S.unity", "r2d2") == {3, 4, 9}
    assert LockFile.read(path).robots == (LockRobot("Assets/S.unity", "r2d2", (3, 4, 9)),)


def test_adopted_robot_slots_are_listed_only_when_there_are_some_and_read_back(tmp_path):
    path = tmp_path / "robot.lock.json"
    made = LockRobot("Assets/S.unity", "r2d2", (3, 9))
    assert '"adopted"' not in LockFile(robots=(made,)).render()
    slots = (("link[0] GameObject", 9), ("robot GameObject", 3))
    adopted = LockRobot("Assets/S.unity", "r2d2", (3, 9), slots)
    path.write_text(LockFile(robots=(adopted,)).render())
    assert '"adopted": {\n    "Assets/S.unity": {\n      "r2d2": {\n' in path.read_text()
    read = LockFile.read(path)
    assert read.robots == (adopted,)
    assert read.robot_adopted("Assets/S.unity", "r2d2") == dict(slots)
    # an interrupted apply's journal adds to them
    journal = LockFile(robots=(LockRobot("Assets/S.unity", "r2d2", (4,), (("x Mesh", 4),)),))
    recovered = read.recovered(journal, tmp_path)
    assert recovered.robot_adopted("Assets/S.unity", "r2d2") == {**dict(slots), "x Mesh": 4}


def test_primitives_are_listed_only_when_there_are_some_and_a_journal_merges_over(tmp_path):
    path = tmp_path / "robot.lock.json"
    assert '"primitives"' not in LockFile().render()
    cube = LockPrimitive("Assets/S.unity", "Ball", "cube", (9, 3, 5))
    lock = LockFile(primitives=(cube,))
    assert '"primitives": {\n    "Assets/S.unity": {\n      "Ball": {\n        "shape": "cube"' in (
        lock.render()
    )
    path.write_text(lock.render())
    assert LockFile.read(path).primitives == (
        LockPrimitive("Assets/S.unity", "Ball", "cube", (3, 5, 9)),
    )
    # An interrupted run that made Ball a sphere: its shape, and what either run made.
    sphere = LockFile(primitives=(LockPrimitive("Assets/S.unity", "Ball", "sphere", (3, 5, 7)),))
    merged = LockFile.read(path).recovered(sphere, tmp_path)
    assert merged.primitives_in("Assets/S.unity") == {
        "Ball": LockPrimitive("Assets/S.unity", "Ball", "sphere", (3, 5, 7, 9))
    }


def test_a_missing_lock_is_empty(tmp_path):
    assert LockFile.read(tmp_path / "none.lock.json") == LockFile()


_EMPTY = '"files": {}, "user_files": {}, "components": []'
_SCENE = '"scene": "Assets/S.unity", "gameobject": "A", "script": "g"'
_INSIDE = "a path inside the project's Assets/ folder"


def _lock(*entries: str) -> str:
    return "{" + ", ".join(['"version": 1', *entries]) + "}"


def _components(*items: str) -> str:
    return '"files": {}, "user_files": {}, "components": [' + ", ".join(items) + "]"


@pytest.mark.parametrize(
    ("text", "detail"),
    [
        (
            "{",
            "invalid JSON at line 1, column 2 (expecting property name enclosed in double quotes)",
        ),
        (
            '{"version": 1,\n  "files": {} "x"}',
            "invalid JSON at line 2, column 15 (expecting ',' delimiter)",
        ),
        ("[]", "the whole file should be an object, found a list"),
        ("7", "the whole file should be an object, found the number 7"),
        ("{" + _EMPTY + "}", "version should be 1, found nothing"),
        ('{"version": 2, ' + _EMPTY + "}", "version should be 1, found the number 2"),
        ('{"version": "1", ' + _EMPTY + "}", 'version should be 1, found the string "1"'),
        ('{"version": true, ' + _EMPTY + "}", "version should be 1, found true"),
        (_lock('"files": {}'), "user_files should be an object, found nothing"),
        (_lock('"files": 1', '"user_files": {}'), "files should be an object, found the number 1"),
        (_lock('"files": []', '"user_files": {}'), "files should be an object, found a list"),
        (_lock('"files": {}', '"user_files": null'), "user_files should be an object, found null"),
        (
            _lock('"files": {"Assets/a.cs": 1}', '"user_files": {}'),
            'files["Assets/a.cs"] should be a sha256 string, found the number 1',
        ),
        (
            _lock('"files": {}', '"user_files": {"Assets/ü.cs": {}}'),
            'user_files["Assets/ü.cs"] should be a sha256 string, found an object',
        ),
        (_lock('"files": {}', '"user_files": {}'), "components should be a list, found nothing"),
        (
            _lock('"files": {}', '"user_files": {}', '"components": {}'),
            "components should be a list, found an object",
        ),
        (_lock(_components("1")), "components[0] should be an object, found the number 1"),
        (
            _lock(_components("{" + _SCENE + "}", '"Assets/S.unity"')),
            'components[1] should be an object, found the string "Assets/S.unity"',
        ),
        (
            _lock(_components('{"scene": "Assets/S.unity", "gameobject": 1, "script": "g"}')),
            "components[0].gameobject should be a string, found the number 1",
        ),
        (
            _lock(_components('{"scene": "Assets/S.unity", "gameobject": "A"}')),
            "components[0].script should be a string, found nothing",
        ),
        (
            _lock(_components("{" + _SCENE + ', "entry": null}')),
            "components[0].entry should be a string, found null",
        ),
        (
            _lock(_components("{" + _SCENE + ', "file_id": "12"}')),
            "components[0].file_id should be a fileID (a positive 64-bit integer), found the "
            'string "12"',
        ),
        (
            _lock(_components("{" + _SCENE + ', "file_id": 0}')),
            "components[0].file_id should be a fileID (a positive 64-bit integer), found the "
            "number 0",
        ),
        (
            _lock(_components(), '"gameobjects": []'),
            "gameobjects should be an object, found a list",
        ),
        (
            _lock(_components(), '"gameobjects": {"Assets/S.unity": {"Robot": -1}}'),
            'gameobjects["Assets/S.unity"]["Robot"] should be a fileID (a positive 64-bit '
            "integer), found the number -1",
        ),
        (
            _lock(_components(), '"gameobjects": {"../S.unity": {}}'),
            f'gameobjects has the key "../S.unity", which is not {_INSIDE}',
        ),
        (
            _lock(_components(), '"robots": {"Assets/S.unity": {"r2d2": 5}}'),
            'robots["Assets/S.unity"]["r2d2"] should be a list of fileIDs, found the number 5',
        ),
        (
            _lock(_components(), '"robots": {"Assets/S.unity": {"r2d2": [1, 0]}}'),
            'robots["Assets/S.unity"]["r2d2"][1] should be a fileID (a positive 64-bit '
            "integer), found the number 0",
        ),
        (
            _lock(_components(), '"robots": {"S.unity": {}}'),
            f'robots has the key "S.unity", which is not {_INSIDE}',
        ),
        (
            _lock(_components(), '"adopted": {"Assets/S.unity": {"r2d2": {"robot Transform": 0}}}'),
            'adopted["Assets/S.unity"]["r2d2"]["robot Transform"] should be a fileID (a positive '
            "64-bit integer), found the number 0",
        ),
        (
            _lock(_components(), '"adopted": {"Assets/S.unity": {"r2d2": [1]}}'),
            'adopted["Assets/S.unity"]["r2d2"] should be an object, found a list',
        ),
        (
            _lock(_components(), '"primitives": {"Assets/S.unity": {"Ball": {"shape": "cube"}}}'),
            'primitives["Assets/S.unity"]["Ball"].file_ids should be a list of fileIDs, found '
            "nothing",
        ),
        (
            _lock(_components(), '"primitives": {"Assets/S.unity": {"Ball": {"file_ids": []}}}'),
            'primitives["Assets/S.unity"]["Ball"].shape should be a string, found nothing',
        ),
        (_lock(_components(), '"kept": {}'), "kept should be a list, found an object"),
        (_lock(_components(), '"kept": [3]'), "kept[0] should be a string, found the number 3"),
        (
            _lock(_components(), '"kept": ["Assets/a.cs", "../a.cs"]'),
            f'kept[1] should be {_INSIDE}, found the string "../a.cs"',
        ),
        (_lock(_components(), '"folders": 1'), "folders should be a list, found the number 1"),
        (
            _lock(_components(), '"folders": ["/etc"]'),
            f'folders[0] should be {_INSIDE}, found the string "/etc"',
        ),
    ],
)
def test_a_malformed_lock_says_what_was_expected_where(tmp_path, text, detail):
    path = tmp_path / "robot.lock.json"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(UserError) as caught:
        LockFile.read(path)
    assert caught.value.message == f"{path} is not a valid unityscaffold lock file: {detail}"
    assert caught.value.hint == (
        "restore it from git, or delete it and run apply again to rebuild it "
        "(generated files that differ from the new output then count as hand edits)"
    )


def test_a_lock_that_is_not_utf8_is_refused(tmp_path):
    path = tmp_path / "robot.lock.json"
    path.write_bytes(b'{"version": 1, "files": {"Assets/\xff.cs": "x"}}')
    with pytest.raises(UserError) as caught:
        LockFile.read(path)
    assert (
        caught.value.message
        == f"{path} is not a valid unityscaffold lock file: it is not UTF-8 text"
    )


@pytest.mark.parametrize(
    ("entry", "detail"),
    [
        (
            '"files": {"../../victim.txt": "x"}, "user_files": {}, "components": []',
            f'files has the key "../../victim.txt", which is not {_INSIDE}',
        ),
        (
            '"files": {"/tmp/victim.txt": "x"}, "user_files": {}, "components": []',
            f'files has the key "/tmp/victim.txt", which is not {_INSIDE}',
        ),
        (
            '"files": {"Assets/../../victim.txt": "x"}, "user_files": {}, "components": []',
            f'files has the key "Assets/../../victim.txt", which is not {_INSIDE}',
        ),
        (
            '"files": {"ProjectSettings/ProjectSettings.asset": "x"}, "user_files": {}, '
            '"components": []',
            f'files has the key "ProjectSettings/ProjectSettings.asset", which is not {_INSIDE}',
        ),
        (
            '"files": {}, "user_files": {"Assets\\\\..\\\\..\\\\victim.txt": "x"}, '
            '"components": []',
            f'user_files has the key "Assets\\\\..\\\\..\\\\victim.txt", which is not {_INSIDE}',
        ),
        (
            _components('{"scene": "../evil.unity", "gameobject": "A", "script": "g"}'),
            f'components[0].scene should be {_INSIDE}, found the string "../evil.unity"',
        ),
    ],
)
def test_a_lock_pointing_outside_the_assets_folder_is_refused(tmp_path, entry, detail):
    """The lock decides what apply deletes and edits: a tampered one must not reach elsewhere."""
    path = tmp_path / "robot.lock.json"
    path.write_text('{"version": 1, ' + entry + "}")
    with pytest.raises(UserError) as caught:
        LockFile.read(path)
    assert caught.value.message == f"{path} is not a valid unityscaffold lock file: {detail}"


@pytest.mark.parametrize(
    ("text", "detail"),
    [
        ('{"version": 1, "files": 1}', "files should be an object, found the number 1"),
        (
            _lock(_components("[]")),
            "components[0] should be an object, found a list",
        ),
        (
            "{not json",
            "invalid JSON at line 1, column 2 (expecting property name enclosed in double quotes)",
        ),
    ],
)
def test_apply_with_a_malformed_lock_stops_with_its_message_and_writes_nothing(
    tmp_path, text, detail
):
    sample = tmp_path / "sample_project"
    shutil.copytree(Path(__file__).resolve().parents[2] / "sample_project", sample)
    lock = sample / "robot.lock.json"
    lock.write_text(text, encoding="utf-8")
    before = snapshot(sample)
    run = run_cli("apply", str(sample / "robot.yaml"))
    assert run.code == 2, run.out + run.err
    assert run.err == (
        f"error: {lock} is not a valid unityscaffold lock file: {detail}\n"
        "  hint: restore it from git, or delete it and run apply again to rebuild it "
        "(generated files that differ from the new output then count as hand edits)\n"
    )
    assert snapshot(sample) == before
