"""Definitions at C#'s edges: accepted ones compile, the others are refused at their line."""

from __future__ import annotations

from pathlib import Path

import pytest
from codegen_helpers import STUB_NEEDS, write_tree
from csharp import ROSSHARP_STUB, compile_cs

from unityscaffold.codegen import GeneratedCode, Options, generate
from unityscaffold.errors import LocatedError
from unityscaffold.interfaces.model import Dialect
from unityscaffold.interfaces.registry import Registry

DOC = "<b> & c ]]> <!-- x --> \u2028 y \u0085 z \x01 \x0b"
# ROS 2 ends lines where Python's splitlines() does, as rosidl does: no \x0b, \x85, \u2028 there.
DOC2 = "<b> & c ]]> <!-- x --> \x01 \x7f"

ROS1_ACCEPTED = {
    "edge_msgs/msg/Huge.msg": (
        "geometry_msgs/Point[100000000] points\n"
        "string[2147483647] names\n"
        "int32[2147483647] values\n"
        "string[65] just_past_inline\n"
    ),
    "edge_msgs/msg/Doc.msg": f"# {DOC}\nint32 a  # {DOC}\n# {DOC}\nint32 B=1\n",
    "edge_msgs/msg/Limits.msg": (
        "float32 MAX=3.4028235e38\nfloat32 TINY=1e-50\nint64 LOW=-9223372036854775808\n"
        f"int32 {'a' * 511}\n"
    ),
}
ROS2_ACCEPTED = {
    "edge_msgs/msg/Huge.msg": (
        "geometry_msgs/Point[100000000] points\nstring<=2147483647[<=2147483647] names\n"
    ),
    "edge_msgs/msg/Doc.msg": f"# {DOC2}\nint32 a  # {DOC2}\n",
    "edge_msgs/msg/Quotes.msg": "string LONE=\"\nstring s '\n",
}


def _registry(tmp: Path, dialect: Dialect, files: dict[str, str]) -> Registry:
    for relative, text in files.items():
        path = tmp / "defs" / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return Registry.load(dialect, [tmp / "defs"])


def _name(dialect: Dialect, relative: str) -> str:
    package, kind, file = relative.split("/")
    stem = file.rsplit(".", 1)[0]
    return f"{package}/{stem}" if dialect is Dialect.ROS1 else f"{package}/{kind}/{stem}"


@pytest.mark.parametrize(
    ("dialect", "files"),
    [(Dialect.ROS1, ROS1_ACCEPTED), (Dialect.ROS2, ROS2_ACCEPTED)],
    ids=["ros1", "ros2"],
)
def test_accepted_edges_compile(
    dialect: Dialect, files: dict[str, str], mcs: str, tmp_path: Path
) -> None:
    registry = _registry(tmp_path, dialect, files)
    roots = [registry.get(_name(dialect, relative)) for relative in files]
    roots += [registry.get(name) for name in STUB_NEEDS[dialect]]
    code = generate(registry, roots, Options(dialect, include_shipped=True))
    text = "".join(f.text for f in code.files if f.path.startswith("Edge/"))
    # A huge array is initialised by an expression, not by a hundred million copies of one.
    assert len(text) < 200_000
    assert "ConvertAll(new Point[100000000], _ => new Point())" in text
    sources = [ROSSHARP_STUB, *write_tree(code, tmp_path / "src")]
    out = tmp_path / "Edges.dll"
    compile_cs(mcs, sources, out, ros2=dialect is Dialect.ROS2).assert_clean()


def _refusal(tmp: Path, dialect: Dialect, relative: str, text: str) -> LocatedError:
    registry = _registry(tmp, dialect, {relative: text})
    with pytest.raises(LocatedError) as caught:
        generate(registry, [registry.get(_name(dialect, relative))], Options(dialect))
    return caught.value


@pytest.mark.parametrize(
    ("dialect", "text", "line", "fragment"),
    [
        (Dialect.ROS1, f"int32 a\nint32 {'a' * 512}\n", 2, "too long for a C# identifier"),
        (Dialect.ROS2, f"int32 a\nint32 {'a' * 512}\n", 2, "too long for a C# identifier"),
        (Dialect.ROS1, f"int32 a\nint32 {'A' * 512}=1\n", 2, "too long for a C# identifier"),
        (Dialect.ROS1, "int32 a\nstring ToString\n", 2, "inherited member ToString()"),
        (Dialect.ROS1, "int32 GetHashCode=1\n", 1, "inherited member GetHashCode()"),
        (Dialect.ROS1, "int32 a\nfloat32 BIG=1e39\n", 2, "does not fit in a C# float"),
        (Dialect.ROS2, "int32 a\nfloat32 BIG=-3.5e38\n", 2, "does not fit in a C# float"),
        (Dialect.ROS2, "float32 big 1e39\n", 1, "does not fit in a C# float"),
    ],
)
def test_what_csharp_cannot_hold_is_refused_at_its_line(
    dialect: Dialect, text: str, line: int, fragment: str, tmp_path: Path
) -> None:
    error = _refusal(tmp_path, dialect, "edge_msgs/msg/Bad.msg", text)
    diagnostic = error.diagnostics[0]
    assert diagnostic.location.path.endswith("edge_msgs/msg/Bad.msg")
    assert diagnostic.location.line == line
    assert fragment in error.render()


@pytest.mark.parametrize("dialect", [Dialect.ROS1, Dialect.ROS2], ids=["ros1", "ros2"])
def test_a_class_name_too_long_for_its_file_is_refused_at_the_definition(
    dialect: Dialect, tmp_path: Path
) -> None:
    name = "A" * 240  # the action's FeedbackMessage/ActionFeedback class would pass 247
    error = _refusal(tmp_path, dialect, f"edge_msgs/action/{name}.action", "---\n---\n")
    assert error.diagnostics[0].location.path.endswith(f"{name}.action")
    assert "more than its file name can hold (247)" in error.render()


def test_the_largest_class_name_fits_and_generates(tmp_path: Path) -> None:
    name = "A" * 247
    registry = _registry(tmp_path, Dialect.ROS1, {f"edge_msgs/msg/{name}.msg": "int32 a\n"})
    code: GeneratedCode = generate(
        registry, [registry.get(f"edge_msgs/{name}")], Options(Dialect.ROS1)
    )
    assert [f.path for f in code.files] == [f"Edge/msg/{name}.cs"]
