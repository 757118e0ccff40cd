"""Runtime tests (hand-written, protocol-independent): checksum, parser, field splitter, codec, JSON."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import dataclasses
import json
import random
import struct
import typing

import pytest
from democodec import codec as c
from democodec.canonical import NaN, f32_text, f64_text, float_from_json, string_text
from democodec.framing import (
    CHECKSUM_SIZE,
    FIELD_DESCRIPTOR_OFFSET,
    FIELD_HEADER_SIZE,
    FIELD_LENGTH_ADJUST,
    FIELD_LENGTH_COUNTS_HEADER,
    FIELD_LENGTH_OFFSET,
    HEADER_SIZE,
    LENGTH_OFFSET,
    MAX_PAYLOAD,
    SET_OFFSET,
    SYNC,
    PacketBuilder,
    Parser,
    RawPacket,
    Skip,
    TrailingBytes,
    checksum_bytes,
    fletcher16,
    iter_fields,
    parse,
)
from democodec.registry import SET_KINDS

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
    if FIELD_LENGTH_COUNTS_HEADER:
        short = bytearray(field(3, b""))
        short[FIELD_LENGTH_OFFSET] = 1
        (t,) = list(iter_fields(0x01, bytes(short)))
        assert t.error == "field length 1 at payload offset 0 is shorter than the field header"


# ----------------------------------------------------------------------------------- codec
class Mode(c.Enum):
    NONE = 0
    PAIR = 1


@dataclasses.dataclass
class Pair(c.Struct):
    a: int = 0
    b: bool = False

    _ATTRS = ("a", "b")
    _OPS = (c.Run(c.P("a", c.U8), c.P("b", c.BOOL)),)
    _SIZE = 2


class PairOrNothing(c.Union):
    _SELECTOR = Mode
    _MEMBERS = {0: None, 1: Pair}


@dataclasses.dataclass
class Everything(c.Field):
    x: int = 0
    v: typing.List[float] = dataclasses.field(default_factory=lambda: [0.0, 0.0])
    n: int = 0
    items: typing.List[int] = dataclasses.field(default_factory=list)
    mode: Mode = Mode.NONE
    choice: typing.Optional[Pair] = None
    pairs: typing.List[Pair] = dataclasses.field(default_factory=list)
    tail: typing.Optional[typing.List[int]] = None

    _ATTRS = ("x", "v", "n", "items", "mode", "choice", "pairs", "tail")
    _OPS = (
        c.Run(c.P("x", c.U16), c.P("v", c.F32, 2), c.P("n", c.U8)),
        c.Counted("items", c.S16, count="n", maximum=3),
        c.Run(c.P("mode", c.enum(Mode, "u8"))),
        c.Choice("choice", PairOrNothing, selector="mode"),
        c.Repeat("pairs", Pair, 1),
        c.Opt(c.Remaining("tail", c.U16, maximum=4)),
    )


BO = c.BYTE_ORDER


def sample_bytes():
    return (
        struct.pack(BO + "Hff", 7, 1.5, -2.0)
        + struct.pack(BO + "Bhh", 2, -1, 300)
        + bytes([1, 9, 1])
        + bytes([4, 0])
        + struct.pack(BO + "HH", 5, 6)
    )


def test_typed_round_trip():
    data = sample_bytes()
    v = Everything.decode(data)
    assert v == Everything(7, [1.5, -2.0], 2, [-1, 300], Mode.PAIR, Pair(9, True), [Pair(4, False)], [5, 6])
    assert v.encode() == data
    assert v.to_json() == (
        '{"x":7,"v":[1.5,-2.0],"n":2,"items":[-1,300],"mode":1,"choice":{"a":9,"b":true},'
        '"pairs":[{"a":4,"b":false}],"tail":[5,6]}'
    )
    assert Everything.from_json(json.loads(v.to_json())) == v
    short = data[:-4]
    assert Everything.decode(short).tail is None
    assert '"tail"' not in Everything.decode(short).to_json()


@pytest.mark.parametrize(
    "mutate,message",
    [
        (lambda d: d[:8], "v[1]: needs 4 bytes at offset 6, 2 left"),
        (lambda d: d[:10] + b"\x04" + d[11:], "items: count 4 exceeds maximum 3"),
        (lambda d: d[:17] + b"\x02" + d[18:], "choice.b: invalid bool value 2 at offset 17"),
        (lambda d: d[:15] + b"\x05" + d[16:], "choice: no member for selector value 5"),
        (lambda d: d[:18], "pairs[0].a: needs 1 bytes at offset 18, 0 left"),
        (lambda d: d + b"\x01", "tail: 5 bytes left at offset 20, not a multiple of 2"),
        (lambda d: d + b"\x00\x01" * 3, "tail: count 5 exceeds maximum 4"),
    ],
)
def test_decode_errors(mutate, message):
    with pytest.raises(c.DecodeError) as e:
        Everything.decode(mutate(sample_bytes()))
    assert str(e.value) == message


def test_unexpected_bytes():
    with pytest.raises(c.DecodeError) as e:
        Pair.decode(b"\x01\x00\x07")
    assert str(e.value) == "1 unexpected bytes at offset 2"


def test_unknown_enum_values_are_kept():
    v = Everything.decode(sample_bytes()[:15] + b"\x00" + sample_bytes()[18:])
    assert v.mode is Mode.NONE and v.choice is None
    assert c.enum(Mode, "u8").post(7, b"", 0) == 7


def test_encode_errors():
    with pytest.raises(c.EncodeError, match="x: 70000 is out of range for u16"):
        Everything(x=70000).encode()
    with pytest.raises(c.EncodeError, match="items: has 1 elements but n is 0"):
        Everything(items=[1]).encode()
    with pytest.raises(c.EncodeError, match="choice: expected a Pair"):
        Everything(mode=Mode.PAIR).encode()
    with pytest.raises(c.EncodeError, match=r"pairs\[0\].b: 2 is not a bool"):
        Everything(pairs=[Pair(1, 2)]).encode()


# ----------------------------------------------------------------------------------- floats, strings
def test_nan_bits_are_kept():
    for bits in (0x7FE5BF7F, 0x7F800001, 0xFFC00000, 0x7FC00000):
        # x, v[0] = the NaN, v[1] = 0.0, n = 0, mode = none, one pair
        data = struct.pack(BO + "HIf", 1, bits, 0.0) + bytes([0, 0, 0, 0])
        v = Everything.decode(data)
        assert isinstance(v.v[0], NaN) and v.v[0].bits == bits
        assert f32_text(v.v[0]) == ('"nan"' if bits == 0x7FC00000 else f'"nan:0x{bits:08x}"')
        assert v.encode()[2:6] == struct.pack(BO + "I", bits)
    assert float_from_json("nan:0x7fe5bf7f", 32).bits == 0x7FE5BF7F
    assert f64_text(float_from_json("nan:0x7ff0000000000001", 64)) == '"nan:0x7ff0000000000001"'
    assert f64_text(float("nan")) == '"nan"'


@pytest.mark.parametrize(
    "value,text",
    [
        (1.0, "1.0"),
        (0.0001, "0.0001"),
        (1e-05, "1e-05"),
        (1e16, "1e+16"),
        (1.5e16, "1.5e+16"),
        (123.456, "123.456"),
        (-0.0, "-0.0"),
        (2.5e-310, "2.5e-310"),
        (float("inf"), '"inf"'),
        (float("-inf"), '"-inf"'),
    ],
)
def test_float_text(value, text):
    assert f64_text(value) == text


def test_float_text_widens_floats():
    x = struct.unpack(">f", struct.pack(">f", 0.1))[0]
    assert f32_text(x) == "0.10000000149011612"


def test_string_text():
    assert string_text(b'a"\\\x00\x1f \x7e\x7f\xff') == '"a\\"\\\\\\u0000\\u001f ~\\u007f\\u00ff"'


# ------------------------------------------------------------------------------ C accelerator
def test_accelerator_is_what_the_environment_asks_for():
    # tests/lang/python.sh runs this suite twice: DEMOCODEC_PURE=1, and with the
    # extension built (DEMOCODEC_EXPECT_ACCELERATED=1), so neither run can silently be the other.
    import os

    import democodec

    if os.environ.get("DEMOCODEC_PURE", "") not in ("", "0"):
        assert not democodec.ACCELERATED
    if os.environ.get("DEMOCODEC_EXPECT_ACCELERATED"):
        assert democodec.ACCELERATED


def _layout_data(items, fill):
    size = sum(s * (1 if n < 0 else n) for _a, _k, s, n, _x in items)
    if fill == "random":
        return bytes(random.Random(size).getrandbits(8) for _ in range(size))
    return bytes([fill]) * size


def test_accelerated_decoder_matches_the_pure_decoder_on_every_fixed_layout():
    # Every field whose layout the C side reads itself, with data of all 0x00, 0x01, 0xFF (NaN
    # floats, invalid bools, unknown enum values, every flag), random bytes, one byte short and
    # one byte long, for each of its per-device layouts: the same entries (repr, line, types) as
    # the pure-Python decoder, errors included.
    from democodec import decode_columns, packets, registry

    checked = 0
    for (set_id, descriptor), classes in registry.FIELDS.items():
        for cls in classes:
            items = c.fast_items(cls)
            if items is None:
                continue
            for fill in (0x00, 0x01, 0xFF, "random"):
                full = _layout_data(items, fill)
                for data in (full, full[:-1], full + b"\x00"):
                    if len(data) > 200:
                        continue
                    packet = PacketBuilder(set_id).add_field(descriptor, data).build()
                    got = packets.decode_packet(packet, 7)
                    want = packets._decode_packet_pure(packet, 7)
                    assert repr(got) == repr(want), (cls.__name__, data.hex())
                    assert got.line() == want.line(), (cls.__name__, data.hex())
                    assert [type(v) for v in got.values()] == [type(v) for v in want.values()]
                    entries = [(o, k, repr(x)) for o, k, x in decode_columns(b"\0" * 7 + packet).entries()]
                    assert entries == [(7, k, repr(f)) for k, f in enumerate(want.fields)], (cls.__name__, data.hex())
                    checked += 1
    assert checked > 0


def test_events_and_packets_copy_and_pickle():
    # RawPacket, Skip, Packet and DecodedField keep their attributes in C base classes when the
    # accelerator is built: copying and pickling must still carry them.
    import copy
    import pickle

    from democodec import decode_all

    data = b"\x00\x01" + PacketBuilder(0x80).add_field(0x01, b"\x00" * 4).build()
    raw = parse(data)
    assert [type(e) for e in raw] == [Skip, RawPacket]
    for e in raw:
        assert copy.copy(e) == e
        assert pickle.loads(pickle.dumps(e)) == e
    for e in decode_all(data):
        assert repr(copy.deepcopy(e)) == repr(e)
        assert repr(pickle.loads(pickle.dumps(e))) == repr(e)


def test_decoding_leaves_the_garbage_collector_as_it_was():
    # The accelerator pauses the collector during a call; it must restore the caller's setting.
    import gc

    from democodec import Decoder, decode_all, decode_columns

    data = PacketBuilder(0x80).add_field(0x01, b"\x00" * 4).build() * 3
    was = gc.isenabled()
    try:
        for enabled in (True, False):
            gc.enable() if enabled else gc.disable()
            decode_all(data)
            decode_columns(data)
            Decoder().feed(data)
            parse(data)
            assert gc.isenabled() == enabled
    finally:
        gc.enable() if was else gc.disable()
