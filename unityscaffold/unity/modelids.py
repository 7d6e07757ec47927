"""The fileIDs Unity gives the objects inside an imported model file (``.dae``, ``.fbx``, …).

Since Unity 2019.1 (``.meta`` ``fileIdsGeneration: 2``) an object of a model is identified by
the 64-bit xxHash (seed 0) of ``Type:<class>-><path><n>``, read as a signed integer: ``path`` is
the GameObject's path in the model (``//RootNode/root`` for the root) and, for a component,
that path and the class (``//RootNode/root/Transform``); a Mesh's path is its name; ``n``
counts earlier objects with the same class and path (0 for the first). A scene refers to a
model's objects by these IDs, so they can be computed without Unity.
"""

from __future__ import annotations

__all__ = ["MODEL_PREFAB_FILE_ID", "ROOT_PATH", "model_file_id", "xxhash64"]

#: The model's own prefab, which a scene's PrefabInstance names as ``m_SourcePrefab``.
MODEL_PREFAB_FILE_ID = 100100000
#: The path of a model's root GameObject (a file with one top node is folded into it).
ROOT_PATH = "//RootNode/root"

_MASK = (1 << 64) - 1
_P1, _P2, _P3 = 0x9E3779B185EBCA87, 0xC2B2AE3D27D4EB4F, 0x165667B19E3779F9
_P4, _P5 = 0x85EBCA77C2B2AE63, 0x27D4EB2F165667C5


def model_file_id(class_name: str, path: str, index: int = 0) -> int:
    """The fileID of the ``index``-th object of ``class_name`` at ``path`` in a model.

    For a component, ``path`` is its GameObject's path: ``model_file_id("MeshFilter",
    ROOT_PATH)`` is the root's MeshFilter; for a Mesh it is the mesh's name.
    """
    key = path if class_name in ("GameObject", "Mesh") else f"{path}/{class_name}"
    value = xxhash64(f"Type:{class_name}->{key}{index}".encode())
    return value - (1 << 64) if value >= 1 << 63 else value


def _rotl(value: int, bits: int) -> int:
    return ((value << bits) | (value >> (64 - bits))) & _MASK


def _round(acc: int, lane: int) -> int:
    return (_rotl((acc + lane * _P2) & _MASK, 31) * _P1) & _MASK


def _lane(data: bytes, at: int, size: int = 8) -> int:
    return int.from_bytes(data[at : at + size], "little")


def xxhash64(data: bytes, seed: int = 0) -> int:
    """XXH64 of ``data`` (the reference algorithm, for the short keys above)."""
    length, at = len(data), 0
    if length >= 32:
        acc = [(seed + _P1 + _P2) & _MASK, (seed + _P2) & _MASK, seed, (seed - _P1) & _MASK]
        while at + 32 <= length:
            acc = [_round(a, _lane(data, at + 8 * i)) for i, a in enumerate(acc)]
            at += 32
        digest = sum(_rotl(a, r) for a, r in zip(acc, (1, 7, 12, 18), strict=True)) & _MASK
        for a in acc:
            digest = ((digest ^ _round(0, a)) * _P1 + _P4) & _MASK
    else:
        digest = (seed + _P5) & _MASK
    digest = (digest + length) & _MASK
    while at + 8 <= length:
        digest = (_rotl(digest ^ _round(0, _lane(data, at)), 27) * _P1 + _P4) & _MASK
        at += 8
    if at + 4 <= length:
        digest = (_rotl(digest ^ ((_lane(data, at, 4) * _P1) & _MASK), 23) * _P2 + _P3) & _MASK
        at += 4
    while at < length:
        digest = (_rotl(digest ^ ((data[at] * _P5) & _MASK), 11) * _P1) & _MASK
        at += 1
    digest = ((digest ^ (digest >> 33)) * _P2) & _MASK
    digest = ((digest ^ (digest >> 29)) * _P3) & _MASK
    return digest ^ (digest >> 32)
