"""Mesh geometries as ROS#'s importer places them: an instance of a model or prefab.

For a ``<mesh>`` visual ROS# instantiates the asset Unity made of the file; for a ``<mesh>``
collision it does the same, then on every object with a MeshFilter adds a MeshCollider on that
mesh (concave) and removes the MeshRenderer and the MeshFilter. A scene records that as a
``PrefabInstance`` with changes (``unity.prefabinstance``). The asset is:

- for an STL file, the prefab ROS#'s STL post-processor would save (``unity.stlprefab``), made
  here with its Mesh assets (``urdf.stl``): the ``.stl`` itself is not copied, so Unity never
  runs that post-processor over these files;
- for a COLLADA file, the model Unity imports from the copied ``.dae`` (with the ``.meta`` of
  ``unity.importers``, and the textures its images name, ``urdf.textures``), whose objects
  have the fileIDs of ``unity.modelids``;
- for a Wavefront OBJ file, the model Unity imports from the copied ``.obj`` with its default
  settings, its root where Unity leaves it (``urdf.objmodel``).

``_FORMATS`` maps each file suffix to its format's builder; any other suffix is a located
error with the reason ROS# and Unity give it (``urdf._unimported``).

A visual's ``<material>`` is put on every renderer of the instance, as ROS#'s
``UrdfMaterial.SetMaterial`` does by setting ``sharedMaterial``: Unity records that as a change
of each renderer's first material slot to the robot's ``Materials/<name>.mat``
(``unity.prefabinstance.material_modifications``; the file's name is ``urdf.materials``'),
kept among the instance's other changes in Unity's order. Without one the model keeps its own
materials. A textured ``<material>`` is one such ``.mat``, like any other.

A COLLADA model's root is posed as Unity imports it and ROS#'s post-processor turns it, and
its inner objects have the fileIDs of the model's node tree (``urdf.colladamodel``, which says
what rests on Unity-written files and what is inferred). A collision on a model adds a
MeshCollider to each node that draws, and a ``<material>`` goes on each node's renderer.

The rest is a located error saying why: other formats (``.fbx``: a root pose no saved scene
shows; ``.gltf``, ``.glb``: no importer without a package ROS# does not use), a collision or
``<material>`` on an OBJ model or on a COLLADA model with a node of several geometries or a
drawn node below one without name or id (which objects Unity makes of them is not checked),
and textures Unity imports with another importer than its TextureImporter
(``urdf.textures``). A textured ``<material>`` is one more ``.mat`` (``urdf.materials``).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

from unityscaffold.errors import DiagnosticSink, SourceLocation
from unityscaffold.unity.importers import model_meta
from unityscaffold.unity.material import MATERIAL_FILE_ID
from unityscaffold.unity.mesh import MESH_FILE_ID
from unityscaffold.unity.modelids import ROOT_PATH, model_file_id
from unityscaffold.unity.prefabinstance import (
    AddedMeshCollider,
    AssetObject,
    ModelInstance,
    material_modifications,
    root_modifications,
)
from unityscaffold.unity.stlprefab import StlPrefab, prefab_meta, stl_prefab, stl_prefab_text
from unityscaffold.urdf import transforms as t
from unityscaffold.urdf._assets import GuidOf, PlannedAsset
from unityscaffold.urdf._components import MaterialRef, material_name
from unityscaffold.urdf._creation import creation_turns, local_position, saved_rotation
from unityscaffold.urdf._material_names import material_stems
from unityscaffold.urdf._packages import ResolvedMesh
from unityscaffold.urdf._unimported import refusal
from unityscaffold.urdf.collada import ColladaFacts, read_collada
from unityscaffold.urdf.colladamodel import (
    DrawnNode,
    drawn_nodes,
    imported_root_pose,
    unchecked_objects,
)
from unityscaffold.urdf.model import Material, Mesh, Robot, Visual
from unityscaffold.urdf.objmodel import UNCHECKED_OBJECTS, CopiedModel, obj_instance
from unityscaffold.urdf.textures import model_textures

__all__ = ["ModelAsset", "ModelPlan", "model_plan"]

_ROOT_GAMEOBJECT = model_file_id("GameObject", ROOT_PATH)
_ROOT_TRANSFORM = model_file_id("Transform", ROOT_PATH)
_TYPE_MODEL, _TYPE_NATIVE = 3, 2
_ONE_PER_NODE = "export the model with one geometry per node, each node named"
_CONVERT = "convert the mesh to STL or COLLADA (.dae)"


@dataclass(frozen=True, slots=True)
class ModelAsset:
    """A file the import puts into the robot's asset folder at ``path`` besides the text
    assets: the STL prefab (rendered once the GUIDs of its ``meshes`` are known), or a copy of
    the model ``source`` (imported at ``global_scale``)."""

    path: str
    source: Path | None = None
    prefab: StlPrefab | None = None
    meshes: tuple[str, ...] = ()
    global_scale: float | None = None

    def content(self, guid_of: GuidOf) -> bytes:
        """The file's bytes; ``guid_of`` gives the GUID of a path in the robot's folder."""
        if self.prefab is not None:
            return stl_prefab_text(self.prefab, [guid_of(m) for m in self.meshes]).encode()
        assert self.source is not None
        return self.source.read_bytes()

    def meta(self, guid: str) -> str:
        """The text of the file's ``.meta`` with ``guid``."""
        if self.prefab is not None:
            return prefab_meta(guid)
        assert self.global_scale is not None
        return model_meta(guid, self.global_scale)


