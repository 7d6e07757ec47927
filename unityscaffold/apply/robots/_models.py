"""A robot's mesh geometries in its scene: each the instance of a prefab or model.

The urdf stage decides what each ``<mesh>`` visual and collision is (``RobotImport.models``:
the source asset, the changes ROS#'s importer leaves, the components it removes and adds;
``urdf.models``); this places one: a fileID for each of its documents from the object's URDF
key, the GUIDs of the robot's assets, the Transform it sits under, and UrdfRobot's "Convex"
switch on the colliders it adds. The documents are owned whole (``unity.owned``).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from unityscaffold.unity.owned import OwnedDocument
from unityscaffold.unity.prefabinstance import ModelInstance, instance_documents

__all__ = ["model_documents"]

FileId = Callable[[str, str, int], int]
#: The class of each document an instance adds, by the first part of its scene role.
_ROLE_CLASSES = {"instance": 1001, "transform": 4, "gameobject": 1, "collider": 64}


def model_documents(
    instance: ModelInstance,
    *,
    key: str,
    file_id: FileId,
    parent: int,
    guids: Mapping[str, str],
    convex: bool | None,
) -> tuple[int, list[OwnedDocument]]:
    """The fileID of the instance root's stripped Transform (its parent lists it among its
    children) and the instance's documents under
    the Transform ``parent``; ``file_id(key, role, class_id)`` names each document, ``guids``
    the robot's assets by their path in its folder."""
    if convex is not None:
        instance = instance.with_convex(convex)
    ids = {}
    for role in instance.scene_roles():
        # named apart from a GameObject's own: a mesh that becomes a box gets its fileIDs
        # anew, not the stripped Transform's
        ids[role] = file_id(key, f"model {role}", _ROLE_CLASSES[role.split(":", 1)[0]])
    laid = instance_documents(instance, parent=parent, ids=ids, guid_of=guids.__getitem__)
    documents = [OwnedDocument(_class_id(text), i, text) for i, text in laid]
    return ids["transform"], documents


def _class_id(text: str) -> int:
    """The class of a document from its header (``--- !u!1001 &…``)."""
    return int(text.split(" ", 2)[1].removeprefix("!u!"))
