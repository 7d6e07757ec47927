"""The installed ROS# package: its version and the GUIDs of its runtime scripts.

GUIDs come from the installed package's own ``.meta`` files when Unity has fetched it (under
``Library/PackageCache``, ``Packages/`` or ``Assets/``); otherwise from the table of release
GUIDs, chosen by the version pinned in ``Packages/manifest.json``. ROS# regenerated every GUID
in 2.1.0 and restored the old ones in 2.2.1, so the version matters.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path

from unityscaffold.errors import UserError
from unityscaffold.unity.project import ScriptInfo
from unityscaffold.unity.values import ScriptRef

__all__ = ["DEFAULT_VERSION", "PACKAGE", "STOCK_SCRIPTS", "RosSharp"]

PACKAGE = "com.siemens.ros-sharp"
DEFAULT_VERSION = "2.2.1"
_RESTORED = {
    "RosConnector": "ff98778ae051cfd40a6e4effdf851ebd",
    "UnityPublisher": "3dcd201cdffc8b841b83588f9c4d4496",
    "UnitySubscriber": "0ae61387da9572f4d9d978ebf49e975c",
    "UnityServiceProvider": "df225416703218b4f9010633994aef66",
    "TwistPublisher": "606c7a0f1a4d07d4a8d2259a5a5bcfe4",
    "JoyPublisher": "92dedf3f173285b4d9a806dec2334596",
    "PoseStampedPublisher": "aa23b622c60c13f48bdfa74b2e974f20",
    "JointStatePublisher": "aae1d8da5a3c0644bb98a540ca597dfb",
    "OdometrySubscriber": "57574a16cdc8b64408e42846c7ae13fd",
    "CompressedImageSubscriber": "c7aa53353797a634581932ea902c2832",
    "RawImageSubscriber": "1629fa27836f759449638b17051e27a6",
    "ImagePublisher": "a908e83b1e7ce9e428caae2838615cc3",
    "JointStateSubscriber": "4fe4cf3b1dd3507418f7ec019f9193ff",
    "TwistSubscriber": "81c5dfb51482c2e47b602e8096d45712",
    "JoySubscriber": "ac3b5c497c54f1b4ab2a96f69bc1586d",
}
_REGENERATED = {
    "RosConnector": "9fb7d56afaa30534e9a7dc10102f9a83",
    "UnityPublisher": "68e31323d2c44f9439e8a4beabf73713",
    "UnitySubscriber": "12ca650114b9ffd439079813edaad695",
    "UnityServiceProvider": "4cf69fc58f219014c93bec73d198cb03",
    "TwistPublisher": "cb5746de853b0c349a0bf251014a451a",
    "JoyPublisher": "65716945d6900964bab8ddfe8be224ff",
    "PoseStampedPublisher": "1b92c95b8e255164b807be06867549a2",
    "JointStatePublisher": "7d43cfd4b13164542998c18e3158bba9",
    "OdometrySubscriber": "bc602252119c10048bcfde9ed59708f3",
    "CompressedImageSubscriber": "27c6d8c44bb45894991c39b55105a85b",
    "RawImageSubscriber": "3736584ded6b65644b6b0925a3a2cb1c",
    "ImagePublisher": "95b94268b572270479500d7d77a37335",
}
# ROS#'s stock components, all built on UnityPublisher/UnitySubscriber/UnityServiceProvider,
# which carry [RequireComponent(typeof(RosConnector))]. (The 2.1.0-2.2.0 table lacks the GUIDs of
# the last three subscribers; with such a pin they resolve only from the installed package.)
STOCK_SCRIPTS = frozenset(_RESTORED) - {
    "RosConnector",
    "UnityPublisher",
    "UnitySubscriber",
    "UnityServiceProvider",
} | {"StringPublisher", "StringSubscriber", "GetParamServiceProvider"}
RESERVED_NAMES = frozenset(_RESTORED) | STOCK_SCRIPTS
_VERSION = re.compile(r"#v?(\d+)\.(\d+)\.(\d+)")


def _version_tuple(text: str) -> tuple[int, int, int] | None:
    match = _VERSION.search(text)
    return (int(match[1]), int(match[2]), int(match[3])) if match else None


def pinned_version(project: Path) -> str | None:
    """The ROS# tag pinned in ``Packages/manifest.json`` (``…ros-sharp.git?path=…#2.2.1``)."""
    try:
        data = json.loads((project / "Packages" / "manifest.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    spec = data.get("dependencies", {}).get(PACKAGE) if isinstance(data, dict) else None
    if not isinstance(spec, str):
        return None
    found = _version_tuple(spec)
    return ".".join(map(str, found)) if found else spec


@dataclass(frozen=True, slots=True)
class RosSharp:
    """Where ROS#'s scripts are, for one Unity project."""

    version: str | None
    installed: dict[str, str]  # class name -> GUID, from the package's own .meta files

    @classmethod
    def of(cls, project: Path, scripts: dict[str, ScriptInfo]) -> RosSharp:
        installed = {
            info.class_name: guid
            for guid, info in sorted(scripts.items())
            if "ros-sharp" in info.path or "RosBridgeClient" in info.path
        }
        return cls(pinned_version(project), installed)

    def _table(self) -> dict[str, str]:
        found = _version_tuple("#" + (self.version or DEFAULT_VERSION))
        if found and (2, 1, 0) <= found <= (2, 2, 0):
            return _REGENERATED
        return _RESTORED

    def knows(self, class_name: str) -> bool:
        return class_name in self.installed or class_name in _RESTORED

    def script(self, class_name: str) -> ScriptRef:
        """The ``m_Script`` reference of a ROS# runtime script."""
        guid = self.installed.get(class_name)
        if guid is None and (self.installed or self.version is not None):
            guid = self._table().get(class_name)
        if guid is None:
            raise UserError(
                f"cannot find ROS#'s {class_name} script: ROS# is not installed in this project",
                hint=f'add "{PACKAGE}": "https://github.com/siemens/ros-sharp.git?path=/{PACKAGE}'
                f'#{DEFAULT_VERSION}" to Packages/manifest.json (scaffold init does this)',
            )
        return ScriptRef(guid, class_name=class_name, namespace="RosSharp.RosBridgeClient")
