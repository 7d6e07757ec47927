"""Benchmark: mesh geometries through the urdf stage, for r2d2 and a robot of STL meshes.

``r2d2``: ROS#'s sample robot (two COLLADA models, each a visual and a collision on four
links), read from the vendored sample beside the repository (``../shared/vendor`` or
``UNITYSCAFFOLD_VENDOR``). ``stl``: a generated chain of links, each with an STL visual and an
STL collision, the STL files shared by groups of links as real robots share them (``--meshes``
files of ``--facets`` facets each). Prints the CPU time of ``import_robot`` (reading, the Mesh
assets, the instances) and of laying out what the writer then writes: every prefab and model
file with its ``.meta``, and every instance's scene documents.

    python3 bench/bench_models.py [--links 500] [--meshes 50] [--facets 2000]
"""

from __future__ import annotations

import argparse
import os
import struct
import tempfile
import time
from pathlib import Path

from unityscaffold.unity.prefabinstance import instance_documents
from unityscaffold.urdf import RobotImport, import_robot

VENDOR = Path(
    os.environ.get("UNITYSCAFFOLD_VENDOR", Path(__file__).resolve().parents[2] / "shared/vendor")
)
R2D2 = VENDOR / "ros-sharp/samples/gazebo-ros2-step1"
GUID = "0123456789abcdef0123456789abcdef"


def stl(path: Path, facets: int) -> None:
    """A binary STL of ``facets`` small triangles along a line."""
    body = b"".join(
        struct.pack("<12fH", 0, 0, 1, i, 0, 0, i + 1, 0, 0, i, 1, 0, 0) for i in range(facets)
    )
    path.write_bytes(b"bench".ljust(80, b" ") + struct.pack("<I", facets) + body)


def stl_robot(folder: Path, links: int, meshes: int, facets: int) -> Path:
    (folder / "desc" / "meshes").mkdir(parents=True)
    for i in range(meshes):
        stl(folder / "desc" / "meshes" / f"part{i}.stl", facets)
    parts = ['<robot name="chain">']
    for i in range(links):
        mesh = f'<mesh filename="package://desc/meshes/part{i % meshes}.stl"/>'
        parts.append(
            f'<link name="l{i}"><visual><geometry>{mesh}</geometry></visual>'
            f"<collision><geometry>{mesh}</geometry></collision></link>"
        )
        if i:
            parts.append(
                f'<joint name="j{i}" type="fixed"><parent link="l{i - 1}"/>'
                f'<child link="l{i}"/></joint>'
            )
    urdf = folder / "chain.urdf"
    urdf.write_text("\n".join([*parts, "</robot>"]), encoding="utf-8")
    return urdf


def lay_out(result: RobotImport) -> int:
    """Everything the writer would write for the models; returns the bytes laid out."""
    size = 0
    for asset in result.model_assets:
        size += len(asset.content(lambda _: GUID)) + len(asset.meta(GUID))
    for instance in result.models.values():
        ids = {role: 1000 + i for i, role in enumerate(instance.scene_roles())}
        documents = instance_documents(instance, parent=1, ids=ids, guid_of=lambda _: GUID)
        size += sum(len(text) for _, text in documents)
    return size


def measure(name: str, urdf: Path, packages: dict[str, Path], project: Path) -> None:
    start = time.process_time()
    result = import_robot(urdf, packages=packages, project=project)
    imported = time.process_time() - start
    start = time.process_time()
    size = lay_out(result)
    laid = time.process_time() - start
    print(
        f"{name:>6} {len(result.models):>9} {len(result.model_assets) + len(result.files):>7}"
        f" {size:>10} {imported:>8.3f} {laid:>8.3f}"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--links", type=int, default=500)
    parser.add_argument("--meshes", type=int, default=50)
    parser.add_argument("--facets", type=int, default=2000)
    options = parser.parse_args()
    print(f"{'robot':>6} {'instances':>9} {'assets':>7} {'bytes':>10} {'import s':>8} {'lay s':>8}")
    if (R2D2 / "custom_r2d2.urdf").is_file():
        meshes = {"urdf_tutorial": R2D2 / "Urdf/file_server2/urdf_tutorial"}
        measure("r2d2", R2D2 / "custom_r2d2.urdf", meshes, R2D2)
    else:
        print(f"  r2d2: not found under {R2D2}")
    with tempfile.TemporaryDirectory() as folder:
        urdf = stl_robot(Path(folder), options.links, options.meshes, options.facets)
        measure("stl", urdf, {}, Path(folder))


if __name__ == "__main__":
    main()
