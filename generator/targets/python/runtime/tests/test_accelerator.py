"""The C accelerator (_speedups.c) against the pure-Python code it replaces: the same events,
packets, values and errors. tests/lang/python.sh runs these tests with the accelerator built and
with TESTPROTO_PURE=1, where both sides are the pure-Python code."""

import copy
import dataclasses as _dc
import gc
import os
import pickle
import random
import struct

import testproto
from testproto import registry, sensor
from testproto.codec import layout as c
from testproto.codec import packets
from testproto.codec.framing import SYNC, PacketBuilder, Parser, RawPacket, Skip, parse
from testproto.codec.packets import Packet, decode_all, decode_columns


def test_accelerator_is_what_the_environment_asks_for():
    # Neither run of tests/lang/python.sh can silently be the other.
    if os.environ.get("TESTPROTO_PURE", "") not in ("", "0"):
        assert not testproto.ACCELERATED
    else:
        assert testproto.ACCELERATED  # conftest.py built it


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
    checked = set()
    for (set_id, descriptor), classes in registry.FIELDS.items():
        for cls in classes:
            items = c.fast_items(cls)
            if items is None:
                continue
            for fill in (0x00, 0x01, 0xFF, "random"):
                full = _layout_data(items, fill)
                for data in (full, full[:-1], full + b"\x00"):
                    packet = PacketBuilder(set_id).add_field(descriptor, data).build()
                    for device in (None, *registry.DEVICES):
                        got = packets.decode_packet(packet, 7, device)
                        want = packets._decode_packet_pure(packet, 7, device)
                        assert repr(got) == repr(want), (cls.__name__, data.hex())
                        assert got.line() == want.line(), (cls.__name__, data.hex())
                        assert [type(v) for v in got.values()] == [type(v) for v in want.values()]
                    entries = [(o, k, repr(x)) for o, k, x in decode_columns(b"\0" * 7 + packet).entries()]
                    want = packets._decode_packet_pure(packet, 7)
                    assert entries == [(7, k, repr(f)) for k, f in enumerate(want.fields)], (cls.__name__, data.hex())
                    checked.add(cls.__name__)
    # Every kind of fixed-size item the C side reads: u16/s8/bool, f32 array/f64/u64/s32, enum,
    # bitfield, string, char, per-device variants, an irregular length byte.
    assert {"Reading", "ScaledAccel", "State", "Temperature_alpha", "Temperature_beta", "Odd"} <= checked


def _stream(seed):
    """Packets of every field of the test protocol (good, short, long data) with garbage between."""
    rng = random.Random(seed)
    out = b""
    for (set_id, descriptor), classes in registry.FIELDS.items():
        size = len(classes[0]().encode())
        data = bytes(rng.getrandbits(8) for _ in range(size + rng.choice((-1, 0, 0, 1)) if size else 0))
        out += bytes(rng.getrandbits(8) for _ in range(rng.randrange(3)))
        out += PacketBuilder(set_id).add_field(descriptor, data).build()
    return out + PacketBuilder(0x01).add_field(0xF1, b"\x02\x00").build() + SYNC + b"\x01"


def test_accelerated_paths_match_the_pure_path():
    for seed in range(5):
        data = _stream(seed)
        parser = Parser()
        parser._scan = parser._scan_pure  # the pure-Python parser loop, also when the accelerator is built
        events = parser.feed(data) + parser.flush()
        assert parse(data) == events
        expected = [packets._decode_packet_pure(e.data, e.offset) if isinstance(e, RawPacket) else e for e in events]
        got = decode_all(data)
        assert [type(x) for x in got] == [type(x) for x in expected]
        assert [repr(x) for x in got] == [repr(x) for x in expected]
        decoder = testproto.Decoder()
        streamed = [x for i in range(0, len(data), 5) for x in decoder.feed(data[i : i + 5])] + decoder.flush()
        assert [repr(x) for x in streamed] == [repr(x) for x in expected]
        for g, e in zip(got, expected):
            if isinstance(g, Packet):
                assert [type(v) for v in g.values()] == [type(v) for v in e.values()]


