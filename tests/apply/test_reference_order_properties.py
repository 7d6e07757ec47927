"""Property: entry order never matters, and neither does a Unity ``Library/``.

Random manifests on a fresh ``init`` project whose entries come in any order, with references
to components of every kind that a later or an earlier entry adds: uGUI's (``Image``, ``Text``),
ROS#'s from the catalog (``JointStateReader``), the project's own script (typed fields), a
generated topic script, and objects' built-in components (``Camera``, ``Rigidbody``), empty
references (``null``) and sibling places included. Each manifest is applied to the project as
``init`` makes it and to the same project with ROS# 2.2.1's package in ``Library/PackageCache``
(as Unity unpacks it): both give the same scene bytes, ``apply --check`` is clean after, and a
second apply writes nothing. Derandomized, so CI sees the same examples on every run.
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

import pytest
from helpers import require, run_cli
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.runtime.bridge import vendor_folder

SCENE = "Assets/Scenes/Main.unity"
HEADER = f"""\
version: 1
ros: 2
project: .
scene: {SCENE}
connector: {{gameobject: RosConnector}}
topics:
  - {{name: /t0, type: geometry_msgs/msg/Twist, direction: publish, gameobject: Robot,
     create: true}}
"""
# The project's own script: a field of each kind a reference may fill.
RIG = """\
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.UI;
using RosSharp.RosBridgeClient;

public class Rig : MonoBehaviour
{
    public GameObject Go;
    public Transform Tr;
    public Camera Cam;
    public Rigidbody Body;
    public Image Pic;
    public JointStateReader Reader;
    public RosGenerated.T0Publisher Gen;
    public List<Transform> Chain;
}
"""


def _ref(*targets: str) -> st.SearchStrategy[str]:
    """One of ``targets`` written as a reference, or null."""
    return st.sampled_from([*(f'"@{t}"' for t in targets), "null"])


# Objects: always declared (they give what the references name), in any order.
OBJECTS = [
    st.just("  - {path: Eye, components: [Camera]}"),
    _ref("Eye").map(
        lambda camera: (
            "  - {path: Canvas, ui: true, components: [{type: Canvas, "
            f"fields: {{m_RenderMode: 1, m_Camera: {camera}}}}}]}}"
        )
    ),
    st.sampled_from(["", ", sibling_index: 1", ", sibling_index: 0"]).map(
        lambda place: f"  - {{path: Canvas/B, ui: true, components: [CanvasRenderer]{place}}}"
    ),
    st.just("  - {path: Canvas/T, ui: true, components: [CanvasRenderer]}"),
    st.just("  - {path: Robot/Body, components: [Rigidbody]}"),
]
# Components that others name: always there.
PROVIDERS = [
    st.just("  - {script: Image, gameobject: Canvas/B}"),
    st.just("  - {script: Text, gameobject: Canvas/T}"),
    st.just("  - {script: JointStateReader, gameobject: Robot/J1, create: true}"),
    st.just("  - {script: JointStateReader, gameobject: Robot/J2, create: true}"),
]
# Components that name others, each drawn or not.
REFERRERS = [
    _ref("Canvas/B:Image", "Canvas/T:Text").map(
        lambda target: (
            f"  - {{script: Button, gameobject: Canvas/B, fields: {{m_TargetGraphic: {target}}}}}"
        )
    ),
    st.lists(_ref("Robot/J1", "Robot/J2"), max_size=3).map(
        lambda items: (
            "  - {script: JointStatePublisher, gameobject: Robot, "
            f"fields: {{Topic: /joints, JointStateReaders: [{', '.join(items)}]}}}}"
        )
    ),
    st.tuples(st.sampled_from(["/a", "/b"]), _ref("Robot/Body", "Eye")).map(
        lambda t: (
            f"  - {{script: TwistPublisher, gameobject: Robot/Body, "
            f"fields: {{Topic: {t[0]}, PublishedTransform: {t[1]}}}}}"
        )
    ),
    _ref("Eye").map(
        lambda camera: (
            "  - {script: ImagePublisher, gameobject: Robot/Cam, create: true, "
            f"fields: {{ImageCamera: {camera}}}}}"
        )
    ),
    st.tuples(
        _ref("Canvas/B"),
        _ref("Robot/Body"),
        _ref("Eye"),
        _ref("Robot/Body"),
        _ref("Canvas/B"),
        _ref("Robot/J2"),
        _ref("Robot"),
        st.lists(_ref("Robot/Body", "Eye", "Canvas/T"), max_size=2),
    ).map(
        lambda v: (
            "  - {script: Rig, gameobject: Robot/Rig, create: true, fields: {"
            f"Go: {v[0]}, Tr: {v[1]}, Cam: {v[2]}, Body: {v[3]}, Pic: {v[4]}, Reader: {v[5]}, "
            f"Gen: {v[6]}, Chain: [{', '.join(v[7])}]}}}}"
        )
    ),
]


@st.composite
def manifests(draw: st.DrawFn) -> str:
    objects = [draw(s) for s in OBJECTS]
    components = [draw(s) for s in PROVIDERS]
    components += [draw(s) for s in REFERRERS if draw(st.booleans())]
    objects = draw(st.permutations(objects))
    components = draw(st.permutations(components))
    return HEADER + "\n".join(["objects:", *objects, "components:", *components]) + "\n"


def _rossharp() -> Path:
    package = vendor_folder("UNITYSCAFFOLD_ROSSHARP", "ros-sharp/2.2.1/com.siemens.ros-sharp")
    require(package, "ROS# 2.2.1's com.siemens.ros-sharp folder (UNITYSCAFFOLD_ROSSHARP)")
    assert package is not None
    return package


@pytest.fixture(scope="module")
def fresh(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """The init project without ``Library/``, and the same with ROS# in its PackageCache."""
    package = _rossharp()
    root = tmp_path_factory.mktemp("fresh")
    bare = root / "bare"
    assert run_cli("init", str(bare), "--ros", "2").code == 0
    scripts = bare / "Assets" / "Scripts"
    scripts.mkdir(parents=True, exist_ok=True)
    (scripts / "Rig.cs").write_text(RIG)
    cached = root / "cached"
    shutil.copytree(bare, cached)
    # Unity unpacks a git package under its name and the commit's short hash.
    shutil.copytree(package, cached / "Library" / "PackageCache" / "com.siemens.ros-sharp@5d8bd3d")
    return bare, cached


def _applied(template: Path, manifest: str, folder: Path) -> bytes:
    project = folder / template.name
    shutil.copytree(template, project, symlinks=True)
    path = project / "robot.yaml"
    path.write_text(manifest)
    first = run_cli("apply", str(path))
    assert first.code == 0, f"{template.name}\n{manifest}{first.err}"
    check = run_cli("apply", "--check", str(path))
    assert check.code == 0, f"{template.name}\n{manifest}{check.out}{check.err}"
    again = run_cli("apply", str(path))
    assert again.code == 0 and again.out.endswith("wrote 0 files, removed 0\n"), (
        f"{template.name}\n{manifest}{again.out}"
    )
    return (project / SCENE).read_bytes()


@settings(
    max_examples=12,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
@given(manifest=manifests())
def test_any_entry_order_applies_and_a_library_changes_nothing(
    fresh: tuple[Path, Path], manifest: str
) -> None:
    bare, cached = fresh
    with tempfile.TemporaryDirectory() as folder:
        without = _applied(bare, manifest, Path(folder))
        with_cache = _applied(cached, manifest, Path(folder))
    assert without == with_cache, manifest
