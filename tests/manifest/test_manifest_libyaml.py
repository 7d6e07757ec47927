"""Plain manifests are composed from libyaml's events into the tree ruamel itself composes;
anything else goes through ruamel, so every text reads, or is refused, exactly as with ruamel
alone."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from ruamel.yaml import YAML

from unityscaffold.errors import LocatedError
from unityscaffold.manifest import _libyaml
from unityscaffold.manifest._yaml import YNode, compose

ROOT = Path(__file__).resolve().parents[2]
MANIFESTS = sorted(
    [ROOT / "sample_project" / "robot.yaml", *(Path(__file__).parent / "valid").glob("*.yaml")]
)


def _outcome(text: str) -> YNode | str | None:
    try:
        return compose(text, "robot.yaml")
    except LocatedError as error:
        return error.render()
    except Exception as error:  # what ruamel raises, the same either way
        return f"{type(error).__name__}: {error}"


def _ruamel_only(text: str, monkeypatch: pytest.MonkeyPatch) -> YNode | str | None:
    with monkeypatch.context() as patch:
        patch.setattr(_libyaml, "_Parser", None)
        return _outcome(text)


@pytest.mark.parametrize("path", MANIFESTS, ids=lambda p: p.name)
def test_real_manifests_take_the_libyaml_way_and_read_as_with_ruamel(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    text = path.read_text(encoding="utf-8")
    assert _libyaml.compose_plain(text, YAML(typ="safe", pure=True).resolver) is not _libyaml.RUAMEL
    assert _outcome(text) == _ruamel_only(text, monkeypatch)


@pytest.mark.parametrize(
    "text",
    [
        "%YAML 1.1\n---\nros: yes\n",  # a directive changes how ruamel resolves
        "ros: !!str 1\n",
        "a: 1\n---\nb: 2\n",
        "a: 1\n...\n...\n",  # libyaml reads one document, ruamel two
        "\ufeffros: 1\n",
        "ros: 1\t\n",
        "ros: 1\rb: 2\n",
        "ros: 1\u2028b: 2\n",
        "topics:\n  -\n",
        "a: *missing\n",
        "[" * (_libyaml.MAX_DEPTH + 1) + "]" * (_libyaml.MAX_DEPTH + 1) + "\n",
    ],
)
def test_texts_outside_the_plain_subset_go_to_ruamel(text: str) -> None:
    assert _libyaml.compose_plain(text, YAML(typ="safe", pure=True).resolver) is _libyaml.RUAMEL


@pytest.mark.parametrize(
    "text", ["a: &x [*x]\n", "a: &x 1\nb: &x 2\nc: *x\n", "<<: {a: 1}\na: 2\n", "a:\n"]
)
def test_aliases_merges_and_empty_values_read_as_with_ruamel(
    text: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    assert _outcome(text) == _ruamel_only(text, monkeypatch)


@pytest.mark.parametrize("tag", ["int", "float", "bool"])
@pytest.mark.parametrize(
    ("text", "at"),
    [("t: !!TAG \n", (1, 4)), ("t: [!!TAG ]\n", (1, 5)), ("t:\n  - !!TAG\n", (2, 5))],
)
def test_an_empty_tagged_value_is_refused_at_its_place_both_ways(
    tag: str, text: str, at: tuple[int, int], monkeypatch: pytest.MonkeyPatch
) -> None:
    """ruamel's constructors raise IndexError or ValueError on an empty !!int, !!float or
    !!bool; the reader turns that into a located error, whichever parser read the text."""
    text = text.replace("TAG", tag)
    with pytest.raises(LocatedError) as caught:
        compose(text, "robot.yaml")
    location = caught.value.location
    assert (location.line, location.col) == at
    assert f"invalid {tag} value ''" in caught.value.render()
    assert _outcome(text) == _ruamel_only(text, monkeypatch)


PIECES = st.sampled_from(
    [
        "topics:", "  - ", "- ", "name: ", "/odom", "type: ", "nav_msgs/Odometry", "{", "}",
        "[", "]", ", ", ": ", ":", "yes", "no", "on", "0o17", "017", "0x1F", "1_000", "1e3",
        ".inf", "~", "null", "'q'", '"d\\n"', "&a ", "*a", "<<: ", "? ", "# c", "|", ">",
        "\t", "  ", "\n", "\r\n", "\r", "\x85", "\u2028", "\n  ", "é", "2001-12-14", "-",
        "!!int ", "!!float ", "!!bool ", "%", "---", "...",
    ]
)  # fmt: skip


@settings(max_examples=1000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(PIECES, max_size=40).map("".join))
def test_any_text_reads_or_is_refused_as_with_ruamel_alone(text: str) -> None:
    with pytest.MonkeyPatch.context() as monkeypatch:
        assert _outcome(text) == _ruamel_only(text, monkeypatch)
