"""The language-neutral command model (generator/commands.py): hand-built IR snippets, the
every-feature fixture, the real IR and its export to ir.json.

The expected values come from the manuals (cited by file and line) or from the rule written in
each test, never from the model itself."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from generator import commands
from generator.commands import ANY, FIELD, NO_REPLY, Condition
from generator.examples import session_example
from generator.export import ir_to_json
from generator.release import spec_hash
from generator.spec import load_spec

ROOT = Path(__file__).resolve().parents[2]
FIXTURE = Path(__file__).parent / "fixtures" / "everything"
IR = json.loads((ROOT / "generated" / "ir.json").read_text(encoding="utf-8"))
MIP = next(p for p in IR["protocols"] if p["name"] == "mip")
MSCIP = next(p for p in IR["protocols"] if p["name"] == "mscip")


def _size(n):
    return {"min": n, "max": n, "fixed": True}


def _q(name, tref, functions=None, optional=False, optional_for=None, count=None, max_count=None):
    return {
        "name": name,
        "type": tref,
        "count": count,
        "max_count": max_count,
        "optional": optional,
        "optional_for": optional_for,
        "functions": functions,
        "size": tref["size"],
    }


U8 = {"kind": "primitive", "name": "u8", "size": _size(1)}
MODE = {"kind": "enum", "name": "Mode", "base": "u8", "size": _size(1)}


def _proto(fields, variants_of=None):
    """A protocol with one command set 0x01 holding `fields` (each: name, id, role, variants)."""
    return {
        "name": "snip",
        "function_selector": {"enum": "Function"},
        "devices": [{"id": "a"}, {"id": "b"}],
        "types": [
            {
                "kind": "enum",
                "name": "Function",
                "base": "u8",
                "values": [
                    {"name": "write", "value": 1},
                    {"name": "read", "value": 2},
                    {"name": "quiet", "value": 6, "devices": ["a"]},
                ],
            },
            {
                "kind": "enum",
                "name": "Mode",
                "base": "u8",
                "values": [{"name": "off", "value": 0}, {"name": "on", "value": 7}],
            },
        ],
        "sets": [{"id": 1, "name": "cmd", "kind": "command", "fields": fields}],
    }


def _variant(params, functions=None, responses=(), device=None, devices=("a", "b"), ack=None, timeout=None):
    return {
        "device": device,
        "devices": list(devices),
        "functions": functions,
        "params": params,
        "responses": list(responses),
        "ack_suppressed_by": ack,
        "timeout": timeout,
    }


def _field(name, fid, role, variants):
    return {"name": name, "id": fid, "role": role, "variants": variants, "functions": None}


REPLY = _field("setting", 0x81, "response", [_variant([_q("x", U8)])])


def test_required_arguments_follow_optional_for():
    # A parameter sent only for write, optional in the layout (it may be cut off at the end of the
    # data) but not listed in optional_for: the caller must give it for write. Listed in
    # optional_for: the caller may leave it out. A plain optional parameter is never required.
    v = _variant(
        [
            _q("instance", U8, functions=["write", "read"]),
            _q("must", U8, functions=["write"], optional=True),
            _q("may", U8, functions=["write"], optional=True, optional_for=["write"]),
            _q("extra", U8, optional=True),
        ],
        functions=["write", "read"],
        responses=[{"id": 0x81, "name": "setting", "when": {"function": "read"}}],
    )
    m = commands.commands(_proto([_field("setting_cmd", 0x01, "command", [v]), REPLY]))
    write, read = m.calls
    assert (write.function, write.function_value) == ("write", 1)
    # Required first, in layout order, then the optional ones.
    assert [(a.name, a.required) for a in write.arguments] == [
        ("instance", True),
        ("must", True),
        ("may", False),
        ("extra", False),
    ]
    assert [(a.name, a.required) for a in read.arguments] == [("instance", True), ("extra", False)]
    # The reply to read only; write gets none (the response's `when` names read).
    assert (write.reply_kind, write.reply) == (NO_REPLY, None)
    assert read.reply_kind == FIELD and (read.reply.descriptor, read.reply.name) == (0x81, "setting")


def test_counts_are_set_from_their_arrays_and_are_not_arguments():
    v = _variant(
        [
            _q("n", U8),
            _q("items", U8, count={"kind": "param", "param": "n"}, max_count=4),
        ]
    )
    m = commands.commands(_proto([_field("list", 0x02, "command", [v])]))
    (call,) = m.calls
    assert call.function is None and call.function_value is None
    assert [a.name for a in call.arguments] == ["items"]
    assert [(c.param, c.array, c.array_required) for c in call.counts] == [("n", "items", True)]


def test_conditions_resolve_function_names_and_enum_values():
    # `when` with a function and an enum value by name; ack suppression by function; an allowance
    # by parameter for one function.
    v = _variant(
        [_q("mode", MODE), _q("ms", U8)],
        functions=["write", "read", "quiet"],
        responses=[
            {"id": 0x81, "name": "setting", "when": {"function": "read", "param": "mode", "value": "on"}},
            {"id": 0x82, "name": "other", "when": None},
        ],
        ack={"function": "quiet"},
        timeout={"ms": 10, "param": "ms", "functions": ["write"]},
    )
    other = _field("other", 0x82, "response", [_variant([])])
    m = commands.commands(_proto([_field("c", 0x03, "command", [v]), REPLY, other]))
    (lay,) = m.layouts
    assert lay.function_values == (1, 2, 6)
    assert lay.replies[0].when == Condition("read", 2, "mode", 7)
    assert lay.replies[1].when is None
    assert lay.ack_suppressed_by == Condition("quiet", 6, None, None)
    assert (lay.timeout.ms, lay.timeout.param, lay.timeout.functions, lay.timeout.function_values) == (
        10,
        "ms",
        ("write",),
        (1,),
    )
    assert lay.reads == ("mode", "ms")
    # read may get either reply (0x82 has no `when`): the call returns whichever came; write only 0x82.
    by_fn = {c.function: c for c in m.calls}
    assert by_fn["read"].reply_kind == ANY
    assert by_fn["write"].reply_kind == FIELD and by_fn["write"].reply.descriptor == 0x82
    assert [(f.name, f.value, f.devices) for f in m.functions] == [
        ("write", 1, ()),
        ("read", 2, ()),
        ("quiet", 6, ("a",)),
    ]


def test_a_call_splits_per_device_only_when_the_arguments_differ():
    same = [
        _variant([_q("x", U8)], device="a", devices=["a"]),
        _variant([_q("x", U8)], device="b", devices=["b"]),
    ]
    differ = [
        _variant([_q("x", U8)], device="a", devices=["a"]),
        _variant([_q("y", U8)], device="b", devices=["b"]),
    ]
    m = commands.commands(_proto([_field("same", 0x04, "command", same), _field("differ", 0x05, "command", differ)]))
    (one,) = m.calls_of(1, "same")
    assert (one.device, one.variants, one.devices) == (None, (0, 1), ("a", "b"))
    a, b = m.calls_of(1, "differ")
    assert (a.device, a.variants, b.device, b.variants) == ("a", (0,), "b", (1,))
    assert m.call(1, "differ", None, "b") is b and m.call(1, "same", None, "b") is one
    assert [x.device for x in m.layouts_of(1, "differ")] == ["a", "b"]


def test_api_sets_group_the_calls_per_set_then_per_command():
    # The rule: one group per command set that has calls, in it one per command field that has
    # calls (a reply field has none), each holding that field's calls; spec order throughout.
    differ = [
        _variant([_q("x", U8)], device="a", devices=["a"]),
        _variant([_q("y", U8)], device="b", devices=["b"]),
    ]
    proto = _proto([_field("ping", 0x01, "command", [_variant([])]), REPLY, _field("differ", 0x05, "command", differ)])
    proto["sets"].append(
        {"id": 2, "name": "other", "kind": "command", "fields": [_field("reset", 0x7E, "command", [_variant([])])]}
    )
    m = commands.commands(proto)
    groups = m.api_sets()
    assert [(g.set, g.set_name, [(c.descriptor, c.field) for c in g.commands]) for g in groups] == [
        (1, "cmd", [(0x01, "ping"), (0x05, "differ")]),
        (2, "other", [(0x7E, "reset")]),
    ]
    assert [c.device for c in groups[0].commands[1].calls] == ["a", "b"]
    assert [c for g in groups for cmd in g.commands for c in cmd.calls] == list(m.calls)


def test_everything_fixture():
    proto = load_spec(FIXTURE, root=FIXTURE)["protocols"][0]
    m = commands.commands(proto)
    # commands.yaml: ping (no parameters), configure (write, read, save; reply 0x82 to read; ack
    # suppressed by its suppress_ack parameter), per_device (dev_a takes a, dev_b b and extra).
    assert [(c.field, c.function, c.device) for c in m.calls] == [
        ("ping", None, None),
        ("configure", "write", None),
        ("configure", "read", None),
        ("configure", "save", None),
        ("per_device", None, "dev_a"),
        ("per_device", None, "dev_b"),
    ]
    set_id = next(s["id"] for s in proto["sets"] if any(f["name"] == "configure" for f in s["fields"]))
    configure = {c.function: c for c in m.calls_of(set_id, "configure")}
    assert [a.name for a in configure["write"].arguments] == ["instance", "mode", "params", "suppress_ack"]
    assert [a.name for a in configure["read"].arguments] == ["instance"]
    assert configure["read"].reply.descriptor == 0x82 and configure["save"].reply_kind == NO_REPLY
    (lay,) = m.layouts_of(set_id, "configure")
    assert lay.ack_suppressed_by == Condition(None, None, "suppress_ack", None)
    dev_b = m.call(set_id, "per_device", None, "dev_b")
    assert [(a.name, a.required) for a in dev_b.arguments] == [("b", True), ("extra", False)]


def test_real_ir_mip():
    m = commands.commands(MIP)
    # 3dm-cv7-ins-docs.txt:7267 Sensor-to-Vehicle Euler (0x0C,0x31): write/read/save/load/default
    # (function selector 0x01..0x05), roll, pitch and yaw sent for write, the reply 0xB1 to read.
    calls = {c.function: c for c in m.calls_of(0x0C, "sensor_to_vehicle_euler")}
    assert list(calls) == ["write", "read", "save", "load", "default"]
    assert [calls[f].function_value for f in calls] == [1, 2, 3, 4, 5]
    assert [(a.name, a.required) for a in calls["write"].arguments] == [
        ("roll", True),
        ("pitch", True),
        ("yaw", True),
    ]
    assert calls["read"].arguments == () and calls["read"].reply.descriptor == 0xB1
    assert all(calls[f].reply_kind == NO_REPLY for f in ("write", "save", "load", "default"))
    # 3dm-gx5-45-dcp.txt:867 GPS Time Update (0x01,0x72): 0x06 applies with no ACK/NACK reply.
    gx5 = next(x for x in m.layouts_of(0x01, "gps_time_update") if x.device == "gx5_45")
    assert gx5.ack_suppressed_by == Condition("write_no_ack", 6, None, None)
    # Both devices write a field selector and its value (3dm-gx5-45-dcp.txt:865,
    # 3dm-cv7-ins-docs.txt:8160): one write call for both, although the GX5-45's layout may leave
    # the value out (its read sends only the selector).
    (write,) = [c for c in m.calls_of(0x01, "gps_time_update") if c.function == "write"]
    assert (write.device, write.variants) == (None, (0, 1))
    assert [(a.name, a.required) for a in write.arguments] == [("field_id", True), ("value", True)]
    # 3dm-cv7-ins-docs.txt:6858 Message Format (0x0C,0x0F): the descriptor count is set from the list.
    write = m.call(0x0C, "message_format", "write", "cv7_ins")
    assert [(c.param, c.array) for c in write.counts] == [("num_descriptors", "descriptors")]
    assert [a.name for a in write.arguments] == ["desc_set", "descriptors"]
    # Data stream control (0x0C,0x11): the GX5-45 selects a device (3dm-gx5-45-dcp.txt:1047), the
    # CV7 a descriptor set (3dm-cv7-ins-docs.txt:6898): one write per device.
    assert [c.device for c in m.calls_of(0x0C, "data_stream_control") if c.function == "write"] == [
        "gx5_45",
        "cv7_ins",
    ]
    # Capture gyro bias (3dm-gx5-45-dcp.txt:1232): the command lasts averaging_time_ms.
    (cap,) = m.layouts_of(0x0C, "capture_gyro_bias")
    assert (cap.timeout.ms, cap.timeout.param) == (0, "averaging_time_ms") and cap.reads == ("averaging_time_ms",)
    # Every command field of every command set has at least one layout and one call.
    for s in MIP["sets"]:
        for f in s["fields"]:
            if s["kind"] == "command" and f["role"] == "command":
                assert len(m.layouts_of(s["id"], f["name"])) == len(f["variants"])
                assert m.calls_of(s["id"], f["name"])


def test_real_ir_mscip_has_no_ack_suppression():
    # MS-CIP acknowledges every command (ms-cip-doc00419-revM.txt: the ack 0x80 answers each).
    m = commands.commands(MSCIP)
    assert m.layouts and all(x.ack_suppressed_by is None for x in m.layouts)
    sample_rate = {c.function: c for c in m.calls_of(0x02, "sample_rate")}
    assert [a.name for a in sample_rate["write"].arguments] == ["decimation"]


@pytest.mark.parametrize("proto", IR["protocols"], ids=lambda p: p["name"])
def test_ir_json_carries_the_model_after_lookup(proto):
    assert list(proto).index("commands") == list(proto).index("lookup") + 1
    assert proto["commands"] == json.loads(json.dumps(commands.export(proto)))
    # Derived from the rest of the entry: the spec hash leaves it out.
    without = {k: v for k, v in proto.items() if k != "commands"}
    assert spec_hash(proto) == spec_hash(without)
    call = proto["commands"]["calls"][0]
    assert set(call) >= {"set", "descriptor", "function", "device", "arguments", "counts", "reply", "reply_field"}


def test_export_round_trips_through_ir_to_json():
    proto = load_spec(FIXTURE, root=FIXTURE)
    out = json.loads(ir_to_json(proto))["protocols"][0]
    assert [c["field"] for c in out["commands"]["calls"]][:2] == ["ping", "configure"]


def test_session_example_resolves_its_calls():
    ex = session_example(MIP)
    # The example runs against the CV7-INS: its data stream control call is the CV7's.
    assert ex["enable"]["calls"]["write"].device == "cv7_ins"
    assert set(ex["setting"]["calls"]) == {"write", "read"}
    assert ex["setting"]["calls"]["read"].reply_kind == FIELD
    assert ex["ping"]["calls"][None].reply_kind == NO_REPLY
