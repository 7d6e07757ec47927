"""Reading the ``robots`` entries: a URDF, where its packages are, and how the robot is kept."""

from __future__ import annotations

import re
from pathlib import Path

from unityscaffold.manifest import _spec as spec
from unityscaffold.manifest._entries import Context, locations, read_scene
from unityscaffold.manifest._objects import read_vector
from unityscaffold.manifest._paths import folder_path, project_path
from unityscaffold.manifest._read import Reader
from unityscaffold.manifest._spec_robots import ENV_NAME, ROBOT, URDF_SUFFIX
from unityscaffold.manifest._yaml import YEntry, YMap, YNode, YScalar
from unityscaffold.manifest.robot_entry import RobotEntry

__all__ = ["read_robot"]

EXPECT_URDF = "a .urdf or .xacro file, relative to the manifest, such as ros/my_robot.urdf"
EXPECT_ASSETS = "a folder inside Assets/, such as Assets/Urdf/r2d2"
_PACKAGE = re.compile(r"^[A-Za-z0-9_.-]+$")
_NEWLINES = {"crlf": "\r\n", "lf": "\n"}


def read_robot(r: Reader, node: YNode, ctx: Context, base: Path) -> RobotEntry | None:
    """One entry; None (after reporting why) when it cannot be used."""
    m = r.mapping(node, ROBOT)
    if m is None:
        return None
    urdf = _urdf(r, m, base)
    gameobject = r.text(m, "gameobject", "a hierarchy path such as World/r2d2", spec.GAMEOBJECT)
    scene = read_scene(r, m, ctx, "robot")
    assets = None
    if (entry := m.get("assets")) is not None:
        value = r.text(m, "assets", EXPECT_ASSETS)
        if value is not None:
            assets = project_path(r, entry, value, ctx.project_root, expected=EXPECT_ASSETS)
            if assets is not None and not assets.startswith("Assets/"):
                r.invalid(entry, EXPECT_ASSETS, hint="Unity imports only what is in Assets/")
                assets = None
    newline = r.choice(m, "plugin_newline", list(_NEWLINES)) or "crlf"
    item = RobotEntry(
        urdf=urdf or base,
        scene=scene or "",
        locations=locations(m),
        gameobject=gameobject,
        packages=_packages(r, m, base),
        assets=assets,
        position=read_vector(r, m, "position", 3),  # type: ignore[arg-type]
        rotation=read_vector(r, m, "rotation", 3),  # type: ignore[arg-type]
        kinematic=r.boolean(m, "kinematic"),
        gravity=r.boolean(m, "gravity"),
        convex=r.boolean(m, "convex"),
        plugin_newline=_NEWLINES[newline],
        args=_texts(r, m, "args", "xacro argument name", "{prefix: left_}"),
        env=_texts(r, m, "env", "environment variable name", "{HUSKY_LMS1XX_ENABLED: '1'}"),
    )
    return item if urdf is not None and scene else None


def _urdf(r: Reader, m: YMap, base: Path) -> Path | None:
    value = r.text(m, "urdf", EXPECT_URDF, URDF_SUFFIX)
    entry = m.get("urdf")
    if value is None or entry is None:
        return None
    if "\\" in value:
        r.invalid(entry, EXPECT_URDF, hint="write '/' between folders")
        return None
    return base / value  # that it exists is apply's to check, as for `interfaces`


def _packages(r: Reader, m: YMap, base: Path) -> tuple[tuple[str, Path], ...]:
    entry = m.get("packages")
    if entry is None or (isinstance(entry.value, YScalar) and entry.value.value is None):
        return ()
    if not isinstance(entry.value, YMap):
        r.invalid(entry, "a mapping of package name to folder, such as {my_robot: ros/my_robot}")
        return ()
    found = []
    for item in entry.value.entries:
        if not _PACKAGE.match(item.key) or item.key in (".", ".."):
            r.error(
                item.key_location,
                f"invalid package name '{item.key}'",
                expected="a ROS package name: letters, digits, '_', '-' or '.'",
            )
            continue
        value = item.value.value if isinstance(item.value, YScalar) else None
        if not isinstance(value, str) or not value:
            r.invalid(item, "a folder relative to the manifest, such as ros/my_robot")
            continue
        folder = folder_path(
            r, YEntry(item.key, item.key_location, item.value), value, base, allow_absolute=True
        )
        if folder is not None:
            found.append((item.key, folder))
    return tuple(found)


def _texts(r: Reader, m: YMap, key: str, name: str, example: str) -> tuple[tuple[str, str], ...]:
    """A mapping of names to text (``args``, ``env``); a value that is not text (a number, a
    boolean, null, a list) is an error at it, since xacro would see its YAML spelling."""
    entry = m.get(key)
    if entry is None or (isinstance(entry.value, YScalar) and entry.value.value is None):
        return ()
    if not isinstance(entry.value, YMap):
        r.invalid(entry, f"a mapping of {name} to text, such as {example}")
        return ()
    found = []
    for item in entry.value.entries:
        if key == "env" and not re.fullmatch(ENV_NAME, item.key):
            r.error(
                item.key_location,
                f"invalid environment variable name '{item.key}'",
                expected="a name xacro can write in $(env NAME): no spaces, '(', ')' or '$'",
            )
            continue
        value = item.value.value if isinstance(item.value, YScalar) else None
        if not isinstance(value, str):
            r.invalid(item, "text (quote numbers and booleans: '0.5', 'true')")
            continue
        found.append((item.key, value))
    return tuple(found)