@dataclass(frozen=True, slots=True)
class ModelPlan:
    """``instances``: the instance each mesh visual's and collision's geometry object is, by
    the object's key (``link[2]/collision[0]/shape``); ``assets``: the files they need."""

    instances: Mapping[str, ModelInstance]
    assets: tuple[PlannedAsset, ...]


def model_plan(
    robot: Robot,
    meshes: Mapping[str, ResolvedMesh],
    stl_meshes: Mapping[ResolvedMesh, int],
) -> ModelPlan:
    """The instances and files for every ``<mesh>`` of ``robot``; ``meshes`` resolves each
    filename, ``stl_meshes`` says into how many Mesh assets each STL file was cut. Every
    geometry that cannot be made as checked is one located error."""
    sink = DiagnosticSink()
    builder = _Builder(sink, stl_meshes, material_stems(robot))
    turns = creation_turns(robot)
    instances: dict[str, ModelInstance] = {}
    for key, link, mesh, visual in _mesh_parts(robot):
        resolved = meshes[mesh.filename]
        instance = builder.instance(mesh, resolved, turns[link], collision=visual is None)
        if instance is not None and visual is not None and visual.material is not None:
            instance = builder.painted(instance, mesh, resolved, visual.material)
        if instance is not None:
            instances[key] = instance
    sink.raise_if_errors()
    return ModelPlan(instances, tuple(sorted(builder.assets.values(), key=lambda a: a.path)))


def _mesh_parts(robot: Robot) -> Iterator[tuple[str, str, Mesh, Visual | None]]:
    """``(key, link name, mesh, visual or None for a collision)`` of every mesh geometry."""
    for i, link in enumerate(robot.links):
        for j, visual in enumerate(link.visuals):
            if isinstance(visual.geometry, Mesh):
                yield f"link[{i}]/visual[{j}]/shape", link.name, visual.geometry, visual
        for j, collision in enumerate(link.collisions):
            if isinstance(collision.geometry, Mesh):
                yield f"link[{i}]/collision[{j}]/shape", link.name, collision.geometry, None


