"""``scaffold msgs gen``: generate ROS# (or ROS-TCP-Connector) C# classes for types or whole
packages."""

from __future__ import annotations

import difflib
import json
import os
from pathlib import Path
from typing import TYPE_CHECKING

import typer

from unityscaffold.cli._options import (
    NoEnvOption,
    PathOption,
    RosOption,
    RuntimeOption,
    dialect_of,
    runtime_of,
)
from unityscaffold.errors import Diagnostic, Exit, LocatedError, UserError
from unityscaffold.fileout import ChangeKind, FileChange, plan_files, write_files
from unityscaffold.interfaces.model import Dialect, Interface
from unityscaffold.interfaces.registry import Registry
from unityscaffold.manifest.runtime import Runtime

if TYPE_CHECKING:  # codegen is imported when `gen` runs: `msgs list` and `show` skip its cost
    from unityscaffold.codegen import GeneratedCode

__all__ = ["register", "resolve_roots", "run"]

# What resolves a ClassClash here, by whether the other class is one ROS# ships.
_CLASH_HINTS = {
    True: "generate into another root namespace with --namespace",
    False: "ROS# names classes by package namespace and type name; rename one type, "
    "or generate them separately with --namespace",
}


def _package_interfaces(registry: Registry, package: str) -> list[Interface]:
    files = [f for f in registry.files() if f.package == package]
    if not files:
        close = difflib.get_close_matches(package, registry.packages(), n=3, cutoff=0.6)
        hint = f"did you mean {' or '.join(close)}?" if close else "give pkg/Type or a package name"
        raise UserError(f"unknown type or package '{package}'", hint=hint)
    found: list[Interface] = []
    problems: list[Diagnostic] = []
    for file in files:
        try:
            found.append(registry.parse(file))
        except LocatedError as error:
            problems.extend(error.diagnostics)
    if problems:
        raise LocatedError(problems)
    return found


def resolve_roots(registry: Registry, names: list[str], everything: bool) -> list[Interface]:
    """The interfaces named by ``pkg/Type`` or package names (``--all``: every type found)."""
    if everything:
        found, problems = registry.parse_all()
        if problems:
            raise LocatedError(problems)
        return found
    if not names:
        raise UserError("no types given", hint="name types (pkg/Type) or packages, or use --all")
    roots: list[Interface] = []
    typed = iter(registry.get_all([name for name in names if "/" in name]))
    for name in names:
        roots += [next(typed)] if "/" in name else _package_interfaces(registry, name)
    return roots


def _check_out_dir(out: Path) -> None:
    if out.exists() and not out.is_dir():
        raise UserError(
            f"output folder {out} exists and is not a folder", hint="pass a folder with --out"
        )


def run(
    names: list[str],
    out: Path,
    dialect: Dialect,
    paths: list[Path],
    include_shipped: bool,
    namespace: str | None,
    everything: bool,
    *,
    use_environment: bool = True,
    write: bool = True,
    runtime: Runtime = Runtime.ROS_SHARP,
) -> tuple[GeneratedCode, list[FileChange]]:
    """Generate ``runtime``'s classes and (unless ``write`` is false) write them; returns what
    was generated and each file's change."""
    from unityscaffold.apply.runtimes import generate_classes
    from unityscaffold.codegen import Options
    from unityscaffold.codegen.layout import output_files
    from unityscaffold.codegen.naming import ClassClash

    _check_out_dir(out)
    registry = Registry.load(dialect, paths, use_environment=use_environment)
    roots = resolve_roots(registry, names, everything)
    options = Options(dialect, include_shipped, namespace)
    try:
        code = generate_classes(runtime, registry, roots, options)
    except ClassClash as clash:
        raise UserError(clash.message, hint=_CLASH_HINTS[clash.with_shipped]) from None
    changes = plan_files(output_files(code, out))
    if write:
        write_files(changes)
    return code, changes


def _relative(change: FileChange, out: Path) -> str:
    return Path(os.path.relpath(change.path, out.resolve())).as_posix()


def _drifted(changes: list[FileChange]) -> list[FileChange]:
    """The files that writing would create or change (what ``--check`` fails on)."""
    return [c for c in changes if c.kind in (ChangeKind.CREATE, ChangeKind.UPDATE)]