def test_column_decode_leaves_out_the_fields_not_asked_for():
    # decode_columns(data, want): the accelerator decodes only the fields the mask asks for (by
    # the packet's set and the field's descriptor), each as without a mask; the packets, the
    # skips and the packets that do not split into fields are the same. The pure decoder gives
    # every field.
    for seed in range(3):
        data = _stream(seed)
        whole = decode_columns(data)
        want = packets.field_mask(sorted(registry.FIELDS)[seed % 2 :: 2])
        got = decode_columns(data, want)
        assert got.packets == whole.packets and repr(got.skips) == repr(whole.skips)
        set_of = {e.offset: e.set for e in decode_all(data) if isinstance(e, Packet)}
        expected = [
            (o, k, repr(x))
            for o, k, x in whole.entries()
            if not testproto.ACCELERATED or k < 0 or want[(set_of[o] << 8) | x.descriptor]
        ]
        assert [(o, k, repr(x)) for o, k, x in got.entries()] == expected
        assert len(expected) < len(whole.entries()) or not testproto.ACCELERATED


def _pure_lines(data):
    """The canonical lines by the pure-Python parser loop and line writers (the reference)."""
    parser = Parser()
    parser._scan = parser._scan_pure
    events = parser.feed(data) + parser.flush()
    return "".join(
        (packets._decode_packet_pure(e.data, e.offset).line() if isinstance(e, RawPacket) else packets.event_line(e))
        + "\n"
        for e in events
    ).encode("ascii")


def test_line_decoder_prints_the_canonical_lines_in_any_chunking():
    # LineDecoder (the decode CLI's loop; in C when the accelerator is built) against the pure
    # path: every fixed layout with NaN floats, invalid bools, unknown enums, strings with bytes to
    # escape, fields one byte short or long, slow layouts, trailing payload bytes, garbage and a
    # cut packet at the end; fed whole, in 5-byte and in 1-byte chunks.
    fills = b""
    for (set_id, descriptor), classes in registry.FIELDS.items():
        items = c.fast_items(classes[0])
        if items is None:
            continue
        for fill in (0x00, 0x01, 0xFF, 0x22, 0x5C, 0x7F, "random"):
            full = _layout_data(items, fill)
            for data in (full, full[:-1], full + b"\x00"):
                fills += b"\x55" + PacketBuilder(set_id).add_field(descriptor, data).build()
    for data in [_stream(seed) for seed in range(5)] + [fills, b"", SYNC, b"\x00" * 3]:
        want = _pure_lines(data)
        for size in (len(data) or 1, 5, 1):
            decoder = packets.LineDecoder()
            got = b"".join(decoder.feed(data[i : i + size]) for i in range(0, len(data), size)) + decoder.flush()
            assert got == want, size


def test_events_and_packets_copy_and_pickle():
    # RawPacket, Skip, Packet and DecodedField keep their attributes in C base classes when the
    # accelerator is built: copying and pickling must still carry them.
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
    data = PacketBuilder(0x80).add_field(0x01, b"\x00" * 4).build() * 3
    was = gc.isenabled()
    try:
        for enabled in (True, False):
            gc.enable() if enabled else gc.disable()
            decode_all(data)
            decode_columns(data)
            testproto.Decoder().feed(data)
            parse(data)
            assert gc.isenabled() == enabled
    finally:
        gc.enable() if was else gc.disable()


@_dc.dataclass
class PlainReading(c.Field):
    """sensor.Reading's layout in a class that is not slotted: the accelerator sets attributes."""

    count: int = 0
    offset: int = 0
    valid: bool = False

    SET, DESCRIPTOR, NAME, ROLE = 0x80, 0x3E, "plain_reading", "data"  # a descriptor no other test decodes
    _ATTRS, _OPS = sensor.Reading._ATTRS, sensor.Reading._OPS