class _Builder:
    """Makes each instance, and each asset once."""

    def __init__(
        self,
        sink: DiagnosticSink,
        stl_meshes: Mapping[ResolvedMesh, int],
        material_stems: Mapping[str, str],
    ) -> None:
        self.sink = sink
        self.stl_meshes = stl_meshes
        self.material_stems = material_stems  # each material's .mat file name
        self.assets: dict[str, ModelAsset | PlannedAsset] = {}
        self.collada: dict[Path, ColladaFacts] = {}
        self.made: dict[tuple[ResolvedMesh, bool, t.Quaternion], ModelInstance | None] = {}
        # each asset path in lower case, with the mesh that first wrote there
        self.claimed: dict[str, tuple[ResolvedMesh, Mesh]] = {}
        # (mesh file, use) whose model was refused already: one error per model and use
        self.reported: set[tuple[str, str]] = set()

    def instance(
        self, mesh: Mesh, resolved: ResolvedMesh, turned: t.Quaternion, *, collision: bool
    ) -> ModelInstance | None:
        """The instance for ``mesh``, whose parent is turned by ``turned`` as ROS# makes it;
        one per file, kind and turn (links share meshes)."""
        key = (resolved, collision, turned)
        if key not in self.made:
            self.made[key] = self._made(mesh, resolved, turned, collision=collision)
        return self.made[key]

    def _made(
        self, mesh: Mesh, resolved: ResolvedMesh, turned: t.Quaternion, *, collision: bool
    ) -> ModelInstance | None:
        suffix = resolved.relative.suffix.lower()
        make = _FORMATS.get(suffix)
        if make is not None:
            return make(self, mesh, resolved, turned, collision)
        reason, hint = refusal(suffix)
        self.sink.error(mesh.location, f"mesh {mesh.filename!r}: {reason}", hint=hint)
        return None

    def _stl(
        self, mesh: Mesh, resolved: ResolvedMesh, turned: t.Quaternion, collision: bool
    ) -> ModelInstance | None:
        stem = PurePosixPath(resolved.package) / resolved.relative.with_suffix("")
        if not self._claim(f"{stem}.prefab", resolved, mesh):
            return None
        return self._stl_instance(resolved, collision=collision)

    def _collada(
        self, mesh: Mesh, resolved: ResolvedMesh, turned: t.Quaternion, collision: bool
    ) -> ModelInstance | None:
        path = PurePosixPath(resolved.package) / resolved.relative
        if not self._claim(str(path), resolved, mesh):
            return None
        return self._collada_instance(mesh, resolved, turned, collision=collision)

    def _obj(
        self, mesh: Mesh, resolved: ResolvedMesh, turned: t.Quaternion, collision: bool
    ) -> ModelInstance | None:
        path = str(PurePosixPath(resolved.package) / resolved.relative)
        if not self._claim(path, resolved, mesh):
            return None
        if collision:
            self._unchecked(mesh, mesh.location, "collision", UNCHECKED_OBJECTS, _CONVERT)
            return None
        self.assets.setdefault(path, CopiedModel(path, resolved.path))
        return obj_instance(path, resolved)

    def _claim(self, path: str, resolved: ResolvedMesh, mesh: Mesh) -> bool:
        """Whether ``path`` is this mesh file's alone, ignoring case: Windows and macOS, where
        Unity users open the project, would make one file of ``arm.prefab`` and
        ``Arm.prefab`` (and of ``arm.STL``'s and ``arm.stl``'s, the same path here)."""
        first, where = self.claimed.setdefault(path.lower(), (resolved, mesh))
        if first == resolved:
            return True
        self.sink.error(
            mesh.location,
            f"mesh {mesh.filename!r} would be written as {path}, which on a case-insensitive "
            f"file system (Windows, macOS) is the file of mesh {where.filename!r} (line "
            f"{where.location.line}): their names differ only by case",
            hint="rename one of the two mesh files (and its <mesh filename>) so that their "
            "names differ by more than case",
        )
        return False

    def painted(
        self, instance: ModelInstance, mesh: Mesh, resolved: ResolvedMesh, material: Material
    ) -> ModelInstance | None:
        """A visual's instance with its URDF material on every renderer of the model, as
        ROS#'s ``UrdfMaterial.SetMaterial`` sets ``sharedMaterial`` on each: a renderer's
        first slot (``Renderer.sharedMaterial`` is its first material)."""
        made = self.assets[instance.source]  # an STL's prefab or the model, with its instance
        if isinstance(made, CopiedModel):
            self._unchecked(mesh, material.location, "<material>", UNCHECKED_OBJECTS, _CONVERT)
            return None
        prefab = made.prefab if isinstance(made, ModelAsset) else None
        if prefab is not None:
            renderers = tuple(part.renderer for part in prefab.parts)
        else:
            facts = self._facts(resolved.path)
            drawn = self._drawn(mesh, facts, material.location, "<material>")
            if drawn is None:
                return None
            renderers = tuple(node.renderer for node in drawn)
        ref = MaterialRef(self.material_stems[material_name(material)])
        mat = AssetObject(ref.path, MATERIAL_FILE_ID, _TYPE_NATIVE)
        return instance.with_changes(material_modifications(renderers, mat))

    def _stl_instance(self, resolved: ResolvedMesh, *, collision: bool) -> ModelInstance:
        folder = PurePosixPath(resolved.package) / resolved.relative.parent
        stem = resolved.relative.stem
        count = self.stl_meshes[resolved]
        prefab = stl_prefab(stem, count)
        path = str(folder / f"{stem}.prefab")
        assets = tuple(str(folder / f"{part.name}.asset") for part in prefab.parts)
        self.assets.setdefault(path, ModelAsset(path, prefab=prefab, meshes=assets))
        changes = root_modifications(
            prefab.transform, prefab.gameobject, stem, (0.0, 0.0, 0.0), t.ALIGNED
        )
        if not collision:
            return ModelInstance(path, _TYPE_MODEL, prefab.transform, changes)
        removed = tuple(i for part in prefab.parts for i in (part.renderer, part.filter))
        added = tuple(
            AddedMeshCollider(part.gameobject, AssetObject(asset, MESH_FILE_ID, _TYPE_NATIVE))
            for part, asset in zip(prefab.parts, assets, strict=True)
        )
        return ModelInstance(path, _TYPE_MODEL, prefab.transform, changes, removed, added)

    def _collada_instance(
        self, mesh: Mesh, resolved: ResolvedMesh, turned: t.Quaternion, *, collision: bool
    ) -> ModelInstance | None:
        facts = self._facts(resolved.path)
        if len(facts.nodes) == 1 and any(math.isnan(v) for v in facts.nodes[0].matrix):
            # the one top node is the model's root, whose pose the scene holds
            self.sink.error(
                facts.nodes[0].location,
                f"model {mesh.filename!r}: its top node's transform is not numbers",
                hint="each <matrix>, <translate>, <rotate>, <scale> and <lookat> holds only "
                "decimal numbers, as many as COLLADA says",
            )
            return None
        path = str(PurePosixPath(resolved.package) / resolved.relative)
        self.assets.setdefault(path, ModelAsset(path, resolved.path, global_scale=facts.meter))
        self._textures(mesh, resolved, facts)
        position, rotation = imported_root_pose(facts)
        changes = root_modifications(
            _ROOT_TRANSFORM,
            _ROOT_GAMEOBJECT,
            resolved.relative.stem,
            local_position(position, turned),
            saved_rotation(rotation),
        )
        if not collision:
            return ModelInstance(path, _TYPE_MODEL, _ROOT_TRANSFORM, changes)
        drawn = self._drawn(mesh, facts, mesh.location, "collision")
        if drawn is None:
            return None
        # ROS#'s ConvertMeshToColliders: on every object with a MeshFilter a MeshCollider on
        # its mesh, then the renderer and the filter destroyed, object by object
        removed = tuple(i for node in drawn for i in (node.renderer, node.filter))
        added = tuple(
            AddedMeshCollider(node.gameobject, AssetObject(path, node.mesh, _TYPE_MODEL))
            for node in drawn
        )
        return ModelInstance(path, _TYPE_MODEL, _ROOT_TRANSFORM, changes, removed, added)

    def _facts(self, path: Path) -> ColladaFacts:
        if path not in self.collada:
            self.collada[path] = read_collada(path)
        return self.collada[path]

    def _drawn(
        self, mesh: Mesh, facts: ColladaFacts, where: SourceLocation, use: str
    ) -> tuple[DrawnNode, ...] | None:
        """The model's drawn nodes, when each one's objects follow from a checked rule; else
        None after saying why (once per model and use)."""
        drawn = drawn_nodes(facts)
        problem = unchecked_objects(drawn)
        if problem is None:
            return drawn
        self._unchecked(mesh, where, use, problem)
        return None

    def _unchecked(
        self, mesh: Mesh, where: SourceLocation, use: str, problem: str, hint: str = _ONE_PER_NODE
    ) -> None:
        """Say, once per model and use, why the model cannot take ``use``."""
        key = (mesh.filename, use)
        if key in self.reported:
            return
        self.reported.add(key)
        self.sink.error(
            where,
            f"model {mesh.filename!r} cannot take a {use} as ROS# makes it: {problem}",
            hint=hint,
        )

    def _textures(self, mesh: Mesh, resolved: ResolvedMesh, facts: ColladaFacts) -> None:
        for texture in model_textures(mesh, resolved, facts.images, self.sink):
            self.assets.setdefault(texture.path, texture)


# How each mesh format's instance is made; any other suffix is refused (``urdf._unimported``).
_FORMATS: dict[
    str, Callable[[_Builder, Mesh, ResolvedMesh, t.Quaternion, bool], ModelInstance | None]
] = {
    ".stl": _Builder._stl,
    ".dae": _Builder._collada,
    ".obj": _Builder._obj,
}
