"""framing.py: Fletcher-16, the packet builder, the stream parser and the field splitter."""

import random

import pytest
from testproto.codec.framing import (
    CHECKSUM_SIZE,
    FIELD_DESCRIPTOR_OFFSET,
    FIELD_HEADER_SIZE,
    FIELD_LENGTH_ADJUST,
    FIELD_LENGTH_COUNTS_HEADER,
    FIELD_LENGTH_OFFSET,
    HEADER_SIZE,
    LENGTH_OFFSET,
    MAX_FIELD_DATA,
    MAX_PAYLOAD,
    SET_OFFSET,
    SYNC,
    FramingError,
    PacketBuilder,
    Parser,
    RawPacket,
    Skip,
    TrailingBytes,
    checksum_bytes,
    field_length_adjust,
    fletcher16,
    iter_fields,
    parse,
)
from testproto.registry import SET_KINDS

SET_ID = SET_KINDS[0][1]


def naive_fletcher16(data):
    sum1 = sum2 = 0
    for b in data:
        sum1 = (sum1 + b) & 0xFF
        sum2 = (sum2 + sum1) & 0xFF
    return (sum1 << 8) | sum2


def packet(descriptor=0x01, data=b"\x01\x02\x03", set_id=SET_ID):
    return PacketBuilder(set_id).add_field(descriptor, data).build()


def garbage(n, seed):
    rng = random.Random(seed)
    return bytes(rng.choice([b for b in range(256) if b != SYNC[0]]) for _ in range(n))


def bytewise(data):
    p = Parser()
    events = []
    for i in range(len(data)):
        events += p.feed(data[i : i + 1])
    return events + p.flush()


# ----------------------------------------------------------------------------------- checksum
def test_fletcher16_known_values():
    assert fletcher16(b"") == 0
    assert fletcher16(b"\x01\x02") == 0x0304
    rng = random.Random(1)
    for n in (1, 2, 7, 255, 1000):
        data = bytes(rng.randrange(256) for _ in range(n))
        assert fletcher16(data) == naive_fletcher16(data)


def test_packet_builder_layout():
    pkt = packet(0x42, b"\xaa\xbb")
    assert pkt[: len(SYNC)] == SYNC
    assert pkt[SET_OFFSET] == SET_ID
    assert pkt[LENGTH_OFFSET] == len(pkt) - HEADER_SIZE - CHECKSUM_SIZE == FIELD_HEADER_SIZE + 2
    field = pkt[HEADER_SIZE : HEADER_SIZE + FIELD_HEADER_SIZE]
    assert field[FIELD_DESCRIPTOR_OFFSET] == 0x42
    assert field[FIELD_LENGTH_OFFSET] == 2 + FIELD_LENGTH_ADJUST
    assert pkt[-CHECKSUM_SIZE:] == checksum_bytes(pkt[:-CHECKSUM_SIZE])


def test_packet_builder_keeps_to_the_maximum_payload():
    b = PacketBuilder(SET_ID).add_field(0x01, bytes(MAX_FIELD_DATA))
    with pytest.raises(FramingError):
        b.add_field(0x02, b"")
    with pytest.raises(FramingError):
        PacketBuilder(SET_ID).add_field(0x01, bytes(MAX_FIELD_DATA + 1))


def test_irregular_length_byte():
    # (0x80, 0x06) of the test protocol has a length byte one less than the rule's.
    assert field_length_adjust(0x80, 0x06) == FIELD_LENGTH_ADJUST - 1
    assert field_length_adjust(0x80, 0x05) == FIELD_LENGTH_ADJUST
    pkt = PacketBuilder(0x80).add_field(0x06, b"\x01\x02\x03\x04").build()
    assert pkt[HEADER_SIZE + FIELD_LENGTH_OFFSET] == 4 + FIELD_LENGTH_ADJUST - 1
    (f,) = iter_fields(0x80, pkt[HEADER_SIZE:-CHECKSUM_SIZE])
    assert (f.descriptor, f.data) == (0x06, b"\x01\x02\x03\x04")


# ----------------------------------------------------------------------------------- parser
def test_garbage_and_resync():
    pkt = packet()
    g1, g2 = garbage(5, 1), garbage(3, 2)
    stream = g1 + pkt + g2 + pkt
    want = [
        Skip(0, g1),
        RawPacket(len(g1), pkt),
        Skip(len(g1) + len(pkt), g2),
        RawPacket(len(g1) + len(pkt) + len(g2), pkt),
    ]
    assert parse(stream) == want
    assert bytewise(stream) == want


def test_bad_checksum_is_one_skip_run():
    pkt = packet()
    bad = pkt[:-1] + bytes([pkt[-1] ^ 0xFF])
    stream = bad + garbage(2, 3) + pkt
    want = [Skip(0, stream[: len(bad) + 2]), RawPacket(len(bad) + 2, pkt)]
    assert parse(stream) == want
    assert bytewise(stream) == want


