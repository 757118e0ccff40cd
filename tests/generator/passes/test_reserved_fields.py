"""reserved_fields: the protocol file's reserved fields, shaped like a field with one layout."""

from tiny_spec import PROTOCOL, build, errors

ACK = (
    "reserved_fields:\n  - id: 0xF1\n    name: ack\n    title: Ack\n    role: ack\n    applies_to: command\n"
    "    sources: [{manual: b.txt, line: 5, stated_length: 4}]\n"
    "    params: [{name: echo, type: u8}, {name: code, type: u8}]\n"
)


def test_a_reserved_field_has_one_layout_for_the_devices_its_sources_cite(tmp_path):
    ctx = build(tmp_path, {"protocol.yaml": PROTOCOL + ACK}, "reserved_fields")
    assert errors(ctx) == []
    (ack,) = ctx.reserved
    assert (ack["id"], ack["applies_to"], ack["devices"], ack["stated_length"]) == (0xF1, "command", ["dev_b"], None)
    (v,) = ack["variants"]
    assert (v["device"], v["devices"], v["functions"], v["layout"]) == (None, ["dev_b"], None, None)
    assert [q["name"] for q in v["params"]] == ["echo", "code"] and v["params"] is ack["params"]
    assert ack["size"] == v["size"] == {"min": 2, "max": 2, "fixed": True}


def test_reserved_field_parameters_are_checked_like_any_others(tmp_path):
    protocol = PROTOCOL + ACK.replace("{name: code, type: u8}", "{name: echo, type: u8}")
    ctx = build(tmp_path, {"protocol.yaml": protocol}, "reserved_fields")
    assert errors(ctx) == [
        "protocol.yaml:26:45: error: reserved field ack: two parameters named 'echo' (expected unique parameter names)"
    ]