def test_slotted_fields_keep_the_dataclass_semantics(monkeypatch):
    # codec.slotted (generated fields, ScaledAccel here; PlainReading above keeps its __dict__): no
    # __dict__, and the fields, equality, repr, pickling, copying and replace() of the dataclass.
    import dataclasses

    v = sensor.ScaledAccel([1.0, 2.0, 3.0], 0.5, 7, -1)
    assert not hasattr(v, "__dict__") and type(v).__slots__ == ("scaled_accel", "time", "ticks", "delta")
    assert [f.name for f in dataclasses.fields(v)] == ["scaled_accel", "time", "ticks", "delta"]
    assert repr(v) == "ScaledAccel(scaled_accel=[1.0, 2.0, 3.0], time=0.5, ticks=7, delta=-1)"
    assert v == sensor.ScaledAccel([1.0, 2.0, 3.0], 0.5, 7, -1) and v != sensor.ScaledAccel()
    assert sensor.ScaledAccel() == sensor.ScaledAccel([0.0, 0.0, 0.0], 0.0, 0, 0)
    assert pickle.loads(pickle.dumps(v)) == v and copy.deepcopy(v) == v and copy.copy(v) == v
    assert dataclasses.replace(v, ticks=8).ticks == 8
    assert sensor.ScaledAccel.decode(v.encode()) == v

    assert hasattr(PlainReading(), "__dict__") and not hasattr(sensor.Reading(), "__dict__")
    real = registry.lookup
    monkeypatch.setattr(registry, "lookup", lambda s, d: (PlainReading,) if (s, d) == (0x80, 0x3E) else real(s, d))
    # Decoded in C (slots stored by offset) and in Python: equal values of the same class.
    packet = PacketBuilder(0x80).add_field(0x02, v.encode()).add_field(0x3E, PlainReading(5, -2, True).encode()).build()
    got, want = packets.decode_packet(packet), packets._decode_packet_pure(packet, 0)
    assert repr(got) == repr(want) and got.values() == want.values()
    assert [type(x) for x in got.values()] == [sensor.ScaledAccel, PlainReading]
    assert got.values()[0] == v and pickle.loads(pickle.dumps(got)).values() == got.values()


def _float_cases():
    rng = random.Random(22)
    cases = [
        0.0,
        -0.0,
        1.0,
        0.1,
        0.3,
        2 / 3,
        100.0,
        1e16,
        1e17,
        1e22,
        1e23,
        1e-4,
        1e-5,
        1.5e-5,
        5e-324,
        2.2250738585072014e-308,
        2.225073858507201e-308,
        1.7976931348623157e308,
        9007199254740993.0,
        123456789012345678.0,
        1234567.0,
        0.001,
        12345678901234567890.0,
    ]
    cases += [float(2.0**e) for e in range(-1074, 1024, 7)]
    cases += [float(10.0**e) for e in range(-323, 309)]
    for _ in range(60000):
        bits = rng.getrandbits(64)
        cases.append(struct.unpack("<d", bits.to_bytes(8, "little"))[0])
        cases.append(struct.unpack("<f", (bits & 0xFFFFFFFF).to_bytes(4, "little"))[0])  # float32
        cases.append(rng.randrange(-(10**17), 10**17) / 10 ** rng.randrange(0, 25))  # short decimals
    return [x for x in cases if x == x and abs(x) != float("inf")]


def test_float_text_is_repr():
    # The JSON line writer's float printer (Grisu3, falling back to Python's own repr where it
    # cannot tell): the text of every value it prints is repr's, and it gives up rarely.
    if not testproto.ACCELERATED:
        return  # the pure run: no C printer to check (the accelerated run checks it)
    from testproto.codec import _speedups

    cases = _float_cases()
    given_up = 0
    for x in cases:
        text = _speedups.float_text(x)
        if text is None:
            given_up += 1
        else:
            assert text == repr(x), (x.hex(), text)
    assert given_up < len(cases) // 20, given_up


def _unpack_texts(offsets, body, n):
    at = struct.unpack(f"<{n + 1}q", offsets)
    return [body[at[i] : at[i + 1]].decode("ascii") for i in range(n)]