def test_truncated_packet_at_end():
    pkt = packet()
    stream = pkt + pkt[:-1]
    want = [RawPacket(0, pkt), Skip(len(pkt), pkt[:-1])]
    assert parse(stream) == want
    assert bytewise(stream) == want


def test_partial_sync_at_end():
    pkt = packet()
    stream = pkt + SYNC[:1]
    assert parse(stream) == [RawPacket(0, pkt), Skip(len(pkt), SYNC[:1])]
    p = Parser()
    assert p.feed(stream) == [RawPacket(0, pkt)]
    assert p.flush() == [Skip(len(pkt), SYNC[:1])]


def test_false_header_running_past_the_end_hides_nothing():
    pkt = packet()
    header = bytearray(HEADER_SIZE)
    header[: len(SYNC)] = SYNC
    header[SET_OFFSET] = SET_ID
    header[LENGTH_OFFSET] = MAX_PAYLOAD
    stream = bytes(header) + pkt
    want = [Skip(0, bytes(header)), RawPacket(len(header), pkt)]
    assert parse(stream) == want
    assert bytewise(stream) == want


def test_length_above_the_maximum_is_a_false_sync():
    assert MAX_PAYLOAD < 255  # the test protocol's maximum leaves room for a bad length byte
    pkt = packet()
    header = bytearray(HEADER_SIZE)
    header[: len(SYNC)] = SYNC
    header[SET_OFFSET] = SET_ID
    header[LENGTH_OFFSET] = MAX_PAYLOAD + 1
    assert Parser().feed(bytes(header) + pkt) == [Skip(0, bytes(header)), RawPacket(len(header), pkt)]


def test_packet_inside_a_false_packet_is_found():
    pkt = packet()
    header = bytearray(HEADER_SIZE)
    header[: len(SYNC)] = SYNC
    header[SET_OFFSET] = SET_ID
    header[LENGTH_OFFSET] = len(pkt)
    tail = b"\x00" * CHECKSUM_SIZE
    stream = bytes(header) + pkt + tail
    events = parse(stream)
    assert events[:2] == [Skip(0, bytes(header)), RawPacket(len(header), pkt)]
    assert bytewise(stream) == events


@pytest.mark.parametrize("chunk", [1, 2, 3, 5, 64])
def test_chunking_does_not_matter(chunk):
    rng = random.Random(chunk)
    size = MAX_PAYLOAD - FIELD_HEADER_SIZE
    stream = b"".join(garbage(rng.randrange(4), i) + packet(i + 1, bytes(min(i, size))) for i in range(20)) + SYNC
    p = Parser()
    events = []
    for i in range(0, len(stream), chunk):
        events += p.feed(stream[i : i + chunk])
    assert events + p.flush() == parse(stream)


def test_pure_parser_loop_matches():
    # The parser loop in C (when the accelerator is built) against the pure-Python loop.
    stream = b"".join(garbage(3, i) + packet(i + 1, bytes(i)) for i in range(30)) + packet()[:-2]
    parser = Parser()
    parser._scan = parser._scan_pure
    assert parse(stream) == parser.feed(stream) + parser.flush()


# ----------------------------------------------------------------------------------- fields
def field(descriptor, data):
    h = bytearray(FIELD_HEADER_SIZE)
    h[FIELD_DESCRIPTOR_OFFSET] = descriptor
    h[FIELD_LENGTH_OFFSET] = len(data) + FIELD_LENGTH_ADJUST
    return bytes(h) + data


def test_field_iterator():
    payload = field(1, b"") + field(2, b"\x05\x06")
    got = list(iter_fields(0x01, payload))
    assert [(f.offset, f.descriptor, f.data) for f in got] == [(0, 1, b""), (FIELD_HEADER_SIZE, 2, b"\x05\x06")]


def test_field_iterator_errors():
    one = field(1, b"\x07")
    (f, t) = list(iter_fields(0x01, one + b"\x09"))
    assert isinstance(t, TrailingBytes) and t.data == b"\x09"
    assert t.error == f"field header at payload offset {len(one)} needs 2 bytes, 1 left"
    over = field(2, b"\x01\x02\x03")[:-1]
    (t,) = list(iter_fields(0x01, over))
    length = over[FIELD_LENGTH_OFFSET]
    assert t.error == f"field length {length} at payload offset 0 overruns the payload ({len(over)} bytes left)"
    short = bytearray(field(3, b""))
    short[FIELD_LENGTH_OFFSET] = 1
    (t,) = list(iter_fields(0x01, bytes(short)))
    if FIELD_LENGTH_COUNTS_HEADER:  # framing a: a length byte below the header size is an error
        assert t.error == "field length 1 at payload offset 0 is shorter than the field header"
    else:  # framing b: the length byte counts the data only
        assert isinstance(t, TrailingBytes) and t.error.startswith("field length 1 at payload offset 0 overruns")
