"""lookup_order: the search order of docs/conformance.md section 2 (a set's own
fields, then reserved fields of its kind, then shared data fields in data sets; first match
wins), on a small protocol written here, on a tiny spec through the passes, and on the real MIP
IR as exported in generated/ir.json."""

from __future__ import annotations

import json
from pathlib import Path

from tiny_spec import build, command_set, data_set

from generator.passes.lookup_order import entries, resolve, set_kind

ROOT = Path(__file__).resolve().parents[3]


def field(name: str, descriptor: int, **extra) -> dict:
    return {"name": name, "id": descriptor, **extra}


PROTOCOL = {
    "set_kinds": {"command": {"first": 0x01, "last": 0x7F}, "data": {"first": 0x80, "last": 0xFF}},
    "sets": [
        {"id": 0x01, "fields": [field("ping", 0x01), field("own_f1", 0xF1)]},
        {"id": 0x0C, "fields": [field("config", 0x01)]},
        {"id": 0x80, "fields": [field("accel", 0x04), field("own_d5", 0xD5)]},
        {"id": 0xFF, "fields": [field("gps_time", 0xD3), field("ref_time", 0xD5), field("ack_in_shared", 0xF1)]},
    ],
    "reserved_fields": [field("ack_nack", 0xF1, applies_to="command"), field("data_f0", 0xF0, applies_to="data")],
    "shared_data": {"set": 0xFF},
}


def names(set_id: int) -> dict[int, str]:
    return {d: f["name"] for d, (_, f) in resolve(PROTOCOL, set_id).items()}


def test_own_fields_come_first_then_reserved_of_the_kind() -> None:
    assert names(0x01) == {0x01: "ping", 0xF1: "own_f1"}  # its own 0xF1 hides the reserved ack
    assert names(0x0C) == {0x01: "config", 0xF1: "ack_nack"}
    owner, _ = resolve(PROTOCOL, 0x0C)[0xF1]
    assert owner is None  # reserved fields have no set


def test_data_sets_add_the_shared_fields_they_do_not_define() -> None:
    got = resolve(PROTOCOL, 0x80)
    assert {d: f["name"] for d, (_, f) in got.items()} == {
        0x04: "accel",
        0xD5: "own_d5",  # its own field, not the shared one
        0xF0: "data_f0",  # reserved of the data kind
        0xD3: "gps_time",
        0xF1: "ack_in_shared",  # command-kind reserved fields do not apply to a data set
    }
    assert got[0xD3][0]["id"] == 0xFF


def test_undefined_sets_resolve_by_kind() -> None:
    assert names(0x42) == {0xF1: "ack_nack"}
    assert names(0x90) == {0xF0: "data_f0", 0xD3: "gps_time", 0xD5: "ref_time", 0xF1: "ack_in_shared"}
    assert names(0x00) == {}  # no kind
    assert set_kind(PROTOCOL, 0x00) is None


def test_mip_shared_timestamps_resolve_in_the_sensor_set() -> None:
    """The real IR: 0xD5 (reference timestamp, CV7 manual) is a shared field in set 0x80."""
    ir = json.loads((ROOT / "generated" / "ir.json").read_text())
    mip = next(p for p in ir["protocols"] if p["package"] == "mipcodec")
    owner, f = resolve(mip, 0x80)[0xD5]
    assert (owner["id"], f["name"]) == (0xFF, "reference_timestamp")
    owner, f = resolve(mip, 0x01)[0xF1]
    assert owner is None and f["name"] == "ack_nack"


def test_the_ir_lookup_holds_every_set_and_the_undefined_ones_by_kind(tmp_path):
    ack = (
        "reserved_fields:\n  - id: 0xF1\n    name: ack\n    title: Ack\n    role: ack\n    applies_to: command\n"
        "    sources: [{manual: a.txt, line: 5}]\n    params: [{name: code, type: u8}]\n"
    )
    from tiny_spec import PROTOCOL

    protocol = PROTOCOL + "shared_data: {set: 0xFF, first_descriptor: 0xD0}\n" + ack
    own = "  - {id: 0x01, name: ping, role: command, title: Ping, sources: [{manual: a.txt, line: 4}], params: []}\n"
    accel = "  - {id: 0x04, name: accel, role: data, title: Accel, sources: [{manual: a.txt, line: 6}], params: []}\n"
    stamp = "  - {id: 0xD3, name: time, role: data, title: Time, sources: [{manual: a.txt, line: 7}], params: []}\n"
    files = {
        "protocol.yaml": protocol,
        "base.yaml": command_set(own),
        "sensor.yaml": data_set(accel),
        "shared.yaml": data_set(stamp, set_id=0xFF, name="shared"),
    }
    lookup = build(tmp_path, files, "lookup_order").lookup
    assert lookup["sets"] == [
        {
            "set": 0x01,
            "fields": [
                {"descriptor": 0x01, "name": "ping", "source": "own", "set": 0x01},
                {"descriptor": 0xF1, "name": "ack", "source": "reserved", "set": None},
            ],
        },
        {
            "set": 0x80,
            "fields": [
                {"descriptor": 0x04, "name": "accel", "source": "own", "set": 0x80},
                {"descriptor": 0xD3, "name": "time", "source": "shared", "set": 0xFF},
            ],
        },
        {"set": 0xFF, "fields": [{"descriptor": 0xD3, "name": "time", "source": "own", "set": 0xFF}]},
    ]
    assert lookup["other_sets"] == {
        "command": [{"descriptor": 0xF1, "name": "ack", "source": "reserved", "set": None}],
        "data": [{"descriptor": 0xD3, "name": "time", "source": "shared", "set": 0xFF}],
    }
    # Readers of the finished IR: a defined set, an undefined one of a kind, an id in no kind.
    protocol = {"set_kinds": {"command": {"first": 0x01, "last": 0x7F}}, "lookup": lookup}
    assert entries(protocol, 0x01) == lookup["sets"][0]["fields"]
    assert entries(protocol, 0x42) == lookup["other_sets"]["command"]
    assert entries(protocol, 0x90) == []


def test_the_exported_lookup_agrees_with_resolve_on_mip() -> None:
    ir = json.loads((ROOT / "generated" / "ir.json").read_text())
    mip = next(p for p in ir["protocols"] if p["package"] == "mipcodec")
    for table in mip["lookup"]["sets"]:
        got = {e["descriptor"]: (e["set"], e["name"]) for e in table["fields"]}
        want = {d: (o["id"] if o else None, f["name"]) for d, (o, f) in resolve(mip, table["set"]).items()}
        assert got == want
