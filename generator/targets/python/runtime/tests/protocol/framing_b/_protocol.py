"""Constants of the test protocol, framing b (TESTPROTO_FRAMING=b): the other branch of every
framing choice that framing a (../_protocol.py) takes. Big-endian values; the descriptor before the
length byte, which counts the data only; the checksum's sum2 byte first; a different sync."""

from __future__ import annotations

from typing import Dict, Tuple

PACKAGE = "testproto"
BYTE_ORDER = ">"

SYNC = b"\xa5\x5a"
HEADER_SIZE = 4  # sync bytes + set + payload length
SET_OFFSET = 2
LENGTH_OFFSET = 3
FIELD_HEADER_SIZE = 2
FIELD_LENGTH_OFFSET = 1
FIELD_DESCRIPTOR_OFFSET = 0
FIELD_LENGTH_COUNTS_HEADER = False
FIELD_LENGTH_ADJUST = 0  # field length byte - data length
MAX_PAYLOAD = 200
MAX_PACKET = 206
MAX_FIELD_DATA = 198
CHECKSUM_SIZE = 2
CHECKSUM_SUM1_FIRST = False
# (set, descriptor) -> extra adjustment of the length byte.
IRREGULAR_LENGTHS: Dict[Tuple[int, int], int] = {
    (0x80, 0x06): -1,
}

DATA_SETS = frozenset((0x80, 0x82))
FIRST_SHARED = 0xD0
# Shared descriptor -> data size of the fields whose value identifies a sample.
TIMESTAMPS: Dict[int, int] = {0xD3: 4}
MAX_KEY = 6
