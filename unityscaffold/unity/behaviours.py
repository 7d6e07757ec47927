"""Which C# class of a script file is a component (a MonoBehaviour), and which one Unity uses.

The rule, small and pure so that it can be stated in the docs and tested on its own:

- A class is a **component** when its base class is ``MonoBehaviour`` or one of Unity's and
  uGUI's own MonoBehaviours (``UIBehaviour``, ``Graphic``, ``Selectable``, ``Image``...), or a
  class of the project or of ROS# that is a component by this same rule.
- It is **not** one when it has no base class, or its base is known to be something else
  (``ScriptableObject``, an editor class, ROS#'s ``Message``...), or is a project or ROS# class
  that is not one.
- Otherwise (a base from a package the tool has no table of) it is **unknown**: it may be one.

Unity binds a script file to the class named like the file; failing that, to the file's only
MonoBehaviour (Unity's manual, "Naming scripts"). ``unity_class`` applies that to a parsed file.
"""

from __future__ import annotations

import enum
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from unityscaffold.unity.csharp import TypeDecl

__all__ = ["Kind", "UnityClass", "base_class", "kind_of", "unity_class"]


class Kind(enum.Enum):
    COMPONENT = "component"
    OTHER = "not a component"
    UNKNOWN = "unknown"


# UnityEngine's and uGUI's MonoBehaviours a script may derive from (abstract ones included).
UNITY_BEHAVIOURS = frozenset(
    {
        "MonoBehaviour",
        "UIBehaviour",
        "Graphic",
        "MaskableGraphic",
        "Selectable",
        "Image",
        "RawImage",
        "Text",
        "Button",
        "Toggle",
        "ToggleGroup",
        "Slider",
        "Scrollbar",
        "ScrollRect",
        "Dropdown",
        "InputField",
        "Mask",
        "RectMask2D",
        "LayoutGroup",
        "HorizontalOrVerticalLayoutGroup",
        "HorizontalLayoutGroup",
        "VerticalLayoutGroup",
        "GridLayoutGroup",
        "LayoutElement",
        "ContentSizeFitter",
        "AspectRatioFitter",
        "CanvasScaler",
        "BaseMeshEffect",
        "Shadow",
        "Outline",
        "BaseRaycaster",
        "GraphicRaycaster",
        "PhysicsRaycaster",
        "Physics2DRaycaster",
        "BaseInputModule",
        "PointerInputModule",
        "StandaloneInputModule",
        "EventSystem",
        "EventTrigger",
    }
)
# Bases known not to make a component: Unity's other script roots, editor classes, and ROS#'s
# message base class (every generated or shipped message class derives from it).
NOT_BEHAVIOURS = frozenset(
    {
        "ScriptableObject",
        "Editor",
        "EditorWindow",
        "PropertyDrawer",
        "PropertyAttribute",
        "StateMachineBehaviour",
        "Attribute",
        "Exception",
        "Message",
    }
)

#: A base class's name -> its kind when the project or ROS# declares it, else None.
Lookup = Callable[[str], "Kind | None"]


def base_class(decl: TypeDecl) -> str | None:
    """The bare name of ``decl``'s base class: the first listed base that is not an interface
    (``IName``), without namespace or type arguments; None when it lists none."""
    for base in decl.bases:
        bare = base.split("<")[0].rsplit(".", 1)[-1].strip()
        if not (len(bare) > 1 and bare[0] == "I" and bare[1].isupper()):
            return bare
    return None


def kind_of(decl: TypeDecl, lookup: Lookup) -> Kind:
    """Whether ``decl`` is a component, by the rule in this module's docstring."""
    if decl.kind != "class":
        return Kind.OTHER
    base = base_class(decl)
    if base is None:
        return Kind.OTHER
    found = lookup(base)
    if found is not None:
        return found
    if base in UNITY_BEHAVIOURS:
        return Kind.COMPONENT
    if base in NOT_BEHAVIOURS:
        return Kind.OTHER
    return Kind.UNKNOWN


@dataclass(frozen=True, slots=True)
class UnityClass:
    """The class Unity binds a script file to (``decl``), or why there is none (``why``)."""

    decl: TypeDecl | None
    why: str = ""


def unity_class(decls: Sequence[TypeDecl], stem: str, lookup: Lookup) -> UnityClass:
    """The class of a file named ``stem``.cs that Unity uses: the top-level class named like the
    file, else the file's one component class; else why there is none."""
    classes = [d for d in decls if d.kind == "class" and not d.outer]
    named = next((d for d in classes if d.name == stem), None)
    if named is not None:
        return UnityClass(named)
    behaviours = [
        d
        for d in classes
        if "abstract" not in d.modifiers and not d.generics and kind_of(d, lookup) != Kind.OTHER
    ]
    if len(behaviours) == 1:
        return UnityClass(behaviours[0])
    if not behaviours:
        declared = ", ".join(d.full_name for d in classes) or "no class"
        return UnityClass(None, f"it declares no MonoBehaviour (it declares {declared})")
    listed = ", ".join(d.full_name for d in behaviours)
    return UnityClass(
        None,
        f"it declares {len(behaviours)} MonoBehaviours and none is named {stem} like the file "
        f"({listed}): Unity cannot tell which one the file is",
    )
