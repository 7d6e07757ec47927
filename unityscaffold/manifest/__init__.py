"""The manifest stage: ``robot.yaml`` read into a typed, validated, located model.

``load_manifest`` reads a file, ``parse_manifest`` text; both raise ``LocatedError`` (with every
problem found, sorted by position) or ``UserError``. The returned ``Manifest`` has every default
applied and every path resolved; nothing is resolved against ROS or the Unity project yet
(unknown types and missing GameObjects are the ``apply`` stage's to report, at the locations
kept in each item's ``locations``). The package's ``schema/robot.schema.json`` is the same key
table as JSON Schema, for editors.
"""

from unityscaffold.manifest.loader import load_manifest, parse_manifest
from unityscaffold.manifest.model import (
    Action,
    Component,
    Connector,
    Manifest,
    ObjectPath,
    Service,
    Topic,
    default_class_name,
)
from unityscaffold.manifest.starter import starter_manifest

__all__ = [
    "Action",
    "Component",
    "Connector",
    "Manifest",
    "ObjectPath",
    "Service",
    "Topic",
    "default_class_name",
    "load_manifest",
    "parse_manifest",
    "starter_manifest",
]
