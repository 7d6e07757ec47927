"""A type a node describes without its source file is written back from its fields: the text
must hash (RIHS01) exactly as the description it came from, for every field kind ROS 2 has."""

from __future__ import annotations

from pathlib import Path

import pytest

from unityscaffold.interfaces.identity_ros2 import Ros2Identity
from unityscaffold.interfaces.live._graph import TypeReply
from unityscaffold.interfaces.live._typedesc import full_text_from_reply
from unityscaffold.interfaces.live.definitions import split_full_text
from unityscaffold.interfaces.model import Dialect, MessageSpec
from unityscaffold.interfaces.registry import Registry

# test_msgs' messages cover every primitive, bounded and unbounded string, and every array
# kind; the others add nested types, constants and empty messages.
ROOTS = [
    "test_msgs/msg/BasicTypes",
    "test_msgs/msg/BoundedSequences",
    "test_msgs/msg/Arrays",
    "test_msgs/msg/UnboundedSequences",
    "test_msgs/msg/MultiNested",
    "test_msgs/msg/Strings",
    "test_msgs/msg/Empty",
    "test_msgs/msg/Constants",
    "sensor_msgs/msg/PointCloud2",
]


def _reply(identity: Ros2Identity, spec: MessageSpec) -> TypeReply:
    """The description a node would send, with no sources (as ``implicit`` types come)."""
    described = identity.description(spec)
    every = [described["type_description"], *described["referenced_type_descriptions"]]
    return TypeReply(
        {},
        {
            d["type_name"]: tuple(
                (
                    f["name"],
                    f["type"]["type_id"],
                    f["type"]["capacity"],
                    f["type"]["string_capacity"],
                    f["type"]["nested_type_name"],
                )
                for f in d["fields"]
            )
            for d in every
        },
    )


@pytest.mark.parametrize("root", ROOTS)
def test_text_written_from_fields_hashes_as_the_description(root: str, tmp_path: Path) -> None:
    registry = Registry.load(Dialect.ROS2)
    spec = registry.message(root)
    identity = Ros2Identity(registry)
    text, lossy = full_text_from_reply(root, _reply(identity, spec))
    used = {m.full_name for m in registry.closure([spec])}
    assert lossy[0] == root and set(lossy) == {root, *used}
    for definition in split_full_text(root, text):
        target = tmp_path / definition.relative_path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(definition.text)
    rebuilt = Registry.load(Dialect.ROS2, [tmp_path], use_environment=False, use_builtin=False)
    assert Ros2Identity(rebuilt).type_hash(rebuilt.message(root)) == identity.type_hash(spec)


def test_a_source_file_is_kept_with_its_final_newline_put_back() -> None:
    registry = Registry.load(Dialect.ROS2)
    spec = registry.message("test_msgs/msg/Constants")
    reply = _reply(Ros2Identity(registry), spec)
    original = "# as the node's package holds it\nint32 X=123\nuint64 Y=5\nbool BOOL_CONST=true\n"
    # Jazzy's nodes send the file without its last newline
    sent = original.removesuffix("\n")
    with_source = TypeReply({"test_msgs/msg/Constants": ("msg", sent)}, reply.fields)
    text, lossy = full_text_from_reply("test_msgs/msg/Constants", with_source)
    assert (text, lossy) == (original, [])


def test_a_type_id_no_msg_file_has_is_refused() -> None:
    reply = TypeReply({}, {"pkg/msg/T": (("x", 12, 0, 0, ""),)})  # long double
    with pytest.raises(ValueError, match=r"field x has type id 12, which no \.msg type has"):
        full_text_from_reply("pkg/msg/T", reply)
