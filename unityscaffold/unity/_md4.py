"""Pure-Python MD4 (RFC 1320).

OpenSSL 3 no longer offers MD4 through ``hashlib``, yet Unity derives the fileID of a
MonoBehaviour class compiled into a DLL from it, so we carry our own small implementation.
"""

from __future__ import annotations

import struct

__all__ = ["md4"]

_MASK = 0xFFFFFFFF


def _rotl(value: int, shift: int) -> int:
    value &= _MASK
    return ((value << shift) | (value >> (32 - shift))) & _MASK


def _pad(message: bytes) -> bytes:
    bit_length = (8 * len(message)) & 0xFFFFFFFFFFFFFFFF
    padded = message + b"\x80" + b"\x00" * ((55 - len(message)) % 64)
    return padded + struct.pack("<Q", bit_length)


def _compress(state: list[int], block: bytes) -> None:
    x = struct.unpack("<16I", block)
    a, b, c, d = state

    def f(u: int, v: int, w: int) -> int:
        return (u & v) | (~u & w)

    def g(u: int, v: int, w: int) -> int:
        return (u & v) | (u & w) | (v & w)

    for i in (0, 4, 8, 12):  # round 1
        a = _rotl(a + f(b, c, d) + x[i], 3)
        d = _rotl(d + f(a, b, c) + x[i + 1], 7)
        c = _rotl(c + f(d, a, b) + x[i + 2], 11)
        b = _rotl(b + f(c, d, a) + x[i + 3], 19)
    for i in (0, 1, 2, 3):  # round 2
        a = _rotl(a + g(b, c, d) + x[i] + 0x5A827999, 3)
        d = _rotl(d + g(a, b, c) + x[i + 4] + 0x5A827999, 5)
        c = _rotl(c + g(d, a, b) + x[i + 8] + 0x5A827999, 9)
        b = _rotl(b + g(c, d, a) + x[i + 12] + 0x5A827999, 13)
    for i in (0, 2, 1, 3):  # round 3
        a = _rotl(a + (b ^ c ^ d) + x[i] + 0x6ED9EBA1, 3)
        d = _rotl(d + (a ^ b ^ c) + x[i + 8] + 0x6ED9EBA1, 9)
        c = _rotl(c + (d ^ a ^ b) + x[i + 4] + 0x6ED9EBA1, 11)
        b = _rotl(b + (c ^ d ^ a) + x[i + 12] + 0x6ED9EBA1, 15)
    for i, value in enumerate((a, b, c, d)):
        state[i] = (state[i] + value) & _MASK


def md4(message: bytes) -> bytes:
    """Return the 16-byte MD4 digest of ``message``."""
    state = [0x67452301, 0xEFCDAB89, 0x98BADCFE, 0x10325476]
    padded = _pad(message)
    for offset in range(0, len(padded), 64):
        _compress(state, padded[offset : offset + 64])
    return struct.pack("<4I", *state)