def test_csv_column_printers_are_the_python_texts():
    # The CSV export's column printers (logs/arrow.py `float_texts`, logs/writers.iso_texts):
    # repr_texts prints each float64 as repr does (nan, inf, -inf as such; a row marked invalid
    # empty); relayout_texts lays out the shortest digits of a number written in another layout
    # (pyarrow's float32 text: "1.5e-05", "1e+16", "100") as repr lays out the same digits, and
    # copies what is not a number; iso_texts writes UTC ns as 2026-03-14T09:14:02.010000Z, the
    # microseconds truncated toward zero, 27 bytes a row.
    if not testproto.ACCELERATED:
        return  # the pure run: no C printers (the accelerated run checks them)
    import datetime
    import decimal

    from testproto.codec import _speedups

    cases = _float_cases()[:20000] + [0.0, -0.0, 1e16, 1e-4, 9.999e-5, 100.0, float("nan"), float("inf"), -1e300]
    n = len(cases)
    valid = bytes(i % 7 != 3 for i in range(n))
    texts = _unpack_texts(*_speedups.repr_texts(struct.pack(f"<{n}d", *cases), 0, n, valid), n)
    for x, ok, text in zip(cases, valid, texts):
        assert text == ("" if not ok else "nan" if x != x else repr(x)), (x, text)
    texts = _unpack_texts(*_speedups.repr_texts(struct.pack(f"<{n}d", *cases), 5, 10), 10)
    assert texts == [repr(x) for x in cases[5:15]]

    given, expect = [], []
    for x in cases[:5000] + [0.0, -0.0, 1e16, 1e-4, 9.999e-5, 100.0]:
        if x != x or abs(x) == float("inf"):
            continue
        digits = decimal.Decimal(repr(x))
        for form in ("e", "f"):  # the same digits, laid out otherwise: 1.2345e+2, 123.45
            given.append(format(digits, form))
            expect.append(repr(x))
    given += ["nan", "-inf", "", "1e5x"]
    expect += ["nan", "-inf", "", "1e5x"]
    body = "".join(given).encode("ascii")
    bounds = [0]
    for t in given:
        bounds.append(bounds[-1] + len(t))
    for wide, code in ((False, "i"), (True, "q")):
        offsets = struct.pack(f"<{len(bounds)}{code}", *bounds)
        assert _unpack_texts(*_speedups.relayout_texts(offsets, body, 0, len(given), wide), len(given)) == expect

    times = [0, 1, 999, 1000, -1, -999, -1000, -1001, 1773479642010000000, 2**63 - 1, -(2**63)]
    times += [random.Random(7).randrange(-(2**63), 2**63) for _ in range(2000)]
    ok = bytes(i != 3 for i in range(len(times)))
    out = _speedups.iso_texts(struct.pack(f"<{len(times)}q", *times), 0, len(times), ok)
    assert len(out) == 27 * len(times)
    for i, t in enumerate(times):
        us = abs(t) // 1000 * (1 if t >= 0 else -1) if ok[i] else 0  # toward zero
        sec, frac = divmod(us, 1_000_000)
        head = (datetime.datetime(1970, 1, 1) + datetime.timedelta(seconds=sec)).strftime("%Y-%m-%dT%H:%M:%S")
        assert out[27 * i : 27 * i + 27].decode() == f"{head}.{frac:06d}Z", t


def test_event_objects_and_their_subclasses_are_freed():
    # The accelerator frees Packet, DecodedField, RawPacket and Skip itself (not through
    # CPython's generic dealloc): each instance gives back its class's reference, also for a
    # subclass with a __dict__ of its own.
    import sys

    class Tagged(Packet):
        pass

    packet = PacketBuilder(0x80).add_field(0x02, bytes(28)).build()
    stream = (b"\x00" + packet) * 200
    classes = (Packet, packets.DecodedField, RawPacket, Skip, Tagged)

    def run() -> None:
        events = decode_all(stream) + Parser().feed(stream)
        assert len(events) == 800
        tagged = [Tagged(7, 0x80, []) for _ in range(100)]
        for t in tagged:
            t.note = "kept in the instance __dict__"

    run()  # warm-up: the interpreter's caches take their references to the classes
    gc.collect()
    before = [sys.getrefcount(k) for k in classes]
    for _ in range(3):
        run()
    gc.collect()
    assert [sys.getrefcount(k) for k in classes] == before


