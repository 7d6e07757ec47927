"""Unity's ROS-TCP-Connector in one project: its pin in ``Packages/manifest.json`` and the
script GUID of its ``ROSConnection`` component.

The GUID is the one in ``Runtime/TcpConnector/ROSConnection.cs.meta`` of the package, the same
in every release from v0.5.0 to v0.7.1; an embedded copy under ``Packages/`` (committed with
the project) gives its own ``.meta``'s instead. ``Library/`` is never read.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

from unityscaffold.unity.meta import read_meta_guid
from unityscaffold.unity.values import ScriptRef

__all__ = [
    "CONNECTION_GUID",
    "DEFAULT_TAG",
    "PACKAGE",
    "PACKAGE_URL",
    "RESERVED_NAMES",
    "connection_script",
    "pin_notes",
]

PACKAGE = "com.unity.robotics.ros-tcp-connector"
DEFAULT_TAG = "v0.7.0"
#: The UPM git URL ``scaffold init --runtime ros-tcp-connector`` pins (the release Unity's
#: Robotics Hub tutorials and the matching ROS-TCP-Endpoint use; v0.7.1 works too).
PACKAGE_URL = (
    f"https://github.com/Unity-Technologies/ROS-TCP-Connector.git?path=/{PACKAGE}#{DEFAULT_TAG}"
)
CONNECTION_GUID = "7acef0b79454c9b4dae3f8139bc4ba77"
_NAMESPACE = "Unity.Robotics.ROSTCPConnector"
_META = "Runtime/TcpConnector/ROSConnection.cs.meta"
#: The package's MonoBehaviours: a generated script must not take their names.
RESERVED_NAMES = frozenset({"ROSConnection", "HudPanel", "TFAttachment"})
#: Releases whose ROSConnection (fields, GUID, endpoint protocol) the scripts are made for.
_SUPPORTED = ("0.7.0", "0.7.1")
_TAG = re.compile(r"#v?(\d+\.\d+\.\d+)")


def connection_script(project: Path) -> ScriptRef:
    """The ``m_Script`` reference of the project's ``ROSConnection``."""
    guid = read_meta_guid(str(project / "Packages" / PACKAGE / _META)) or CONNECTION_GUID
    return ScriptRef(guid, class_name="ROSConnection", namespace=_NAMESPACE)


def _pinned(project: Path) -> str | None:
    try:
        data = json.loads((project / "Packages" / "manifest.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    deps = data.get("dependencies") if isinstance(data, dict) else None
    spec = deps.get(PACKAGE) if isinstance(deps, dict) else None
    return spec if isinstance(spec, str) else None


def pin_notes(project: Path) -> tuple[str, ...]:
    """Notes when the project does not pin a release the generated scripts are made for."""
    if (project / "Packages" / PACKAGE / "package.json").is_file():
        return ()  # an embedded copy: the project's own choice
    spec = _pinned(project)
    if spec is None:
        return (
            f"Packages/manifest.json does not list {PACKAGE}; add "
            f'"{PACKAGE}": "{PACKAGE_URL}" to its dependencies (scaffold init --runtime '
            "ros-tcp-connector does this), or the generated scripts will not compile",
        )
    found = _TAG.search(spec)
    version = found.group(1) if found else spec
    if version not in _SUPPORTED:
        return (
            f"Packages/manifest.json pins {PACKAGE} {version}; the generated scripts "
            f"are made for {' and '.join(_SUPPORTED)} (its ROSConnection and the endpoint's "
            "protocol change between minor releases): pin #" + DEFAULT_TAG,
        )
    return ()
