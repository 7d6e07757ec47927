"""Whatever the text, loading a manifest either accepts it or refuses it cleanly, and both
outcomes mean something:

- refused: a ``UserError`` (never an internal error) whose diagnostics point at real lines of
  this file, quoting them as they are;
- accepted: the JSON Schema accepts the same document (the schema is never stricter than the
  loader), and a well-formed manifest reads back as written;
- a well-formed manifest with one mistake is refused at the line of that mistake.
"""

from __future__ import annotations

import io
import json
import re
from pathlib import Path
from typing import Any

import pytest
from helpers import build_tree, require
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from ruamel.yaml import YAML

from unityscaffold.errors import LocatedError, ScaffoldError, UserError
from unityscaffold.interfaces.model import Dialect
from unityscaffold.manifest import load_manifest, parse_manifest, starter_manifest
from unityscaffold.manifest.model import Manifest
from unityscaffold.manifest.schema import load_schema

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
_SAFE_YAML = YAML(typ="safe", pure=True)


@pytest.fixture(scope="module")
def schema() -> Any:
    """The shipped JSON Schema as a validator (jsonschema is a test dependency)."""
    try:
        import jsonschema
    except ImportError:
        jsonschema = None
    require(jsonschema, "jsonschema (a test dependency)")
    return jsonschema.Draft202012Validator(load_schema())


def _check(text: str, schema: Any) -> Manifest | UserError:
    """Load ``text``; assert what acceptance or refusal promises; return the outcome."""
    try:
        manifest = parse_manifest(text, PATH)
    except ScaffoldError as error:
        assert isinstance(error, UserError), f"not a user error: {error!r}"
        assert error.render().strip()
        if isinstance(error, LocatedError):
            _assert_located_in(error, text)
        return error
    errors = [e.message for e in schema.iter_errors(_SAFE_YAML.load(text))]
    assert errors == [], f"the loader accepted what the schema refuses:\n{text}"
    return manifest


def _assert_located_in(error: LocatedError, text: str) -> None:
    lines = text.splitlines() or [""]
    for diagnostic in error.diagnostics:
        where = diagnostic.location
        assert where.path == str(PATH)
        # every refusal has a place, even one about the whole file (empty, nested too deeply)
        assert where.line >= 1 and where.col >= 1, diagnostic.render()
        assert where.line <= len(lines) + 1, diagnostic.render()
        if where.source_line is not None and where.line <= len(lines):
            assert where.source_line == lines[where.line - 1], diagnostic.render()


@FUZZ
@given(text=st.text(max_size=200))
def test_any_text_is_accepted_or_refused_at_its_own_lines(text: str, schema: Any) -> None:
    _check(text, schema)


@FUZZ
@given(document=st.dictionaries(st.sampled_from(KEYS), VALUES, max_size=8))
def test_any_yaml_structure_is_accepted_or_refused_cleanly(
    document: dict[str, object], schema: Any
) -> None:
    _check(json.dumps(document, default=str), schema)  # JSON is YAML; flow style: every shape


@FUZZ
@given(data=st.data())
def test_mangled_starter_manifests_are_accepted_or_refused_cleanly(
    data: st.DataObject, schema: Any
) -> None:
    text = re.sub(r"(?m)^#(  - |    \w)", r"\1", starter_manifest(2, "Assets/S.unity"))
    cut = data.draw(st.integers(0, len(text)))
    insert = data.draw(st.text(alphabet=" \t:-[]{}&*!#@'\"\n|>?,", max_size=4))
    _check(text[:cut] + insert + text[cut + data.draw(st.integers(0, 3)) :], schema)


# --- well-formed manifests, and the same with one mistake ------------------------------------

TOPIC_NAMES = ["/cmd_vel", "/odom", "/scan", "/robot/imu", "joint_states"]
SERVICE_NAMES = ["/reset", "/set_mode", "/robot/calibrate"]
TYPES = {
    1: (["geometry_msgs/Twist", "nav_msgs/Odometry", "my_robot/Wheel"], ["std_srvs/Trigger"]),
    2: (["geometry_msgs/msg/Twist", "sensor_msgs/msg/LaserScan"], ["std_srvs/srv/Trigger"]),
}


