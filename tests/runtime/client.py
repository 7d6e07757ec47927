"""ROS#'s real client library (RosBridgeClient, pure C#) compiled with Mono's mcs for the runtime
tests, and test programs built on it.

The sources are ROS# 2.2.1's unmodified ``Runtime/Libraries/RosBridgeClient`` (github.com/
siemens/ros-sharp, tag 2.2.1), from ``UNITYSCAFFOLD_ROSSHARP`` or beside the repository where CI
puts it, with
three exclusions: ``UrdfTransfer/`` (needs a newer C# and is not part of messaging),
``MessageTypes/ROS2/`` (these tests speak ROS 1), and ``Serializers/MicrosoftSerializer.cs``,
replaced by ``csharp/MicrosoftSerializerUnavailable.cs`` because System.Text.Json needs
System.Memory, which Debian's Mono lacks. Everything runs with ``SerializerEnum.Newtonsoft_JSON``.
"""

from __future__ import annotations

import shutil
import subprocess
from collections.abc import Sequence
from pathlib import Path

HERE = Path(__file__).resolve().parent
CSHARP = HERE / "csharp"
FACADES = Path("/usr/lib/mono/4.5/Facades")
# The client's own sources trigger warnings we do not own (obsolete APIs, unused fields).
THIRD_PARTY_FLAGS = ("-langversion:7.2", "-nologo", "-nowarn:0108,0114,0169,0414,0612,0618,0649")


# Without ROS#'s message classes, the client keeps only its two hand-written ROS 1 primitives
# (which generated classes use for ``time`` and ``duration``) and drops its Fibonacci examples.
PRIMITIVES = ("MessageTypes/ROS1/Std/msg/Time.cs", "MessageTypes/ROS1/Std/msg/Duration.cs")


def rossharp_sources(package: Path, *, with_messages: bool) -> list[Path]:
    """The client's ``.cs`` files; ``with_messages`` keeps ROS#'s shipped ROS 1 classes."""
    client = package / "Runtime" / "Libraries" / "RosBridgeClient"
    sources = []
    for path in sorted(client.rglob("*.cs")):
        relative = path.relative_to(client).as_posix()
        if relative.startswith(("UrdfTransfer/", "MessageTypes/ROS2/")):
            continue
        if relative == "Serializers/MicrosoftSerializer.cs":
            continue
        leaves_out = relative.startswith(("MessageTypes/ROS1/", "Actionlib/Fibonacci"))
        if not with_messages and leaves_out and relative not in PRIMITIVES:
            continue
        sources.append(path)
    return [*sources, CSHARP / "MicrosoftSerializerUnavailable.cs"]


def mcs_compile(
    mcs: str,
    sources: Sequence[Path],
    out: Path,
    *,
    references: Sequence[Path] = (),
    target: str = "library",
    main: str | None = None,
    defines: Sequence[str] = (),
) -> None:
    """Compile or fail with mcs's output (errors only; third-party warnings are not ours)."""
    args = [mcs, *THIRD_PARTY_FLAGS, f"-target:{target}", f"-out:{out}"]
    if main:
        args.append(f"-main:{main}")
    args += [f"-define:{d}" for d in defines]
    args += [f"-r:{r}" for r in references]
    args += [str(s) for s in sources]
    done = subprocess.run(args, capture_output=True, text=True, timeout=600, check=False)
    if done.returncode != 0:
        errors = [line for line in done.stdout.splitlines() if "error" in line]
        raise AssertionError(f"mcs failed for {out.name}:\n" + "\n".join(errors[:40]))


def plugin_references(package: Path) -> list[Path]:
    """The DLLs ROS# ships in ``Plugins/`` plus Mono's netstandard facade and System.Net.Http."""
    return [
        *sorted((package / "Plugins").glob("*.dll")),
        FACADES / "netstandard.dll",
        Path("System.Net.Http.dll"),
    ]


def build_client(
    mcs: str, package: Path, out: Path, *, message_sources: Sequence[Path] | None = None
) -> Path:
    """``out/RosBridgeClient.dll`` with ROS#'s plugin DLLs beside it (mono loads them from there).
    With ``message_sources``, those classes replace ROS#'s shipped ones in the assembly."""
    out.mkdir(parents=True, exist_ok=True)
    for dll in (package / "Plugins").glob("*.dll"):
        shutil.copy2(dll, out / dll.name)
    assembly = out / "RosBridgeClient.dll"
    mcs_compile(
        mcs,
        [
            *rossharp_sources(package, with_messages=message_sources is None),
            *(message_sources or ()),
        ],
        assembly,
        references=plugin_references(package),
    )
    return assembly


STJ_STAND_IN = "SystemTextJsonStandIn.cs"


def build_ros2_client(mcs: str, package: Path, out: Path) -> Path:
    """``out/RosBridgeClient.dll`` compiled with ``-define:ROS2`` (ROS#'s ROS 2 build: its ROS 2
    message classes and action API), ROS#'s plugin DLLs beside it.

    ROS#'s ROS 2 action consumer reads feedback and results with System.Text.Json's
    ``JsonSerializer`` whatever serializer is chosen; that DLL cannot run on Debian's Mono (see
    the module docstring), so ``csharp/SystemTextJsonStandIn.cs`` is compiled in its place.
    """
    out.mkdir(parents=True, exist_ok=True)
    for dll in (package / "Plugins").glob("*.dll"):
        if dll.name != "System.Text.Json.dll":
            shutil.copy2(dll, out / dll.name)
    client = package / "Runtime" / "Libraries" / "RosBridgeClient"
    sources = [
        path
        for path in sorted(client.rglob("*.cs"))
        if not path.relative_to(client).as_posix().startswith("UrdfTransfer/")
        and path.name != "MicrosoftSerializer.cs"
    ]
    references = [r for r in plugin_references(package) if r.name != "System.Text.Json.dll"]
    assembly = out / "RosBridgeClient.dll"
    mcs_compile(
        mcs,
        [*sources, *(CSHARP / n for n in ("MicrosoftSerializerUnavailable.cs", STJ_STAND_IN))],
        assembly,
        references=references,
        defines=["ROS2"],
    )
    return assembly
