"""Mesh geometries as ROS#'s importer places them: an instance of a model or prefab.

For a ``<mesh>`` visual ROS# instantiates the asset Unity made of the file; for a ``<mesh>``
collision it does the same, then on every object with a MeshFilter adds a MeshCollider on that
mesh (concave) and removes the MeshRenderer and the MeshFilter. A scene records that as a
``PrefabInstance`` with changes (``unity.prefabinstance``). The asset is:

- for an STL file, the prefab ROS#'s STL post-processor would save (``unity.stlprefab``), made
  here with its Mesh assets (``urdf.stl``): the ``.stl`` itself is not copied, so Unity never
  runs that post-processor over these files;
- for a COLLADA file, the model Unity imports from the copied ``.dae`` (with the ``.meta`` of
  ``unity.importers``, and the PNG textures its images name), whose objects have the fileIDs
  of ``unity.modelids``.

A visual's ``<material>`` is put on every renderer of the instance, as ROS#'s
``UrdfMaterial.SetMaterial`` does by setting ``sharedMaterial``: Unity records that as a change
of each renderer's first material slot to the robot's ``Materials/<name>.mat``
(``unity.prefabinstance.material_modifications``), kept among the instance's other changes in
Unity's order. Without one the model keeps its own materials.

Only what Unity-written files show is made; the rest is a located error saying why:
other formats (``.obj``, ``.fbx``: Unity's own import, no saved scene to check), models not
``Y_UP`` (ROS# turns their root otherwise), a single top node that is moved (folded into the
root), collisions with a model of several nodes or geometries (the colliders' targets are not
checked), other texture formats, and a ``<material>`` on a COLLADA visual unless the model is one
node drawn in one part (the renderers of other nodes are not checked, nor which slots of a
renderer with several ``sharedMaterial`` replaces). A textured ``<material>`` is refused for
every visual (``urdf.materials``).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

from unityscaffold.errors import DiagnosticSink
from unityscaffold.unity.importers import model_meta, texture_meta
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
from unityscaffold.urdf._components import MaterialRef, material_name
from unityscaffold.urdf._packages import ResolvedMesh
from unityscaffold.urdf.collada import ColladaFacts, read_collada
from unityscaffold.urdf.model import Material, Mesh, Robot, Visual

__all__ = ["COLLADA_Y_UP_ROTATION", "ModelAsset", "ModelPlan", "model_plan"]

#: The model root's turn ROS#'s post-processor gives a Y_UP COLLADA file: Euler(-90, 90, 0).
COLLADA_Y_UP_ROTATION: t.Quaternion = (-0.5, 0.5, 0.5, 0.5)
_ROOT_GAMEOBJECT = model_file_id("GameObject", ROOT_PATH)
_ROOT_TRANSFORM = model_file_id("Transform", ROOT_PATH)
_ROOT_FILTER = model_file_id("MeshFilter", ROOT_PATH)
_ROOT_RENDERER = model_file_id("MeshRenderer", ROOT_PATH)
_PLAIN_NAME = re.compile(r"[A-Za-z0-9_]+")
_TYPE_MODEL, _TYPE_NATIVE = 3, 2

GuidOf = Callable[[str], str]


@dataclass(frozen=True, slots=True)
class ModelAsset:
    """A file the import puts into the robot's asset folder at ``path`` besides the text
    assets: the STL prefab (rendered once the GUIDs of its ``meshes`` are known), or a copy of
    ``source`` (a model when ``global_scale`` is set, else a texture)."""

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
        if self.global_scale is not None:
            return model_meta(guid, self.global_scale)
        return texture_meta(guid)


@dataclass(frozen=True, slots=True)
class ModelPlan:
    """``instances``: the instance each mesh visual's and collision's geometry object is, by
    the object's key (``link[2]/collision[0]/shape``); ``assets``: the files they need."""

    instances: Mapping[str, ModelInstance]
    assets: tuple[ModelAsset, ...]


def model_plan(
    robot: Robot,
    meshes: Mapping[str, ResolvedMesh],
    stl_meshes: Mapping[ResolvedMesh, int],
) -> ModelPlan:
    """The instances and files for every ``<mesh>`` of ``robot``; ``meshes`` resolves each
    filename, ``stl_meshes`` says into how many Mesh assets each STL file was cut. Every
    geometry that cannot be made as checked is one located error."""
    sink = DiagnosticSink()
    builder = _Builder(sink, stl_meshes)
    instances: dict[str, ModelInstance] = {}
    for key, mesh, visual in _mesh_parts(robot):
        resolved = meshes[mesh.filename]
        instance = builder.instance(mesh, resolved, collision=visual is None)
        if instance is not None and visual is not None and visual.material is not None:
            instance = builder.painted(instance, mesh, resolved, visual.material)
        if instance is not None:
            instances[key] = instance
    sink.raise_if_errors()
    return ModelPlan(instances, tuple(sorted(builder.assets.values(), key=lambda a: a.path)))


