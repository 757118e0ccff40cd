"""Golden vectors and stream corpus (generated from tests/vectors/demo/ and
tests/streams/demo/): decode whole and fed in chunks of every size, encode back."""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import pytest
from democodec import packets
from democodec import (
    Decoder,
    Packet,
    Parser,
    RawPacket,
    Skip,
    Trailing,
    decode_all,
    decode_columns,
    decode_bytes,
    decode_packet,
    decode_stream,
    encode_lines,
    parse,
)
from democodec.packets import event_line

CASES = [
    {
        "name": "demo_ping_command",
        "hex": "a5a5010201004e23",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:11",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}'],
    },
    {
        "name": "demo_ack",
        "hex": "a5a5010480020100d2cd",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:22",
        "expect": ['{"offset":0,"set":1,"fields":[{"descriptor":128,"name":"ack","values":{"echo":1,"code":0}}]}'],
    },
    {
        "name": "demo_configure_write_gpio",
        "hex": "a5a501080206010101050100647f",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:32",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":2,"name":"configure","values":{"function":1,"instance":1,"mode":1,"params":{"pin":5,"polarity":true},"suppress_ack":false}}]}'
        ],
    },
    {
        "name": "demo_configure_write_none",
        "hex": "a5a501060204010200015b9c",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:45",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":2,"name":"configure","values":{"function":1,"instance":2,"mode":0,"params":null,"suppress_ack":true}}]}'
        ],
    },
    {
        "name": "demo_configure_read",
        "hex": "a5a501040202020358da",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:55",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":2,"name":"configure","values":{"function":2,"instance":3}}]}'
        ],
    },
    {
        "name": "demo_configuration_response",
        "hex": "a5a5017f827d0102006400c8616263000000000020202020202020202020206c6162656c3ff00000000000000000000000000000000000000000000000000000000000003ff00000000000000000000000000000000000000000000000000000000000003ff000000000000000000001ffffffff00000002fffffffe3001ffff78797a9f15",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:65",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":130,"name":"configuration","values":{"instance":1,"count":2,"rates":[100,200],"name":"abc\\u0000\\u0000\\u0000\\u0000\\u0000","label":"           label","matrix":[1.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,1.0],"fixed":[1,-1,2,-2],"flags":12289,"signed":-1,"tail":["x","y","z"]}}]}'
        ],
    },
    {
        "name": "demo_per_device_dev_a",
        "hex": "a5a5010603040102030462ab",
        "device": "dev_a",
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:97",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":3,"name":"per_device","device":"dev_a","values":{"a":16909060}}]}'
        ],
    },
    {
        "name": "demo_per_device_dev_b_with_extra",
        "hex": "a5a5010b03090000000000000001076ac6",
        "device": "dev_b",
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:108",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":3,"name":"per_device","device":"dev_b","values":{"b":1,"extra":7}}]}'
        ],
    },
    {
        "name": "demo_per_device_dev_b_without_extra",
        "hex": "a5a5010a030800000000000000ff5f46",
        "device": "dev_b",
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:119",
        "expect": [
            '{"offset":0,"set":1,"fields":[{"descriptor":3,"name":"per_device","device":"dev_b","values":{"b":255}}]}'
        ],
    },
    {
        "name": "demo_sample_repeated",
        "hex": "a5a5903e011d3f8000000000000000000000000000000102030405060708fe3f000000011d0000000000000000000000003f80000000000000000000007fbf800000f1a4",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:130",
        "expect": [
            '{"offset":0,"set":144,"fields":[{"descriptor":1,"name":"sample","values":{"quat":[1.0,0.0,0.0,0.0],"big":72623859790382856,"small":-2,"f":0.5}},{"descriptor":1,"name":"sample","values":{"quat":[0.0,0.0,0.0,1.0],"big":0,"small":127,"f":-1.0}}]}'
        ],
    },
    {
        "name": "demo_receiver_1_shared_and_layout",
        "hex": "a5a5911ed308000000003b9aca0003124046c00000000000c05e90000000000000037f56",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:147",
        "expect": [
            '{"offset":0,"set":145,"fields":[{"descriptor":211,"name":"timestamp","values":{"nanoseconds":1000000000}},{"descriptor":3,"name":"llh_position","values":{"latitude":45.5,"longitude":-122.25,"valid_flags":3}}]}'
        ],
    },
    {
        "name": "demo_receiver_2_same_layout",
        "hex": "a5a5921403124046c00000000000c05e9000000000000003fc84",
        "device": None,
        "rejected": False,
        "where": "tests/golden/vectors/demo/everything.yaml:161",
        "expect": [
            '{"offset":0,"set":146,"fields":[{"descriptor":3,"name":"llh_position","values":{"latitude":45.5,"longitude":-122.25,"valid_flags":3}}]}'
        ],
    },
    {
        "name": "demo_ping_bad_checksum",
        "hex": "a5a5010201004f23",
        "device": None,
        "rejected": True,
        "where": "tests/golden/vectors/demo/everything.yaml:171",
        "expect": ['{"offset":0,"skipped":"a5a5010201004f23"}'],
    },
]


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
