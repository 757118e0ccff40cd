"""protocol_file: the framing's derived constants, the function selector and the protocol's sources."""

from tiny_spec import PROTOCOL, build, errors


def test_framing_constants_are_derived_from_the_protocol_file(tmp_path):
    ctx = build(tmp_path, {}, "protocol_file")
    f = ctx.framing
    assert errors(ctx) == []
    assert (f["header_size"], f["set_offset"], f["length_offset"]) == (4, 2, 3)
    assert (f["field_length_offset"], f["field_descriptor_offset"], f["field_length_adjust"]) == (0, 1, 2)
    assert (f["max_packet"], f["max_field_data"]) == (261, 253)


def test_a_field_length_that_excludes_the_header_leaves_more_data(tmp_path):
    protocol = PROTOCOL.replace("field_length_counts_header: true", "field_length_counts_header: false").replace(
        "field_header: [length, descriptor]", "field_header: [descriptor, length]"
    )
    f = build(tmp_path, {"protocol.yaml": protocol}, "protocol_file").framing
    assert (f["field_length_offset"], f["field_descriptor_offset"], f["field_length_adjust"]) == (1, 0, 0)
    assert f["max_field_data"] == 253  # 255 - 2 for the field header, below the 255 a size byte holds


def test_the_function_selector_enum_must_exist(tmp_path):
    ctx = build(tmp_path, {"protocol.yaml": PROTOCOL + "function_selector: {enum: Function}\n"}, "protocol_file")
    assert errors(ctx) == [
        "protocol.yaml:19:27: error: function selector enum 'Function' is not defined (expected an enum defined in the spec)"
    ]
    assert ctx.function_values == {}


def test_function_selector_values_and_protocol_sources(tmp_path):
    protocol = PROTOCOL.replace("sources: [{manual: a.txt, line: 1}]", "sources: [{manual: c.txt, line: 1}]") + (
        "function_selector: {enum: Function}\n"
        "enums:\n  - name: Function\n    type: u8\n    values: [{name: write, value: 1}, {name: read, value: 2}]\n"
    )
    ctx = build(tmp_path, {"protocol.yaml": protocol}, "protocol_file")
    assert ctx.function_values == {"write": 1, "read": 2}
    assert errors(ctx) == [
        "protocol.yaml:5:20: error: unknown manual 'c.txt'"
        " (expected one of the manuals listed under devices in the protocol file: a.txt, b.txt)"
    ]
