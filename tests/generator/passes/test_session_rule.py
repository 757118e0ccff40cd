"""session_rule: the reply-time allowance of long commands (`timeout`) and how a reply is matched
(`session`: the ack field's descriptor, echo and code)."""

from tiny_spec import PROTOCOL, build, command_set, errors

ACK = """\
reserved_fields:
  - id: 0xF1
    name: ack_nack
    title: Ack
    role: ack
    applies_to: command
    sources: [{manual: a.txt, line: 2}]
    params:
      - {name: echo, type: u8}
      - {name: code, type: AckCode}
enums:
  - name: AckCode
    type: u8
    values:
      - {name: ok, value: 0}
      - {name: failed, value: 4}
  - name: Function
    type: u8
    values:
      - {name: write, value: 1}
      - {name: save, value: 3}
function_selector: {enum: Function}
"""
CAPTURE = """\
  - id: 0x01
    name: capture
    role: command
    title: Capture
    sources: [{manual: a.txt, line: 4}]
    timeout: {ms: 50, param: time_ms, sources: [{manual: a.txt, line: 5}]}
    params: [{name: time_ms, type: u16}]
  - id: 0x02
    name: settings
    role: command
    title: Settings
    functions: [write, save]
    sources: [{manual: a.txt, line: 6}]
    timeout: {ms: 1000, functions: [save], sources: [{manual: a.txt, line: 7}]}
    params: []
"""


def _protocol(ack: str = ACK) -> str:
    return PROTOCOL + ack


def test_timeouts_and_the_ack_rule(tmp_path):
    ctx = build(tmp_path, {"protocol.yaml": _protocol(), "base.yaml": command_set(CAPTURE)}, "session_rule")
    assert errors(ctx) == []
    capture, settings = ctx.sets[0]["fields"]
    assert capture["variants"][0]["timeout"] == {
        "ms": 50,
        "param": "time_ms",
        "functions": None,
        "sources": [{"manual": "a.txt", "line": 5}],
    }
    assert (
        settings["variants"][0]["timeout"]["functions"] == ["save"]
        and settings["variants"][0]["timeout"]["param"] is None
    )
    assert ctx.session == {
        "ack": 0xF1,
        "ack_name": "ack_nack",
        "echo": "echo",
        "code": "code",
        "code_enum": "AckCode",
        "ok": 0,
    }


def test_bad_timeouts_are_located(tmp_path):
    bad = CAPTURE.replace("param: time_ms", "param: nope").replace("functions: [save]", "functions: [write, load]")
    bad = bad.replace("functions: [write, save]\n", "functions: [write, save]\n", 1)
    got = errors(build(tmp_path, {"protocol.yaml": _protocol(), "base.yaml": command_set(bad)}, "session_rule"))
    assert any("timeout parameter 'nope'" in e for e in got), got
    assert any("load" in e for e in got), got


def test_an_ack_field_a_session_cannot_read(tmp_path):
    ack = ACK.replace("{name: echo, type: u8}", "{name: echo, type: u16}")
    got = errors(build(tmp_path, {"protocol.yaml": _protocol(ack), "base.yaml": command_set(CAPTURE)}, "session_rule"))
    assert any("two one-byte parameters" in e for e in got), got
    ack = ACK.replace("{name: ok, value: 0}", "{name: ok, value: 9}")
    got = errors(build(tmp_path, {"protocol.yaml": _protocol(ack), "base.yaml": command_set(CAPTURE)}, "session_rule"))
    assert any("no value 0" in e for e in got), got


def test_no_ack_field_no_session(tmp_path):
    ctx = build(tmp_path, {"base.yaml": command_set(CAPTURE.split("  - id: 0x02")[0])}, "session_rule")
    assert errors(ctx) == [] and ctx.session is None
