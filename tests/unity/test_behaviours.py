"""The rule for what is a component (a MonoBehaviour) and which class of a file Unity uses."""

from __future__ import annotations

import pytest

from unityscaffold.unity.behaviours import Kind, base_class, kind_of, unity_class
from unityscaffold.unity.csharp import parse_file

PROJECT = {"Mover": Kind.COMPONENT, "Settings": Kind.OTHER}


def _lookup(name: str) -> Kind | None:
    return PROJECT.get(name)


def _decl(source: str):
    (decl,) = [d for d in parse_file(source, "X.cs") if not d.outer]
    return decl


@pytest.mark.parametrize(
    ("source", "kind"),
    [
        ("public class A : MonoBehaviour { }", Kind.COMPONENT),
        ("public class A : UnityEngine.MonoBehaviour { }", Kind.COMPONENT),
        ("public class A : UIBehaviour { }", Kind.COMPONENT),
        ("public class A : Graphic, ILayoutElement { }", Kind.COMPONENT),
        ("public class A : UnityEngine.UI.Selectable { }", Kind.COMPONENT),
        ("public class A : IDisposable, Mover { }", Kind.COMPONENT),  # the project's, found
        ("public class A : Settings { }", Kind.OTHER),  # the project's, not one
        ("public class A : ScriptableObject { }", Kind.OTHER),
        ("public class A : Message { }", Kind.OTHER),  # ROS#'s message base
        ("public class A { }", Kind.OTHER),
        ("public class A : IDisposable { }", Kind.OTHER),
        ("public struct A { }", Kind.OTHER),
        ("public class A : NetworkBehaviour { }", Kind.UNKNOWN),  # another package's base
        ("public class A : Base<int> { }", Kind.UNKNOWN),
    ],
)
def test_a_class_is_a_component_by_its_base(source: str, kind: Kind) -> None:
    assert kind_of(_decl(source), _lookup) is kind


def test_the_project_and_rossharp_are_asked_before_unitys_table() -> None:
    # A project class named Image that is no component is not uGUI's Image.
    assert kind_of(_decl("class A : Image { }"), lambda n: Kind.OTHER) is Kind.OTHER


def test_base_class_skips_interfaces_and_type_arguments() -> None:
    assert base_class(_decl("class A : IFoo, Sub.UnitySubscriber<Twist> { }")) == (
        "UnitySubscriber"
    )
    assert base_class(_decl("class A : IFoo { }")) is None


def _unity_class(source: str, stem: str):
    return unity_class(parse_file(source, f"{stem}.cs"), stem, _lookup)


def test_unity_uses_the_class_named_like_the_file_first() -> None:
    chosen = _unity_class("class Helper : MonoBehaviour { }\nclass File : Settings { }", "File")
    assert chosen.decl is not None and chosen.decl.name == "File"


def test_else_the_files_one_component() -> None:
    chosen = _unity_class(
        "namespace N { class Helper { }\nabstract class Base : MonoBehaviour { }\n"
        "class Float64Publisher : MonoBehaviour { class Inner : MonoBehaviour { } } }",
        "PubHeadTorque",
    )
    assert chosen.decl is not None and chosen.decl.full_name == "N.Float64Publisher"


def test_else_why_there_is_none() -> None:
    assert _unity_class("class A { }", "F").why == "it declares no MonoBehaviour (it declares A)"
    two = _unity_class("class A : MonoBehaviour { }\nclass B : Mover { }", "F")
    assert two.decl is None
    assert two.why.startswith("it declares 2 MonoBehaviours and none is named F like the file")
