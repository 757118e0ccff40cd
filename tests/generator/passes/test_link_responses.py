"""link_responses: a command's responses name response fields of the same set; the reply code rule."""

from tiny_spec import PROTOCOL, build, command_set, errors

CMD = "  - {{id: 0x01, name: cmd, role: command, title: C, sources: [{{manual: a.txt, line: 4}}], response: {r}, params: []}}\n"
REPLY = "  - {id: 0x81, name: reply, role: response, title: R, sources: [{manual: a.txt, line: 5}], params: []}\n"
OTHER = "  - {id: 0x02, name: other, role: command, title: O, sources: [{manual: a.txt, line: 6}], params: []}\n"


def _link(tmp_path, fields: str, protocol: str = PROTOCOL):
    return build(tmp_path, {"protocol.yaml": protocol, "base.yaml": command_set(fields)}, "link_responses")


def test_a_response_gets_its_field_name(tmp_path):
    ctx = _link(tmp_path, CMD.format(r="0x81") + REPLY)
    assert errors(ctx) == []
    (r,) = ctx.sets[0]["fields"][0]["variants"][0]["responses"]
    assert (r["id"], r["when"], r["name"]) == (0x81, None, "reply")


def test_a_response_must_exist_and_be_a_response(tmp_path):
    ctx = _link(
        tmp_path, CMD.format(r="0x83") + CMD.format(r="0x02").replace("0x01, name: cmd", "0x03, name: c3") + OTHER
    )
    assert errors(ctx) == [
        "base.yaml:7:99: error: base.cmd: response 0x83 does not exist in set 0x01"
        " (expected the descriptor of a field with role response in the same set)",
        "base.yaml:8:98: error: base.c3: response 0x02 is 'other', a command field (expected a field with role response)",
    ]


def test_the_reply_code_rule(tmp_path):
    protocol = PROTOCOL + "response_descriptor: {command_or: 0x80}\n"
    ctx = _link(
        tmp_path,
        CMD.format(r="0x81")
        + REPLY.replace("0x81", "0x82")
        + CMD.format(r="0x82").replace("0x01, name: cmd", "0x03, name: c3"),
        protocol,
    )
    assert errors(ctx) == [
        "base.yaml:7:99: error: base.cmd: response 0x81 does not exist in set 0x01"
        " (expected the descriptor of a field with role response in the same set)",
        "base.yaml:9:98: error: base.c3: response 0x82 breaks the reply code rule"
        " (expected 0x83 (command 0x03 | 0x80, protocol response_descriptor))",
    ]