@st.composite
def well_formed(draw: st.DrawFn) -> dict[str, Any]:
    """A manifest that must be accepted: valid values, unique names, options that fit."""
    ros = draw(st.sampled_from([1, 2]))
    message_types, service_types = TYPES[ros]
    topics = []
    for name in draw(st.lists(st.sampled_from(TOPIC_NAMES), unique=True, max_size=4)):
        topic = {"name": name, "type": draw(st.sampled_from(message_types))}
        topic["direction"] = draw(st.sampled_from(["publish", "subscribe"]))
        if topic["direction"] == "publish":
            rate = draw(st.none() | st.integers(1, 100) | st.floats(0.5, 50.0))
            topic.update({} if rate is None else {"rate": rate})
        else:
            topic.update(
                draw(st.fixed_dictionaries({}, optional={"throttle": st.integers(0, 500)}))
            )
            topic.update(draw(st.fixed_dictionaries({}, optional={"queue": st.integers(1, 10)})))
        topics.append(topic)
    services = []
    for name in draw(st.lists(st.sampled_from(SERVICE_NAMES), unique=True, max_size=2)):
        role = draw(st.sampled_from(["client", "server"]))
        services.append({"name": name, "type": draw(st.sampled_from(service_types)), "role": role})
    return {
        "version": 1,
        "ros": ros,
        "scene": "Assets/Scenes/Main.unity",
        "topics": topics,
        "services": services,
    }


def _block_yaml(document: dict[str, Any]) -> str:
    """``document`` in block style, one key per line (so a mistake has a line of its own)."""
    writer = YAML(typ="safe", pure=True)
    writer.default_flow_style = False
    writer.sort_base_mapping_type_on_output = False  # type: ignore[assignment]
    out = io.StringIO()
    writer.dump(document, out)
    return out.getvalue()


@FUZZ
@given(document=well_formed())
def test_a_well_formed_manifest_is_accepted_and_reads_as_written(
    document: dict[str, Any], schema: Any
) -> None:
    manifest = _check(_block_yaml(document), schema)
    assert isinstance(manifest, Manifest), manifest.render()
    assert manifest.ros is Dialect(document["ros"])
    read_topics = [
        (t.name, t.type, t.direction.value, t.rate, t.throttle, t.queue) for t in manifest.topics
    ]
    assert read_topics == [
        (
            t["name"],
            t["type"],
            t["direction"],
            t.get("rate"),
            t.get("throttle"),
            t.get("queue"),
        )
        for t in document["topics"]
    ]
    read_services = [(s.name, s.type, s.role.value) for s in manifest.services]
    assert read_services == [(s["name"], s["type"], s["role"]) for s in document["services"]]


# (where, key, value): one mistake each, put into a well-formed manifest.
MISTAKES = [
    ("top", "ros", 3),
    ("top", "versoin", 1),
    ("top", "scene", "Assets/Scenes/Main.scene"),
    ("topic", "direction", "sideways"),
    ("topic", "rat", 10),
    ("topic", "name", "/cmd vel"),
    ("topic", "queue", 0),
    ("service", "role", "both"),
]


@FUZZ
@given(document=well_formed(), mistake=st.sampled_from(MISTAKES))
def test_one_mistake_in_a_well_formed_manifest_is_refused_at_its_line(
    document: dict[str, Any], mistake: tuple[str, str, object], schema: Any
) -> None:
    where, key, value = mistake
    message_types, service_types = TYPES[document["ros"]]
    if where == "top":
        entry = document
    elif where == "topic":
        if not document["topics"]:
            document["topics"].append(
                {"name": "/extra", "type": message_types[0], "direction": "subscribe"}
            )
        entry = document["topics"][-1]
    else:
        if not document["services"]:
            document["services"].append(
                {"name": "/extra", "type": service_types[0], "role": "client"}
            )
        entry = document["services"][-1]
    entry[key] = value
    text = _block_yaml(document)
    outcome = _check(text, schema)
    assert isinstance(outcome, LocatedError), f"accepted with {key}: {value!r}:\n{text}"
    lines = [d.location.source_line or "" for d in outcome.diagnostics]
    assert any(line.lstrip(" -").startswith(f"{key}:") for line in lines), outcome.render()


