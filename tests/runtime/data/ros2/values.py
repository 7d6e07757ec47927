"""Random ROS 2 messages and their field-by-field comparison, for the rclpy sides of the round
trips (roundtrip_node.py, service_node.py); read from each class's rosidl type description
(``SLOT_TYPES``), so every Jazzy type is covered without a table of its own."""

import importlib
import string
import struct

from rosidl_parser.definition import (
    AbstractNestedType,
    AbstractString,
    AbstractWString,
    Array,
    BasicType,
    BoundedSequence,
    BoundedString,
    BoundedWString,
    NamespacedType,
)

INTEGERS = {
    "int8": (-(2**7), 2**7 - 1),
    "uint8": (0, 2**8 - 1),
    "int16": (-(2**15), 2**15 - 1),
    "uint16": (0, 2**16 - 1),
    "int32": (-(2**31), 2**31 - 1),
    "uint32": (0, 2**32 - 1),
    "int64": (-(2**63), 2**63 - 1),
    "uint64": (0, 2**64 - 1),
}
# ASCII without quotes, backslash and control characters: those are a known defect between
# ROS# and rosbridge (test_wire_defects.py), not what this round trip is about.
SAFE_TEXT = string.ascii_letters + string.digits + " -_.,;:!?()[]{}<>/=+*&%$#@~^|"


def message_class(name):
    """``pkg/msg/Name``, ``pkg/srv/Name`` or ``pkg/action/Name`` (``_Goal``, ``_Result``,
    ``_Feedback`` for an action's parts) as its rclpy class."""
    package, kind, short = name.split("/")
    if kind == "action" and "_" in short:
        action, part = short.rsplit("_", 1)
        return getattr(getattr(importlib.import_module(f"{package}.action"), action), part)
    return getattr(importlib.import_module(f"{package}.{kind}"), short)


def _float32(rng):
    value = rng.choice([rng.uniform(-1e6, 1e6), rng.uniform(-1, 1), 3.4e38, -1.5e-38])
    return struct.unpack("<f", struct.pack("<f", value))[0]


def _basic(rng, name):
    if name in INTEGERS:
        low, high = INTEGERS[name]
        return rng.choice([low, high, rng.randint(low, high), rng.randint(low, high)])
    if name == "boolean":
        return rng.choice([True, False])
    if name == "octet":
        return bytes([rng.choice([0, 255, rng.randint(0, 255)])])
    if name == "char":
        return rng.choice(SAFE_TEXT)
    if name == "float":
        return _float32(rng)
    if name == "double":
        # At most 15 significant digits (the limit aside): Newtonsoft on Mono writes some 17-digit
        # doubles one digit short, a known defect of Mono's "R" format (test_wire_defects.py).
        value = rng.choice([rng.uniform(-1e12, 1e12), rng.uniform(-1, 1)])
        return rng.choice([float(f"{value:.15g}"), 1.7976931348623157e308])
    raise NotImplementedError(name)


def random_value(rng, slot):
    if isinstance(slot, AbstractNestedType):
        if isinstance(slot, Array):
            count = slot.size
        elif isinstance(slot, BoundedSequence):
            count = rng.randint(1, slot.maximum_size)
        else:
            count = rng.randint(1, 3)
        return [random_value(rng, slot.value_type) for _ in range(count)]
    if isinstance(slot, AbstractString | AbstractWString):
        limit = slot.maximum_size if isinstance(slot, BoundedString | BoundedWString) else 12
        return "".join(rng.choice(SAFE_TEXT) for _ in range(rng.randint(1, limit)))
    if isinstance(slot, BasicType):
        return _basic(rng, slot.typename)
    if isinstance(slot, NamespacedType):
        return random_message(rng, message_class("/".join([*slot.namespaces, slot.name])))
    raise NotImplementedError(repr(slot))


def random_message(rng, cls):
    message = cls()
    for name, slot in zip(cls.get_fields_and_field_types(), cls.SLOT_TYPES, strict=True):
        setattr(message, name, random_value(rng, slot))
    return message


def difference(sent, got, path):
    """The first field where ``got`` differs from ``sent`` (messages, lists, values), or None."""
    if hasattr(sent, "get_fields_and_field_types"):
        for name in sent.get_fields_and_field_types():
            found = difference(getattr(sent, name), getattr(got, name), f"{path}.{name}")
            if found:
                return found
        return None
    sent, got = _plain(sent), _plain(got)
    if not isinstance(sent, str | bytes | int | float | bool):
        sent, got = list(sent), list(got)
        if len(sent) != len(got):
            return f"{path}: length {len(got)}, sent {len(sent)}"
        for index, (a, b) in enumerate(zip(sent, got, strict=True)):
            found = difference(a, b, f"{path}[{index}]")
            if found:
                return found
        return None
    if sent != got:
        return f"{path}: got {got!r}, sent {sent!r}"
    return None


def _plain(value):
    """A numpy scalar (an item of a fixed-size array) as the Python value it holds."""
    if hasattr(value, "item") and not hasattr(value, "__len__"):
        return value.item()
    return value
