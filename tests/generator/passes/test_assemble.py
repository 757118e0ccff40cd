"""assemble: the protocol entry in its exported shape (docs/ir.md), with no builder notes left."""

from tiny_spec import build, command_set, errors

CMD = "  - {id: 0x01, name: cmd, role: command, title: C, sources: [{manual: a.txt, line: 4}], response: 0x81, params: []}\n"
REPLY = "  - {id: 0x81, name: reply, role: response, title: R, sources: [{manual: a.txt, line: 5}], params: []}\n"


def _keys(value, out: set) -> set:
    if isinstance(value, dict):
        for k, v in value.items():
            out.add(k)
            _keys(v, out)
    elif isinstance(value, list):
        for v in value:
            _keys(v, out)
    return out


def test_the_protocol_entry_has_the_documented_keys_and_no_notes(tmp_path):
    ctx = build(tmp_path, {"base.yaml": command_set(CMD + REPLY)}, "assemble")
    assert errors(ctx) == []
    assert list(ctx.ir) == [
        "name",
        "title",
        "package",
        "byte_order",
        "sources",
        "devices",
        "response_descriptor",
        "strings",
        "framing",
        "set_kinds",
        "shared_data",
        "samples",
        "session",
        "session_example",
        "time",
        "simulation",
        "settings",
        "capabilities",
        "link",
        "function_selector",
        "reserved_fields",
        "types",
        "field_layouts",
        "sets",
        "lookup",
        "value_paths",
    ]
    assert not [k for k in _keys(ctx.ir, set()) if k.startswith("_")]
    field = ctx.ir["sets"][0]["fields"][0]
    assert list(field)[:3] == ["id", "name", "role"] and list(field)[-1] == "stated_lengths"
    assert ctx.ir["strings"] == {"padding": "nul", "justify": "left"}
