"""samples.py: continuation packets grouped by their shared timestamp (docs/conformance.md section 6)."""

from testproto.codec.framing import (
    FIELD_DESCRIPTOR_OFFSET,
    FIELD_HEADER_SIZE,
    FIELD_LENGTH_ADJUST,
    FIELD_LENGTH_OFFSET,
    PacketBuilder,
    RawPacket,
)
from testproto.codec.samples import DATA_SETS, TIMESTAMPS, SampleGrouper, SampleTracker, sample_key


def _stamped(stamp: int, *fields: tuple, key: bool = True) -> bytes:
    descriptor, size = next(iter(TIMESTAMPS.items()))
    b = PacketBuilder(min(DATA_SETS))
    if key:
        b.add_field(descriptor, bytes([stamp]) * size)
    for d, data in fields:
        b.add_field(d, data)
    return b.build()


def test_sample_key_is_the_leading_shared_timestamps():
    descriptor, size = next(iter(TIMESTAMPS.items()))
    header = bytearray(FIELD_HEADER_SIZE)
    header[FIELD_DESCRIPTOR_OFFSET] = descriptor
    header[FIELD_LENGTH_OFFSET] = size + FIELD_LENGTH_ADJUST
    assert sample_key(_stamped(9, (0x01, b"a"))) == bytes(header) + bytes([9]) * size
    assert sample_key(_stamped(9, (0x01, b"a"), key=False)) is None
    # A timestamp after the first non-shared field is not part of the key.
    late = PacketBuilder(min(DATA_SETS)).add_field(0x01, b"a").add_field(descriptor, bytes(size)).build()
    assert sample_key(late) is None


def test_sample_grouper_merges_continuation_packets():
    stamp = next(iter(TIMESTAMPS))
    packets = [
        _stamped(1, (0x01, b"a")),
        _stamped(1, (0x02, b"b")),  # same key: continuation
        _stamped(2, (0x03, b"c")),  # new key: completes the first sample
        _stamped(0, (0x04, b"d"), key=False),  # no key: a sample on its own
    ]
    tracker = SampleTracker()
    assert [tracker.feed(p) for p in packets] == [(0, False), (0, True), (1, False), (2, False)]
    grouper = SampleGrouper()
    done = []
    for offset, p in enumerate(packets):
        done += grouper.feed(RawPacket(offset * 100, p))
    assert [s.number for s in done] == [0, 1]
    first = done[0]
    assert first.offsets == [0, 100]
    # The continuation's copy of the timestamp is dropped; its own fields follow.
    assert [f.descriptor for f in first.fields] == [stamp, 0x01, 0x02]
    rest = grouper.flush()
    assert [(s.number, [f.descriptor for f in s.fields]) for s in rest] == [(2, [0x04])]
    assert grouper.flush() == []
    # A continuation after a flush (e.g. on a read timeout) is delivered on its own, with the
    # same sample number and its shared fields.
    g2 = SampleGrouper()
    assert g2.feed(_stamped(7, (0x05, b"e"))) == []
    [head] = g2.flush()
    assert g2.feed(_stamped(7, (0x06, b"f"))) == []
    [late] = g2.flush()
    assert (head.number, late.number) == (0, 0)
    assert [f.descriptor for f in late.fields] == [stamp, 0x06]
    # Command-set packets are not samples.
    assert tracker.feed(PacketBuilder(0x01).build()) is None
