"""Compiling generated ROS-TCP-Connector scripts with Mono's mcs against the connector itself.

The vendored package's ``Runtime/MessageGeneration``, ``Runtime/Messages`` and
``Runtime/TcpConnector`` (ROSConnection, its topic states, HUD and senders) are compiled
against a stand-in of the UnityEngine members they use (``apply/stubs/UnityEngine.cs`` and
``UnityEngineConnector.cs``), as Unity compiles the package, then the project's scripts against
that, with warnings as errors. Two things mcs 6.8 cannot take are handled here, each stated:

- ``ROSConnection.Update`` deconstructs a ``System.Tuple`` (``(string topic, byte[] contents) =
  data;``), which needs C# 7's custom deconstruction that mcs lacks: that one line is rewritten
  to ``Item1``/``Item2``, which means the same;
- the ``TF*.cs`` files (TF listening) need ``Runtime/ROSGeometry``, a wrapper around the whole of
  Unity's vector and quaternion maths; ROSConnection uses only ``TFSystem.GetOrCreateInstance()``
  (when ``listenForTFMessages``), which a one-method stand-in provides.
"""

from __future__ import annotations

from pathlib import Path

from csharp import MCS_FLAGS, Compiled, compile_cs

from tests.codegen.rostcp.tcp_helpers import connector_package

REPO = Path(__file__).resolve().parent.parent
STUBS = REPO / "tests" / "apply" / "stubs"
_TUPLE_LINE = "(string topic, byte[] contents) = data;"
_TF_STAND_IN = """\
namespace Unity.Robotics.ROSTCPConnector
{
    public class TFSystem
    {
        public static TFSystem GetOrCreateInstance() { return null; }
    }
}
"""

__all__ = [
    "COMPILE_ONLY",
    "MCS_FLAGS",
    "RUNNABLE",
    "compile_connector",
    "compile_with_connector",
    "connector",
]


def connector() -> Path:
    """The vendored package (skipped locally, failed in CI when missing)."""
    return connector_package()


def _tcp_sources(out: Path) -> list[Path]:
    folder = out / "TcpConnector"
    folder.mkdir(parents=True, exist_ok=True)
    sources = []
    for source in sorted((connector() / "Runtime" / "TcpConnector").glob("*.cs")):
        if source.name.startswith("TF"):
            continue
        text = source.read_text(encoding="utf-8")
        if source.name == "ROSConnection.cs":
            assert _TUPLE_LINE in text, "the vendored ROSConnection.cs changed: revisit this"
            text = text.replace(
                _TUPLE_LINE, "string topic = data.Item1; byte[] contents = data.Item2;"
            )
        (folder / source.name).write_text(text, encoding="utf-8")
        sources.append(folder / source.name)
    stand_in = folder / "TFSystemStandIn.cs"
    stand_in.write_text(_TF_STAND_IN, encoding="utf-8")
    return [*sources, stand_in]


COMPILE_ONLY = (STUBS / "UnityEngine.cs", STUBS / "UnityEngineConnector.cs")
#: The stand-in that runs: the frame loop of tests/runtime with the connector's extra members.
RUNNABLE = (REPO / "tests" / "runtime" / "csharp" / "UnityEngineRuntime.cs", COMPILE_ONLY[1])


def compile_connector(
    mcs: str, out: Path, *, ros2: bool, engine: tuple[Path, ...] = COMPILE_ONLY
) -> tuple[Path, Path]:
    """UnityEngine's stand-in (``engine``: its sources) and the connector's runtime (as the
    package's assembly)."""
    out.mkdir(parents=True, exist_ok=True)
    unity = compile_cs(mcs, list(engine), out / "UnityEngine.dll", ros2=False)
    unity.assert_clean()
    runtime = connector() / "Runtime"
    sources = sorted((runtime / "MessageGeneration").rglob("*.cs"))
    sources += sorted((runtime / "Messages").rglob("*.cs"))
    sources += _tcp_sources(out)
    # The package's own code is not ours to hold to -warnaserror (it has unused fields).
    package = compile_cs(
        mcs,
        sources,
        out / "Unity.Robotics.ROSTCPConnector.dll",
        ros2=ros2,
        references=(unity.assembly,),
        strict=False,
    )
    assert package.returncode == 0, package.output
    return unity.assembly, package.assembly


def compile_with_connector(mcs: str, sources: list[Path], out: Path, *, ros2: bool) -> Compiled:
    """``sources`` (a project's scripts) compiled against the connector, warnings as errors."""
    engine, package = compile_connector(mcs, out / ("ros2" if ros2 else "ros1"), ros2=ros2)
    return compile_cs(
        mcs, sources, out / "Assembly-CSharp.dll", ros2=ros2, references=(engine, package)
    )
