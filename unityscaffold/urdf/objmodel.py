"""The model Unity imports from a Wavefront OBJ file, as far as ROS#'s instance of it shows.

ROS# makes no asset of its own for an ``.obj``: its importer loads the model Unity imported
(``LocateAssetHandler.FindUrdfAsset<GameObject>`` on the file's own path, which
``UrdfAssetPathHandler`` changes only for ``.stl``) and instantiates it, and its
``ColladaAssetPostProcessor`` returns at once for anything but a ``.dae``. So:

- **Root pose.** Unity's own. An OBJ file has no node transforms and no axis system: Unity
  reads it Y up (its FBX SDK importer) and mirrors x into its left-handed axes, which leaves
  every transform as it was, so the model's root is at the origin, unturned (Unity's manual,
  "Model file formats" and the Model Import Settings' ``bakeAxisConversion``, which only bakes
  a file's axis conversion). ROS#'s ``SetParentAndAlign`` keeps that pose, as for an STL
  prefab: the instance root's position is 0 and its rotation the identity with the negative
  zeros re-parenting leaves (``transforms.ALIGNED``). Inferred from those rules: no Unity-
  written scene holding an ``.obj`` instance made by ROS# is at hand.
- **File.** Only the ``.obj`` is copied, as ROS#'s ``UrdfTransferFromRos`` fetches a
  ``<mesh>``'s file and only a ``.dae``'s images besides it (not an ``.obj``'s ``mtllib``):
  Unity imports it with its default material. Its ``.meta`` is the default one
  (``unity.importers.default_model_meta``).
- **Objects inside.** Which GameObjects Unity makes of an OBJ's objects and groups (``o``,
  ``g``; a file without either), and so the fileIDs of their renderers and meshes, is not shown
  by any Unity-written file at hand: a collision (whose MeshColliders name them) or a
  ``<material>`` (set on each renderer) on an OBJ model is refused with that reason
  (``UNCHECKED_OBJECTS``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from unityscaffold.unity.importers import default_model_meta
from unityscaffold.unity.modelids import ROOT_PATH, model_file_id
from unityscaffold.unity.prefabinstance import ModelInstance, root_modifications
from unityscaffold.urdf import transforms as t
from unityscaffold.urdf._assets import GuidOf
from unityscaffold.urdf._packages import ResolvedMesh

__all__ = ["UNCHECKED_OBJECTS", "CopiedModel", "obj_instance"]

_ROOT_GAMEOBJECT = model_file_id("GameObject", ROOT_PATH)
_ROOT_TRANSFORM = model_file_id("Transform", ROOT_PATH)
_TYPE_MODEL = 3

#: Why a collision or ``<material>`` on an OBJ model is refused.
UNCHECKED_OBJECTS = (
    "which objects Unity makes of an OBJ file's objects and groups (and so the fileIDs of the "
    "renderers and meshes ROS# changes) is not checked against a Unity-written file"
)


@dataclass(frozen=True, slots=True)
class CopiedModel:
    """A model file copied as it is to ``path`` in the robot's asset folder, which Unity
    imports with its default settings."""

    path: str
    source: Path

    def content(self, guid_of: GuidOf) -> bytes:
        """The file's bytes (it names no other asset, so ``guid_of`` is not asked)."""
        return self.source.read_bytes()

    def meta(self, guid: str) -> str:
        """The text of the file's ``.meta`` with ``guid``."""
        return default_model_meta(guid)


def obj_instance(path: str, resolved: ResolvedMesh) -> ModelInstance:
    """The instance ROS# makes of the OBJ model at ``path``: its root named after the file
    (``InstantiatePrefab`` names it after the model), at the origin, unturned."""
    changes = root_modifications(
        _ROOT_TRANSFORM,
        _ROOT_GAMEOBJECT,
        resolved.relative.stem,
        (0.0, 0.0, 0.0),
        t.ALIGNED,
    )
    return ModelInstance(path, _TYPE_MODEL, _ROOT_TRANSFORM, changes)
