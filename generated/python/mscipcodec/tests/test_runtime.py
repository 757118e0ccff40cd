"""The runtime on this protocol's own layouts: the C accelerator against the pure-Python decoder.

The runtime's unit tests (checksum, parser, field splitter, codec, JSON, samples, CLI) run on a
test protocol where the runtime is written (generator/targets/python/runtime/tests/).
"""

# ruff: noqa: I001  (whether the package is first- or third-party depends on where ruff runs)

import random

from mscipcodec import codec as c
from mscipcodec.framing import PacketBuilder


# ------------------------------------------------------------------------------ C accelerator
def test_accelerator_is_what_the_environment_asks_for():
    # tests/lang/python.sh runs this suite twice: MSCIPCODEC_PURE=1, and with the
    # extension built (MSCIPCODEC_EXPECT_ACCELERATED=1), so neither run can silently be the other.
    import os

    import mscipcodec

    if os.environ.get("MSCIPCODEC_PURE", "") not in ("", "0"):
        assert not mscipcodec.ACCELERATED
    if os.environ.get("MSCIPCODEC_EXPECT_ACCELERATED"):
        assert mscipcodec.ACCELERATED


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
    from mscipcodec import decode_columns, packets, registry

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
