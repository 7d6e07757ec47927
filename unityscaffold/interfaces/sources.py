"""Where interface definitions are looked for, and which packages are found there.

Order (the first definition of a type wins): folders the user gives; the ROS environment
(``ROS_PACKAGE_PATH`` for ROS 1, ``AMENT_PREFIX_PATH`` for ROS 2, ``CMAKE_PREFIX_PATH``,
``/opt/ros/<distro>``, Debian's ``/usr/share``, and the Python prefix where the PyPI ROS 2
wheels install); last, the definitions built into unityscaffold, so that the standard
interfaces resolve on a machine with no ROS at all.

A package is a folder with a ``msg/``, ``srv/`` or ``action/`` child. Its name comes from
``package.xml`` when there is one, else from the folder's own name; never from where generated
code is written (ROS# issue #480).
"""

from __future__ import annotations

import os
import re
import sys
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from unityscaffold.errors import SourceLocation
from unityscaffold.interfaces.model import Dialect, InterfaceKind

__all__ = [
    "InterfaceFile",
    "PackageDir",
    "SearchRoot",
    "builtin_root",
    "find_packages",
    "package_name_location",
    "search_roots",
]

_ROS1_DISTROS = frozenset(
    [
        "boxturtle",
        "cturtle",
        "diamondback",
        "electric",
        "fuerte",
        "groovy",
        "hydro",
        "indigo",
        "jade",
        "kinetic",
        "lunar",
        "melodic",
        "noetic",
    ]
)
_SUBDIRS = tuple(kind.value for kind in InterfaceKind)
_SKIP_DIRS = frozenset({"build", "devel", "log", "node_modules", "__pycache__"})
_PACKAGE_NAME = re.compile(r"<name>\s*([^<\s]+)\s*</name>")


@dataclass(frozen=True, slots=True)
class SearchRoot:
    """A folder to search, and why it is searched (shown to users)."""

    path: Path
    origin: str
    recursive: bool = True


@dataclass(frozen=True, slots=True)
class InterfaceFile:
    package: str
    name: str
    kind: InterfaceKind
    path: Path
    origin: str = ""


@dataclass(frozen=True, slots=True)
class PackageDir:
    name: str
    path: Path
    origin: str

    def files(self) -> Iterator[InterfaceFile]:
        """The package's interface files, sorted by kind and name."""
        for kind in InterfaceKind:
            folder = self.path / kind.value
            try:
                entries = sorted(os.listdir(folder))
            except OSError:
                continue
            for entry in entries:
                if entry.endswith(kind.suffix) and not entry.startswith("."):
                    yield InterfaceFile(
                        self.name, entry[: -len(kind.suffix)], kind, folder / entry, self.origin
                    )


def builtin_root(dialect: Dialect) -> Path:
    return Path(__file__).parent / "builtin" / f"ros{int(dialect)}"


def _split_env(value: str | None) -> list[Path]:
    return [Path(p) for p in (value or "").split(os.pathsep) if p]


def _opt_ros_shares(dialect: Dialect) -> list[Path]:
    try:
        distros = sorted(os.listdir("/opt/ros"))
    except OSError:
        return []
    wanted = [d for d in distros if (d in _ROS1_DISTROS) == (dialect is Dialect.ROS1)]
    return [Path("/opt/ros") / d / "share" for d in wanted]


