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
  have the fileIDs of ``unity.modelids``.

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

The rest is a located error saying why: other formats (``.obj``, ``.fbx``: Unity's own import,
no saved scene to check), a collision or ``<material>`` on a model with a node of several
geometries or a drawn node below one without name or id (which objects Unity makes of them is
not checked), and textures Unity imports with another importer than its TextureImporter
(``urdf.textures``). A textured ``<material>`` is one more ``.mat`` (``urdf.materials``).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
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
from unityscaffold.urdf._material_names import material_stems
from unityscaffold.urdf._packages import ResolvedMesh
from unityscaffold.urdf.collada import ColladaFacts, ColladaNode, read_collada
from unityscaffold.urdf.colladamodel import DrawnNode, drawn_nodes, imported_root_pose, rotate, turn
from unityscaffold.urdf.model import Material, Mesh, Robot, Vector3, Visual
from unityscaffold.urdf.textures import model_textures

__all__ = ["ModelAsset", "ModelPlan", "model_plan"]

_ROOT_GAMEOBJECT = model_file_id("GameObject", ROOT_PATH)
_ROOT_TRANSFORM = model_file_id("Transform", ROOT_PATH)
_TYPE_MODEL, _TYPE_NATIVE = 3, 2


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
    turns = _creation_turns(robot)
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


def _creation_turns(robot: Robot) -> dict[str, t.Quaternion]:
    """How each link's geometries' parents are turned in the world when ROS# makes them: as
    the link's parent link is, since ROS# poses a link (its joint's origin) only after making
    its visuals and collisions, and its children after that (``UrdfLinkExtensions.Create``),
    with the robot's root at the origin unturned."""
    turns: dict[str, t.Quaternion] = {}
    # (a link, how its parent is turned in the world, its own turn in its parent)
    stack: list[tuple[str, t.Quaternion, t.Quaternion]] = [
        (robot.root.name, t.IDENTITY, t.IDENTITY)
    ]
    while stack:
        name, above, own = stack.pop()
        if name in turns:
            continue
        turns[name] = above
        posed = turn(above, own)
        for joint in robot.child_joints(name):
            stack.append((joint.child, posed, t.origin_rotation(joint.origin)))
    return {link.name: turns.get(link.name, t.IDENTITY) for link in robot.links}


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
            return self._collada(mesh, resolved, turned, collision=collision)
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
        ROS#'s ``UrdfMaterial.SetMaterial`` sets ``sharedMaterial`` on each: a renderer's
        first slot (``Renderer.sharedMaterial`` is its first material)."""
        made = self.assets[instance.source]  # an STL's prefab or the model, with its instance
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
        self, mesh: Mesh, resolved: ResolvedMesh, turned: t.Quaternion, *, collision: bool
    ) -> ModelInstance | None:
        facts = self._facts(resolved.path)
        path = str(PurePosixPath(resolved.package) / resolved.relative)
        self.assets.setdefault(path, ModelAsset(path, resolved.path, global_scale=facts.meter))
        self._textures(mesh, resolved, facts)
        position, rotation = imported_root_pose(facts)
        changes = root_modifications(
            _ROOT_TRANSFORM,
            _ROOT_GAMEOBJECT,
            resolved.relative.stem,
            _local_position(position, turned),
            _saved_rotation(rotation),
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
        problem = _unchecked(drawn)
        if problem is None:
            return drawn
        key = (mesh.filename, use)
        if key not in self.reported:
            self.reported.add(key)
            self.sink.error(
                where,
                f"model {mesh.filename!r} cannot take a {use} as ROS# makes it: {problem}",
                hint="export the model with one geometry per node, each node named",
            )
        return None

    def _textures(self, mesh: Mesh, resolved: ResolvedMesh, facts: ColladaFacts) -> None:
        for texture in model_textures(mesh, resolved, facts.images, self.sink):
            self.assets.setdefault(texture.path, texture)


def _unchecked(drawn: tuple[DrawnNode, ...]) -> str | None:
    """Why the objects of a model's drawn nodes do not follow from a rule seen in Unity's
    files, if they do not: how the FBX SDK splits a node of several geometries into objects,
    and what it names a node with neither name nor id, no Unity-written file here shows."""
    for node in drawn:
        if node.node.geometries > 1:
            return (
                f"its node {_shown(node.node)} draws {node.node.geometries} geometries, and "
                "which objects Unity makes of them is not checked against a Unity-written file"
            )
        if "//" in node.path.removeprefix("//") or node.path.endswith("/"):
            return (
                "a node without name or id leads to its node "
                f"{_shown(node.node)}, and what Unity names such a node is not checked"
            )
    return None


def _shown(node: ColladaNode) -> str:
    return f"{node.name or node.id!r} (line {node.location.line})"


def _local_position(position: Vector3, turned: t.Quaternion) -> Vector3:
    """Where ROS#'s ``SetParentAndAlign`` leaves the instance's root: at the model's root
    position in world axes, under a parent turned by ``turned`` (the links above it, posed
    before this link is), so in its parent's axes that position turned back."""
    if position == (0.0, 0.0, 0.0):
        return position
    inverse = (-turned[0], -turned[1], -turned[2], turned[3])
    x, y, z = (t.f32(v) + 0.0 for v in rotate(inverse, position))
    return (x, y, z)


def _saved_rotation(rotation: t.Quaternion) -> t.Quaternion:
    """A rotation as the scene saves the instance root's: float32, with the sign of zero that
    re-parenting leaves on x, y and z (-0: the r2d2 and UR3 scenes, ``unity.transforms``'s
    ``ALIGNED``). What double arithmetic leaves of an exact 0 (below 1e-9) is 0, as Unity's
    float arithmetic has it."""
    x, y, z, w = (t.f32(v) if abs(v) >= 1e-9 else 0.0 for v in rotation)
    return (x or -0.0, y or -0.0, z or -0.0, w)
