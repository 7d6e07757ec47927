"""Changing an object's `primitive`: the new shape replaces what apply made for the old one (the
lock records it), and never touches a component the user declared or added by hand."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from helpers import run_cli

from unityscaffold.unity.scene import SceneDocument

HEADER = "version: 1\nros: 2\nproject: .\nscene: Assets/Scenes/Main.unity\n"
BOX = (
    "--- !u!65 &{id}\nBoxCollider:\n  m_ObjectHideFlags: 0\n"
    "  m_CorrespondingSourceObject: {{fileID: 0}}\n  m_PrefabInstance: {{fileID: 0}}\n"
    "  m_PrefabAsset: {{fileID: 0}}\n  m_GameObject: {{fileID: {go}}}\n"
    "  m_Material: {{fileID: 0}}\n"
    "  m_IncludeLayers:\n    serializedVersion: 2\n    m_Bits: 0\n  m_ExcludeLayers:\n"
    "    serializedVersion: 2\n    m_Bits: 0\n  m_LayerOverridePriority: 0\n  m_IsTrigger: 1\n"
    "  m_ProvidesContacts: 0\n  m_Enabled: 1\n  serializedVersion: 3\n"
    "  m_Size: {{x: 2, y: 2, z: 2}}\n  m_Center: {{x: 0, y: 0, z: 0}}\n"
)


@pytest.fixture
def project(tmp_path: Path) -> Path:
    assert run_cli("init", str(tmp_path / "p"), "--ros", "2").code == 0
    return tmp_path / "p"


def _apply(project: Path, body: str, *extra: str):
    (project / "robot.yaml").write_text(HEADER + body)
    return run_cli("apply", str(project / "robot.yaml"), *extra)


def _scene(project: Path) -> Path:
    return project / "Assets" / "Scenes" / "Main.unity"


def _components(project: Path, path: str) -> list[tuple[str, int, str]]:
    """(class, fileID, document text) of each component of ``path``, in m_Component order."""
    scene = SceneDocument.load(_scene(project))
    found = []
    for comp in scene.components_of(scene.find_gameobject(path)):
        doc = scene.document(comp.file_id)
        assert doc is not None
        found.append((comp.type_name, comp.file_id, doc.text))
    return found


def _add_by_hand(project: Path, path: str) -> int:
    """A trigger BoxCollider added to ``path`` in Unity (a fileID Unity would pick)."""
    scene = SceneDocument.load(_scene(project))
    go = scene.find_gameobject(path).file_id
    text = _scene(project).read_text()
    file_id = 1234567
    text = text.replace(
        f"--- !u!1 &{go}\nGameObject:\n",
        BOX.format(id=file_id, go=go) + f"--- !u!1 &{go}\nGameObject:\n",
    )
    last = text.index("  m_Layer:", text.index(f"--- !u!1 &{go}\n"))
    text = text[:last] + f"  - component: {{fileID: {file_id}}}\n" + text[last:]
    _scene(project).write_text(text)
    return file_id


def test_a_new_shape_replaces_the_old_shapes_collider(project):
    assert _apply(project, "objects:\n  - {path: Ball, primitive: cube}\n").code == 0
    before = {c: i for c, i, _ in _components(project, "Ball")}
    run = _apply(project, "objects:\n  - {path: Ball, primitive: sphere}\n")
    assert run.code == 0, run.err
    assert (
        "remove BoxCollider from Ball (its cube primitive made it; it is a sphere now)" in run.out
    )
    after = _components(project, "Ball")
    assert [c for c, _, _ in after] == ["Transform", "MeshFilter", "MeshRenderer", "SphereCollider"]
    # The MeshFilter and MeshRenderer are the same components, with the sphere's mesh.
    assert [i for _, i, _ in after[:3]] == [before[c] for c, _, _ in after[:3]]
    assert "m_Mesh: {fileID: 10207," in after[1][2]
    check = _apply(project, "objects:\n  - {path: Ball, primitive: sphere}\n", "--check")
    assert check.code == 0, check.out
    lock = json.loads((project / "robot.lock.json").read_text())
    made = lock["primitives"]["Assets/Scenes/Main.unity"]["Ball"]
    assert made == {"shape": "sphere", "file_ids": sorted(i for _, i, _ in after[1:])}


def test_a_plane_made_a_cube_loses_its_mesh_collider(project):
    assert _apply(project, "objects:\n  - {path: Floor, primitive: plane}\n").code == 0
    run = _apply(project, "objects:\n  - {path: Floor, primitive: cube}\n")
    assert run.code == 0, run.err
    classes = [c for c, _, _ in _components(project, "Floor")]
    assert classes == ["Transform", "MeshFilter", "MeshRenderer", "BoxCollider"]


def test_a_collider_both_shapes_make_stays_and_takes_the_new_shapes_values(project):
    assert _apply(project, "objects:\n  - {path: Pipe, primitive: cylinder}\n").code == 0
    (collider,) = [c for c in _components(project, "Pipe") if c[0] == "CapsuleCollider"]
    assert "m_Radius: 0.5000001" in collider[2]
    assert _apply(project, "objects:\n  - {path: Pipe, primitive: capsule}\n").code == 0
    (now,) = [c for c in _components(project, "Pipe") if c[0] == "CapsuleCollider"]
    assert now[1] == collider[1]
    assert "  m_Radius: 0.5\n" in now[2] and "  m_Center: {x: 0, y: 0, z: 0}\n" in now[2]


def test_a_collider_the_user_declared_or_added_by_hand_stays(project):
    body = (
        "objects:\n  - path: Ball\n    primitive: cube\n"
        "    components: [{type: BoxCollider, fields: {m_IsTrigger: true}}]\n"
        "  - {path: Crate, primitive: cube}\n"
    )
    assert _apply(project, body).code == 0
    by_hand = _add_by_hand(project, "Crate")
    run = _apply(project, body.replace("primitive: cube", "primitive: sphere"))
    assert run.code == 0, run.err
    # Ball's BoxCollider is declared under `components`: the user's.
    assert [c for c, _, _ in _components(project, "Ball")] == [
        "Transform", "MeshFilter", "MeshRenderer", "BoxCollider", "SphereCollider",
    ]  # fmt: skip
    # Crate's own BoxCollider goes; the one added in Unity stays.
    crate = _components(project, "Crate")
    assert [(c, i) for c, i, _ in crate if c == "BoxCollider"] == [("BoxCollider", by_hand)]
    assert [c for c, _, _ in crate][-1] == "SphereCollider"


def test_a_collider_found_on_the_object_before_its_primitive_stays_the_users(project):
    assert _apply(project, "objects:\n  - {path: Crate}\n").code == 0
    by_hand = _add_by_hand(project, "Crate")
    assert _apply(project, "objects:\n  - {path: Crate, primitive: cube}\n").code == 0
    assert [c for c, _, _ in _components(project, "Crate")].count("BoxCollider") == 1
    run = _apply(project, "objects:\n  - {path: Crate, primitive: sphere}\n")
    assert run.code == 0, run.err
    assert ("BoxCollider", by_hand) in [(c, i) for c, i, _ in _components(project, "Crate")]


def test_a_collider_no_lock_records_is_kept_with_a_note(project):
    # A cube made by an apply from before the lock recorded primitives.
    assert _apply(project, "objects:\n  - {path: Ball, primitive: cube}\n").code == 0
    lock = project / "robot.lock.json"
    data = json.loads(lock.read_text())
    del data["primitives"]
    lock.write_text(json.dumps(data, indent=2) + "\n")
    run = _apply(project, "objects:\n  - {path: Ball, primitive: sphere}\n")
    assert run.code == 0, run.err
    assert (
        "note: Ball keeps its BoxCollider beside the sphere's SphereCollider: no lock records "
        "that apply made it (remove it in Unity if an earlier primitive did)"
    ) in run.out
    classes = [c for c, _, _ in _components(project, "Ball")]
    assert classes == ["Transform", "MeshFilter", "MeshRenderer", "BoxCollider", "SphereCollider"]
    again = _apply(project, "objects:\n  - {path: Ball, primitive: sphere}\n")
    assert again.code == 0 and "note:" not in again.out, again.out
