"""``scaffold scene``: inspect a scene and attach components by hand."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated

import typer

from unityscaffold.errors import LocatedError, UserError
from unityscaffold.unity.catalog import rossharp_catalog
from unityscaffold.unity.index import GameObject
from unityscaffold.unity.project import find_project_root, script_index, script_ref_for_file
from unityscaffold.unity.scene import GameObjectNotFound, SceneDocument
from unityscaffold.unity.setvalue import component_label, parse_assignment, parse_value
from unityscaffold.unity.ugui import UGUI_SCRIPTS
from unityscaffold.unity.values import ScriptRef

app = typer.Typer(help="Inspect Unity scenes and attach components.", no_args_is_help=True)

_SET_HELP = (
    "Set a serialized field (repeatable; order = declaration order for new fields). VALUE is a "
    "YAML scalar or flow value: 10, 0.1, true, text, 'a: b', [1, 2], {x: 0, y: 1}, "
    "{fileID: N}, {fileID: F, guid: G, type: 3}. Same-scene references: @Path/To/Object for a "
    "GameObject, @Path/To/Object:Transform or @RosConnector:RosConnector for a component by "
    "class or script name; '@@x' is the literal string '@x'."
)


def _script_names(scene_path: Path) -> dict[str, str]:
    """GUID -> class name: the project's scripts, ROS#'s from its catalog and uGUI's (so that a
    scene names them before Unity has installed the packages)."""
    names = {guid: name for name, (_, guid) in UGUI_SCRIPTS.items()}
    names.update(rossharp_catalog().all_class_names())
    root = find_project_root(scene_path.parent)
    if root is None:
        return names
    return {**names, **{guid: info.class_name for guid, info in script_index(root).items()}}


def _load_checked(path: Path) -> SceneDocument:
    scene = SceneDocument.load(path)
    problems = scene.validate()
    if problems:
        raise LocatedError(problems)
    return scene


def _node_json(scene: SceneDocument, go: GameObject, names: dict[str, str]) -> dict[str, object]:
    comps = [] if go.is_prefab_instance else scene.components_of(go)
    return {
        "path": go.path,
        "name": go.name,
        "fileID": go.file_id,
        "prefabInstance": go.is_prefab_instance,
        "components": [
            {
                "fileID": c.file_id,
                "class": c.type_name,
                "name": component_label(c, names),
                "script": None
                if c.script is None
                else {
                    "guid": c.script.guid,
                    "fileID": c.script.file_id,
                    "name": names.get(c.script.guid),
                },
            }
            for c in comps
        ],
    }


@app.command("ls")
def ls(
    scene: Annotated[Path, typer.Argument(help="A .unity scene or .prefab file.")],
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON instead of a tree.")] = False,
) -> None:
    """Show the hierarchy with each GameObject's components (script names when resolvable).

    Example:

      scaffold scene ls Assets/Scenes/Main.unity --json
    """
    doc = _load_checked(scene)
    names = _script_names(scene)
    if as_json:
        nodes = [_node_json(doc, go, names) for go in doc.gameobjects()]
        # "generation" is the era's key since the first release; scripts may read it.
        payload = {"path": str(scene), "generation": doc.era.label, "gameobjects": nodes}
        typer.echo(json.dumps(payload, indent=2))
        return
    for depth, go in doc.tree():
        if go.is_prefab_instance:
            typer.echo(f"{'  ' * depth}{go.name}  (prefab instance &{go.file_id})")
            continue
        labels = ", ".join(component_label(c, names) for c in doc.components_of(go))
        typer.echo(f"{'  ' * depth}{go.name}  [{labels}]")


def _script_ref(script: Path | None, guid: str | None, dll_class: str | None) -> ScriptRef:
    if (script is None) == (guid is None):
        raise UserError("give exactly one of --script FILE.cs or --guid GUID")
    if script is not None:
        if dll_class:
            raise UserError("--dll-class goes with --guid (the DLL's GUID), not --script")
        return script_ref_for_file(script)
    assert guid is not None
    try:
        if dll_class:
            namespace, _, name = dll_class.rpartition(".")
            return ScriptRef.for_dll_class(guid, namespace, name)
        return ScriptRef(guid)
    except ValueError as exc:
        raise UserError(
            str(exc), hint="a GUID is 32 lowercase hex digits, as in .meta files"
        ) from None


@app.command("attach")
def attach(
    scene: Annotated[Path, typer.Argument(help="A .unity scene or .prefab file.")],
    gameobject: Annotated[
        str, typer.Option("--gameobject", "-g", help="Hierarchy path: Robot/base_link.")
    ],
    script: Annotated[
        Path | None, typer.Option("--script", help="The .cs file (its .meta gives the GUID).")
    ] = None,
    guid: Annotated[
        str | None, typer.Option("--guid", help="The script's (or DLL's) GUID.")
    ] = None,
    dll_class: Annotated[
        str | None,
        typer.Option("--dll-class", help="Namespace.Class inside the DLL given by --guid."),
    ] = None,
    assignments: Annotated[
        list[str] | None, typer.Option("--set", help=_SET_HELP, metavar="NAME=VALUE")
    ] = None,
    create: Annotated[
        bool, typer.Option("--create", help="Create missing GameObjects on the path.")
    ] = False,
    dry_run: Annotated[
        bool, typer.Option("--dry-run", help="Print the unified diff; write nothing.")
    ] = False,
) -> None:
    """Attach a MonoBehaviour to a GameObject, or update the one already there (idempotent).

    Example:

      scaffold scene attach Assets/Scenes/Main.unity -g Robot/lidar \\
          --script Assets/Scripts/Lidar.cs --set Range=12.5 --create
    """
    ref = _script_ref(script, guid, dll_class)
    pairs = [parse_assignment(a) for a in assignments or []]
    doc = _load_checked(scene)
    names = _script_names(scene)
    try:
        go = doc.ensure_gameobject(gameobject, create=create)
    except GameObjectNotFound as error:
        hint = "add it in Unity, or pass --create to create it (and any missing parents)"
        raise UserError(error.message, hint=hint) from None
    fields = [(name, parse_value(value, doc, names)) for name, value in pairs]
    comp = doc.ensure_component(go, ref, fields)
    label = ref.class_name or names.get(ref.guid) or ref.guid
    if dry_run:
        typer.echo(doc.diff() or f"no changes: {label} on {go.path} is up to date", nl=False)
        if not doc.changed:
            typer.echo("")
        return
    wrote = doc.write()
    state = "updated" if wrote else "unchanged"
    typer.echo(f"{state} {scene}: {label} on {go.path} (&{comp.file_id})")