def test_decoded_values_are_built_on_first_read_once():
    # With the accelerator a DecodedField of a fixed layout builds its value when `value` is first
    # read (then keeps it); either way the values equal the pure decoder's, and a field made in
    # Python, or whose value is set or deleted, behaves as a plain attribute.
    packet = PacketBuilder(0x80).add_field(0x02, sensor.ScaledAccel([1.0, 2.0, 3.0], 0.5, 7, -1).encode()).build()
    data = packet * 3
    got = [f for e in decode_all(data) for f in e.fields]
    want = [f for e in parse(data) for f in packets._decode_packet_pure(e.data, e.offset).fields]
    assert len(got) == 3 and all(type(f) is packets.DecodedField for f in got)
    for g, w in zip(got, want):
        first = g.value
        assert g.value is first and first == w.value and type(first) is type(w.value)
    field = got[0]
    field.value = sensor.ScaledAccel()
    assert field.value == sensor.ScaledAccel()
    del field.value
    assert not hasattr(field, "value")
    made = packets.DecodedField(0x02, want[0].value)
    assert made.value is want[0].value and made.descriptor == 0x02


def test_column_tables_read_the_same_in_every_form():
    # decode_columns hands its column buffers over without a copy: `columns`, `offsets` and `index`
    # (arrays made on first use) and `arrays()` (numpy views, when numpy is there) hold the same
    # numbers, row for row, as the entries.
    values = [sensor.ScaledAccel([float(k), -1.5, 2.0**k], k / 4, k, -k) for k in range(50)]
    data = b"".join(
        b"\x00" * (k % 3) + PacketBuilder(0x80).add_field(0x02, v.encode()).build() for k, v in enumerate(values)
    )
    cols = decode_columns(data)
    if not testproto.ACCELERATED:
        assert not cols.tables and len(cols.others) == len(values)
        return
    table = cols.tables[(0x80, 0x02)]
    assert len(table) == len(values) and [table.row(i) for i in range(len(values))] == values
    offsets = [e.offset for e in parse(data) if isinstance(e, RawPacket)]
    assert list(table.offsets) == offsets and list(table.index) == [0] * len(values)
    assert list(table.columns["ticks"]) == list(range(50))
    try:
        import numpy as np
    except ImportError:
        return
    arrays = table.arrays()
    assert arrays["scaled_accel"].shape == (50, 3)
    assert arrays["scaled_accel"].tolist() == [v.scaled_accel for v in values]
    assert np.array_equal(arrays["time"], np.asarray(table.columns["time"]))


def _shortest_f32(x):
    """The shortest digits of a finite float32 x != 0 by the definition, in exact rational
    arithmetic: the decimals of the fewest significant digits that read back as x (inside the
    interval halfway to its neighbours, the ends included when its significand is even), the
    closest to x (a tie to the even last digit); (digits, decimal point: 0.d1d2... x 10^point)."""
    import fractions
    import math

    bits = struct.unpack("<I", struct.pack("<f", x))[0] & 0x7FFFFFFF
    frac, bexp = bits & 0x7FFFFF, bits >> 23
    m, e = (frac | 0x800000, bexp - 150) if bexp else (frac, -149)
    v = fractions.Fraction(m) * fractions.Fraction(2) ** e
    ulp = fractions.Fraction(2) ** e
    low = v - (ulp / 4 if frac == 0 and bexp > 1 else ulp / 2)
    high = v + ulp / 2
    inside = (lambda d: low <= d <= high) if m % 2 == 0 else (lambda d: low < d < high)
    top = math.floor(math.log10(v)) + 1  # the decimal point after the first digit (or one off)
    for p in range(1, 10):
        best = None
        for point in (top - 1, top, top + 1):
            scale = fractions.Fraction(10) ** (point - p)
            q = v / scale
            for k in (math.floor(q) - 1, math.floor(q), math.floor(q) + 1, math.floor(q) + 2):
                if not 10 ** (p - 1) <= k < 10**p:
                    continue
                d = k * scale
                if inside(d):
                    key = (abs(d - v), k % 2)
                    if best is None or key < best[0]:
                        best = (key, str(k).rstrip("0"), point)
        if best is not None:
            return best[1], best[2]
    raise AssertionError(x)


