"""Constants of the MicroStrain MIP, generated from the IR: the only protocol input of the runtime.

The runtime modules (framing, codec, packets, samples, cli) are the same plain files in every
package (generator/targets/python/runtime/); what they need to know about this protocol they
import from here. _protocol.h holds the same facts for the C accelerator.
"""

from __future__ import annotations

from typing import Dict, FrozenSet, Tuple

PACKAGE = "mipcodec"
BYTE_ORDER = ">"  # struct byte order of every multi-byte value on the wire

# Framing (protocols[].framing).
SYNC = b"\x75\x65"
HEADER_SIZE = 4  # sync bytes + set + payload length
SET_OFFSET = 2
LENGTH_OFFSET = 3
FIELD_HEADER_SIZE = 2
FIELD_LENGTH_OFFSET = 0
FIELD_DESCRIPTOR_OFFSET = 1
FIELD_LENGTH_COUNTS_HEADER = True
FIELD_LENGTH_ADJUST = 2  # field length byte - data length
MAX_PAYLOAD = 255
MAX_PACKET = 261
# Foreign frames the parser reports between packets (docs/conformance.md section 1).
FOREIGN_NMEA = True  # NMEA-0183 sentences, at most NMEA_MAX bytes
FOREIGN_RTCM3 = True
NMEA_MAX = 128
MAX_FIELD_DATA = 253
CHECKSUM_SIZE = 2
CHECKSUM_SUM1_FIRST = True  # Fletcher-16 bytes on the wire: sum1 then sum2 when True
# Fields whose length byte differs from the rule above, (set, descriptor) -> extra adjustment
# (the spec's length_byte_adjust).
IRREGULAR_LENGTHS: Dict[Tuple[int, int], int] = {}

# Samples: the rule exported as `samples` in generated/ir.json (first_shared 0x100: no shared
# descriptors).
DATA_SETS: FrozenSet[int] = frozenset(
    (
        0x80,
        0x81,
        0x82,
        0x91,
        0x92,
        0x93,
        0x94,
        0xA0,
    )
)
FIRST_SHARED = 0xD0
# Shared descriptor -> data size of the fields whose value identifies a sample.
TIMESTAMPS: Dict[int, int] = {0xD3: 12, 0xD5: 8, 0xD7: 10}
MAX_KEY = 36
