"""ROS#'s catalog: the committed data is exactly what the extractor derives from ROS#'s sources,
and it holds the facts the rest of the tool relies on.

``unityscaffold/unity/rossharp_catalog.json`` is written by ``scripts/update_rossharp_catalog.py``
from ROS# 2.2.1's ``com.siemens.ros-sharp`` (``UNITYSCAFFOLD_ROSSHARP``) and the table of every
release's script GUIDs (``UNITYSCAFFOLD_ROSSHARP_GUIDS``); both default to the vendored copies
beside the repository. Without them the regeneration test skips locally and fails under CI=true.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from helpers import require, text_diff

from unityscaffold.unity.catalog import imported_by_unity, rossharp_catalog, scripts_fingerprint

REPO = Path(__file__).resolve().parents[2]
SCRIPT = REPO / "scripts" / "update_rossharp_catalog.py"
COMMITTED = REPO / "unityscaffold" / "unity" / "rossharp_catalog.json"
VENDOR = REPO.parent / "shared" / "vendor" / "ros-sharp"


def test_the_catalog_is_what_the_script_derives_from_rossharp(tmp_path: Path) -> None:
    package = Path(
        os.environ.get("UNITYSCAFFOLD_ROSSHARP", VENDOR / "2.2.1" / "com.siemens.ros-sharp")
    )
    guids = Path(os.environ.get("UNITYSCAFFOLD_ROSSHARP_GUIDS", VENDOR / "script-guids.tsv"))
    require(
        (package / "Runtime").is_dir() and guids.is_file(),
        "ROS# 2.2.1's com.siemens.ros-sharp and its GUID table "
        "(UNITYSCAFFOLD_ROSSHARP, UNITYSCAFFOLD_ROSSHARP_GUIDS)",
    )
    out = tmp_path / "catalog.json"
    result = subprocess.run(
        [sys.executable, str(SCRIPT), str(package), str(guids), "--output", str(out)],
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, result.stderr
    expected, actual = COMMITTED.read_bytes(), out.read_bytes()
    assert actual == expected, text_diff(
        expected, actual, "unityscaffold/unity/rossharp_catalog.json"
    )


def test_guids_follow_rossharps_releases() -> None:
    connector = rossharp_catalog().named("RosConnector")
    assert connector is not None
    # ROS# regenerated every GUID in 2.1.0 and restored the old ones in 2.2.1.
    assert dict(connector.guids) == {
        "2.0.0": "ff98778ae051cfd40a6e4effdf851ebd",
        "2.1.0": "9fb7d56afaa30534e9a7dc10102f9a83",
        "2.1.1": "9fb7d56afaa30534e9a7dc10102f9a83",
        "2.2.0": "9fb7d56afaa30534e9a7dc10102f9a83",
        "2.2.1": "ff98778ae051cfd40a6e4effdf851ebd",
    }


def test_fields_include_inherited_ones_first_with_their_types() -> None:
    subscriber = rossharp_catalog().named("TwistSubscriber")
    assert subscriber is not None
    assert subscriber.bases == ("UnitySubscriber", "MonoBehaviour")
    assert subscriber.requires == ("RosConnector",)
    assert [(f.name, f.csharp, f.unity) for f in subscriber.fields] == [
        ("Topic", "string", "string"),
        ("TimeStep", "float", "float"),
        ("EnsureThreadSafety", "bool", "bool"),
        ("SubscribedTransform", "Transform", "ref:Transform"),
    ]


def test_enums_hidden_and_list_fields() -> None:
    catalog = rossharp_catalog()
    connector = catalog.named("RosConnector")
    publisher = catalog.named("JointStatePublisher")
    assert connector is not None and publisher is not None
    # [HideInInspector] fields are still serialized; properties (RosSocket) are not fields.
    assert [f.name for f in connector.fields] == [
        "selectedRosVersion",
        "SecondsTimeout",
        "Serializer",
        "protocol",
        "RosBridgeServerUrl",
    ]
    assert catalog.enums["RosSharp.RosBridgeClient.RosVersion"] == {"ROS1": 0, "ROS2": 1}
    readers = publisher.field("JointStateReaders")
    assert readers is not None
    assert readers.unity == "ref:RosSharp.RosBridgeClient.JointStateReader[]"


def test_abstract_generic_and_editor_classes_are_not_attachable() -> None:
    catalog = rossharp_catalog()
    flags = {s.class_name: s.attachable for s in catalog.scripts}
    assert not flags["UnityPublisher"] and not flags["JoyAxisWriter"]
    assert not flags["RosConnectorEditor"] and not flags["UrdfJoint"]
    assert flags["UrdfJointRevolute"] and flags["JointStatePatcher"]
    assert sum(flags.values()) == 51


def test_every_release_has_a_fingerprint_of_its_own() -> None:
    catalog = rossharp_catalog()
    assert sorted(catalog.fingerprints.values()) == sorted(catalog.releases)


def test_a_fingerprint_counts_what_unity_imports_and_nothing_else() -> None:
    scripts = [("Runtime/A.cs", "1" * 32), ("Editor/B.cs", "2" * 32)]
    extra = [("Samples~/S/C.cs", "3" * 32), (".hidden/D.cs", "4" * 32)]
    assert scripts_fingerprint(scripts + extra) == scripts_fingerprint(reversed(scripts))
    assert scripts_fingerprint(scripts) != scripts_fingerprint(
        [*scripts[:1], ("Editor/B.cs", "5" * 32)]
    )
    assert imported_by_unity("Runtime/X~y.cs") and not imported_by_unity("X~/y.cs")
