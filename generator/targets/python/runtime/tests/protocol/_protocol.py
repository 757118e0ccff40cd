"""Constants of the test protocol, framing a (the default; framing_b/ has the other branch of each
choice): what the generator renders from the IR into _protocol.py."""

from __future__ import annotations

from typing import Dict, Tuple

PACKAGE = "testproto"
BYTE_ORDER = "<"  # little-endian, unlike the real specs: the runtime's other branch

SYNC = b"\x75\x65"
HEADER_SIZE = 4  # sync bytes + set + payload length
SET_OFFSET = 2
LENGTH_OFFSET = 3
FIELD_HEADER_SIZE = 2
FIELD_LENGTH_OFFSET = 0
FIELD_DESCRIPTOR_OFFSET = 1
FIELD_LENGTH_COUNTS_HEADER = True
FIELD_LENGTH_ADJUST = 2  # field length byte - data length
MAX_PAYLOAD = 250  # below 255: a larger length byte is a false sync
MAX_PACKET = 256
MAX_FIELD_DATA = 248
CHECKSUM_SIZE = 2
CHECKSUM_SUM1_FIRST = True
# (set, descriptor) -> extra adjustment of the length byte.
IRREGULAR_LENGTHS: Dict[Tuple[int, int], int] = {
    (0x80, 0x06): -1,
}

DATA_SETS = frozenset((0x80, 0x82))
FIRST_SHARED = 0xD0
# Shared descriptor -> data size of the fields whose value identifies a sample.
TIMESTAMPS: Dict[int, int] = {0xD3: 4}
MAX_KEY = 6
