"""The forms a URDF names a file in (``<mesh filename>``, ``<texture filename>``), told apart.

A ROS package and a path inside it: ``package://pkg/path`` (the one form ROS# 2.2.1's importer
reads, ``UrdfAssetPathHandler.GetRelativeAssetPathFromUrdfPath``) and ``$(find pkg)/path`` (a
xacro substitution left in a plain URDF). A file on disk: a ``file:`` URI (RFC 8089:
``file:///abs``, ``file://localhost/abs``, ``file:/abs``, percent-encoded), which is what
``file://$(find pkg)/…`` becomes once xacro expands it, an absolute path, or a path relative to
the URDF's folder (``../meshes/base.stl``, as some descriptions ship). Which package holds a
file on disk is ``_packages``' to find.

A ``\\`` is a folder separator in every form: ROS#'s ``SetSeparatorChar`` leaves it one on
Windows, where its samples were made, and a URDF is meant to name the same file everywhere.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from urllib.parse import unquote

__all__ = ["InPackage", "OnDisk", "Refused", "parse_filename"]

_PACKAGE_RE = re.compile(r"package://([^/]+)/(.+)|\$\(find ([^)\s]+)\)/(.+)")
_SCHEME_RE = re.compile(r"([A-Za-z][A-Za-z0-9+.-]*):")
_DRIVE_RE = re.compile(r"/?[A-Za-z]:/")


@dataclass(frozen=True, slots=True)
class InPackage:
    """``package://package/relative`` or ``$(find package)/relative``; ``relative`` may still
    hold ``..`` (the caller refuses it)."""

    package: str
    relative: PurePosixPath


@dataclass(frozen=True, slots=True)
class OnDisk:
    """A file named by where it is: ``path`` is absolute and free of ``.`` and ``..`` (without
    following symbolic links); ``form`` says how it was named, for messages."""

    path: Path
    form: str


@dataclass(frozen=True, slots=True)
class Refused:
    """A filename that names no file this tool can read; ``reason`` follows the filename in
    the error, ``hint`` says what to write instead."""

    reason: str
    hint: str


_WRITE = (
    "write package://<package>/<path>, file://$(find <package>)/<path> or a path relative "
    "to the URDF"
)


def parse_filename(filename: str, urdf_folder: Path) -> InPackage | OnDisk | Refused:
    """What ``filename`` names; a relative path is taken from ``urdf_folder`` (absolute)."""
    text = filename.replace("\\", "/")
    if text.startswith(("package://", "$(find ")):
        match = _PACKAGE_RE.fullmatch(text)
        if match is None:
            return Refused("names no file inside a ROS package", _WRITE)
        return InPackage(match[1] or match[3], PurePosixPath(match[2] or match[4]))
    scheme = _SCHEME_RE.match(text)
    if _DRIVE_RE.match(text):
        return _windows_drive()
    if scheme is not None and scheme[1].lower() == "file":
        rest = text[scheme.end() :]
        if rest.removeprefix("//").startswith("$(find "):  # a xacro's file://$(find pkg)/…
            return parse_filename(rest.removeprefix("//"), urdf_folder)
        return _file_uri(rest)
    if scheme is not None:
        return Refused(
            f"is a {scheme[1]}: URI, and only files in the repository are read",
            "copy the file into a package in the repository and " + _WRITE,
        )
    if not text:
        return Refused("is empty", _WRITE)
    if text.startswith("/"):
        return OnDisk(_normal(Path(text)), "absolute path")
    return OnDisk(_normal(urdf_folder / text), "path relative to the URDF")


def _file_uri(rest: str) -> OnDisk | Refused:
    """The file of a ``file:`` URI after its ``file:``."""
    if rest.startswith("//"):
        host, slash, path = rest[2:].partition("/")
        if host.lower() not in ("", "localhost"):
            return Refused(
                f"names a file on the host {host!r}",
                "a file:// URI needs three slashes (file:///<absolute path>); " + _WRITE,
            )
        rest = slash + path
    if not rest.startswith("/"):
        return Refused("is a file: URI without an absolute path", _WRITE)
    path = unquote(rest)  # RFC 8089: a URI's path is percent-encoded (%20 is a space)
    if _DRIVE_RE.match(path):
        return _windows_drive()
    return OnDisk(_normal(Path(path)), "file URI")


def _windows_drive() -> Refused:
    return Refused(
        "names a file on a Windows drive, outside the repository",
        "name the file inside a package of the repository: " + _WRITE,
    )


def _normal(path: Path) -> Path:
    # '..' is taken away by the text, as a URI's dot segments are (RFC 3986 5.2.4); where the
    # file really is, after symbolic links, is checked by the caller
    return Path(os.path.normpath(path))
