"""Property: every apply that succeeds is a fixed point, whatever the layout.

Random valid manifests on a fresh ``init`` project (ROS 2, no ``Library/``): topics and services
on new, existing and connector GameObjects; ROS#'s stock scripts from the catalog (two instances
of one told apart by ``id``) with fields of every kind set, references to GameObjects,
transforms, built-in components and scripts by class included; declared objects with their
transform, flags, built-in components and UI layout. After ``apply``, ``apply --check`` exits 0
and a second ``apply`` writes nothing. Derandomized, so CI sees the same examples on every run.
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

import pytest
from helpers import run_cli
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from unityscaffold.unity.catalog import CatalogField, CatalogScript, rossharp_catalog

CATALOG = rossharp_catalog()
STOCK = [s for s in CATALOG.scripts if s.attachable]
TOPIC_TYPES = [
    "std_msgs/msg/String",
    "geometry_msgs/msg/Twist",
    "sensor_msgs/msg/Imu",
    "nav_msgs/msg/Odometry",
]
# New paths (created by apply, parents included), objects the init scene has, and the
# connector's own GameObject (chosen per manifest among these).
NEW = ["Robot", "Robot/Base", "Robot/Base/Lidar", "Arm/Link1"]
EXISTING = ["Main Camera", "Directional Light"]
CONNECTOR = ["RosConnector", "Robot", "Main Camera"]
_SCALARS = {
    "int": st.integers(-1000, 1000).map(str),
    "float": st.sampled_from(["0", "0.25", "-3.5", "1e-3", "100"]),
    "bool": st.sampled_from(["true", "false"]),
    "string": st.sampled_from(["/topic", "a b", "''", "'#x: y'", '"q\\"uote"']),
}


def _refers(field: CatalogField) -> str | None:
    """The class a reference field holds (None for any other field)."""
    kind = field.unity.removesuffix("[]")
    return kind[4:].rsplit(".", 1)[-1] if kind.startswith("ref:") else None


# Stock scripts with a field of a ROS# script class, drawn more often than the others.
REFERRING = [
    s for s in STOCK if any(_refers(f) not in (None, "Transform", "GameObject") for f in s.fields)
]
# A class -> the first attachable ROS# script of that class or deriving from it.
_CONCRETE = {
    name: script
    for script in reversed(STOCK)
    for name in (script.class_name, *script.bases)
    if name not in ("MonoBehaviour",)
}
# Built-in components the init scene has, on the GameObjects that hold them.
_BUILT_IN = {"Camera": "Main Camera", "Light": "Directional Light"}
_STRUCTS = {
    "Vector2": "{x: 1, y: -2}",
    "Vector3": "{x: 0.5, y: 0, z: -1}",
    "Quaternion": "{x: 0, y: 0, z: 0, w: 1}",
    "Color": "{r: 1, g: 0.5, b: 0, a: 1}",
}


@pytest.fixture(scope="module")
def fresh(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("fresh") / "p"
    assert run_cli("init", str(root), "--ros", "2").code == 0
    assert not (root / "Library").exists()
    return root


def _field_value(
    field: CatalogField, targets: list[str], holders: dict[str, list[str]]
) -> st.SearchStrategy[str] | None:
    """A strategy for a manifest value of ``field`` (None: a kind not drawn here).

    ``holders`` maps a class to the GameObjects the manifest puts a script of it (or of a
    subclass) on; a field of a script class refers to one of them.
    """
    kind = field.unity.removesuffix("[]")
    one: st.SearchStrategy[str] | None
    if kind in _SCALARS:
        one = _SCALARS[kind]
    elif kind in _STRUCTS:
        one = st.just(_STRUCTS[kind])
    elif kind.startswith("enum:"):
        one = st.sampled_from(sorted(CATALOG.enums[kind[5:]]))
    elif kind in ("ref:Transform", "ref:GameObject"):
        one = st.sampled_from(targets).map(lambda p: f'"@{p}"')
    elif kind.startswith("ref:") and holders.get(kind[4:].rsplit(".", 1)[-1]):
        one = st.sampled_from(holders[kind[4:].rsplit(".", 1)[-1]]).map(lambda p: f'"@{p}"')
    else:
        return None  # a component nothing in this manifest provides
    if field.unity.endswith("[]"):
        return st.lists(one, max_size=2).map(lambda items: "[" + ", ".join(items) + "]")
    return one


@st.composite
def manifests(draw: st.DrawFn) -> str:
    connector = draw(st.sampled_from(CONNECTOR))
    places = st.sampled_from([*NEW, *EXISTING, connector])
    lines = [
        "version: 1",
        "ros: 2",
        "project: .",
        "scene: Assets/Scenes/Main.unity",
        f"connector: {{gameobject: {connector}}}",
    ]
    used = {connector}
    topics = draw(st.lists(st.sampled_from(TOPIC_TYPES), max_size=3))
    if topics:
        lines.append("topics:")
    for index, type_name in enumerate(topics):
        place = draw(places)
        used.add(place)
        direction = draw(st.sampled_from(["publish", "subscribe"]))
        lines.append(
            f"  - {{name: /t{index}, type: {type_name}, direction: {direction}, "
            f'gameobject: "{place}", create: true}}'
        )
    if draw(st.booleans()):
        place = draw(places)
        used.add(place)
        role = draw(st.sampled_from(["client", "server"]))
        lines += [
            "services:",
            f'  - {{name: /reset, type: std_srvs/srv/Trigger, role: {role}, gameobject: "{place}",'
            " create: true}",
        ]
    scripts = st.one_of(st.sampled_from(STOCK), st.sampled_from(REFERRING))
    stock = draw(st.lists(st.tuples(scripts, places), max_size=4, unique=True))
    # Scripts the drawn ones refer to by class (JointStatePublisher's JointStateReaders...),
    # added on a drawn GameObject so that such references get drawn too.
    for script, _ in list(stock):
        for field in script.fields:
            wanted = field.unity.removesuffix("[]").rsplit(".", 1)[-1]
            concrete = _CONCRETE.get(wanted) if field.unity.startswith("ref:") else None
            if concrete is not None and draw(st.booleans()):
                stock.append((concrete, draw(places)))
    stock = list({(s.class_name, p): (s, p) for s, p in stock}.values())
    # A second instance of a script on the same GameObject: both are then told apart by `id`.
    if stock and draw(st.booleans()):
        stock.append(draw(st.sampled_from(stock)))
    twice = {(s.class_name, p) for s, p in stock if stock.count((s, p)) > 1}
    used |= {p for _, p in stock}
    objects, built_in = draw(_objects())
    used |= {path for path, _ in built_in}
    # Where exactly one component fits a class: a reference there is not ambiguous.
    fitting: dict[tuple[str, str], int] = {}
    for script, place in stock:
        for name in (script.class_name, *script.bases):
            fitting[name, place] = fitting.get((name, place), 0) + 1
    for place, name in [*built_in, *((p, c) for c, p in _BUILT_IN.items())]:
        fitting[name, place] = 1
    holders: dict[str, list[str]] = {}
    for (name, place), count in sorted(fitting.items()):
        if count == 1:
            holders.setdefault(name, []).append(place)
    targets = sorted(used | set(EXISTING))
    if stock:
        lines.append("components:")
    seen: dict[tuple[str, str], int] = {}
    for script, place in stock:
        lines += [
            f"  - script: {script.class_name}",
            f'    gameobject: "{place}"',
            "    create: true",
        ]
        if (script.class_name, place) in twice:
            index = seen[script.class_name, place] = seen.get((script.class_name, place), -1) + 1
            lines.append(f"    id: i{index}")
        fields = _fields(draw, script, targets, holders)
        if fields:
            lines.append("    fields: {" + ", ".join(fields) + "}")
    return "\n".join(lines + objects) + "\n"


_VECTOR = st.lists(
    st.sampled_from(["0", "1", "-2.5", "0.1", "90", "45", "-30"]), min_size=3, max_size=3
)
TAGS = ["Untagged", "Respawn", "Finish", "EditorOnly", "MainCamera", "Player", "GameController"]
BUILT_IN = ["Rigidbody", "BoxCollider", "SphereCollider", "CapsuleCollider", "Light", "Camera"]
UI = [
    "  - {path: Canvas, ui: true, components: [Canvas, CanvasRenderer]}",
    "  - {path: Canvas/Panel, ui: {anchor_min: [0, 1], anchor_max: [0, 1], position: [90, -20],"
    " size: [160, 30]}, components: [CanvasRenderer]}",
]


@st.composite
def _objects(draw: st.DrawFn) -> tuple[list[str], list[tuple[str, str]]]:
    """Declared objects (transform, flags, built-in components, UI) and (path, class) of the
    built-in components they declare."""
    paths = draw(st.lists(st.sampled_from([*NEW, *EXISTING]), max_size=3, unique=True))
    lines: list[str] = []
    built_in: list[tuple[str, str]] = []
    for path in paths:
        keys = [f'path: "{path}"']
        for key in ("position", "rotation", "scale"):
            if draw(st.booleans()):
                keys.append(f"{key}: [{', '.join(draw(_VECTOR))}]")
        if draw(st.booleans()):
            keys.append(f"active: {draw(st.sampled_from(['true', 'false']))}")
        if draw(st.booleans()):
            keys.append(f"tag: {draw(st.sampled_from(TAGS))}")
        if draw(st.booleans()):
            keys.append(f"layer: {draw(st.integers(0, 31))}")
        classes = draw(st.lists(st.sampled_from(BUILT_IN), max_size=2, unique=True))
        if classes:
            keys.append(f"components: [{', '.join(classes)}]")
        built_in += [(path, c) for c in classes]
        lines.append("  - {" + ", ".join(keys) + "}")
    if draw(st.booleans()):
        lines += UI
    return (["objects:", *lines] if lines else []), built_in


def _fields(
    draw: st.DrawFn, script: CatalogScript, targets: list[str], holders: dict[str, list[str]]
) -> list[str]:
    chosen = draw(st.lists(st.sampled_from(script.fields), unique=True)) if script.fields else []
    chosen += [f for f in script.fields if f not in chosen and _refers(f) in holders]
    found = []
    for field in chosen:
        strategy = _field_value(field, targets, holders)
        if strategy is not None:
            found.append(f"{field.name}: {draw(strategy)}")
    return found


@settings(
    max_examples=50,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
@given(manifest=manifests())
def test_every_successful_apply_is_a_fixed_point(fresh: Path, manifest: str) -> None:
    with tempfile.TemporaryDirectory() as folder:
        project = Path(folder) / "p"
        shutil.copytree(fresh, project)
        path = project / "robot.yaml"
        path.write_text(manifest)
        first = run_cli("apply", str(path))
        assert first.code == 0, manifest + first.err
        check = run_cli("apply", "--check", str(path))
        assert check.code == 0, manifest + check.out + check.err
        again = run_cli("apply", str(path))
        assert again.code == 0 and again.out.endswith("wrote 0 files, removed 0\n"), (
            manifest + again.out
        )
