"""A consumer of the installed mipcodec package written against its documented API (README,
getting-started page): checked with `mypy --strict` against the installed wheel, then run.

    python typed_mipcodec.py HEX

HEX is the golden example data packet (the CV7 manual's scaled accelerometer example,
tests/vectors/mip/sensor.yaml `scaled_accel_example`). The assert_type lines state the types the
API promises; mypy fails the consumer test when one is wider (Any) or different.
"""

from __future__ import annotations

import math
import sys
from typing import TYPE_CHECKING, List, Optional, Union

import mipcodec
from mipcodec import (
    DecodedField,
    Decoder,
    Nmea,
    Packet,
    PacketBuilder,
    Parser,
    RawPacket,
    Rtcm,
    SampleGrouper,
    Skip,
    decode_all,
    decode_columns,
    decode_packet,
    encode_line,
)
from mipcodec.base import Ping
from mipcodec.codec.framing import MAX_PACKET
from mipcodec.reserved import AckNack
from mipcodec.sensor import ScaledAccel
from mipcodec.types import AckCode, AidingLlhValidFlags

if TYPE_CHECKING:
    from typing_extensions import assert_type


def accel_values(packet: Packet) -> List[ScaledAccel]:
    """The scaled accelerometer values of a decoded packet."""
    out: List[ScaledAccel] = []
    for entry in packet.fields:
        if isinstance(entry, DecodedField) and isinstance(entry.value, ScaledAccel):
            out.append(entry.value)
    return out


def check(condition: bool, what: str) -> None:
    if not condition:
        print(f"typed_mipcodec: {what}", file=sys.stderr)
        sys.exit(1)


def main(argv: List[str]) -> int:
    data = bytes.fromhex(argv[1])

    # The stream parser, fed in blocks, then flushed.
    parser = Parser()
    # (NMEA sentences and RTCM3 frames between packets are events too where the protocol has them)
    events: List[Union[RawPacket, Skip, Nmea, Rtcm]] = parser.feed(data[:5]) + parser.feed(data[5:]) + parser.flush()
    raw = [e for e in events if isinstance(e, RawPacket)]
    check(len(raw) == 1 and len(events) == 1, f"parser events {events}")
    packet = decode_packet(raw[0].data, raw[0].offset)
    if TYPE_CHECKING:
        assert_type(packet, Packet)
        assert_type(packet.set, int)
        assert_type(raw[0].data, bytes)

    # The typed value: a list of floats, the NaN keeping its bits.
    accel = accel_values(packet)
    check(len(accel) == 1, f"decoded {packet!r}")
    x, y, z = accel[0].scaled_accel
    if TYPE_CHECKING:
        assert_type(accel[0].scaled_accel, List[float])
    check(abs(x - 0.24452066) < 1e-7 and abs(y + 0.0043405485) < 1e-9, f"values {x}, {y}")
    check(math.isnan(z) and isinstance(z, mipcodec.NaN) and z.bits == 0x7FE5BF7F, f"NaN bits of {z!r}")

    # decode() of a layout class returns that class; encode() gives the field data back.
    field_data = data[6:-2]
    again = ScaledAccel.decode(field_data)
    if TYPE_CHECKING:
        assert_type(again, ScaledAccel)
        assert_type(ScaledAccel.from_json({"scaled_accel": [1.0, 2.0, 3.0]}), ScaledAccel)
    check(again.encode() == field_data, "ScaledAccel.encode() is not the field data")
    check(again.to_json() == accel[0].to_json(), "to_json differs")

    # Whole-stream and chunked decoding, samples and the column API.
    decoded = decode_all(data + data)
    if TYPE_CHECKING:
        assert_type(decoded, List[Union[Packet, Skip, Nmea, Rtcm]])
    offsets = [e.offset for e in decoded if isinstance(e, Packet)]
    check(offsets == [0, len(data)], f"decode_all found packets at {offsets}")
    decoder = Decoder()
    chunked = decoder.feed(data) + decoder.flush()
    if TYPE_CHECKING:
        assert_type(chunked, List[Union[Packet, Skip, Nmea, Rtcm]])
    check(len(chunked) == 1 and isinstance(chunked[0], Packet), f"Decoder gave {chunked}")
    grouper = SampleGrouper()
    samples = grouper.feed(raw[0]) + grouper.flush()
    check(len(samples) == 1 and samples[0].set == 0x80, f"samples {samples}")
    cols = decode_columns(data)
    check(cols.packets == 1, f"decode_columns counted {cols.packets} packets")
    row: Optional[ScaledAccel] = None
    for table in cols.tables.values():
        value = table.row(0)
        if isinstance(value, ScaledAccel):
            row = value
    entries = cols.entries()
    check(len(entries) == 1, f"decode_columns entries {entries}")

    # Building a command, and a packet from a canonical JSON line.
    command = PacketBuilder(Ping.SET).add(Ping()).build()
    if TYPE_CHECKING:
        assert_type(command, bytes)
    check(len(command) <= MAX_PACKET and decode_packet(command).values()[0].NAME == "ping", "ping")
    check(encode_line(packet.line()) == data, "encode_line(decode_packet(...).line()) is not the packet")

    # Enums: a value the spec does not name decodes as a plain int, and the annotation says so.
    acks = [AckNack.decode(bytes([0x01, code])).ack_code for code in (0x00, 0x7E)]
    if TYPE_CHECKING:
        assert_type(acks[0], Union[AckCode, int])
    check(acks[0] is AckCode.OK and type(acks[1]) is int and acks[1] == 0x7E, f"ack codes {acks!r}")
    named = [a.name for a in acks if isinstance(a, AckCode)]
    check(named == ["OK"], f"named ack codes {named}")

    # Bitfields: members are bool (one bit) and the operators keep the type.
    flags = AidingLlhValidFlags(AidingLlhValidFlags.LATITUDE) | AidingLlhValidFlags.HEIGHT
    if TYPE_CHECKING:
        assert_type(flags, AidingLlhValidFlags)
        assert_type(flags.latitude, bool)
    check(flags.latitude and flags.height and not flags.longitude, f"bitfield {flags!r}")
    print(f"typed_mipcodec: ok (accelerated={mipcodec.ACCELERATED}, column row {row!r})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
