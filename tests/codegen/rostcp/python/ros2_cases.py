"""Reference cases for ROS 2, made with rclpy (run with the ROS 2 Jazzy venv's Python).

``make``: reads type names from stdin (``pkg/msg/Name``, ``pkg/srv/Name_Request``), writes one
line per case: ``type, case, serialize_message() as hex, padding mask as hex, payload end,
the values as JSON`` (tab-separated). Cases: the default instance, then ``--random`` seeded
random instances with extremes, NaN/±inf/-0.0, UTF-8 text and sequence lengths 0-3 (within
bounds). rmw_fastrtps leaves alignment padding uninitialised and may return a buffer longer
than the payload, so the reference is walked by type (XCDRv1: primitives aligned to their size
counted after the 4-byte header, strings and sequences a uint32 count, an empty struct one
byte) to find the padding bytes and the payload's end.

``check``: reads ``type, case, bytes as hex`` lines (what the C# side serialized), makes the
same cases again, and prints one line per case whose bytes ``deserialize_message`` does not
turn back into the original values.
"""

from __future__ import annotations

import argparse
import importlib
import json
import random
import struct
import sys

from rclpy.serialization import deserialize_message, serialize_message
from rosidl_parser import definition as idl

INTS = {
    "int8": (-(2**7), 2**7 - 1),
    "uint8": (0, 2**8 - 1),
    "int16": (-(2**15), 2**15 - 1),
    "uint16": (0, 2**16 - 1),
    "int32": (-(2**31), 2**31 - 1),
    "uint32": (0, 2**32 - 1),
    "int64": (-(2**63), 2**63 - 1),
    "uint64": (0, 2**64 - 1),
}
SIZES = {"boolean": 1, "octet": 1, "char": 1, "float": 4, "double": 8}
SIZES.update({name: int(name.lstrip("uint")) // 8 for name in INTS})
FLOATS = {"float": "f", "double": "d"}
SPECIAL = [float("nan"), float("inf"), float("-inf"), -0.0, 0.0, 1e-45, 3.4028234663852886e38]
TEXTS = ["", "plain", "ünïcödé", "日本語", "robot 🤖", 'quote " and \\ tab\t', "x" * 40]


def message_class(name: str) -> type:
    package, kind, short = name.split("/")
    module = importlib.import_module(f"{package}.{kind}")
    if kind == "srv" and "_" in short:
        service, _, half = short.rpartition("_")
        return getattr(getattr(module, service), half)
    return getattr(module, short)


def _nested(kind: idl.NamespacedType) -> type:
    return getattr(importlib.import_module(".".join(kind.namespaces)), kind.name)


def _scalar(rng: random.Random, kind: object) -> object:
    if isinstance(kind, idl.NamespacedType):
        return _random(rng, _nested(kind))
    if isinstance(kind, idl.BoundedString):
        return rng.choice([t for t in TEXTS if len(t) <= kind.maximum_size])
    if isinstance(kind, idl.UnboundedString):
        return rng.choice(TEXTS)
    name = kind.typename
    if name == "boolean":
        return rng.random() < 0.5
    if name == "octet":
        return bytes([rng.choice([0, 255, rng.randint(0, 255)])])
    if name == "char":
        return chr(rng.choice([0, 255, rng.randint(0, 255)]))
    if name in INTS:
        low, high = INTS[name]
        return rng.choice([low, high, 0, rng.randint(low, high)])
    value = rng.choice([*SPECIAL, rng.uniform(-1e6, 1e6)])
    return struct.unpack("<" + FLOATS[name], struct.pack("<" + FLOATS[name], value))[0]


def _random(rng: random.Random, cls: type) -> object:
    message = cls()
    for field, kind in zip(cls.get_fields_and_field_types(), cls.SLOT_TYPES, strict=True):
        if not isinstance(kind, idl.AbstractNestedType):
            setattr(message, field, _scalar(rng, kind))
            continue
        if isinstance(kind, idl.Array):
            count = kind.size
        else:
            bound = kind.maximum_size if isinstance(kind, idl.BoundedSequence) else 3
            count = rng.randint(0, min(3, bound))
        setattr(message, field, [_scalar(rng, kind.value_type) for _ in range(count)])
    return message


def _dump_scalar(value: object, kind: object) -> object:
    if isinstance(kind, idl.NamespacedType):
        return dump(value)
    if isinstance(kind, idl.AbstractString):
        return value
    name = kind.typename
    if name == "boolean":
        return "1" if value else "0"
    if name == "octet":
        return str(value[0] if isinstance(value, bytes) else int(value))
    if name == "char":
        return str(ord(value) if isinstance(value, str) else int(value))
    if name in FLOATS:
        return struct.pack(">" + FLOATS[name], float(value)).hex()
    return str(int(value))


def dump(message: object) -> dict[str, object]:
    """The values of ``message`` as WireCheck.cs reads them."""
    cls = type(message)
    values: dict[str, object] = {}
    for field, kind in zip(cls.get_fields_and_field_types(), cls.SLOT_TYPES, strict=True):
        value = getattr(message, field)
        if isinstance(kind, idl.AbstractNestedType):
            values[field] = [_dump_scalar(v, kind.value_type) for v in value]
        else:
            values[field] = _dump_scalar(value, kind)
    return values


class _Walk:
    """Where a CDR payload's padding is, by type (XCDRv1, little-endian)."""

    def __init__(self, data: bytes) -> None:
        self.data, self.at, self.padding = data, 4, set()

    def align(self, size: int) -> None:
        while (self.at - 4) % size:
            self.padding.add(self.at)
            self.at += 1

    def count(self) -> int:
        self.align(4)
        value = int.from_bytes(self.data[self.at : self.at + 4], "little")
        self.at += 4
        return value

    def one(self, kind: object) -> None:
        if isinstance(kind, idl.NamespacedType):
            self.message(_nested(kind))
        elif isinstance(kind, idl.AbstractString):
            length = self.count()  # moves past the count first
            self.at += length
        else:
            self.align(SIZES[kind.typename])
            self.at += SIZES[kind.typename]

    def many(self, kind: object, count: int) -> None:
        if isinstance(kind, idl.BasicType) and count:
            self.align(SIZES[kind.typename])
            self.at += SIZES[kind.typename] * count
        elif not isinstance(kind, idl.BasicType):
            for _ in range(count):
                self.one(kind)

    def message(self, cls: type) -> None:
        if not cls.SLOT_TYPES:
            self.at += 1  # structure_needs_at_least_one_member
        for kind in cls.SLOT_TYPES:
            if isinstance(kind, idl.Array):
                self.many(kind.value_type, kind.size)
            elif isinstance(kind, idl.AbstractSequence):
                self.many(kind.value_type, self.count())
            else:
                self.one(kind)


def cases(name: str, randoms: int, seed: int) -> list[tuple[str, object]]:
    cls = message_class(name)
    rng = random.Random(f"{seed}/{name}")
    return [("default", cls())] + [(f"random{i}", _random(rng, cls)) for i in range(randoms)]


def make(names: list[str], randoms: int, seed: int) -> str:
    out = []
    for name in names:
        for label, message in cases(name, randoms, seed):
            data = serialize_message(message)
            walk = _Walk(data)
            walk.message(type(message))
            mask = bytes(1 if i in walk.padding else 0 for i in range(len(data)))
            values = json.dumps(dump(message), ensure_ascii=True)
            out.append(f"{name}\t{label}\t{data.hex()}\t{mask.hex()}\t{walk.at}\t{values}\n")
    return "".join(out)


def check(lines: list[str], randoms: int, seed: int) -> str:
    ours: dict[str, dict[str, str]] = {}
    for line in lines:
        name, label, data = line.split("\t")
        ours.setdefault(name, {})[label] = data
    out = []
    for name, labels in ours.items():
        for label, message in cases(name, randoms, seed):
            try:
                back = deserialize_message(bytes.fromhex(labels[label]), type(message))
                same = dump(back) == dump(message)
            except Exception as error:
                same, back = False, error
            if not same:
                out.append(f"{name}\t{label}\t{back!r:.300}\n")
    return "".join(out)


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("mode", choices=["make", "check"])
    parser.add_argument("--random", type=int, default=4)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    given = sys.stdin.read()
    if args.mode == "make":
        sys.stdout.write(make(given.split(), args.random, args.seed))
    else:
        sys.stdout.write(check(given.splitlines(), args.random, args.seed))
    return 0


if __name__ == "__main__":
    sys.exit(main())
