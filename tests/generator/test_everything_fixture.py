"""The fixture protocol in fixtures/everything uses every feature of the spec format; check the IR."""

from pathlib import Path

from generator.spec import load_spec
from generator.stated_lengths import lint_stated_lengths

FIXTURE = Path(__file__).parent / "fixtures" / "everything"


def _proto():
    return load_spec(FIXTURE, root=FIXTURE)["protocols"][0]


def _field(p, set_name, name):
    s = next(s for s in p["sets"] if s["name"] == set_name)
    return next(f for f in s["fields"] if f["name"] == name)


def test_framing_is_data():
    f = _proto()["framing"]
    assert f["sync"] == [0xA5, 0xA5]
    assert f["field_descriptor_offset"] == 0 and f["field_length_offset"] == 1
    assert f["field_length_adjust"] == 0
    assert f["header_size"] == 4 and f["max_packet"] == 4 + 255 + 2


def test_union_struct_and_optional_params():
    cfg = _field(_proto(), "commands", "configure")["variants"][0]
    assert cfg["functions"] == ["write", "read", "save"]
    names = [q["name"] for q in cfg["params"]]
    assert names == ["instance", "mode", "params", "suppress_ack"]
    assert [q["optional"] for q in cfg["params"]] == [False, True, True, True]
    union = cfg["params"][2]["type"]
    assert union["kind"] == "union" and union["selector"] == "mode"
    # union size: none (0) .. threshold (8 + 8 + 12 = 28)
    assert union["size"] == {"min": 0, "max": 28, "fixed": False}
    assert cfg["responses"] == [{"id": 0x82, "when": {"function": "read"}, "name": "configuration"}]
    assert cfg["ack_suppressed_by"] == {"param": "suppress_ack"}
    # selector byte + instance are the only required bytes
    assert cfg["size"]["min"] == 2


def test_arrays_strings_bitfields_enums():
    p = _proto()
    resp = _field(p, "commands", "configuration")["variants"][0]
    by = {q["name"]: q for q in resp["params"]}
    assert by["rates"]["count"] == {"kind": "param", "param": "count"} and by["rates"]["max_count"] == 10
    assert by["name"]["type"] == {
        "kind": "string",
        "length": 8,
        "padding": "nul",
        "justify": "left",
        "size": {"min": 8, "max": 8, "fixed": True},
    }
    assert by["label"]["type"]["justify"] == "right"
    assert by["matrix"]["alias"] == "matrix3d" and by["matrix"]["count"] == {"kind": "fixed", "value": 9}
    assert by["matrix"]["size"]["min"] == 72
    assert by["fixed"]["size"]["min"] == 16
    assert by["tail"]["count"] == {"kind": "remaining"}
    # offsets are known up to the first variable-size parameter
    assert by["instance"]["offset"] == 0 and by["count"]["offset"] == 1 and by["rates"]["offset"] == 2
    assert by["name"]["offset"] is None
    flags = next(t for t in p["types"] if t["name"] == "Flags")
    level = next(m for m in flags["members"] if m["name"] == "level")
    assert (level["first_bit"], level["last_bit"], level["width"], level["mask"]) == (12, 15, 4, 0xF000)
    mode = next(t for t in p["types"] if t["name"] == "Mode")
    assert [(v["name"], v["value"], v["devices"]) for v in mode["values"]][3:] == [
        ("fast", 3, ["dev_a"]),
        ("quiet", 3, ["dev_b"]),
    ]
    signed = next(t for t in p["types"] if t["name"] == "Signed")
    assert signed["base"] == "s16" and signed["values"][0]["value"] == -1


def test_variants_devices_shared_and_repeats():
    p = _proto()
    pd = _field(p, "commands", "per_device")
    assert [v["device"] for v in pd["variants"]] == ["dev_a", "dev_b"]
    assert pd["devices"] == ["dev_a", "dev_b"]
    assert pd["variants"][1]["size"] == {"min": 8, "max": 9, "fixed": False}
    shared = next(s for s in p["sets"] if s["id"] == 0xFF)
    assert shared["shared"] is True and shared["fields"][0]["id"] == 0xD3
    sample = _field(p, "data", "sample")
    assert sample["repeats"] is True and sample["size"]["min"] == 16 + 8 + 1 + 4
    assert p["reserved_fields"][0]["applies_to"] == "command"


def test_stated_length_lint_uses_framing():
    # configure is stated as 5 but its full length is 1 + 1 + 1 + 28 + 1 = 32 data bytes (+0 header)
    items = [i for i in lint_stated_lengths({"protocols": [_proto()]}) if i["name"] == "commands.configure"]
    assert len(items) == 1 and items[0]["stated"] == 5


def test_field_layout_shared_by_two_sets():
    p = _proto()
    a = _field(p, "receiver_1", "llh_position")["variants"][0]
    b = _field(p, "receiver_2", "llh_position")["variants"][0]
    assert a["layout"] == b["layout"] == "LlhPosition"
    assert a["params"] == b["params"]
    assert [q["name"] for q in a["params"]] == ["latitude", "longitude", "valid_flags"]
    assert a["size"] == {"min": 18, "max": 18, "fixed": True}
    # the stated length 18 agrees (this framing counts only data bytes), so the lint is silent
    assert not [i for i in lint_stated_lengths({"protocols": [p]}) if i["name"] == "receiver_1.llh_position"]
