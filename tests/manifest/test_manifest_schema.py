"""The shipped JSON Schema is the key table the validator reads, and agrees with it on samples."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from ruamel.yaml import YAML

from unityscaffold.errors import LocatedError
from unityscaffold.manifest import _spec as spec
from unityscaffold.manifest import load_manifest
from unityscaffold.manifest.schema import build_schema, load_schema, render_schema
from unityscaffold.resources import schema_text

HERE = Path(__file__).parent
VALID = sorted((HERE / "valid").glob("*.yaml"))
REPO = HERE.parent.parent
# Bad manifests whose mistake is structural, so the schema must reject them too.
SCHEMA_REJECTS = [
    "object_sibling_index_errors",
    "unknown_key_misspelled",
    "unknown_top_level_key",
    "unknown_key_no_suggestion",
    "enum_direction",
    "enum_role",
    "enum_serializer_and_protocol",
    "rate_on_subscribe",
    "throttle_and_queue_on_publish",
    "rate_not_positive",
    "throttle_negative_queue_zero",
    "missing_required_keys",
    "missing_version_and_ros",
    "unsupported_version",
    "ros_version_3",
    "ros_version_as_text",
    "output_not_in_assets",
    "scene_not_unity_file",
    "topic_name_invalid",
    "type_invalid",
    "service_type_on_topic",
    "message_type_on_service",
    "url_invalid",
    "class_override_not_identifier",
    "namespace_invalid",
    "topics_not_a_list",
    "entry_not_a_mapping",
    "number_for_text",
    "boolean_written_yes",
    "numbers_past_csharp_types",
]


def _jsonschema():
    """The jsonschema library: a test dependency, so missing it fails in CI (see conftest)."""
    from helpers import require

    try:
        import jsonschema
    except ImportError:
        jsonschema = None
    require(jsonschema, "jsonschema (a test dependency)")
    return jsonschema


def _yaml(path: Path) -> Any:
    return YAML(typ="safe", pure=True).load(path.read_text(encoding="utf-8"))


def _validator() -> Any:
    jsonschema = _jsonschema()
    return jsonschema.Draft202012Validator(load_schema())


def test_shipped_schema_is_the_generated_one() -> None:
    shipped = (REPO / "unityscaffold/schema/robot.schema.json").read_text(encoding="utf-8")
    assert shipped == render_schema(), (
        "regenerate: python -m unityscaffold.manifest.schema"
        " > unityscaffold/schema/robot.schema.json"
    )


def test_schema_is_found_at_runtime() -> None:
    assert schema_text() == render_schema()


def _object_schemas(schema: dict[str, Any]) -> dict[str, dict[str, Any]]:
    return {
        "manifest": schema,
        **{name: d for name, d in schema["$defs"].items() if d.get("type") == "object"},
    }


def test_schema_and_validator_allow_the_same_keys() -> None:
    objects = _object_schemas(load_schema())
    assert set(objects) == {s.ref for s in spec.SECTIONS}
    for section in spec.SECTIONS:
        shown = objects[section.ref]
        assert list(shown["properties"]) == list(section.names), section.label
        assert shown.get("required", []) == list(section.required), section.label
        assert shown["additionalProperties"] is False
        assert all(p.get("description") for p in shown["properties"].values())


def test_schema_is_valid_draft_2020_12() -> None:
    jsonschema = _jsonschema()
    jsonschema.Draft202012Validator.check_schema(build_schema())


@pytest.mark.parametrize("case", VALID, ids=[c.stem for c in VALID])
def test_valid_samples_pass_the_schema(case: Path) -> None:
    load_manifest(case)
    errors = [e.message for e in _validator().iter_errors(_yaml(case))]
    assert errors == []


@pytest.mark.parametrize("name", SCHEMA_REJECTS)
def test_structural_mistakes_fail_the_schema_too(name: str) -> None:
    case = HERE / "invalid" / f"{name}.yaml"
    with pytest.raises(LocatedError):
        load_manifest(case)
    assert not _validator().is_valid(_yaml(case))


def test_patterns_mean_the_same_in_python_and_json_schema() -> None:
    jsonschema = _jsonschema()
    import re

    samples = [
        "/cmd_vel",
        "cmd_vel",
        "/a/_b",
        "/cmd//vel",
        "/scan/",
        "2d",
        "p/msg/A",
        "p/A",
        "p/srv/A",
        "Robot/base_link",
        "/Robot",
        "Main.unity",
        "ws://h:9090/x",
        "My.Ns",
        "a-b",
        "ws://",
        "_x",
        "A_1",
        "192.168.1.10",
        "robot-1.local",
        "-robot",
        "tcp://robot",
    ]
    for name, pattern in spec.patterns().items():
        check = jsonschema.Draft202012Validator({"type": "string", "pattern": pattern})
        for sample in samples:
            assert bool(re.search(pattern, sample)) == check.is_valid(sample), (name, sample)


def test_docs_describe_every_key_in_its_section() -> None:
    docs = (REPO / "docs" / "manifest.md").read_text(encoding="utf-8")
    headings = {
        "manifest": "## Top level",
        "connector": "## `connector`",
        "tcpConnector": "## `connector` under `runtime: ros-tcp-connector`",
        "topic": "## `topics`",
        "service": "## `services`",
        "action": "## `actions`",
        "component": "## `components`",
        "object": "## `objects`",
        "robot": "## `robots`",
    }
    # Mappings inside an object's row are described in prose there, each key in backticks.
    inline = {"ui": "## `objects`", "builtinComponent": "## `objects`"}
    for section in spec.SECTIONS:
        if section.ref in inline:
            start = docs.index(inline[section.ref])
            text = docs[start : docs.find("\n## ", start + 1)]
            assert all(f"`{name}`" in text for name in section.names), section.label
            continue
        start = docs.index(headings[section.ref])
        end = docs.find("\n## ", start + 1)
        rows = [
            line.split("|")[1].strip().strip("`")
            for line in docs[start : end if end > 0 else None].splitlines()
            if line.startswith("| `")
        ]
        assert rows == list(section.names), section.label
