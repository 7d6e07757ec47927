"""The value Unity serializes for a new component's field, from its C# initializer as the C#
reader keeps it; anything but a plain value is refused (None), never guessed."""

from __future__ import annotations

import pytest

from unityscaffold.unity.csharp import parse_file
from unityscaffold.unity.initializers import field_default
from unityscaffold.unity.values import Enum, FieldValue, InlineMap, ObjectRef

NO_CALLS = {"m_PersistentCalls": {"m_Calls": []}}
ENUMS = {"Demo.Gear": {"Park": 0, "Drive": 3}}


def _initializer(declaration: str) -> str | None:
    """The initializer of the one field ``declaration`` declares, as the reader keeps it."""
    decls = parse_file(f"class C : MonoBehaviour {{ {declaration} }}", "C.cs")
    return decls[0].fields[0].initializer


def _xyz(*values: float) -> InlineMap:
    return InlineMap(tuple(zip("xyz", values, strict=True)))


CASES: list[tuple[str, str, FieldValue | None]] = [
    ("int", "public int N;", 0),
    ("int", "public int N = -12;", -12),
    ("int", "public long N = 0x10L;", 16),
    ("float", "public float F = 2.5f;", 2.5),
    ("float", "public float F = .5F;", 0.5),
    ("float", "public float F = 1e-3f;", 0.001),
    ("float", "public float F = 60 * 5;", None),
    ("bool", "public bool B = true;", True),
    ("string", "public string S;", ""),
    ("string", "public string S = null;", ""),
    ("string", 'public string S = "a;b{c}\\n\\u00e9";', "a;b{c}\né"),
    ("string", 'public string S = @"C:\\dir ""x""";', 'C:\\dir "x"'),
    ("string", 'public string S = $"{N}";', None),
    ("string", "public string S = string.Empty;", ""),
    ("string", "public string S = Application.productName;", None),
    ("enum:Demo.Gear", "public Gear G;", Enum(0)),
    ("enum:Demo.Gear", "public Gear G = Gear.Drive;", Enum(3)),
    ("enum:Demo.Gear", "public Gear G = Demo.Gear.Drive;", Enum(3)),
    ("enum:Demo.Gear", "public Gear G = (Gear)3;", Enum(3)),
    ("enum:Demo.Gear", "public Gear G = Gear.Reverse;", None),
    ("Vector3", "public Vector3 V;", _xyz(0, 0, 0)),
    ("Vector3", "public Vector3 V = Vector3.up;", _xyz(0, 1, 0)),
    ("Vector3", "public Vector3 V = new Vector3(1, 2f);", _xyz(1, 2, 0)),
    ("Vector3", "public Vector3 V = new Vector3(x, 0, 0);", None),
    ("Quaternion", "public Quaternion Q;", InlineMap.of(x=0, y=0, z=0, w=0)),
    ("Color", "public Color C = new Color(1, 0, 0);", InlineMap.of(r=1.0, g=0.0, b=0.0, a=1.0)),
    ("ref:Transform", "public Transform T;", ObjectRef(0)),
    ("ref:Transform", "public Transform T = null;", ObjectRef(0)),
    ("int[]", "public int[] A;", []),
    ("int[]", "public int[] A = new int[0];", []),
    ("int[]", "public int[] A = new int[] { 1, 2 };", [1, 2]),
    ("int[]", "public int[] A = new int[3];", [0, 0, 0]),
    ("string[]", "public List<string> A = new List<string> { \"a\" };", ["a"]),
    ("string[]", "public List<string> A = new List<string>();", []),
    ("string[]", "public List<string> A = Load();", None),
    ("raw:UnityEvent", "public UnityEvent E;", NO_CALLS),
    ("raw:UnityEvent", "public UnityEvent E = new UnityEvent();", NO_CALLS),
    ("raw:Settings", "public Settings S;", None),
]  # fmt: skip


@pytest.mark.parametrize(("kind", "declaration", "expected"), CASES, ids=[c[1] for c in CASES])
def test_a_fields_new_value_is_its_initializer_or_its_types_zero(kind, declaration, expected):
    csharp = declaration.split()[1]
    assert field_default(kind, _initializer(declaration), ENUMS, csharp) == expected


def test_a_field_with_a_collection_initializer_is_read_with_the_fields_after_it():
    # its braces once ended the declaration: the field and its initializer were lost
    decls = parse_file(
        "class C : MonoBehaviour { public float[] A = new float[] { 1, 2 }; public int B; }", "C.cs"
    )
    assert [(f.name, f.initializer) for f in decls[0].fields] == [
        ("A", "new float[] { 1, 2 }"),
        ("B", None),
    ]


def test_a_string_literal_with_braces_and_semicolons_does_not_split_declarations():
    decls = parse_file('class C { public string S = "};{"; public int N = 1; }', "C.cs")
    assert [f.name for f in decls[0].fields] == ["S", "N"]
    assert field_default("string", decls[0].fields[0].initializer, {}) == "};{"
