"""The `link` facts of the spec (generator/passes/link.py) against what the manuals state.

Golden values:
- 3dm-gx5-45-dcp.txt line 1296: UART1 rates 9600, 19200, 115200 (default), 230400, 460800, 921600;
  line 1297: a 0.25 s delay after a baud-rate change (CV7 lines 7417 and 8144: 250 ms);
- 3dm-cv7-ins-docs.txt line 2718: UART1 115200, 230400, 460800, 921600, 3000000, no default stated;
- ms-cip-doc00419-revM.txt line 539 (Table 20): 9600 ... 921600; line 528: messages after the reply
  are at the new rate (no settle time); no idle or resume command in that manual;
- GX5-45 lines 558-562, CV7 lines 4123-4127: accelerometer vector (a 14-byte field) and internal
  timestamp (a 6-byte field), both at 100 Hz, need 60 x 100 + 10 (14 x 100 + 6 x 100) = 26000 baud;
- GX5-45 line 761 and 759: ping is 0x01,0x01, set to idle 0x01,0x02; line 832: resume 0x01,0x06.
"""

from generator.spec import load_spec

IR = {p["name"]: p for p in load_spec()["protocols"]}


def _field_size(proto: dict, set_id: int, descriptor: int) -> int:
    s = next(s for s in proto["sets"] if s["id"] == set_id)
    f = next(f for f in s["fields"] if f["id"] == descriptor)
    size = f["variants"][0]["size"]
    assert size["fixed"]
    return size["min"]


def test_mip_commands_and_settle_time():
    link = IR["mip"]["link"]
    assert (link["idle"]["set"], link["idle"]["descriptor"]) == (0x01, 0x02)
    assert (link["ping"]["set"], link["ping"]["descriptor"]) == (0x01, 0x01)
    assert (link["resume"]["set"], link["resume"]["descriptor"]) == (0x01, 0x06)
    assert link["baud_settle"]["ms"] == 250
    assert {(s["manual"], s["line"]) for s in link["baud_settle"]["sources"]} >= {
        ("3dm-gx5-45-dcp.txt", 1297),
        ("3dm-cv7-ins-docs.txt", 7417),
    }


def test_mip_baud_rates_per_device():
    rates = {e["device"]: e for e in IR["mip"]["link"]["baud_rates"]}
    assert rates["gx5_45"]["rates"] == [9600, 19200, 115200, 230400, 460800, 921600]
    assert rates["gx5_45"]["default"] == 115200
    assert rates["cv7_ins"]["rates"] == [115200, 230400, 460800, 921600, 3000000]
    assert rates["cv7_ins"]["default"] is None


def test_mip_bandwidth_reproduces_the_manuals_example():
    proto = IR["mip"]
    b = proto["link"]["bandwidth"]
    accel = _field_size(proto, 0x80, 0x04) + b["field_overhead"]  # scaled accelerometer vector
    # the internal timestamp (a u32, 0x80,0x0E of older models) is in neither manual's tables: its
    # 6-byte field is the manual's, its 4 data bytes plus the field header
    stamp = 4 + b["field_overhead"]
    assert (accel, stamp) == (14, 6)
    bits = b["uart_word_bits"] * (b["packet_overhead"] * 100 + accel * 100 + stamp * 100)
    assert bits == 26000


def test_mscip_states_only_what_its_manual_says():
    link = IR["mscip"]["link"]
    assert link["idle"] is None and link["resume"] is None and link["bandwidth"] is None
    assert (link["ping"]["set"], link["ping"]["descriptor"]) == (0x01, 0x02)
    assert link["baud_settle"]["ms"] == 0
    (entry,) = link["baud_rates"]
    assert entry["rates"] == [9600, 19200, 115200, 230400, 460800, 921600] and entry["default"] is None
