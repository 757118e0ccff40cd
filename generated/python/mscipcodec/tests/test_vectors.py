"""Golden vectors and stream corpus of mscipcodec (tests/vector_cases.py, generated from the spec's
tests/vectors/ and tests/streams/): decode whole and fed in chunks of every size, encode back.
Plain source, the same in every package (generator/targets/python/runtime/package_tests/)."""

import pytest
from vector_cases import CASES, package

packets = package.codec.packets
Decoder, Packet, Parser, RawPacket, Skip, Trailing = (
    package.Decoder,
    package.Packet,
    package.Parser,
    package.RawPacket,
    package.Skip,
    package.Trailing,
)
decode_all, decode_bytes, decode_columns, decode_packet, decode_stream, encode_lines, parse = (
    package.decode_all,
    package.decode_bytes,
    package.decode_columns,
    package.decode_packet,
    package.decode_stream,
    package.encode_lines,
    package.parse,
)
event_line = packets.event_line


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_decode_whole(case):
    assert decode_bytes(bytes.fromhex(case["hex"]), case["device"]) == case["expect"], case["where"]


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_decode_every_chunking(case):
    data = bytes.fromhex(case["hex"])
    for size in range(1, len(data)):
        lines = list(decode_stream((data[i : i + size] for i in range(0, len(data), size)), case["device"]))
        assert lines == case["expect"], f"{case['where']}: decoded in chunks of {size} bytes"
        decoder = Decoder(case["device"])
        events = [e for i in range(0, len(data), size) for e in decoder.feed(data[i : i + size])] + decoder.flush()
        lines = [event_line(e) if isinstance(e, Skip) else e.line() for e in events]
        assert lines == case["expect"], f"{case['where']}: Decoder fed chunks of {size} bytes"
        if case["device"] is None:  # the decode CLI's loop (in C with the accelerator)
            text = packets.LineDecoder()
            out = b"".join(text.feed(data[i : i + size]) for i in range(0, len(data), size)) + text.flush()
            want = "".join(line + "\n" for line in case["expect"]).encode("ascii")
            assert out == want, f"{case['where']}: LineDecoder fed chunks of {size} bytes"


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_encode(case):
    assert encode_lines(case["expect"]).hex() == case["hex"], case["where"]


def _pure_events(data):
    parser = Parser()
    parser._scan = parser._scan_pure  # the pure-Python parser loop, also when the accelerator is built
    return parser.feed(data) + parser.flush()


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_accelerated_paths_match_the_pure_path(case):
    # parse / decode_packet / decode_all (in C when the accelerator is built) against the
    # pure-Python parser and decoder: the same events, lines, values and types.
    data = bytes.fromhex(case["hex"])
    events = _pure_events(data)
    assert parse(data) == events, case["where"]
    expected = [
        packets._decode_packet_pure(e.data, e.offset, case["device"]) if isinstance(e, RawPacket) else e for e in events
    ]
    got = decode_all(data, case["device"])
    decoder = Decoder(case["device"])
    streamed = [x for i in range(0, len(data), 5) for x in decoder.feed(data[i : i + 5])] + decoder.flush()
    assert [repr(x) for x in streamed] == [repr(x) for x in expected], case["where"]
    assert [type(x) for x in got] == [type(x) for x in expected], case["where"]
    assert [repr(x) for x in got] == [repr(x) for x in expected], case["where"]
    assert [event_line(x) if isinstance(x, Skip) else x.line() for x in got] == case["expect"], case["where"]
    for g, e in zip(got, expected):
        if isinstance(g, Packet):
            assert [type(f) for f in g.fields] == [type(f) for f in e.fields], case["where"]
            assert [type(v) for v in g.values()] == [type(v) for v in e.values()], case["where"]
            assert decode_packet(_raw(events, g.offset), g.offset, case["device"]).line() == e.line(), case["where"]


def _raw(events, offset):
    return next(e.data for e in events if isinstance(e, RawPacket) and e.offset == offset)


def _pure_entries(events):
    """(offset, index, repr) of every field entry, as Columns.entries() gives them."""
    out = []
    for e in events:
        if isinstance(e, RawPacket):
            p = packets._decode_packet_pure(e.data, e.offset)
            if any(isinstance(f, Trailing) for f in p.fields):
                out.append((p.offset, -1, repr(p)))
            else:
                out.extend((p.offset, k, repr(f)) for k, f in enumerate(p.fields))
    return out


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_decode_columns_matches_the_pure_path(case):
    # The columnar API (tables of numbers in C when accelerated, objects otherwise) holds every
    # field entry of the pure-Python decoder (no device: decode_columns has no device choice).
    data = bytes.fromhex(case["hex"])
    events = _pure_events(data)
    cols = decode_columns(data)
    assert cols.packets == sum(isinstance(e, RawPacket) for e in events), case["where"]
    assert cols.skips == [e for e in events if isinstance(e, Skip)], case["where"]
    assert [(o, k, repr(x)) for o, k, x in cols.entries()] == _pure_entries(events), case["where"]
    for table in cols.tables.values():
        assert len(table.offsets) == len(table.index) == len(table)
