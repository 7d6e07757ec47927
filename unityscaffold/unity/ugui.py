"""uGUI's scripts (``com.unity.ugui``) by class name, for manifests that name them.

A uGUI script's GUID is the same in every project (its ``.cs.meta`` ships with the package), so
``script: Image`` needs neither ``Library/`` nor a GUID. The GUIDs were read from scenes Unity
2022.3 saved, each checked against the serialized fields that follow it in those scenes (Image
has ``m_Sprite``, Text ``m_FontData``, Button ``m_OnClick``, Slider ``m_FillRect``, Toggle
``m_IsOn``, CanvasScaler ``m_UiScaleMode``, GraphicRaycaster ``m_BlockingMask``, EventSystem
``m_FirstSelected``, StandaloneInputModule ``m_HorizontalAxis``).
"""

from __future__ import annotations

from unityscaffold.unity.values import ScriptRef

__all__ = ["UGUI_SCRIPTS", "ugui_class", "ugui_script"]

#: class -> (namespace, GUID)
UGUI_SCRIPTS: dict[str, tuple[str, str]] = {
    "Button": ("UnityEngine.UI", "4e29b1a8efbd4b44bb3f3716e73f07ff"),
    "CanvasScaler": ("UnityEngine.UI", "0cd44c1031e13a943bb63640046fad76"),
    "EventSystem": ("UnityEngine.EventSystems", "76c392e42b5098c458856cdf6ecaaaa1"),
    "GraphicRaycaster": ("UnityEngine.UI", "dc42784cf147c0c48a680349fa168899"),
    "Image": ("UnityEngine.UI", "fe87c0e1cc204ed48ad3b37840f39efc"),
    "Slider": ("UnityEngine.UI", "67db9e8f0e2ae9c40bc1e2b64352a6b4"),
    "StandaloneInputModule": ("UnityEngine.EventSystems", "4f231c4fb786f3946a6b90b886c48677"),
    "Text": ("UnityEngine.UI", "5f7201a12d95ffc409449d95f23cf332"),
    "Toggle": ("UnityEngine.UI", "9085046f02f69544eb97fd06b6048fe2"),
}


def ugui_script(name: str) -> ScriptRef | None:
    """uGUI's script ``name`` (``Image`` or ``UnityEngine.UI.Image``), or None."""
    namespace, _, class_name = name.rpartition(".")
    found = UGUI_SCRIPTS.get(class_name)
    if found is None or (namespace and namespace != found[0]):
        return None
    return ScriptRef(found[1], class_name=class_name, namespace=found[0], assembly="UnityEngine.UI")


def ugui_class(guid: str) -> str | None:
    """The class of a uGUI script GUID (for ``scene ls``), or None."""
    return next((name for name, (_, g) in UGUI_SCRIPTS.items() if g == guid), None)
