"""A robot with a Wavefront OBJ visual applies as ROS#'s importer makes it: the ``.obj`` copied
into the robot's folder with the default ``.meta`` (``unity.importers.default_model_meta``), the
visual's geometry object an instance of it (``urdf.objmodel``); a second apply writes nothing
and ``--check`` is clean."""

from __future__ import annotations

from pathlib import Path

from robot_helpers import (
    HEADER,
    apply,
    apply_writes_nothing,
    inertial,
    init_project,
    meta_guid,
    prefab_instances,
)

OBJ = "o arm\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
URDF = f"""<robot name="bot">
  <link name="base">{inertial()}
    <visual><geometry><mesh filename="package://desc/meshes/arm.obj"/></geometry></visual>
  </link>
</robot>
"""


def test_a_robot_with_an_obj_visual_applies_once_and_then_writes_nothing(tmp_path: Path) -> None:
    project = init_project(
        tmp_path,
        {
            "ros/bot.urdf": URDF,
            "ros/desc/meshes/arm.obj": OBJ,
            "robot.yaml": HEADER + "    packages: {desc: ros/desc}\n",
        },
    )
    run = apply(project)
    assert run.code == 0, run.out + run.err
    copied = project / "Assets/Urdf/bot/desc/meshes/arm.obj"
    assert copied.read_text() == OBJ
    meta = Path(f"{copied}.meta").read_text()
    assert "ModelImporter:" in meta and "  animationType: 2\n" in meta
    ((parent, instance),) = prefab_instances(project)
    assert parent == "bot/base/Visuals/unnamed"
    # the model's own prefab (Unity's fileID 100100000 for a model) by the copied file's GUID
    guid = meta_guid(Path(f"{copied}.meta"))
    assert f"m_SourcePrefab: {{fileID: 100100000, guid: {guid}, type: 3}}" in instance
    assert "propertyPath: m_Name\n      value: arm\n" in instance
    apply_writes_nothing(project)
    assert apply(project, "--check").code == 0
