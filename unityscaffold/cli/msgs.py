"""``scaffold msgs``: list, show and generate ROS interface types."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import typer

from unityscaffold.cli._options import (
    JsonOption,
    NoEnvOption,
    PathOption,
    RosOption,
    dialect_of,
)
from unityscaffold.errors import Exit, LocatedError
from unityscaffold.interfaces.describe import Describer
from unityscaffold.interfaces.model import Interface, MessageSpec
from unityscaffold.interfaces.registry import Registry

app = typer.Typer(
    help="List, show and generate ROS message, service and action types.",
    no_args_is_help=True,
)


def _print_json(data: Any) -> None:
    typer.echo(json.dumps(data, indent=2, ensure_ascii=False))


def _indent(text: str, prefix: str = "    ") -> str:
    return "\n".join(prefix + line if line else line for line in text.split("\n"))


@app.command("list")
def list_types(
    package: str | None = typer.Option(None, "--package", "-p", help="Only this package."),
    live: str | None = typer.Option(
        None,
        "--live",
        metavar="URL",
        help="List the types of the active topics of a running system instead: a ROS 1 master "
        "(http://HOST:11311) or a rosbridge (ws://HOST:9090).",
    ),
    timeout: float = typer.Option(5.0, "--timeout", help="Seconds to wait for --live answers."),
    ros: int | None = RosOption,
    path: list[Path] = PathOption,
    no_env: bool = NoEnvOption,
    as_json: bool = JsonOption,
) -> None:
    """List every known type, grouped by package, with where it was found.

    A malformed file is reported (file:line:col) without hiding the good types; the exit
    status is then 2.

    Examples:

      scaffold msgs list --package sensor_msgs

      scaffold msgs list --ros 1 --path ~/catkin_ws/src --no-env
    """
    if live is not None:
        _list_live(live, timeout, as_json)
        return
    registry = Registry.load(dialect_of(ros), path, use_environment=not no_env)
    files = [f for f in registry.files() if package is None or f.package == package]
    if package is not None and not files:
        from unityscaffold.errors import UserError

        raise UserError(
            f"no package '{package}' found",
            hint="known packages: " + ", ".join(registry.packages()),
        )
    problems: list[str] = []
    groups: dict[str, dict[str, Any]] = {}
    for file in files:
        try:
            registry.parse(file)
        except LocatedError as error:
            problems.append(error.render())
            continue
        group = groups.setdefault(
            file.package,
            {
                "package": file.package,
                "path": str(file.path.parent.parent),
                "origin": file.origin,
                "types": [],
            },
        )
        group["types"].append({"type": f"{file.package}/{file.name}", "kind": file.kind.value})
    if as_json:
        _print_json(list(groups.values()))
    else:
        for group in groups.values():
            typer.echo(f"{group['package']}  ({group['path']}, {group['origin']})")
            for entry in group["types"]:
                typer.echo(f"  {entry['kind']:<6} {entry['type']}")
    for problem in problems:
        typer.echo(problem, err=True)
    if problems:
        raise typer.Exit(int(Exit.USER_ERROR))


def _list_live(url: str, timeout: float, as_json: bool) -> None:
    from unityscaffold.interfaces.live import list_live_types

    topics = list_live_types(url, timeout=timeout)
    if as_json:
        _print_json([{"topic": topic, "type": type_name} for topic, type_name in topics])
        return
    width = max((len(topic) for topic, _ in topics), default=0)
    for topic, type_name in topics:
        typer.echo(f"{topic:<{width}}  {type_name}")


def _show_text(
    describer: Describer, interface: Interface, data: dict[str, Any], registry: Registry
) -> None:
    typer.echo(f"{data['type']}  ({data['kind']}, {registry.dialect.label})")
    file = registry.file_of(interface)
    origin = f" ({file.origin})" if file else ""
    typer.echo(f"  source:     {data['source']}{origin}")
    if isinstance(interface, MessageSpec) and not interface.text and interface.owner:
        # rosidl makes it from its owner's file (_FeedbackMessage, _SendGoal_Request, _Event):
        # its definition below starts with the types it uses, not with text of its own.
        typer.echo(f"  derived:    by rosidl from {interface.owner}, with no text of its own")
    for other in registry.shadowed(interface):
        same = file is not None and other.path.read_bytes() == file.path.read_bytes()
        note = "same text" if same else "DIFFERENT text"
        typer.echo(f"  not used:   {other.path} ({other.origin}; {note})")
    identity = describer.identity(interface)
    if identity["md5sum"]:
        typer.echo(f"  md5sum:     {identity['md5sum']}")
    if identity["type_hash"]:
        typer.echo(f"  type hash:  {identity['type_hash']}")
    for part in ("request", "response", "goal", "result", "feedback"):
        if part in data:
            sub = data[part]
            suffix = f"  md5sum {sub['md5sum']}" if sub["md5sum"] else ""
            typer.echo(f"  {part}:{' ' * (10 - len(part))}{sub['type']}{suffix}")
    _fields_text(data)
    typer.echo("  definition:")
    typer.echo(_indent(data["definition"]))


def _fields_text(data: dict[str, Any]) -> None:
    for constant in data["constants"]:
        typer.echo(f"  const  {constant['type']} {constant['name']} = {constant['text']}")
    for field in data["fields"]:
        default = f" = {field['default']!r}" if field["default"] is not None else ""
        typer.echo(f"  field  {field['type']} {field['name']}{default}")


@app.command("show")
def show(
    types: list[str] = typer.Argument(
        ..., metavar="TYPE...", help="Types such as geometry_msgs/Twist or std_srvs/Trigger."
    ),
    ros: int | None = RosOption,
    path: list[Path] = PathOption,
    no_env: bool = NoEnvOption,
    as_json: bool = JsonOption,
) -> None:
    """Show types: fields, constants, source file, md5sum (ROS 1) or type hash (ROS 2), definition.

    Service halves are accepted as types too: pkg/SrvRequest (ROS 1), pkg/srv/Srv_Request (ROS 2).

    Examples:

      scaffold msgs show geometry_msgs/msg/Twist

      scaffold msgs show nav_msgs/GetMap --ros 1 --json
    """
    registry = Registry.load(dialect_of(ros), path, use_environment=not no_env)
    describer = Describer(registry)
    interfaces = registry.get_all(types)
    described = [describer.describe(interface) for interface in interfaces]
    if as_json:
        _print_json(described)
        return
    for index, (interface, data) in enumerate(zip(interfaces, described, strict=True)):
        if index:
            typer.echo()
        _show_text(describer, interface, data, registry)


from unityscaffold.cli import msgs_gen  # noqa: E402

msgs_gen.register(app)
