"""Reference cases for ROS 1, made with Debian's genpy (run under /usr/bin/python3).

Reads type names from stdin (``pkg/Name`` for a message, ``pkg/srv/NameRequest`` for a service
half), writes one line per case to stdout: ``type, case, genpy's serialize() as hex, the
values as JSON`` (tab-separated). Cases: the default instance, then ``--random`` seeded random
instances with extremes, NaN/±inf/-0.0, UTF-8 text and array lengths 0-3.
"""

from __future__ import annotations

import argparse
import importlib
import io
import json
import random
import struct
import sys

import genpy

INTS = {
    "int8": (-(2**7), 2**7 - 1),
    "uint8": (0, 2**8 - 1),
    "byte": (-(2**7), 2**7 - 1),
    "char": (0, 2**8 - 1),
    "int16": (-(2**15), 2**15 - 1),
    "uint16": (0, 2**16 - 1),
    "int32": (-(2**31), 2**31 - 1),
    "uint32": (0, 2**32 - 1),
    "int64": (-(2**63), 2**63 - 1),
    "uint64": (0, 2**64 - 1),
}
FLOATS = {"float32": "<f", "float64": "<d"}
SPECIAL = [float("nan"), float("inf"), float("-inf"), -0.0, 0.0, 1e-45, 3.4028234663852886e38]
TEXTS = ["", "plain", "ünïcödé", "日本語", "robot 🤖", 'quote " and \\ tab\t', "x" * 40]


def _class(name: str) -> type:
    package, _, rest = name.partition("/")
    kind, _, short = rest.rpartition("/")
    module = importlib.import_module(f"{package}.{kind or 'msg'}")
    return getattr(module, short)


def _split(slot_type: str) -> tuple[str, int | None, bool]:
    """(base, fixed size, is array)."""
    if slot_type.endswith("]"):
        base, _, size = slot_type[:-1].partition("[")
        return base, int(size) if size else None, True
    return slot_type, None, False


def _scalar(rng: random.Random, base: str) -> object:
    if base == "bool":
        return rng.random() < 0.5
    if base in INTS:
        low, high = INTS[base]
        return rng.choice([low, high, 0, rng.randint(low, high)])
    if base in FLOATS:
        value = rng.choice([*SPECIAL, rng.uniform(-1e6, 1e6)])
        return struct.unpack(FLOATS[base], struct.pack(FLOATS[base], value))[0]
    if base == "string":
        return rng.choice(TEXTS)
    if base == "time":
        return genpy.Time(rng.randint(0, 2**32 - 1), rng.randint(0, 999_999_999))
    if base == "duration":
        return genpy.Duration(rng.randint(-(2**31), 2**31 - 1), rng.randint(0, 999_999_999))
    if base == "Header":
        base = "std_msgs/Header"
    return _random(rng, _class(base))


def _random(rng: random.Random, cls: type) -> object:
    message = cls()
    for slot, slot_type in zip(cls.__slots__, cls._slot_types, strict=True):
        base, size, is_array = _split(slot_type)
        if not is_array:
            setattr(message, slot, _scalar(rng, base))
            continue
        count = size if size is not None else rng.randint(0, 3)
        values = [_scalar(rng, base) for _ in range(count)]
        if base in ("uint8", "char"):
            values = bytes(values)
        setattr(message, slot, values)
    return message


def _dump(value: object, slot_type: str) -> object:
    base, _, is_array = _split(slot_type)
    if is_array:
        items = (
            list(value)
            if not isinstance(value, bytes | str)
            else list(bytearray(value.encode() if isinstance(value, str) else value))
        )
        return [_dump(v, base) for v in items]
    if base == "bool":
        return "1" if value else "0"
    if base in INTS:
        return str(int(value))
    if base in FLOATS:
        return struct.pack(">" + FLOATS[base][1], value).hex()
    if base == "string":
        return value
    if base in ("time", "duration", "std_msgs/Time", "std_msgs/Duration"):
        if base.startswith("std_msgs/"):
            inner = value.data
            flat = {"sec": str(inner.secs), "nanosec": str(inner.nsecs)}
            return flat if base == "std_msgs/Time" else {"data": flat}
        return {"sec": str(value.secs), "nanosec": str(value.nsecs)}
    return _message(value)


def _message(message: object) -> dict[str, object]:
    cls = type(message)
    if cls._type == "std_msgs/Time":
        return _dump(message, "std_msgs/Time")  # the connector's class is the bare time
    return {
        slot: _dump(getattr(message, slot), slot_type)
        for slot, slot_type in zip(cls.__slots__, cls._slot_types, strict=True)
    }


def _serialize(message: object) -> str:
    buffer = io.BytesIO()
    message.serialize(buffer)
    return buffer.getvalue().hex()


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--random", type=int, default=4)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    out = []
    for name in sys.stdin.read().split():
        cls = _class(name)
        cases = [("default", cls())]
        rng = random.Random(f"{args.seed}/{name}")
        cases += [(f"random{i}", _random(rng, cls)) for i in range(args.random)]
        for case, message in cases:
            values = json.dumps(_message(message), ensure_ascii=True)
            out.append(f"{name}\t{case}\t{_serialize(message)}\t{values}\n")
    sys.stdout.write("".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