def _mesh_parts(robot: Robot) -> Iterator[tuple[str, Mesh, Visual | None]]:
    """``(key, mesh, visual or None for a collision)`` of every mesh geometry."""
    for i, link in enumerate(robot.links):
        for j, visual in enumerate(link.visuals):
            if isinstance(visual.geometry, Mesh):
                yield f"link[{i}]/visual[{j}]/shape", visual.geometry, visual
        for j, collision in enumerate(link.collisions):
            if isinstance(collision.geometry, Mesh):
                yield f"link[{i}]/collision[{j}]/shape", collision.geometry, None


class _Builder:
    """Makes each instance, and each asset once."""

    def __init__(self, sink: DiagnosticSink, stl_meshes: Mapping[ResolvedMesh, int]) -> None:
        self.sink = sink
        self.stl_meshes = stl_meshes
        self.assets: dict[str, ModelAsset] = {}
        self.collada: dict[Path, ColladaFacts] = {}
        self.made: dict[tuple[ResolvedMesh, bool], ModelInstance | None] = {}
        # each asset path in lower case, with the mesh that first wrote there
        self.claimed: dict[str, tuple[ResolvedMesh, Mesh]] = {}

    def instance(
        self, mesh: Mesh, resolved: ResolvedMesh, *, collision: bool
    ) -> ModelInstance | None:
        """The instance for ``mesh``; one per file and kind (links share meshes)."""
        if (resolved, collision) not in self.made:
            self.made[resolved, collision] = self._made(mesh, resolved, collision=collision)
        return self.made[resolved, collision]

    def _made(self, mesh: Mesh, resolved: ResolvedMesh, *, collision: bool) -> ModelInstance | None:
        suffix = resolved.relative.suffix.lower()
        if suffix == ".stl":
            stem = PurePosixPath(resolved.package) / resolved.relative.with_suffix("")
            return (
                self._stl(resolved, collision=collision)
                if self._claim(f"{stem}.prefab", resolved, mesh)
                else None
            )
        if suffix == ".dae":
            path = PurePosixPath(resolved.package) / resolved.relative
            if not self._claim(str(path), resolved, mesh):
                return None
            return self._collada(mesh, resolved, collision=collision)
        self.sink.error(
            mesh.location,
            f"mesh {mesh.filename!r}: {suffix or 'a file without extension'} models are not "
            "supported: Unity imports them itself, and no Unity-written scene here shows "
            "the fileIDs and root rotation it gives them",
            hint="convert the mesh to STL or COLLADA (.dae, Y up)",
        )
        return None

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
        ROS#'s ``UrdfMaterial.SetMaterial`` sets ``sharedMaterial`` on each."""
        prefab = self.assets[instance.source].prefab  # an STL's, made with its instance
        if prefab is not None:
            renderers = tuple(part.renderer for part in prefab.parts)
        elif self._one_slot(mesh, self._facts(resolved.path), material):
            renderers = (_ROOT_RENDERER,)
        else:
            return None
        mat = AssetObject(MaterialRef(material_name(material)).path, MATERIAL_FILE_ID, _TYPE_NATIVE)
        return instance.with_changes(material_modifications(renderers, mat))

    def _one_slot(self, mesh: Mesh, facts: ColladaFacts, material: Material) -> bool:
        """Whether the model's one renderer is its root's, with one material slot: the
        renderers of a model of several nodes, and what ``sharedMaterial`` does to a renderer
        of several slots, are not checked against Unity."""
        (node, *others) = facts.nodes  # one at least: _checked refused a model of none
        if others or node.has_children:
            why = "it has several nodes, whose renderers are not checked against Unity"
        elif node.geometries != 1 or node.parts != 1:
            why = (
                f"its node {node.name!r} is drawn in {node.parts} parts, each with a "
                "material slot of its own, and which slots ROS#'s material replaces is not "
                "checked against Unity"
            )
        else:
            return True
        self.sink.error(
            material.location,
            f"a <material> on the visual of model {mesh.filename!r} is not supported: {why} "
            "(only a model of one node drawn in one part is)",
            hint="remove the <material> (the model keeps its own), or export the model as "
            "one node with one geometry of one material",
        )
        return False

    def _stl(self, resolved: ResolvedMesh, *, collision: bool) -> ModelInstance:
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

    def _collada(
        self, mesh: Mesh, resolved: ResolvedMesh, *, collision: bool
    ) -> ModelInstance | None:
        facts = self._facts(resolved.path)
        if not self._checked(mesh, facts, collision=collision):
            return None
        path = str(PurePosixPath(resolved.package) / resolved.relative)
        self.assets.setdefault(path, ModelAsset(path, resolved.path, global_scale=facts.meter))
        self._textures(mesh, resolved, facts)
        changes = root_modifications(
            _ROOT_TRANSFORM,
            _ROOT_GAMEOBJECT,
            resolved.relative.stem,
            (0.0, 0.0, 0.0),
            COLLADA_Y_UP_ROTATION,
        )
        if not collision:
            return ModelInstance(path, _TYPE_MODEL, _ROOT_TRANSFORM, changes)
        # one node, folded into the root: its mesh is named after the node
        mesh_id = model_file_id("Mesh", facts.nodes[0].name)
        collider = AddedMeshCollider(_ROOT_GAMEOBJECT, AssetObject(path, mesh_id, _TYPE_MODEL))
        removed = (_ROOT_RENDERER, _ROOT_FILTER)
        return ModelInstance(path, _TYPE_MODEL, _ROOT_TRANSFORM, changes, removed, (collider,))

    def _facts(self, path: Path) -> ColladaFacts:
        if path not in self.collada:
            self.collada[path] = read_collada(path)
        return self.collada[path]

    def _checked(self, mesh: Mesh, facts: ColladaFacts, *, collision: bool) -> bool:
        """Whether the model is one whose instance Unity-written files show; else say why."""
        name = repr(mesh.filename)
        reason, hint = None, None
        if facts.up_axis != "Y_UP":
            reason = (
                f"model {name} is {facts.up_axis}: ROS# turns such a model's root by its own "
                "rule, and no Unity-written scene here shows the rotation saved for it "
                "(only Y_UP is checked)"
            )
            hint = "export the model with Y up, or convert it to STL"
        elif not facts.nodes:
            reason = f"model {name} has no nodes in its visual scene: there is nothing to show"
            hint = "export the model again with its geometry"
        elif len(facts.nodes) == 1 and facts.nodes[0].moved:
            reason = (
                f"model {name}: its one top node {facts.nodes[0].name!r} is moved or turned, "
                "which Unity folds into the model's root (not checked against a saved scene)"
            )
            hint = "apply the node's transform to its geometry (freeze transforms) and export"
        elif collision:
            reason = _collision_problem(name, facts)
            hint = "give the collision an STL mesh, or a model of one node with one geometry"
        if reason is None:
            return True
        self.sink.error(mesh.location, reason, hint=hint)
        return False

    def _textures(self, mesh: Mesh, resolved: ResolvedMesh, facts: ColladaFacts) -> None:
        """Copy the images the model names that exist beside it (Unity imports the model
        without a missing one, as the r2d2 sample's normal maps are)."""
        for image in facts.images:
            inside = _inside_package(resolved.relative.parent, image)
            if inside is None:
                self.sink.error(
                    mesh.location,
                    f"model {mesh.filename!r} names the image {str(image)!r} outside its "
                    "package folder",
                    hint="keep the model's textures beside it, named by relative paths",
                )
                continue
            source = resolved.path.parent / image
            if not source.is_file():
                continue
            if image.suffix.lower() != ".png":
                self.sink.error(
                    mesh.location,
                    f"model {mesh.filename!r} uses the texture {str(image)!r}: only PNG "
                    "textures' import settings are checked against Unity's",
                    hint="convert the texture to PNG and name it so in the model",
                )
                continue
            path = str(PurePosixPath(resolved.package) / inside)
            self.assets.setdefault(path, ModelAsset(path, source))


