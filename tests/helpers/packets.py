"""Fletcher-16 and packets, written once for every Python test.

`framing` is the IR's framing of a protocol (generated/ir.json, `protocols[i]["framing"]`):
sync bytes, header size, offsets of the set and length bytes, and the order of the checksum bytes.
This is deliberately the byte-serial textbook Fletcher-16 (sum1, sum2 modulo 256), independent of
every generated runtime, so that the tests check the runtimes against it.
"""

from __future__ import annotations


def fletcher16(data: bytes) -> bytes:
    """The two sums (sum1, sum2) of the bytes, modulo 256, in that order."""
    s1 = s2 = 0
    for b in data:
        s1 = (s1 + b) & 0xFF
        s2 = (s2 + s1) & 0xFF
    return bytes([s1, s2])


def checksum(framing: dict, body: bytes) -> bytes:
    """The checksum bytes of a packet whose bytes up to the checksum are `body`, in the
    protocol's order (framing["checksum"]["order"], e.g. ["sum1", "sum2"])."""
    s1, s2 = fletcher16(body)
    sums = {"sum1": s1, "sum2": s2}
    return bytes(sums[k] for k in framing["checksum"]["order"])


def packet(framing: dict, set_id: int, payload: bytes, bad_checksum: bool = False) -> bytes:
    """A whole packet: header (sync, set, payload length), payload and checksum. With
    bad_checksum the first checksum byte has its low bit flipped."""
    header = bytearray(framing["header_size"])
    header[: len(framing["sync"])] = bytes(framing["sync"])
    header[framing["set_offset"]] = set_id
    header[framing["length_offset"]] = len(payload)
    body = bytes(header) + payload
    check = checksum(framing, body)
    if bad_checksum:
        check = bytes([check[0] ^ 0x01]) + check[1:]
    return body + check