def _report(code: GeneratedCode, changes: list[FileChange], out: Path, *, check: bool) -> None:
    for change in changes:
        if change.kind is not ChangeKind.UNCHANGED:
            reason = f" ({change.reason})" if change.reason else ""
            typer.echo(f"{change.kind.value:9} {_relative(change, out)}{reason}")
    for skipped in code.skipped:
        typer.echo(f"{'skip':9} {skipped.path} ({skipped.ros_type}): {skipped.reason}")
        if skipped.warning:
            typer.echo(f"warning: {skipped.warning}", err=True)
    counts = {k: sum(1 for c in changes if c.kind is k) for k in ChangeKind}
    would = "would be " if check else ""
    typer.echo(
        f"{len(code.files)} classes generated, {len(code.skipped)} skipped; "
        f"files: {counts[ChangeKind.CREATE]} {would}created, "
        f"{counts[ChangeKind.UPDATE]} {would}updated, "
        f"{counts[ChangeKind.UNCHANGED]} unchanged, {counts[ChangeKind.SKIP]} kept"
    )


def _json(code: GeneratedCode, changes: list[FileChange], out: Path, *, check: bool) -> str:
    data = {
        "out": out.as_posix(),
        "check": check,
        "up_to_date": not _drifted(changes),
        "files": [
            {"path": _relative(c, out), "change": c.kind.value, "reason": c.reason or None}
            for c in changes
        ],
        "generated": [
            {"type": f.ros_type, "class": f.cs_class.full_name, "path": f.path} for f in code.files
        ],
        "skipped": [
            {"type": s.ros_type, "class": s.cs_class.full_name, "path": s.path, "reason": s.reason}
            for s in code.skipped
        ],
    }
    return json.dumps(data, indent=2)


def register(app: typer.Typer) -> None:
    """Add the ``gen`` command to the ``msgs`` group."""

    @app.command("gen")
    def gen(
        names: list[str] = typer.Argument(
            None, metavar="TYPE_OR_PACKAGE...", help="Types (pkg/Type, pkg/msg/Type) or packages."
        ),
        out: Path = typer.Option(
            ..., "--out", "-o", help="Output folder, e.g. Assets/RosMessages."
        ),
        ros: int | None = RosOption,
        paths: list[Path] = PathOption,
        no_env: bool = NoEnvOption,
        include_shipped: bool = typer.Option(
            False,
            "--include-shipped",
            help="Also generate types ROS# already ships (not with ros-tcp-connector: its "
            "registry holds one class per ROS name).",
        ),
        namespace: str = typer.Option(
            None,
            "--namespace",
            help="Root namespace instead of RosSharp.RosBridgeClient.MessageTypes (generates "
            "all), or for ros-tcp-connector instead of RosMessageTypes (its shipped classes "
            "stay referenced).",
        ),
        runtime: str = RuntimeOption,
        everything: bool = typer.Option(False, "--all", help="Generate every type found."),
        check: bool = typer.Option(
            False,
            "--check",
            help="Write nothing; exit 1 if a file in --out would be created or changed.",
        ),
        quiet: bool = typer.Option(
            False, "--quiet", "-q", help="Print only errors (and, with --check, what differs)."
        ),
        as_json: bool = typer.Option(False, "--json", help="Print the result as JSON."),
    ) -> None:
        """Generate ROS# (or ROS-TCP-Connector) C# classes for types and everything they use.

        Examples:

          scaffold msgs gen my_msgs/msg/Status -o Assets/RosMessages

          scaffold msgs gen my_msgs -o Assets/Ros --runtime ros-tcp-connector

          scaffold msgs gen my_msgs --ros 1 --path ~/ws/src -o Assets/Ros

          scaffold msgs gen my_msgs -o Assets/Ros --check   (1 if stale)
        """
        code, changes = run(
            list(names or []),
            out,
            dialect_of(ros),
            list(paths),
            include_shipped,
            namespace,
            everything,
            use_environment=not no_env,
            write=not check,
            runtime=runtime_of(runtime),
        )
        if as_json:
            typer.echo(_json(code, changes, out, check=check))
        elif not quiet:
            _report(code, changes, out, check=check)
        drifted = _drifted(changes)
        if check and drifted:
            if not as_json:
                # Also under --quiet: a failed check says what differs and what fixes it.
                for change in drifted if quiet else ():
                    typer.echo(f"{change.kind.value:9} {_relative(change, out)}", err=True)
                typer.echo(
                    f"{out}: {len(drifted)} files differ from what msgs gen generates; "
                    "run the same command without --check",
                    err=quiet,
                )
            raise typer.Exit(int(Exit.DRIFT))
