"""Options shared by several commands, so they read and behave the same everywhere."""

from __future__ import annotations

import os
from pathlib import Path

import typer

from unityscaffold.errors import UserError
from unityscaffold.interfaces.model import Dialect
from unityscaffold.manifest.runtime import Runtime

RosOption: int | None = typer.Option(
    None,
    "--ros",
    metavar="1|2",
    help="ROS version whose rules apply. Default: $ROS_VERSION when set, else 2.",
)
PathOption: list[Path] = typer.Option(
    [],
    "--path",
    metavar="DIR",
    help="Folder to search for ROS packages before the ROS environment and the built-in "
    "definitions; repeatable.",
)
JsonOption: bool = typer.Option(False, "--json", help="Print JSON for scripts.")


def dialect_of(ros: int | None) -> Dialect:
    """The dialect for ``--ros``, falling back to ``$ROS_VERSION`` and then ROS 2."""
    if ros is None:
        env = os.environ.get("ROS_VERSION", "").strip()
        ros = int(env) if env in ("1", "2") else 2
    if ros not in (1, 2):
        raise UserError(f"--ros must be 1 or 2, not {ros}")
    return Dialect(ros)


NoEnvOption: bool = typer.Option(
    False,
    "--no-env",
    help="Ignore the ROS environment (ROS_PACKAGE_PATH, AMENT_PREFIX_PATH, /opt/ros, /usr/share): "
    "search only --path folders and the built-in standard definitions.",
)


MANIFEST_NAME = "robot.yaml"


def find_manifest(given: Path | None) -> Path:
    """``given``, or the nearest ``robot.yaml`` from the current folder upward, as git looks for
    ``.git``: the search ends at the folder holding ``.git`` (a repository's root) or at the
    file system's root. A manifest found above is returned relative to the current folder
    (``../robot.yaml``), so messages name it as the user would type it. Nothing found gives
    ``robot.yaml``, which the command then reports as missing.
    """
    if given is not None:
        return given
    here = Path.cwd()
    for folder in (here, *here.parents):
        candidate = folder / MANIFEST_NAME
        if candidate.is_file():
            return Path(MANIFEST_NAME) if folder == here else Path(os.path.relpath(candidate))
        if (folder / ".git").exists():
            break
    return Path(MANIFEST_NAME)


RuntimeOption: str = typer.Option(
    "ros-sharp",
    "--runtime",
    metavar="ros-sharp|ros-tcp-connector",
    help="The Unity library to talk to ROS through: Siemens' ROS# (rosbridge) or Unity's "
    "ROS-TCP-Connector (ROS-TCP-Endpoint).",
)


def runtime_of(text: str) -> Runtime:
    """The runtime ``--runtime`` names."""
    choices = [r.value for r in Runtime]
    if text not in choices:
        raise UserError(
            f"--runtime must be {' or '.join(choices)}, not {text}",
            hint="ros-sharp is Siemens' ROS#; ros-tcp-connector is Unity's ROS-TCP-Connector",
        )
    return Runtime(text)
