"""``scaffold apply``, ``scaffold plan`` and ``scaffold init``: the main job."""

from __future__ import annotations

import json
import os
from pathlib import Path

import typer

from unityscaffold.apply.init import init_project
from unityscaffold.apply.report import plan_diff, plan_json, plan_summary
from unityscaffold.apply.run import Mode, Outcome, run
from unityscaffold.cli import _recorder
from unityscaffold.cli._options import RuntimeOption, find_manifest, runtime_of
from unityscaffold.errors import Exit, UserError
from unityscaffold.manifest.modeline import stale_schema

ManifestArgument: Path | None = typer.Argument(
    None,
    metavar="[MANIFEST]",
    help="The manifest. Default: robot.yaml in this folder or the nearest folder above it "
    "(up to the repository's root).",
    show_default=False,
)
RosEnvOption: bool = typer.Option(
    False,
    "--ros-env",
    help="Also search the ROS environment for interfaces. Off by default so that output "
    "depends only on files in the repository and the built-in standard definitions.",
)
JsonOption: bool = typer.Option(False, "--json", help="Print the plan as JSON for scripts.")


def _show(outcome: Outcome, manifest: Path, *, quiet: bool, as_json: bool, diff: bool) -> None:
    plan = outcome.plan
    if as_json:
        data = plan_json(plan)
        data["written"] = [plan.relative(p) for p in outcome.written]
        data["deleted"] = [plan.relative(p) for p in outcome.deleted]
        typer.echo(json.dumps(data, indent=2))
        return
    if not quiet:
        typer.echo(plan_summary(plan, manifest_as=str(manifest)))
        if diff:
            text = plan_diff(plan)
            if text:
                typer.echo(text, nl=False)


def _schema_note(manifest: Path) -> None:
    """A note on stderr when the schema copy the manifest's first line names is out of date."""
    stale = stale_schema(manifest)
    if stale is not None:
        shown = stale if stale.is_absolute() else Path(os.path.relpath(stale))
        state = "is missing" if not stale.exists() else "is older than this scaffold's schema"
        typer.echo(
            f"note: {shown} (the schema editors check {manifest} with) {state}; "
            f"refresh it with `scaffold schema -o {shown}`",
            err=True,
        )


def _verified(outcome: Outcome) -> None:
    """Tell the no-op record when this run found the project in sync and wrote nothing."""
    plan = outcome.plan
    if plan.in_sync and not plan.conflicts and not outcome.written and not outcome.deleted:
        _recorder.verified()


def _drift_advice(manifest: Path, outcome: Outcome) -> str:
    """The last line of a failed ``--check``: what differs and the command that fixes it."""
    if outcome.plan.conflicts:
        return (
            f"{manifest}: generated files were edited by hand; move the change to the .User.cs "
            f"files, then run `scaffold apply {manifest}` (or `scaffold apply --force "
            f"{manifest}` to discard it)"
        )
    return (
        f"{manifest}: the Unity project differs from the manifest; run "
        f"`scaffold apply {manifest}` and commit the result"
    )


def apply_command(
    given: Path | None = ManifestArgument,
    check: bool = typer.Option(
        False, "--check", help="Write nothing; exit 1 if the project differs from the manifest."
    ),
    dry_run: bool = typer.Option(False, "--dry-run", help="Same as `scaffold plan`."),
    force: bool = typer.Option(
        False, "--force", help="Overwrite generated files even if edited by hand."
    ),
    quiet: bool = typer.Option(
        False,
        "--quiet",
        "-q",
        help="Print only errors (with --check: one line on stderr when the project differs).",
    ),
    follow_renames: bool = typer.Option(
        False,
        "--follow-renames",
        help="A GameObject apply made or used that was renamed or moved in Unity since: "
        "keep using it where it is now and rewrite the manifest's lines to its new path "
        "(for a RosConnector left at its default, add connector: {gameobject: NEW}). "
        "Without it apply stops and names those lines (it never creates a second one, nor "
        "takes another object that now has the old name).",
    ),
    ros_env: bool = RosEnvOption,
    as_json: bool = JsonOption,
) -> None:
    """Make the Unity project match the manifest: generate code, wire scenes, write the lock.

    Running it again changes nothing. Generated files edited by hand stop it (see --force);
    your code belongs in the *.User.cs files, which are created once and never rewritten.
    GameObjects are known by identity: one renamed or moved in Unity stops apply with the
    manifest lines to change (see --follow-renames).

    Examples:

      scaffold apply                      (robot.yaml here or above)

      scaffold apply my_robot/robot.yaml

      scaffold apply --check --quiet      (in CI: exit 1 on drift)
    """
    manifest = find_manifest(given)
    mode = Mode.CHECK if check else Mode.PLAN if dry_run else Mode.APPLY
    outcome = run(
        manifest, mode, force=force, use_environment=ros_env, follow_renames=follow_renames
    )
    _show(outcome, manifest, quiet=quiet, as_json=as_json, diff=dry_run)
    if not quiet and not as_json:
        _schema_note(manifest)
    if mode is Mode.CHECK and not (outcome.plan.in_sync and not outcome.plan.conflicts):
        if not as_json:
            # Also under --quiet: a check that fails must say why and what to do.
            typer.echo(_drift_advice(manifest, outcome), err=quiet)
        raise typer.Exit(int(Exit.DRIFT))
    if mode is Mode.APPLY and not quiet and not as_json:
        typer.echo(f"wrote {len(outcome.written)} files, removed {len(outcome.deleted)}")
    _verified(outcome)


def plan_command(
    given: Path | None = ManifestArgument,
    ros_env: bool = RosEnvOption,
    as_json: bool = JsonOption,
) -> None:
    """Show what apply would change (summary and unified diff); write nothing.

    Examples:

      scaffold plan

      scaffold plan my_robot/robot.yaml --json
    """
    manifest = find_manifest(given)
    outcome = run(manifest, Mode.PLAN, use_environment=ros_env)
    _show(outcome, manifest, quiet=False, as_json=as_json, diff=True)
    if not as_json:
        _schema_note(manifest)
    _verified(outcome)


def init_command(
    directory: Path = typer.Argument(..., metavar="DIR", help="Folder for the new project."),
    ros: int = typer.Option(2, "--ros", metavar="1|2", help="ROS version of the robot."),
    runtime: str = RuntimeOption,
    force: bool = typer.Option(
        False,
        "--force",
        help="Add the template to a non-empty folder (keeps existing files; in an existing "
        "project, adds the runtime's package to Packages/manifest.json and uses its first "
        "scene).",
    ),
) -> None:
    """Create a template Unity project (2022.3, ROS# or ROS-TCP-Connector pinned) with a
    starter robot.yaml.

    Examples:

      scaffold init my_robot

      scaffold init my_robot --ros 1

      scaffold init my_robot --ros 1 --runtime ros-tcp-connector
    """
    if ros not in (1, 2):
        raise UserError(f"--ros must be 1 or 2, not {ros}")
    changes = init_project(directory, ros, force=force, runtime=runtime_of(runtime))
    created = sum(1 for c in changes if c.writes)
    typer.echo(
        f"created {created} files in {directory}; next: scaffold apply {directory / 'robot.yaml'}"
    )


def register(app: typer.Typer) -> None:
    """Add ``apply``, ``plan`` and ``init`` to the root app."""
    app.command("apply")(apply_command)
    app.command("plan")(plan_command)
    app.command("init")(init_command)
