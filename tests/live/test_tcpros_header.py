"""The TCPROS connection header and one header exchange, against scripted peers."""

from __future__ import annotations

import socket
import struct
import threading
from collections.abc import Callable, Iterator

import pytest
from hypothesis import given
from hypothesis import strategies as st

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live._tcpros import (
    MalformedHeader,
    decode_header,
    encode_header,
    exchange,
)

_keys = st.text(
    st.characters(blacklist_characters="=", blacklist_categories=("Cs",)), min_size=1, max_size=10
)
_values = st.text(st.characters(blacklist_categories=("Cs",)), max_size=50)


@given(st.dictionaries(_keys, _values, max_size=6))
def test_headers_round_trip(fields: dict[str, str]) -> None:
    encoded = encode_header(fields)
    assert struct.unpack_from("<I", encoded)[0] == len(encoded) - 4
    assert decode_header(encoded[4:]) == fields


def test_the_wire_format_is_length_prefixed_key_value_fields() -> None:
    assert encode_header({"md5sum": "*", "type": "a=b"}) == (
        b"\x18\x00\x00\x00\x08\x00\x00\x00md5sum=*\x08\x00\x00\x00type=a=b"
    )


@pytest.mark.parametrize(
    "body",
    [b"\x01\x00", b"\x09\x00\x00\x00short", b"\x03\x00\x00\x00abc", b"\x03\x00\x00\x00a=\xff"],
)
def test_malformed_headers_are_refused(body: bytes) -> None:
    with pytest.raises(MalformedHeader):
        decode_header(body)


@pytest.fixture()
def peer() -> Iterator[Callable[[bytes], int]]:
    """A TCP peer that reads one request and answers with the given bytes, then closes."""
    servers: list[socket.socket] = []

    def start(reply: bytes) -> int:
        server = socket.socket()
        server.bind(("127.0.0.1", 0))
        server.listen(1)
        servers.append(server)

        def serve() -> None:
            connection, _ = server.accept()
            with connection:
                connection.recv(65536)
                connection.sendall(reply)

        threading.Thread(target=serve, daemon=True).start()
        return int(server.getsockname()[1])

    yield start
    for server in servers:
        server.close()


def test_exchange_returns_the_reply_header(peer: Callable[[bytes], int]) -> None:
    port = peer(encode_header({"type": "std_msgs/String", "md5sum": "992ce8a1"}) + b"data")
    reply = exchange("127.0.0.1", port, {"topic": "/a"}, timeout=1, peer="publisher of /a")
    assert reply == {"type": "std_msgs/String", "md5sum": "992ce8a1"}


@pytest.mark.parametrize(
    ("reply", "message"),
    [
        (b"", "publisher of /imu closed the connection before sending its header"),
        (
            encode_header({"error": "md5sums do not match"}),
            "publisher of /imu rejected the probe: md5sums do not match",
        ),
        (b"\xff\xff\xff\x7f", "sent a 2147483647-byte header; that is not TCPROS"),
        (b"\x05\x00\x00\x00\x01\x00\x00\x00x", "sent a malformed TCPROS header"),
    ],
)
def test_exchange_failures_name_the_peer(
    peer: Callable[[bytes], int], reply: bytes, message: str
) -> None:
    port = peer(reply)
    with pytest.raises(UserError, match=message.replace("(", r"\(")):
        exchange("127.0.0.1", port, {"topic": "/imu"}, timeout=1, peer="publisher of /imu")


def test_a_refused_connection_is_reported() -> None:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    with pytest.raises(UserError, match="publisher of /imu refused the connection"):
        exchange("127.0.0.1", port, {}, timeout=1, peer="publisher of /imu")


def test_a_silent_peer_times_out() -> None:
    with socket.socket() as silent:
        silent.bind(("127.0.0.1", 0))
        silent.listen(1)
        with pytest.raises(UserError, match=r"did not answer within 0\.3 s"):
            exchange("127.0.0.1", silent.getsockname()[1], {}, timeout=0.3, peer="node /x")