# --- paths through symbolic links ------------------------------------------------------------

# Folders of a project on disk (tmp/p) beside a folder outside it, with links of every kind:
# to the project, inside it, out of it, to nowhere, and to themselves.
LINKS = {
    "u": "p",
    "p/Assets/In": "p/Assets/Real",
    "p/Assets/Out": "outside",
    "p/Assets/Dangling": "nowhere",
    "p/Assets/Loop": "p/Assets/Loop",
    "loop": "loop",
}
PROJECTS = [".", "p", "u", "u/", "u/..", "u/Assets/..", "p/Assets/In/../..", "loop", "nowhere"]
INSIDE = [
    "Assets/Gen", "Assets/In", "Assets/In/Gen", "Assets/Out", "Assets/Out/Gen", "Assets/Dangling",
    "Assets/Loop", "Assets/Loop/x", "Assets/In/..", "Assets/In/../Gen", "Assets/Out/../Gen",
]  # fmt: skip


@pytest.fixture(scope="module")
def linked(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("linked")
    for folder in ("p/Assets/Real", "p/ProjectSettings", "outside"):
        (root / folder).mkdir(parents=True)
    for link, target in LINKS.items():
        (root / link).symlink_to(root / target, target_is_directory=True)
    return root


@FUZZ
@given(
    project=st.sampled_from(PROJECTS),
    output=st.sampled_from(INSIDE),
    scene=st.sampled_from(INSIDE),
    script=st.sampled_from(INSIDE),
)
def test_paths_through_links_are_accepted_inside_the_project_or_refused_cleanly(
    linked: Path, project: str, output: str, scene: str, script: str
) -> None:
    text = (
        f"version: 1\nros: 2\nproject: {project}\noutput: {output}\nscene: {scene}/S.unity\n"
        f"components:\n  - {{script: {script}/A.cs, gameobject: G}}\n"
    )
    try:
        manifest = load_manifest(build_tree(linked, {"robot.yaml": text}) / "robot.yaml")
    except ScaffoldError as error:
        assert isinstance(error, LocatedError), f"not a located user error: {error!r}"
        assert all(d.location.line >= 1 for d in error.diagnostics), error.render()
        return
    root = manifest.project_root
    assert root == root.resolve(), "the project root is not its real path"
    for inside in (manifest.output_dir, manifest.scene_path(manifest.scenes[0])):
        assert inside.is_relative_to(root)
        assert inside.resolve().is_relative_to(root.resolve()), f"{inside} leaves {root}"


def test_a_project_folder_the_system_cannot_name_is_refused_at_its_line() -> None:
    # Found by the fuzz test above once the project folder was resolved: a lone surrogate.
    outcome = _check('{"version": 1, "ros": 2, "project": "\\ud800"}', None)
    assert isinstance(outcome, LocatedError)
    assert any(d.message.startswith("invalid value for 'project'") for d in outcome.diagnostics)


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
        with pytest.raises(LocatedError):
            parse_manifest(text, PATH)


def test_a_tagged_mapping_key_is_refused_at_its_position() -> None:
    # Found by the fuzz test above: the loader accepted a key carrying a local tag.
    text = (
        "version: 1\nros: 2\ncomponents:\n  - {script: A, gameobject: B, fields: {T: /,!x, Y: 1}}\n"
    )
    outcome = _check(text, None)
    assert isinstance(outcome, LocatedError)
    assert outcome.diagnostics[0].message == "unsupported YAML tag '!x,'"
