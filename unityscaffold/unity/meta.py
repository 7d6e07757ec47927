"""``.meta`` files: deterministic GUIDs and the layouts Unity writes for scripts and folders.

A GUID is ``md5(salt + ":" + project-relative posix path)``: stable for the same project and
path on any machine, different between projects. An existing ``.meta`` always wins: its GUID is
read, never replaced, so references to existing assets stay valid.
"""

from __future__ import annotations

import hashlib
import re
from pathlib import Path, PurePosixPath

__all__ = [
    "folder_meta",
    "guid_for",
    "meta_guid",
    "monoscript_meta",
    "native_format_meta",
    "read_meta_guid",
]

_GUID_LINE_RE = re.compile(r"^guid: ([0-9a-f]{32})\s*$", re.M)
_DRIVE_RE = re.compile(r"[A-Za-z]:")  # compiled once: guid_for runs for every generated file


def _reserved(guid: str) -> bool:
    # all zeros is "none"; 0000000000000000e000…/f000… are Unity's built-in resources
    return guid.startswith("0" * 16)


def guid_for(salt: str, asset_path: str) -> str:
    """The GUID for ``asset_path`` (project-relative, e.g. ``Assets/Scripts/Foo.cs``)."""
    posix = asset_path.replace("\\", "/")
    if not posix or posix.startswith("/") or _DRIVE_RE.match(posix):
        raise ValueError(f"asset path must be relative to the project root: {asset_path!r}")
    parts = posix.split("/")
    # A path with no empty or "." part is already in normal form; PurePosixPath (a tenth of the
    # cost of this function, which runs for every generated file) is for the others.
    normal = PurePosixPath(posix).as_posix() if "" in parts or "." in parts else posix
    seed, attempt = f"{salt}:{normal}", 0
    while True:
        data = seed if attempt == 0 else f"{seed}#{attempt}"
        guid = hashlib.md5(data.encode("utf-8")).hexdigest()
        if not _reserved(guid):
            return guid
        attempt += 1


def monoscript_meta(guid: str) -> str:
    """A ``.cs.meta`` as Unity 2018.3+ writes it (empty values keep their trailing space)."""
    return (
        "fileFormatVersion: 2\n"
        f"guid: {guid}\n"
        "MonoImporter:\n"
        "  externalObjects: {}\n"
        "  serializedVersion: 2\n"
        "  defaultReferences: []\n"
        "  executionOrder: 0\n"
        "  icon: {instanceID: 0}\n"
        "  userData: \n"
        "  assetBundleName: \n"
        "  assetBundleVariant: \n"
    )


def folder_meta(guid: str) -> str:
    """A folder's ``.meta``."""
    return (
        "fileFormatVersion: 2\n"
        f"guid: {guid}\n"
        "folderAsset: yes\n"
        "DefaultImporter:\n"
        "  externalObjects: {}\n"
        "  userData: \n"
        "  assetBundleName: \n"
        "  assetBundleVariant: \n"
    )


def native_format_meta(guid: str, main_object_file_id: int) -> str:
    """The ``.meta`` of a file Unity saves in its own format (``.mat``, ``.asset``)."""
    return (
        "fileFormatVersion: 2\n"
        f"guid: {guid}\n"
        "NativeFormatImporter:\n"
        "  externalObjects: {}\n"
        f"  mainObjectFileID: {main_object_file_id}\n"
        "  userData: \n"
        "  assetBundleName: \n"
        "  assetBundleVariant: \n"
    )


def read_meta_guid(path: str | Path) -> str | None:
    """The GUID in a ``.meta`` file, or None if the file is missing or has none."""
    try:  # open() rather than Path.read_text: no path object to build per file of a package
        with open(path, encoding="utf-8", errors="replace") as handle:
            text = handle.read()
    except (FileNotFoundError, NotADirectoryError, IsADirectoryError):
        return None
    match = _GUID_LINE_RE.search(text)
    return match.group(1) if match else None


def meta_guid(meta_path: str | Path, salt: str, asset_path: str) -> str:
    """The GUID an asset has (from its existing ``.meta``) or will get (deterministically)."""
    return read_meta_guid(meta_path) or guid_for(salt, asset_path)
