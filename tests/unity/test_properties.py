"""Property tests: random sequences of edits keep scenes valid, readable and idempotent."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from unityscaffold.unity.scene import SceneDocument
from unityscaffold.unity.values import ObjectRef, ScriptRef

DATA = Path(__file__).resolve().parents[1] / "data" / "unity"
BASES = {
    "2022-scene": DATA / "ros-sharp" / "FibonacciActionScene.unity",
    "2020-scene": DATA / "unity-robotics-hub" / "EmptyScene.unity",
    "2020-prefab": DATA / "unity-robotics-hub" / "Table.prefab",
}
SCRIPTS = [ScriptRef(c * 32) for c in "abc"] + [
    ScriptRef.for_dll_class("f70555f144d8491a825f0804e09c671c", "UnityEngine.UI", "Text")
]
Check = Callable[[SceneDocument], None]

names = st.sampled_from(["Robot", "base_link", "camera", "Main Camera", "Ünïcode", "a b"])
paths = st.lists(names, min_size=1, max_size=3).map("/".join)
scalars = st.one_of(
    st.integers(-(2**31), 2**31 - 1),
    st.booleans(),
    st.floats(width=32, allow_nan=False),
    st.text(st.characters(codec="utf-8", exclude_categories=["Cs"]), max_size=30),
)
values = st.one_of(scalars, st.lists(scalars, max_size=3), st.tuples(st.just("ref"), paths))
fields = st.lists(
    st.tuples(st.sampled_from(["Topic", "Rate", "Enabled", "Target", "Items"]), values),
    max_size=4,
    unique_by=lambda f: f[0],
)
edits = st.lists(
    st.one_of(
        st.tuples(st.just("go"), paths),
        st.tuples(st.just("attach"), paths, st.integers(0, len(SCRIPTS) - 1), fields),
        st.tuples(st.just("remove"), paths, st.integers(0, len(SCRIPTS) - 1)),
    ),
    min_size=1,
    max_size=6,
)


def _root(scene: SceneDocument, path: str) -> str:
    # a prefab has one root: keep every generated path under it
    return path if scene.is_scene else f"{scene.roots()[0].name}/{path}"


def _value(scene: SceneDocument, value: object) -> object:
    if isinstance(value, tuple):
        return ObjectRef(scene.ensure_gameobject(_root(scene, value[1])).file_id)
    return value


def _apply(scene: SceneDocument, sequence: list[tuple]) -> None:  # type: ignore[type-arg]
    for edit in sequence:
        path = _root(scene, edit[1])
        if edit[0] == "go":
            scene.ensure_gameobject(path)
        elif edit[0] == "attach":
            resolved = [(name, _value(scene, v)) for name, v in edit[3]]
            scene.ensure_component(scene.ensure_gameobject(path), SCRIPTS[edit[2]], resolved)
        else:
            found = scene.find_component(
                scene.ensure_gameobject(path), SCRIPTS[edit[2]].guid, SCRIPTS[edit[2]].file_id
            )
            if found is not None:
                scene.remove_component(found)


def _reattaches(sequence: list[tuple]) -> bool:  # type: ignore[type-arg]
    """Whether a component is removed and then attached again: on a second pass it goes behind
    the components attached in between (as in Unity), so the text differs in order only."""
    removed = set()
    for edit in sequence:
        if edit[0] == "remove":
            removed.add((edit[1], edit[2]))
        elif edit[0] == "attach" and (edit[1], edit[2]) in removed:
            return True
    return False


@pytest.mark.parametrize("base", sorted(BASES))
@settings(
    max_examples=30, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(sequence=edits)
def test_random_edit_sequences_keep_scenes_valid_and_idempotent(
    base: str,
    sequence: list[tuple],
    assert_sound: Check,  # type: ignore[type-arg]
) -> None:
    assume(not _reattaches(sequence))
    scene = SceneDocument.load(BASES[base])
    _apply(scene, sequence)
    assert scene.validate() == []
    once = scene.text()
    again = SceneDocument.parse(once, scene.path)
    _apply(again, sequence)
    assert again.text() == once
    assert_sound(again)
