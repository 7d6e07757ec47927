"""A document's YAML check answers what PyYAML's full load answers, problem and place alike."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from unityscaffold.unity._split import split_text
from unityscaffold.unity._yamlcheck import yaml_problem

_LOADER = getattr(yaml, "CBaseLoader", yaml.BaseLoader)


def _loaded(body: str) -> tuple[str, tuple[int, int] | None] | None:
    """The answer of a full load: the reference the check must agree with."""
    try:
        yaml.load(body, Loader=_LOADER)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        problem = getattr(exc, "problem", None) or str(exc).strip().split("\n")[0]
        return problem, (mark.line, mark.column) if mark is not None else None
    return None


# Bodies only the composer or the constructor refuses (the parse alone finds them sound), then
# sound bodies near them, then ones the parser refuses.
BODIES = {
    "a key that is a flow list": "Object:\n  [a, b]: 1\n",
    "a key that is a flow mapping": "Object:\n  m_Data: {{x: 1}: 2}\n",
    "an explicit key that is a block list": "Object:\n  ? - a\n    - b\n  : 1\n",
    "a key that is a list deep in a list": "Object:\n  m_List:\n  - {[a]: 1}\n",
    "an undefined alias": "Object:\n  m_Name: *nowhere\n",
    "an alias to its own list": "Object:\n  m_List: &loop [*loop]\n",
    "an anchor given twice": "Object:\n  a: &x 1\n  b: &x 2\n  c: *x\n",
    "two documents": "Object:\n  m_Name: a\n--- \nObject:\n  m_Name: b\n",
    "an alias to a sound anchor": "Object:\n  a: &x 1\n  b: *x\n",
    "an explicit scalar key": "Object:\n  ? m_Name\n  : a\n",
    "keys after a nested value": "Object:\n  m_A: {x: [1, {y: 2}], z: 3}\n  m_B: [[1], {c: d}]\n",
    "a flow mapping of implicit nulls": "Object:\n  m_Set: {a, b}\n",
    "an empty body": "",
    "a tab in the indentation": "Object:\n\tm_Name: a\n",
    "an unclosed flow mapping": "Object:\n  m_Data: {x: 1\n  m_Name: a\n",
    "an unclosed quoted string": 'Object:\n  m_Name: "abc\n',
}


@pytest.mark.parametrize("case", sorted(BODIES))
def test_the_check_agrees_with_a_full_load(case: str) -> None:
    body = BODIES[case]
    assert yaml_problem(body) == _loaded(body)


def test_the_bodies_only_a_full_load_refuses_are_refused() -> None:
    refused = [
        "a key that is a flow list",
        "a key that is a flow mapping",
        "an explicit key that is a block list",
        "a key that is a list deep in a list",
        "an undefined alias",
        "an alias to its own list",
        "an anchor given twice",
        "two documents",
    ]
    for case in refused:
        assert yaml_problem(BODIES[case]) is not None, case


def test_every_document_unity_wrote_is_found_sound(corpus_file: Path) -> None:
    split = split_text(corpus_file.read_text(encoding="utf-8"), str(corpus_file))
    for doc in split.docs:
        assert yaml_problem(doc.text[doc.text.index("\n") + 1 :]) is None, doc.header