def test_f32_texts_are_the_shortest_float32_digits():
    # The CSV printer of float32 columns (logs/arrow.py `_c_float_texts`): Grisu3 with a float's
    # boundaries, an exact search where Grisu3 gives up (about 1% of all float32, mostly above
    # 2^24), laid out as repr lays out the same digits: each text against the definition
    # (_shortest_f32), on random float32 bit patterns, decimals, integers above 2^24 and powers of
    # two (whose lower neighbour is the closer one).
    if not testproto.ACCELERATED:
        return  # the pure run: no C printer (the accelerated run checks it)
    import decimal

    from testproto.codec import _speedups

    rng = random.Random(50)
    cases = [struct.unpack("<f", struct.pack("<I", rng.getrandbits(32)))[0] for _ in range(2000)]
    cases += [rng.randrange(-(10**7), 10**7) / 10 ** rng.randrange(0, 9) for _ in range(1000)]
    cases += [float(rng.randrange(1 << 24, 1 << 40)) for _ in range(1000)]
    cases += [float(2.0**k) for k in range(-149, 128)] + [1e-45, 3.4028235e38, 1.1754942e-38, 0.1, 97474816.0]
    cases = [struct.unpack("<f", struct.pack("<f", x))[0] for x in cases if x == x and abs(x) < 3.4028236e38]
    cases = [x for x in cases if abs(x) != float("inf")]
    n = len(cases)
    valid = bytes(i % 11 != 5 for i in range(n))
    texts = _unpack_texts(*_speedups.f32_texts(struct.pack(f"<{n}f", *cases), 0, n, valid), n)
    for x, ok, text in zip(cases, valid, texts):
        if not ok:
            assert text == ""
            continue
        if x == 0:
            assert text == ("-0.0" if struct.pack("<f", x)[3] & 0x80 else "0.0")
            continue
        digits, point = _shortest_f32(x)
        want = repr(float(decimal.Decimal(f"{'-' if x < 0 else ''}0.{digits}e{point}")))
        assert text == want, (x, text, want)
    special = struct.pack("<4f", float("nan"), float("inf"), float("-inf"), 1.5)
    assert _unpack_texts(*_speedups.f32_texts(special, 1, 3), 3) == ["inf", "-inf", "1.5"]
    assert _unpack_texts(*_speedups.f32_texts(special, 0, 1), 1) == ["nan"]


def test_csv_rows_are_the_cells_joined():
    # The CSV export's row writer (logs/export.py `CsvRows`): int64 and uint64 digits, texts as they
    # are (int32 or int64 offsets, from a row offset), true/false, the empty cell where a row is
    # marked invalid; cells joined by ",", each row ended by "\n"; bad offsets are a ValueError.
    if not testproto.ACCELERATED:
        return  # the pure run: no C writer (the accelerated run checks it)
    import pytest
    from testproto.codec import _speedups

    ints = [0, -1, 2**63 - 1, -(2**63), 42]
    uints = [2**64 - 1, 0, 7, 10**19, 1]
    words = ["", "a", "2026-03-14T09:14:02.010000Z", "-1.5e-05", "x" * 70, "tail"]
    bounds = [0]
    for w in words:
        bounds.append(bounds[-1] + len(w))
    body = "".join(words).encode()
    columns = [
        (0, struct.pack("<5q", *ints), None, 0, None),
        (1, struct.pack("<5Q", *uints), None, 0, bytes([1, 1, 0, 1, 1])),
        (2, struct.pack(f"<{len(bounds)}i", *bounds), body, 1, None),
        (3, struct.pack(f"<{len(bounds)}q", *bounds), body, 0, bytes([1, 0, 1, 1, 1])),
        (4, bytes([1, 0, 1, 1, 0]), None, 0, bytes([1, 1, 1, 0, 1])),
    ]
    want = "".join(
        ",".join(
            [
                str(ints[i]),
                "" if i == 2 else str(uints[i]),
                words[i + 1],
                "" if i == 1 else words[i],
                "" if i == 3 else ("true" if (1, 0, 1, 1, 0)[i] else "false"),
            ]
        )
        + "\n"
        for i in range(5)
    )
    assert _speedups.csv_rows(columns, 5).decode() == want
    assert _speedups.csv_rows(columns, 0) == b""
    bad = [(2, struct.pack("<3i", 0, 5, 2), b"hello", 0, None)]  # a span that ends before it starts
    with pytest.raises(ValueError):
        _speedups.csv_rows(bad, 2)
    with pytest.raises(ValueError):
        _speedups.csv_rows([(0, struct.pack("<2q", 1, 2), None, 0, None)], 3)  # too few values
    with pytest.raises(ValueError):
        _speedups.csv_rows([(2, struct.pack("<2i", 0, 99), b"short", 0, None)], 1)  # past the text
