"""A Wavefront OBJ mesh as ROS#'s importer makes it: an instance of the model Unity imports.

Where the values come from:
- ROS# 2.2.1 ``Editor/Urdf``: ``UrdfGeometryVisual.CreateMeshVisual`` instantiates the model
  at the mesh's path (``UrdfAssetPathHandler`` renames only ``.stl``), its
  ``ColladaAssetPostProcessor`` returns for all but ``.dae``, and ``SetParentAndAlign`` keeps
  the root's pose; ``UrdfTransferFromRos`` copies a mesh's file alone (a ``.dae``'s images
  besides, never an ``.mtl``).
- The root's fileIDs: Unity's model rule (``unity.modelids``), the values the r2d2 scene holds
  for its models' roots (Transform ``-8679921383154817045``, GameObject ``919132149155446097``).
- The root's pose: an OBJ file has no transforms and no axis system, and Unity only mirrors x
  (its manual's model import rules): position 0, identity, saved with the ``-0`` of
  re-parenting (``urdf.transforms.ALIGNED``, as the r2d2 scene's STL-free roots show).
- The ``.meta``: the 2022.3 ``ModelImporter`` layout of the r2d2 sample's ``.dae.meta``, with
  Unity's defaults for the four settings ROS#'s post-processor sets on a ``.dae`` only
  (``globalScale: 1``, ``importCameras: 1``, ``importLights: 1``, ``animationType: 2``), as
  in the 2022.3 ``.obj.meta`` of a default import in github.com/Unity-Technologies/ml-agents at
  d7b7509c, ``Project/Assets/3D-FUTURE-model/01fdf241-67bb-482c-844c-61e261b8d484/
  normalized_model.obj.meta`` (the same settings, every one; it lacks the two empty
  ``rigImport…`` lines of the r2d2 layout, which is kept).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError
from unityscaffold.urdf import import_robot

OBJ = "o arm\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
ROOT_TRANSFORM, ROOT_GAMEOBJECT = -8679921383154817045, 919132149155446097


def obj_robot(tmp_path: Path, part: str, *, inner: str = "", origin: str = "") -> Path:
    """A robot whose second link, under a joint turned 90° about z, has ``part`` of desc/arm.obj."""
    (tmp_path / "desc").mkdir(exist_ok=True)
    (tmp_path / "desc" / "arm.obj").write_text(OBJ, encoding="utf-8")
    urdf = tmp_path / "r.urdf"
    urdf.write_text(
        '<robot name="r"><link name="a"/>\n'
        f'<joint name="j" type="fixed"><parent link="a"/><child link="b"/>{origin}</joint>\n'
        f'<link name="b"><{part}><geometry>\n'
        f'   <mesh filename="package://desc/arm.obj"/></geometry>{inner}</{part}></link></robot>',
        encoding="utf-8",
    )
    return urdf


@pytest.mark.parametrize("origin", ["", '<origin xyz="1 2 3" rpy="0 0 1.5707963"/>'])
def test_an_obj_visual_is_an_instance_of_the_copied_file_at_the_origin_unturned(
    tmp_path: Path, origin: str
) -> None:
    """However the link is turned, ROS# leaves the root as Unity imported it."""
    result = import_robot(
        obj_robot(tmp_path, "visual", origin=origin), packages={}, project=tmp_path
    )
    instance = result.models["link[1]/visual[0]/shape"]
    assert (instance.source, instance.source_type, instance.root_transform) == (
        "desc/arm.obj",
        3,
        ROOT_TRANSFORM,
    )
    assert [(m.target, m.property_path, m.value) for m in instance.modifications] == [
        (ROOT_TRANSFORM, "m_LocalPosition.x", "0"),
        (ROOT_TRANSFORM, "m_LocalPosition.y", "0"),
        (ROOT_TRANSFORM, "m_LocalPosition.z", "0"),
        (ROOT_TRANSFORM, "m_LocalRotation.w", "1"),
        (ROOT_TRANSFORM, "m_LocalRotation.x", "-0"),
        (ROOT_TRANSFORM, "m_LocalRotation.y", "-0"),
        (ROOT_TRANSFORM, "m_LocalRotation.z", "-0"),
        (ROOT_TRANSFORM, "m_LocalEulerAnglesHint.x", "0"),
        (ROOT_TRANSFORM, "m_LocalEulerAnglesHint.y", "0"),
        (ROOT_TRANSFORM, "m_LocalEulerAnglesHint.z", "0"),
        (ROOT_GAMEOBJECT, "m_Name", "arm"),
    ]
    assert instance.removed == () and instance.added == ()


def test_an_obj_model_is_copied_alone_with_the_meta_unity_writes_by_default(
    tmp_path: Path, r2d2_urdf: Path
) -> None:
    (tmp_path / "desc").mkdir()
    (tmp_path / "desc" / "arm.mtl").write_text("newmtl red\nKd 1 0 0\n", encoding="utf-8")
    result = import_robot(obj_robot(tmp_path, "visual"), packages={}, project=tmp_path)
    (model,) = result.model_assets
    assert model.path == "desc/arm.obj"
    assert model.content(lambda _: "") == OBJ.encode()
    sample = r2d2_urdf.parent / "Urdf/file_server2/urdf_tutorial/meshes/l_finger.dae.meta"
    guid = "15265ff30491d0e4c83378cfb1d1583d"  # the sample's, so only the settings differ
    expected = (
        sample.read_text(encoding="utf-8")
        .replace("    importCameras: 0\n", "    importCameras: 1\n")
        .replace("    importLights: 0\n", "    importLights: 1\n")
        .replace("  animationType: 0\n", "  animationType: 2\n")
    )
    assert "    globalScale: 1\n" in expected  # the sample's unit is the metre: ROS#'s scale 1
    assert model.meta(guid) == expected


@pytest.mark.parametrize(
    ("part", "inner", "column", "use"),
    [
        ("collision", "", "4", "collision"),
        ("visual", '<material name="red"><color rgba="1 0 0 1"/></material>', "56", "<material>"),
    ],
)
def test_a_collision_or_material_on_an_obj_model_is_refused_for_its_unchecked_objects(
    tmp_path: Path, part: str, inner: str, column: str, use: str
) -> None:
    """Both change objects inside the model, whose fileIDs no Unity-written file shows."""
    urdf = obj_robot(tmp_path, part, inner=inner)
    with pytest.raises(LocatedError) as caught:
        import_robot(urdf, packages={}, project=tmp_path)
    message = caught.value.render()
    assert message.startswith(
        f"{urdf}:4:{column}: error: model 'package://desc/arm.obj' cannot take a {use} as "
        "ROS# makes it: which objects Unity makes of an OBJ file's objects and groups"
    ), message
    assert "hint: convert the mesh to STL or COLLADA (.dae)" in message
