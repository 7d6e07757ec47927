"""The rospy side of the message round trip; runs under Debian's /usr/bin/python3.

For every planned type it publishes one instance with random non-default values in every field
on the plan's input topic (again every half second until answered), subscribes to its output
topic, and compares the first message that comes back with what it sent, field by field: exact,
except std_msgs/Header.seq, which every ROS 1 publisher overwrites. Float32 fields hold values
that float32 represents exactly, so they compare exactly too.
A plan entry may also "set" fields to given values after the random fill ({"a.b": {"string":
"x"}}, {"float": "nan"}, {"duration": [secs, nsecs]}) and "delay" its first publication (s).
Writes {key: null | "first difference"} as JSON, or "no answer" for one that never came back;
the key is the entry's "key", else its type.
Usage: roundtrip_node.py PLAN.json RESULT.json SEED TIMEOUT
"""

import json
import random
import string
import struct
import sys
import threading
import time

import genpy
import roslib.message
import rospy

INTEGERS = {
    "int8": (-(2**7), 2**7 - 1),
    "byte": (-(2**7), 2**7 - 1),
    "uint8": (0, 2**8 - 1),
    "char": (0, 2**8 - 1),
    "int16": (-(2**15), 2**15 - 1),
    "uint16": (0, 2**16 - 1),
    "int32": (-(2**31), 2**31 - 1),
    "uint32": (0, 2**32 - 1),
    "int64": (-(2**63), 2**63 - 1),
    "uint64": (0, 2**64 - 1),
}
# ASCII without quotes (double and single), backslash and control characters: a known
# defect between ROS# and rosbridge, reproduced separately in test_wire_defects.py.
STARTUP = 60.0  # seconds the C# side may take to subscribe
SAFE_TEXT = string.ascii_letters + string.digits + " -_.,;:!?()[]{}<>/=+*&%$#@~^|"


def random_integer(rng, low, high):
    return rng.choice([low, high, rng.randint(low, high), rng.randint(low, high)])


def random_float32(rng):
    value = rng.choice([rng.uniform(-1e6, 1e6), rng.uniform(-1, 1), 3.4e38, -1.5e-38])
    return struct.unpack("<f", struct.pack("<f", value))[0]


def random_value(rng, slot_type):
    if slot_type.endswith("]"):
        base, size = slot_type[:-1].split("[")
        count = int(size) if size else rng.randint(1, 3)
        if base in ("uint8", "char"):
            return bytes(rng.randint(0, 255) for _ in range(count))
        return [random_value(rng, base) for _ in range(count)]
    if slot_type in INTEGERS:
        return random_integer(rng, *INTEGERS[slot_type])
    if slot_type == "bool":
        return rng.choice([True, False])
    if slot_type == "float32":
        return random_float32(rng)
    if slot_type == "float64":
        return rng.choice([rng.uniform(-1e12, 1e12), rng.uniform(-1, 1), 1.7976931348623157e308])
    if slot_type == "string":
        return "".join(rng.choice(SAFE_TEXT) for _ in range(rng.randint(1, 12)))
    if slot_type == "time":
        return genpy.Time(rng.randint(1, 2**31 - 1), rng.randint(0, 999999999))
    if slot_type == "duration":
        # Non-negative: negative durations are a known defect (test_wire_defects.py).
        return genpy.Duration(rng.randint(0, 2**31 - 1), rng.randint(0, 999999999))
    return random_message(rng, roslib.message.get_message_class(slot_type))


def random_message(rng, cls):
    message = cls()
    for name, slot_type in zip(cls.__slots__, cls._slot_types, strict=True):
        setattr(message, name, random_value(rng, slot_type))
    return message


def special(value):
    ((kind, given),) = value.items()
    if kind == "float":
        return float(given)
    if kind == "duration":
        return genpy.Duration(*given)
    if kind == "time":
        return genpy.Time(*given)
    return given


def set_fields(message, settings):
    for path, value in settings.items():
        *parents, name = path.split(".")
        owner = message
        for parent in parents:
            owner = getattr(owner, parent)
        setattr(owner, name, special(value))


def difference(sent, got, path, slot_type):
    """The first field where ``got`` differs from ``sent``, or None."""
    if slot_type.endswith("]") and not slot_type.startswith(("uint8[", "char[")):
        base = slot_type[: slot_type.index("[")]
        if len(sent) != len(got):
            return f"{path}: length {len(got)}, sent {len(sent)}"
        for index, (a, b) in enumerate(zip(sent, got, strict=True)):
            found = difference(a, b, f"{path}[{index}]", base)
            if found:
                return found
        return None
    if isinstance(sent, genpy.Message):
        for name, inner in zip(sent.__slots__, sent._slot_types, strict=True):
            if slot_type == "std_msgs/Header" and name == "seq":
                continue
            found = difference(getattr(sent, name), getattr(got, name), f"{path}.{name}", inner)
            if found:
                return found
        return None
    if isinstance(sent, bytes):
        got = bytes(got) if not isinstance(got, str) else got.encode("latin-1")
    if sent != got and not (sent != sent and got != got):  # NaN equals NaN here
        return f"{path}: got {got!r}, sent {sent!r}"
    return None


def key(entry):
    return entry.get("key", entry["type"])


def main(plan_path, result_path, seed, timeout):
    with open(plan_path) as handle:
        plan = json.load(handle)
    rng = random.Random(int(seed))
    rospy.init_node("roundtrip", disable_signals=True)
    lock = threading.Lock()
    results = {}
    pending = []

    def receiver(entry, sent):
        def receive(message):
            with lock:
                if key(entry) not in results:
                    results[key(entry)] = difference(sent, message, "", entry["type"])

        return receive

    for entry in plan:
        cls = roslib.message.get_message_class(entry["type"])
        sent = random_message(rng, cls)
        set_fields(sent, entry.get("set", {}))
        publisher = rospy.Publisher(entry["in"], cls, queue_size=1)
        rospy.Subscriber(entry["out"], cls, receiver(entry, sent))
        pending.append((entry, publisher, sent))
    print("ready", flush=True)
    # TIMEOUT and "delay" count from the echo's first subscription (rosbridge's, to any input),
    # not from here: the C# side starts after "ready", later still on a loaded machine.
    start = time.monotonic()
    deadline = start + STARTUP
    subscribed = False
    while time.monotonic() < deadline:
        with lock:
            pending = [p for p in pending if key(p[0]) not in results]
        if not pending:
            break
        if not subscribed and any(p.get_num_connections() for _, p, _ in pending):
            subscribed = True
            start = time.monotonic()
            deadline = start + float(timeout)
        for entry, publisher, sent in pending:
            late = time.monotonic() - start < entry.get("delay", 0)
            if publisher.get_num_connections() and not late:
                publisher.publish(sent)
        time.sleep(0.5)
    for entry, _publisher, _sent in pending:
        results.setdefault(key(entry), "no answer")
    with open(result_path, "w") as handle:
        json.dump(results, handle, indent=1, sort_keys=True)
    rospy.signal_shutdown("done")


if __name__ == "__main__":
    main(*sys.argv[1:])
