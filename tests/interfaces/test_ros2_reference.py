"""Every Jazzy interface: parsed as rosidl_adapter does, type hashes equal to the shipped JSON."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import pytest

from unityscaffold.interfaces.identity_ros2 import Ros2Identity
from unityscaffold.interfaces.model import ActionSpec, Dialect, MessageSpec, ServiceSpec
from unityscaffold.interfaces.registry import Registry


@pytest.fixture(scope="module")
def registry(ros2_share) -> Registry:
    packages = sorted(
        p.parent
        for p in ros2_share.glob("*/package.xml")
        if any((p.parent / k).is_dir() for k in ("msg", "srv", "action"))
    )
    return Registry.load(Dialect.ROS2, packages, use_environment=False, use_builtin=False)


@pytest.fixture(scope="module")
def parser():
    from helpers import require

    try:
        from rosidl_adapter import parser as module
    except ImportError:
        module = None
    require(module, "rosidl_adapter (PyPI ros-jazzy-rosidl-adapter)")
    return module


def _their_fields(spec):
    return [
        (
            str(f.type.pkg_name or ""),
            f.type.type,
            f.type.is_array,
            f.type.array_size,
            f.type.is_upper_bound,
            f.type.string_upper_bound,
            f.name,
            tuple(f.default_value) if isinstance(f.default_value, list) else f.default_value,
        )
        for f in spec.fields
    ]


def _our_fields(spec: MessageSpec):
    rows = []
    for f in spec.fields:
        ref = f.type
        package, base = ("", ref.base) if ref.is_builtin else (ref.package, ref.short_name)
        rows.append(
            (
                package,
                base,
                ref.is_array,
                ref.size,
                ref.array.value == "bounded",
                ref.string_bound,
                f.name,
                f.default,
            )
        )
    return rows


def _compare(ours: MessageSpec, theirs) -> list[str]:
    problems = []
    if _our_fields(ours) != _their_fields(theirs):
        problems.append(f"{ours.full_name}: fields differ")
    their_constants = [(c.type, c.name, c.value) for c in theirs.constants]
    if [(c.type, c.name, c.value) for c in ours.constants] != their_constants:
        problems.append(f"{ours.full_name}: constants differ")
    return problems


def _ament_index_interfaces(share: Path) -> set[str]:
    """Every interface the installed packages register: ``pkg/msg/Name`` and the like.

    rosidl lists each package's interface files in the ament index, one ``msg/Name.msg`` (or
    ``.srv``, ``.action``, and the ``.idl`` generated from them) per line.
    """
    found = set()
    for package in (share / "ament_index" / "resource_index" / "rosidl_interfaces").iterdir():
        for line in package.read_text().splitlines():
            kind, _, file_name = line.partition("/")
            stem, _, suffix = file_name.rpartition(".")
            if suffix == kind:
                found.add(f"{package.name}/{kind}/{stem}")
    return found


def test_every_interface_the_jazzy_wheels_register_is_found_and_parses(registry, ros2_share):
    interfaces, problems = registry.parse_all()
    assert problems == []
    expected = _ament_index_interfaces(ros2_share)
    assert {i.kind.value for i in interfaces} == {"msg", "srv", "action"}
    assert sorted(i.full_name for i in interfaces) == sorted(expected)


def test_every_interface_parses_like_rosidl_adapter(registry, parser):
    problems = []
    for file in registry.files():
        ours = registry.parse(file)
        if isinstance(ours, MessageSpec):
            problems += _compare(ours, parser.parse_message_file(file.package, str(file.path)))
        elif isinstance(ours, ServiceSpec):
            theirs = parser.parse_service_file(file.package, str(file.path))
            problems += _compare(ours.request, theirs.request)
            problems += _compare(ours.response, theirs.response)
        else:
            theirs = parser.parse_action_file(file.package, str(file.path))
            for part in ("goal", "result", "feedback"):
                problems += _compare(getattr(ours, part), getattr(theirs, part))
    assert problems == []


def test_every_type_hash_equals_the_shipped_json(registry, ros2_share):
    """Each interface's ``.json`` lists the hashes of the types the file defines (the interface,
    and for services and actions every part rosidl derives) and of the types they refer to; we
    derive exactly the former, with equal hashes."""
    identity = Ros2Identity(registry)
    missing, extra, mismatches = [], [], []
    for file in registry.files():
        interface = registry.parse(file)
        shipped = json.loads(file.path.with_suffix(".json").read_text())
        expected = {h["type_name"]: h["hash_string"] for h in shipped["type_hashes"]}
        prefix = interface.full_name
        defined = {n for n in expected if n == prefix or n.startswith(prefix + "_")}
        own = [interface]
        if isinstance(interface, ServiceSpec):
            own += list(interface.parts)
        if isinstance(interface, ActionSpec):
            own += list(interface.messages) + list(interface.services)
        names = {item.full_name for item in own}
        missing += sorted(defined - names)
        extra += sorted(names - defined)
        mismatches += [
            item.full_name
            for item in own
            if item.full_name in defined and identity.type_hash(item) != expected[item.full_name]
        ]
    assert (missing, extra, mismatches) == ([], [], [])


def test_each_type_hash_is_the_sha256_of_its_description_as_one_json_text(registry):
    """``type_hash`` puts the JSON text together from each description's own text, made once
    per type; it must be the text ``json.dumps`` gives for the whole description."""
    identity = Ros2Identity(registry)
    for file in registry.files():
        interface = registry.parse(file)
        own = [interface]
        if isinstance(interface, ServiceSpec):
            own += list(interface.parts)
        if isinstance(interface, ActionSpec):
            own += list(interface.messages) + list(interface.services)
        for item in own:
            description = identity.description(item)
            text = json.dumps(description, ensure_ascii=True, separators=(", ", ": "))
            digest = hashlib.sha256(text.encode("utf-8")).hexdigest()
            assert identity.type_hash(item) == f"RIHS01_{digest}", item.full_name
