"""The straight-line packet decoders' plan (generator/packet_plan.py, issue 38): which members a data
set's packet struct has and which layouts decode with constant-offset loads. Hand-built parameter
lists, then the real IR (sizes from the manuals' stated field lengths)."""

import json
from pathlib import Path

from generator import model, packet_plan
from generator.spec import load_spec

from .test_model import MODE, PAIR, PROTO, _prim, _q, _size

ROOT = Path(__file__).resolve().parents[2]
FIXTURE = Path(__file__).parent / "fixtures" / "everything"


def _plan(params, functions=None):
    return packet_plan.fast_layout(model.params(PROTO, params, functions))


def test_plain_values_load_at_constant_offsets():
    fast = _plan(
        [
            _q("x", _prim("u16", 2)),
            _q("v", _prim("float", 4), count={"kind": "fixed", "value": 3}, size=_size(12)),
            _q("mode", MODE),
            _q("ok", _prim("bool", 1)),
        ]
    )
    # 2 + 3 * 4 + 1 + 1 bytes, each value right after the one before it
    assert fast.size == 16
    assert [(x.param, x.index, x.primitive, x.off) for x in fast.loads] == [
        ("x", None, "u16", 0),
        ("v", 0, "float", 2),
        ("v", 1, "float", 6),
        ("v", 2, "float", 10),
        ("mode", None, "u8", 14),
        ("ok", None, "bool", 15),
    ]
    assert fast.bools == (15,)


def test_function_selector_is_the_first_load():
    fast = _plan([_q("x", _prim("s32", 4))], functions=["write", "read"])
    assert [(x.param, x.off) for x in fast.loads] == [("function", 0), ("x", 1)] and fast.size == 5


def test_anything_but_plain_values_has_no_fast_path():
    u8 = _q("n", _prim("u8", 1))
    assert _plan([]) is None
    assert _plan([u8, _q("o", _prim("u16", 2), optional=True)]) is None
    assert (
        _plan([u8, _q("items", PAIR, count={"kind": "param", "param": "n"}, max_count=10, size=_size(0, 30))]) is None
    )
    assert _plan([_q("rest", _prim("u16", 2), count={"kind": "remaining"}, max_count=9, size=_size(0, 18))]) is None
    assert _plan([_q("label", {"kind": "string", "length": 8, "padding": "nul", "size": _size(8)})]) is None
    assert _plan([_q("pair", PAIR)]) is None  # a struct: its own reader


def _ir(name):
    ir = json.loads((ROOT / "generated" / "ir.json").read_text())
    return next(p for p in ir["protocols"] if p["name"] == name)


def test_mip_sensor_set_members():
    proto = _ir("mip")
    plans = packet_plan.packet_plans(proto)
    # only data sets get a decoder (0x01 base commands, 0x0C 3DM commands: none)
    assert plans[0x01] is None and plans[0x0C] is None
    sensor = plans[0x80]
    assert sensor.set["id"] == 0x80
    by = {m.descriptor: m for m in sensor.members}
    # Scaled accelerometer (0x80, 0x04): stated length 14 (3dm-gx5-45-dcp.txt line 2035) = the
    # two-byte field header + three floats (x, y, z).
    accel = by[0x04]
    assert accel.source == "own" and accel.field_set == 0x80 and accel.field["name"] == "scaled_accel"
    assert accel.fast.size == 12 and [x.off for x in accel.fast.loads] == [0, 4, 8]
    assert {x.primitive for x in accel.fast.loads} == {"float"}
    # members follow the set's lookup, which is ordered by descriptor
    table = next(t["fields"] for t in proto["lookup"]["sets"] if t["set"] == 0x80)
    assert [m.descriptor for m in sensor.members] == [
        e["descriptor"]
        for e in table
        if len(
            next(
                f
                for s in proto["sets"]
                for f in s["fields"]
                if e["source"] != "reserved" and s["id"] == e["set"] and f["id"] == e["descriptor"]
            )["variants"]
        )
        == 1
    ]
    # the shared data fields (set 0xFF) are members of every data set
    shared = [m for m in sensor.members if m.source == "shared"]
    assert shared and all(m.field_set == 0xFF for m in shared)


def test_fields_with_per_device_variants_are_left_to_the_general_dispatch():
    proto = _ir("mip")
    plans = packet_plan.packet_plans(proto)
    multi = [(s["id"], f["id"]) for s in proto["sets"] if plans[s["id"]] for f in s["fields"] if len(f["variants"]) > 1]
    assert multi, "the MIP spec has data fields with per-device layouts"
    for set_id, descriptor in multi:
        assert descriptor not in [m.descriptor for m in plans[set_id].members if m.source == "own"]


def test_everything_fixture_every_data_set_has_a_plan():
    proto = load_spec(FIXTURE, root=FIXTURE)["protocols"][0]
    plans = packet_plan.packet_plans(proto)
    for s in proto["sets"]:
        assert (plans[s["id"]] is not None) == (s["kind"] == "data")
        for m in plans[s["id"]].members if plans[s["id"]] else ():
            assert len(m.field["variants"]) == 1 and m.variant is m.field["variants"][0]
            if m.fast:
                assert m.fast.size == m.variant["size"]["min"] == m.variant["size"]["max"]
