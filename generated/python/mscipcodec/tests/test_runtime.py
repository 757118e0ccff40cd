"""The C accelerator against the pure-Python decoder on this protocol's own layouts. The runtime's
unit tests run on a test protocol where it is written (generator/targets/python/runtime/tests/)."""

import os
import random

import mscipcodec
from mscipcodec import decode_columns, registry
from mscipcodec.codec import layout, packets
from mscipcodec.codec.framing import PacketBuilder


def test_accelerator_is_what_the_environment_asks_for():
    # tests/lang/python.sh runs this suite twice: MSCIPCODEC_PURE=1, and with the
    # extension built (MSCIPCODEC_EXPECT_ACCELERATED=1), so neither run can silently be the other.
    if os.environ.get("MSCIPCODEC_PURE", "") not in ("", "0"):
        assert not mscipcodec.ACCELERATED
    if os.environ.get("MSCIPCODEC_EXPECT_ACCELERATED"):
        assert mscipcodec.ACCELERATED


def test_accelerated_decoder_matches_the_pure_decoder_on_every_fixed_layout():
    # Every field whose layout the C side reads itself, with data of all 0x00, 0x01, 0xFF (NaN
    # floats, invalid bools, unknown enum values, every flag), random bytes, one byte short and
    # one byte long, for each of its per-device layouts: the same entries (repr, line, types) as
    # the pure-Python decoder, errors included.
    checked = 0
    for (set_id, descriptor), classes in registry.FIELDS.items():
        for cls in classes:
            items = layout.fast_items(cls)
            if items is None:
                continue
            size = sum(s * (1 if n < 0 else n) for _a, _k, s, n, _x in items)
            for fill in (b"\x00", b"\x01", b"\xff", bytes(random.Random(size).getrandbits(8) for _ in range(size))):
                full = fill * size if len(fill) == 1 else fill
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
