"""Our classes under System.Text.Json's default contract, checked statically.

ROS#'s default serializer (``SerializerEnum.Microsoft``) is System.Text.Json, whose DLL needs
System.Memory: Debian's Mono 6.8 does not ship it and no registry reachable here (Debian, PyPI,
npm) carries it, so it cannot run in these tests. Instead a C# program reflects over every class
we generate (all ROS 1 message types and both halves of every service, --include-shipped) and
this test asserts what the default contract needs for a faithful round trip: a public
parameterless constructor, every ROS field as a public read-write instance property named
exactly as on the wire (the default has no naming policy), and no public instance fields (the
default skips fields)."""

from __future__ import annotations

from pathlib import Path

from processes import run

from tests.runtime.client import CSHARP, mcs_compile
from tests.runtime.runtime_helpers import (
    TIME_PRIMITIVES,
    message_types,
    ros1_registry,
    service_types,
)
from unityscaffold.codegen import ClassRole, Options, generate
from unityscaffold.interfaces.model import Dialect


def test_every_generated_class_fits_system_text_json_defaults(
    mcs: str, mono: str, ours_only_client: Path, tmp_path: Path
) -> None:
    program = tmp_path / "StjContract.exe"
    mcs_compile(mcs, [CSHARP / "StjContract.cs"], program, target="exe")
    done = run([mono, str(program), str(ours_only_client)], timeout=120, check=True)
    seen = {}
    for line in done.stdout.splitlines():
        name, constructor, properties, fields = line.split("\t")
        seen[name] = (constructor, properties.split(",") if properties else [], fields)
    registry = ros1_registry()
    specs = [s for s in message_types(registry) if s.full_name not in TIME_PRIMITIVES]
    services = service_types(registry)
    code = generate(registry, [*specs, *services], Options(Dialect.ROS1, include_shipped=True))
    classes = [(spec, code.message_class(spec.full_name).full_name) for spec in specs]
    for service in services:
        halves = code.classes[f"{service.package}/srv/{service.name}"]
        classes.append((service.request, halves[ClassRole.REQUEST].full_name))
        classes.append((service.response, halves[ClassRole.RESPONSE].full_name))
    problems = []
    for spec, cs_class in classes:
        constructor, properties, fields = seen[cs_class]
        wire = sorted(f.name for f in spec.fields)
        if constructor != "ctor":
            problems.append(f"{cs_class}: no public parameterless constructor")
        if sorted(properties) != wire:
            problems.append(f"{cs_class}: properties {properties}, ROS fields {wire}")
        if fields:
            problems.append(f"{cs_class}: public fields {fields}")
    assert not problems, "\n".join(problems)
    assert (len(specs), len(services)) == (161, 30)
