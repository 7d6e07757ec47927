"""Reading a URDF file: XML, then the grammar, then the tree checks, all problems at once."""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from pathlib import Path

from unityscaffold.errors import DiagnosticSink, UserError
from unityscaffold.urdf._reader import read_robot
from unityscaffold.urdf._tree import check_tree
from unityscaffold.urdf._xacro import expand_xacro, is_xacro
from unityscaffold.urdf._xml import XmlSource, parse_xml
from unityscaffold.urdf.model import Robot

__all__ = ["parse_urdf", "read_urdf"]


def parse_urdf(raw: bytes, path: str = "<urdf>") -> Robot:
    """The robot in ``raw`` (a URDF's bytes); every problem is a diagnostic of one
    ``LocatedError`` (``path:line:col: message`` and a hint)."""
    source = XmlSource(path, raw)
    document = parse_xml(source)
    sink = DiagnosticSink()
    robot = read_robot(source, document, sink)
    if robot is not None:
        complete = len(robot.joints) == len(document.elements("joint")) and len(robot.links) == len(
            document.elements("link")
        )
        check_tree(robot, sink, complete=complete)
    sink.raise_if_errors()
    assert robot is not None  # read_robot gives None only after an error
    return robot


def read_urdf(
    path: str | Path,
    *,
    packages: Mapping[str, Path] | None = None,
    xacro_args: Mapping[str, str] | None = None,
    xacro_env: Mapping[str, str] | None = None,
) -> Robot:
    """The robot in the URDF file at ``path``; a ``.xacro`` file is expanded first, its
    ``$(find)`` resolved through ``packages``, its ``$(arg)`` given by ``xacro_args`` and its
    ``$(env)`` and ``$(optenv)`` by ``xacro_env``."""
    path = Path(path)
    try:
        if is_xacro(path) and path.is_file():
            expanded = expand_xacro(
                path, packages=packages or {}, args=xacro_args or {}, env=xacro_env or {}
            )
            # the expanded URDF has no file of its own: its lines are the xacro output's
            robot = parse_urdf(expanded.urdf, f"{path} (expanded by xacro)")
            return dataclasses.replace(robot, notes=expanded.warnings)
        raw = path.read_bytes()
    except OSError as error:
        raise UserError(
            f"cannot read the URDF {str(path)!r}: {error.strerror or error}",
            hint="check the path (a .urdf or .xacro file)",
        ) from None
    return parse_urdf(raw, str(path))