def search_roots(
    dialect: Dialect,
    user_paths: Sequence[Path | str] = (),
    *,
    environ: Mapping[str, str] | None = None,
    use_environment: bool = True,
    use_builtin: bool = True,
) -> list[SearchRoot]:
    """Every folder to search, in priority order."""
    env = os.environ if environ is None else environ
    roots = [SearchRoot(Path(p), "given path") for p in user_paths]
    if use_environment:
        if dialect is Dialect.ROS1:
            roots += [
                SearchRoot(p, "ROS_PACKAGE_PATH") for p in _split_env(env.get("ROS_PACKAGE_PATH"))
            ]
        else:
            roots += [
                SearchRoot(p / "share", "AMENT_PREFIX_PATH", recursive=False)
                for p in _split_env(env.get("AMENT_PREFIX_PATH"))
            ]
        roots += [
            SearchRoot(p / "share", "CMAKE_PREFIX_PATH", recursive=False)
            for p in _split_env(env.get("CMAKE_PREFIX_PATH"))
        ]
        roots += [SearchRoot(p, "/opt/ros", recursive=False) for p in _opt_ros_shares(dialect)]
        if dialect is Dialect.ROS1:
            roots.append(SearchRoot(Path("/usr/share"), "Debian packages", recursive=False))
        else:
            prefix_share = Path(sys.prefix) / "share"
            if (prefix_share / "ament_index").is_dir():
                roots.append(
                    SearchRoot(prefix_share, "Python prefix (ROS 2 wheels)", recursive=False)
                )
    if use_builtin:
        roots.append(SearchRoot(builtin_root(dialect), "built-in", recursive=False))
    return roots


def _is_package(path: Path | str) -> bool:
    # Called for every folder of /usr/share, most of which have none of the three children:
    # strings joined once, and os.access, which answers "missing" without raising (an
    # exception per missing child cost isdir more than its system call).
    prefix = os.path.join(path, "")
    for sub in _SUBDIRS:
        child = prefix + sub
        if os.access(child, os.F_OK) and os.path.isdir(child):
            return True
    return False


def package_name(path: Path) -> str:
    """The name in ``package.xml`` if the folder has one, else the folder's name."""
    try:
        text = (path / "package.xml").read_text(encoding="utf-8", errors="replace")
    except OSError:
        return path.name
    match = _PACKAGE_NAME.search(text)
    return match.group(1) if match else path.name


def package_name_location(interface_file: str | None, package: str) -> SourceLocation:
    """Where the name of the package holding ``interface_file`` (``PKG/msg/Name.msg``) is
    written: its ``package.xml`` name, with line and column, or else the package folder, whose
    name it is. For an error about the package name itself; reads the file again on purpose,
    as only a failing run needs the place."""
    if interface_file is None:
        return SourceLocation(package)
    folder = Path(interface_file).parent.parent
    manifest = folder / "package.xml"
    try:
        text = manifest.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return SourceLocation(str(folder))
    match = _PACKAGE_NAME.search(text)
    if match is None:
        return SourceLocation(str(folder))
    start = match.start(1)
    line = text.count("\n", 0, start)
    col = start - (text.rfind("\n", 0, start) + 1)
    return SourceLocation(str(manifest), line + 1, col + 1, text.splitlines()[line])


def _walk(root: SearchRoot) -> Iterator[Path]:
    if not root.path.is_dir():
        return
    if _is_package(root.path):
        yield root.path
        if not root.recursive:
            return
    if not root.recursive:
        for entry in sorted(os.scandir(root.path), key=lambda e: e.name):
            if entry.is_dir() and not entry.name.startswith(".") and _is_package(entry.path):
                yield Path(entry.path)
        return
    for current, dirs, _files in os.walk(root.path):
        dirs[:] = sorted(
            d for d in dirs if not d.startswith(".") and d not in _SKIP_DIRS and d not in _SUBDIRS
        )
        for d in dirs:
            candidate = Path(current) / d
            if _is_package(candidate):
                yield candidate


def find_packages(roots: Sequence[SearchRoot]) -> list[PackageDir]:
    """Every package under the roots, in priority order (a name may appear more than once)."""
    found: list[PackageDir] = []
    seen: set[Path] = set()
    for root in roots:
        for path in _walk(root):
            resolved = path.resolve()
            if resolved not in seen:
                seen.add(resolved)
                found.append(PackageDir(package_name(path), path, root.origin))
    return found