def _collision_problem(name: str, facts: ColladaFacts) -> str | None:
    """Why a MeshCollider cannot be placed on the model's mesh as checked, if it cannot."""
    node = facts.nodes[0]
    if len(facts.nodes) > 1 or node.has_children:
        return (
            f"model {name} has several nodes: a collision needs every node's mesh, and "
            "only a model of one node is checked against a Unity-written scene"
        )
    if node.geometries != 1:
        return (
            f"model {name}: its node {node.name!r} has {node.geometries} geometries, and "
            "only a node with one is checked against a Unity-written scene"
        )
    if node.name != node.id or not _PLAIN_NAME.fullmatch(node.name):
        return (
            f"model {name}: its node's name {node.name!r} (id {node.id!r}) is not one "
            "whose mesh name is checked (letters, digits and '_', the same as its id)"
        )
    return None


def _inside_package(folder: PurePosixPath, image: PurePosixPath) -> PurePosixPath | None:
    """``folder / image`` with ``..`` resolved, or None if it leaves the package."""
    if image.is_absolute() or ":" in str(image):
        return None
    parts: list[str] = []
    for part in (*folder.parts, *image.parts):
        if part == "..":
            if not parts:
                return None
            parts.pop()
        elif part != ".":
            parts.append(part)
    return PurePosixPath(*parts)
