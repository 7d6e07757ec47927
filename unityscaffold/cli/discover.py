"""``scaffold discover``: topics, services and definitions from a live ROS system or a bag."""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path
from typing import Any

import typer

from unityscaffold.cli._options import find_manifest
from unityscaffold.errors import UserError
from unityscaffold.fileout import write_if_changed
from unityscaffold.interfaces import live
from unityscaffold.interfaces.live.definitions import StagedCache, stage_definitions
from unityscaffold.interfaces.model import Dialect
from unityscaffold.manifest import edit

_HELP = (
    "Read topics, services, actions and their definitions from a running ROS system or a "
    "bag.\n\n"
    "The definitions are written as .msg (and .srv, .action) files to a cache folder next to "
    "the manifest (checked against the system's ROS 1 md5sums or ROS 2 RIHS01 hashes), and the "
    "topics, services and actions are added to the manifest, keeping its comments and layout. "
    "With --print, a manifest fragment is printed instead. Without MANIFEST, robot.yaml in this "
    "folder or the nearest folder above it (up to the repository's root) is used.\n\n"
    "--ros2 joins the ROS 2 graph itself (no rosbridge needed; the `ros2` extra installs "
    "rclpy): ROS_DOMAIN_ID and the other ROS 2 variables of this shell apply.\n\n"
    "Examples:\n\n"
    "  scaffold discover --master http://robot:11311\n\n"
    "  scaffold discover my_robot/robot.yaml --rosbridge ws://robot:9090\n\n"
    "  scaffold discover --ros2 --select '^/robot/'\n\n"
    "  scaffold discover --bag run1.mcap --print"
)


def register(app: typer.Typer) -> None:
    """Add the ``discover`` command to the root app."""
    app.command("discover", help=_HELP)(discover_command)


_MANIFEST: Path | None = typer.Argument(
    None, metavar="[MANIFEST]", help="The manifest to add to.", show_default=False
)
_MASTER: str | None = typer.Option(
    None, "--master", metavar="URL", help="A ROS 1 master, e.g. http://localhost:11311."
)
_ROSBRIDGE: str | None = typer.Option(
    None, "--rosbridge", metavar="URL", help="A rosbridge (ROS 1 or 2), e.g. ws://localhost:9090."
)
_BAG: Path | None = typer.Option(
    None, "--bag", metavar="FILE", help="A ROS 1 .bag, a ROS 2 .db3/.mcap file or bag folder."
)
_ROS2: bool = typer.Option(
    False, "--ros2", help="The ROS 2 graph this machine sees, through rclpy (no rosbridge)."
)
_SELECT: str | None = typer.Option(
    None, "--select", metavar="REGEX", help="Only names this regular expression matches."
)
_EXCLUDE: str | None = typer.Option(
    None, "--exclude", metavar="REGEX", help="Leave out names this regular expression matches."
)
_ALL: bool = typer.Option(
    False,
    "--all",
    help="Include ROS plumbing (/rosout, /rosapi/*, rosbridge's /client_count, logger and "
    "parameter services, ROS 2 hidden names).",
)
_CACHE: Path | None = typer.Option(
    None,
    "--cache",
    metavar="DIR",
    help="Definitions cache folder (default: ros_definitions next to the manifest).",
)
_PRINT: bool = typer.Option(
    False, "--print", help="Print a manifest fragment instead of editing the manifest."
)
_DRY_RUN: bool = typer.Option(False, "--dry-run", help="Discover and verify; write nothing.")
_JSON: bool = typer.Option(False, "--json", help="Print the result as one JSON document.")
_TIMEOUT: float = typer.Option(
    2.0, "--timeout", min=0.05, metavar="SECONDS", help="Time limit of each network step."
)
_WAIT: float = typer.Option(
    5.0,
    "--wait",
    min=0.1,
    metavar="SECONDS",
    help="--ros2: the longest wait for the graph to settle (it stops early once it does).",
)
_PROGRESS: bool = typer.Option(
    False, "--progress", help="Show progress on stderr even when it is not a terminal."
)


def discover_command(
    given: Path | None = _MANIFEST,
    master: str | None = _MASTER,
    rosbridge: str | None = _ROSBRIDGE,
    bag: Path | None = _BAG,
    ros2: bool = _ROS2,
    select: str | None = _SELECT,
    exclude: str | None = _EXCLUDE,
    everything: bool = _ALL,
    cache: Path | None = _CACHE,
    print_fragment: bool = _PRINT,
    dry_run: bool = _DRY_RUN,
    as_json: bool = _JSON,
    timeout: float = _TIMEOUT,
    wait: float = _WAIT,
    progress: bool = _PROGRESS,
) -> None:
    _require_one_source(master, rosbridge, bag, ros2)
    manifest = find_manifest(given)
    text = _manifest_text(manifest, required=not print_fragment)
    cache = cache if cache is not None else manifest.parent / "ros_definitions"
    folders = edit.interface_folders(text or "", manifest.parent)
    found = live.discover(
        master_url=master,
        rosbridge_url=rosbridge,
        bag=bag,
        ros2=ros2,
        timeout=timeout,
        wait=wait,
        names=live.NameFilter.of(select, exclude, include_system=everything),
        dialect=_manifest_dialect(text),
        progress=_progress_printer(progress),
        search_paths=folders,
    )
    changes = _manifest_changes(found, manifest, None if print_fragment else text, cache)
    staged = stage_definitions(found, cache, search_paths=folders)
    _finish(staged, manifest, changes, dry_run=dry_run, write_manifest=not print_fragment)
    _report(
        found,
        staged,
        changes,
        manifest,
        print_fragment=print_fragment,
        as_json=as_json,
        dry_run=dry_run,
    )


