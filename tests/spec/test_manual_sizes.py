"""Field sizes computed from the MIP spec against sizes the manuals state in prose (not in the
per-field tables, whose lengths the CV7 pages get wrong for vectors and matrices).

Golden values, all from 3dm-cv7-ins-docs.txt:
- line 3976-3984 ("MIP Continuation Packets"): the filter (0x82) message format 11, 10, 01, 02,
  04, 05, 06, 07, 08, 09, 40, 41, 36, 37, 42 needs 290 payload bytes; the first packet carries
  11 .. 36 and the continuation 37, 42 (so 11 .. 36 fit in 255 bytes, 11 .. 37 do not);
- line 4006-4010: the same with shared D3 instead of 11 also needs 290 bytes, and D3 is repeated
  in the continuation packet (D3, 37, 42);
- line 3951 and 4123: the scaled accelerometer field is 14 bytes (field header included).
"""

from generator.spec import load_spec

PROTO = load_spec()["protocols"][0]
SETS = {s["id"]: s for s in PROTO["sets"]}
MAX_PAYLOAD = PROTO["framing"]["max_payload"]


def field_bytes(set_id: int, descriptor: int) -> int:
    """Field length on the wire: header + fixed data size."""
    s = SETS[PROTO["shared_data"]["set"]] if descriptor >= PROTO["shared_data"]["first_descriptor"] else SETS[set_id]
    f = next(f for f in s["fields"] if f["id"] == descriptor)
    size = f["variants"][0]["size"]
    assert size["fixed"], f"0x{set_id:02X},0x{descriptor:02X} is not fixed-size"
    assert all(v["size"] == size for v in f["variants"])
    return PROTO["framing"]["field_header_size"] + size["min"]


FORMAT = [0x11, 0x10, 0x01, 0x02, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0x40, 0x41, 0x36, 0x37, 0x42]


def split(descriptors: list[int], repeated: list[int]) -> list[list[int]]:
    """Packets as the device fills them: whole fields up to the maximum payload, with the
    leading shared fields repeated at the front of each continuation packet."""
    packets, current = [], []
    for d in descriptors:
        if current and sum(field_bytes(0x82, x) for x in current + [d]) > MAX_PAYLOAD:
            packets.append(current)
            current = list(repeated)
        current.append(d)
    return packets + [current]


def test_continuation_example_needs_290_bytes():
    assert sum(field_bytes(0x82, d) for d in FORMAT) == 290
    assert split(FORMAT, []) == [FORMAT[:13], [0x37, 0x42]]


def test_shared_timestamp_continuation_example():
    fmt = [0xD3] + FORMAT[1:]
    assert sum(field_bytes(0x82, d) for d in fmt) == 290
    assert split(fmt, [0xD3]) == [fmt[:13], [0xD3, 0x37, 0x42]]


def test_scaled_accel_field_is_14_bytes():
    assert field_bytes(0x80, 0x04) == 14
