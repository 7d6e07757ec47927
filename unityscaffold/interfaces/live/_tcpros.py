"""The TCPROS connection header, and one header exchange with a ROS 1 node.

Wire format: a little-endian uint32 with the length of what follows, then fields, each a
little-endian uint32 length and ``key=value`` (the value may itself contain ``=``). A node answers
a header with ``md5sum: '*'`` and ``type: '*'`` (topics) or ``probe: '1'`` (services) with its own
header, which carries the type, the md5sum and, for topics, the full message definition.
"""

from __future__ import annotations

import socket
import struct
from collections.abc import Mapping

from unityscaffold.errors import UserError

__all__ = ["MAX_HEADER", "decode_header", "encode_header", "exchange"]

# Full definitions of the largest standard types are a few kB; anything near this is not TCPROS.
MAX_HEADER = 16 * 1024 * 1024
_U32 = struct.Struct("<I")


class MalformedHeader(ValueError):
    """Bytes that are not a TCPROS header."""


def encode_header(fields: Mapping[str, str]) -> bytes:
    body = b"".join(
        _U32.pack(len(item)) + item
        for item in (f"{key}={value}".encode() for key, value in fields.items())
    )
    return _U32.pack(len(body)) + body


def decode_header(body: bytes) -> dict[str, str]:
    """The fields of a header body (without its leading total length)."""
    fields: dict[str, str] = {}
    offset = 0
    while offset < len(body):
        if offset + 4 > len(body):
            raise MalformedHeader(f"truncated field length at byte {offset}")
        (size,) = _U32.unpack_from(body, offset)
        offset += 4
        if offset + size > len(body):
            raise MalformedHeader(
                f"field at byte {offset} claims {size} bytes, {len(body) - offset} remain"
            )
        item = body[offset : offset + size]
        offset += size
        key, equals, value = item.partition(b"=")
        if not equals:
            raise MalformedHeader(f"field {item[:40]!r} has no '='")
        try:
            fields[key.decode()] = value.decode()
        except UnicodeDecodeError:
            raise MalformedHeader(f"field {item[:40]!r} is not UTF-8 text") from None
    return fields


def exchange(
    host: str, port: int, fields: Mapping[str, str], *, timeout: float, peer: str
) -> dict[str, str]:
    """Send ``fields`` to ``host:port`` and return the reply header; ``peer`` names the node
    in errors, e.g. "publisher of /imu"."""
    try:
        with socket.create_connection((host, port), timeout=timeout) as sock:
            sock.settimeout(timeout)
            sock.sendall(encode_header(fields))
            (size,) = _U32.unpack(_read_exactly(sock, 4, peer))
            if size > MAX_HEADER:
                raise UserError(
                    f"{peer} at {host}:{port} sent a {size}-byte header; that is not TCPROS"
                )
            reply = decode_header(_read_exactly(sock, size, peer))
    except ConnectionRefusedError:
        raise UserError(f"{peer} refused the connection ({host}:{port})") from None
    except TimeoutError:
        raise UserError(f"{peer} did not answer within {timeout:g} s ({host}:{port})") from None
    except MalformedHeader as exc:
        raise UserError(f"{peer} sent a malformed TCPROS header ({host}:{port}): {exc}") from None
    except OSError as exc:
        raise UserError(f"cannot reach {peer} at {host}:{port}: {exc.strerror or exc}") from None
    if "error" in reply:
        raise UserError(f"{peer} rejected the probe: {reply['error']}")
    return reply


def _read_exactly(sock: socket.socket, size: int, peer: str) -> bytes:
    chunks: list[bytes] = []
    remaining = size
    while remaining:
        chunk = sock.recv(min(remaining, 1 << 16))
        if not chunk:
            raise UserError(f"{peer} closed the connection before sending its header")
        chunks.append(chunk)
        remaining -= len(chunk)
    return b"".join(chunks)