def _require_one_source(
    master: str | None, rosbridge: str | None, bag: Path | None, ros2: bool
) -> None:
    if sum(s is not None for s in (master, rosbridge, bag)) + ros2 != 1:
        raise UserError(
            "give exactly one source: --master URL, --rosbridge URL, --ros2 or --bag FILE"
        )


def _manifest_changes(
    found: live.Discovery, manifest: Path, text: str | None, cache: Path
) -> edit.ManifestEdit:
    """``text`` (the manifest's) with what was found added; for None (``--print``), a fragment."""
    entry = Path(os.path.relpath(cache, manifest.parent)).as_posix()
    if text is None:
        return edit.ManifestEdit(edit.manifest_fragment(found, cache_entry=entry))
    return edit.edit_manifest(text, found, cache_entry=entry, path=str(manifest))


def _manifest_text(manifest: Path, *, required: bool) -> str | None:
    if not required and not manifest.exists():
        return None
    return edit.read_manifest(manifest)


def _manifest_dialect(text: str | None) -> Dialect | None:
    """The manifest's ``ros:`` value, used only when a source cannot tell by itself."""
    if text is None:
        return None
    for line in text.splitlines():
        key, _, value = line.partition(":")
        if key == "ros" and value.split("#")[0].strip() in ("1", "2"):
            return Dialect(int(value.split("#")[0].strip()))
    return None


def _progress_printer(forced: bool) -> live.Progress | None:
    if not (forced or sys.stderr.isatty()):
        return None

    def show(done: int, total: int, name: str) -> None:
        end = "\n" if done == total else ""
        typer.echo(f"\rprobing {done}/{total}: {name[:60]:<60}", err=True, nl=False)
        if end:
            typer.echo("", err=True)

    return show


def _finish(
    staged: StagedCache,
    manifest: Path,
    changes: edit.ManifestEdit,
    *,
    dry_run: bool,
    write_manifest: bool,
) -> None:
    """Everything was verified: move the cache into place, then write the manifest."""
    if dry_run:
        staged.discard()
        return
    staged.commit()
    if write_manifest and changes.changed:
        write_if_changed(manifest, changes.text)


def _report(
    found: live.Discovery,
    staged: StagedCache,
    changes: edit.ManifestEdit,
    manifest: Path,
    *,
    print_fragment: bool,
    as_json: bool,
    dry_run: bool,
) -> None:
    warnings = [*found.warnings, *staged.warnings]
    for warning in warnings:
        typer.echo(f"warning: {warning}", err=True)
    if as_json:
        document: dict[str, Any] = {
            **found.to_json(),
            "warnings": warnings,
            "cache": str(staged.target),
            "cache_files_changed": [p.as_posix() for p in staged.changed],
            "added_topics": list(changes.added_topics),
            "added_services": list(changes.added_services),
            "added_actions": list(changes.added_actions),
            "already_listed": list(changes.already_listed),
            "written": not dry_run,
        }
        if print_fragment:
            document["fragment"] = changes.text
        typer.echo(json.dumps(document, indent=2))
        return
    if print_fragment:
        typer.echo(changes.text, nl=False)
        return
    verb = "would add" if dry_run else "added"
    actions = bool(found.actions)
    found_counts = _counts(len(found.topics), len(found.services), len(found.actions), actions)
    added = _counts(
        len(changes.added_topics), len(changes.added_services), len(changes.added_actions), actions
    )
    typer.echo(f"found {found_counts} in {found.origin}; {verb} {added} to {manifest}")
    if changes.already_listed:
        typer.echo(f"already listed: {', '.join(changes.already_listed)}")
    typer.echo(
        f"{len(staged.changed)} definition files {'would change' if dry_run else 'written'}"
        f" in {staged.target}"
    )


def _counts(topics: int, services: int, actions: int, with_actions: bool) -> str:
    """``3 topics and 2 services``, or ``3 topics, 2 services and 1 actions``."""
    if not with_actions:
        return f"{topics} topics and {services} services"
    return f"{topics} topics, {services} services and {actions} actions"
