"""Whatever the text, loading a manifest either succeeds or raises a ScaffoldError."""

from __future__ import annotations

import contextlib
import json
import re
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from unityscaffold.errors import LocatedError, ScaffoldError
from unityscaffold.manifest import parse_manifest, starter_manifest

PATH = Path("/fuzz/robot.yaml")
KEYS = [
    "version",
    "ros",
    "project",
    "output",
    "scene",
    "connector",
    "topics",
    "services",
    "components",
    "name",
    "type",
    "direction",
    "rate",
    "throttle",
    "queue",
    "role",
    "gameobject",
    "fields",
    "script",
    "class",
    "create",
    "url",
    "timeout",
    "<<",
]
SCALARS = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-5, 100),
    st.floats(allow_nan=True),
    st.sampled_from(
        [
            "publish",
            "subscribe",
            "client",
            "/cmd_vel",
            "p/A",
            "Assets/S.unity",
            "@A/B:C",
            "@",
            "..",
            "/abs",
            "ws://h:1",
            "Assets/Gen",
            "yes",
        ]
    ),
    st.text(max_size=8),
)
VALUES = st.recursive(
    SCALARS,
    lambda inner: st.one_of(
        st.lists(inner, max_size=4),
        st.dictionaries(st.one_of(st.sampled_from(KEYS), st.text(max_size=5)), inner, max_size=5),
    ),
    max_leaves=25,
)
FUZZ = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _load(text: str) -> None:
    try:
        parse_manifest(text, PATH)
    except ScaffoldError as error:
        assert error.render()
        if isinstance(error, LocatedError):
            for diagnostic in error.diagnostics:
                assert diagnostic.location.path == str(PATH)


@FUZZ
@given(st.text(max_size=200))
def test_any_text_loads_or_raises_a_scaffold_error(text: str) -> None:
    _load(text)


@FUZZ
@given(st.dictionaries(st.sampled_from(KEYS), VALUES, max_size=8))
def test_any_yaml_structure_loads_or_raises_a_scaffold_error(document: dict[str, object]) -> None:
    _load(json.dumps(document, default=str))  # JSON is YAML; flow style covers every shape


@FUZZ
@given(st.data())
def test_mangled_starter_manifests_load_or_raise_a_scaffold_error(data: st.DataObject) -> None:
    text = re.sub(r"(?m)^#(  - |    \w)", r"\1", starter_manifest(2, "Assets/S.unity"))
    cut = data.draw(st.integers(0, len(text)))
    insert = data.draw(st.text(alphabet=" \t:-[]{}&*!#@'\"\n|>?,", max_size=4))
    _load(text[:cut] + insert + text[cut + data.draw(st.integers(0, 3)) :])


def test_deep_nesting_and_alias_bombs_are_user_errors() -> None:
    for text in [
        "[" * 1100,
        "a: " + "{b: " * 3000,
        "[" * 300 + "]" * 300,
        "a: &a [x, x, x, x, x, x, x, x, x]\n"
        + "".join(
            f"{c}: &{c} [*{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}]\n"
            for p, c in zip("abcdefgh", "bcdefghi", strict=True)
        ),
    ]:
        with contextlib.suppress(ScaffoldError):
            parse_manifest(text, PATH)
