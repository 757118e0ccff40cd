"""link: the protocol file's `link` section (idle, ping and resume commands, idle attempts, baud
settle time, baud rates per device, the UART bandwidth calculation), checked against the spec and
exported with every key present."""

from tiny_spec import PROTOCOL, build, command_set, errors

COMMANDS = """\
  - {id: 0x01, name: ping, role: command, title: Ping, sources: [{manual: a.txt, line: 4}], params: []}
  - {id: 0x02, name: set_to_idle, role: command, title: Idle, sources: [{manual: a.txt, line: 5}], params: []}
  - id: 0x09
    name: speed
    role: command
    title: Speed
    sources: [{manual: a.txt, line: 6}]
    params: [{name: baud, type: u32}]
"""

LINK = """\
link:
  idle: {command: set_to_idle, sources: [{manual: a.txt, line: 5}]}
  ping: {command: ping, sources: [{manual: a.txt, line: 4}, {manual: b.txt, line: 4}]}
  baud_settle: {ms: 250, sources: [{manual: a.txt, line: 7}]}
  baud_rates:
    - {device: dev_b, rates: [115200, 921600], sources: [{manual: b.txt, line: 8}]}
    - {device: dev_a, port: main, rates: [9600, 115200], default: 115200, sources: [{manual: a.txt, line: 8}]}
  bandwidth: {uart_word_bits: 10, packet_overhead: 6, field_overhead: 2, sources: [{manual: a.txt, line: 9}]}
"""


def _build(tmp_path, link: str):
    return build(tmp_path, {"protocol.yaml": PROTOCOL + link, "base.yaml": command_set(COMMANDS)}, until="link")


def test_the_section_is_resolved_and_every_key_exported(tmp_path):
    ctx = _build(tmp_path, LINK)
    assert errors(ctx) == []
    link = ctx.link
    assert link["idle"] == {
        "command": "set_to_idle",
        "set": 0x01,
        "descriptor": 0x02,
        "sources": [{"manual": "a.txt", "line": 5}],
    }
    assert (link["ping"]["set"], link["ping"]["descriptor"]) == (0x01, 0x01)
    assert link["resume"] is None  # not given: null, not absent
    assert link["idle_attempts"] == {"count": 3, "sources": []}  # the default
    assert link["baud_settle"] == {"ms": 250, "sources": [{"manual": "a.txt", "line": 7}]}
    # in the protocol file's device order, whatever the section's order
    assert [e["device"] for e in link["baud_rates"]] == ["dev_a", "dev_b"]
    assert link["baud_rates"][0]["default"] == 115200 and link["baud_rates"][0]["port"] == "main"
    assert link["baud_rates"][1]["default"] is None
    assert link["bandwidth"]["uart_word_bits"] == 10


def test_without_a_section_every_fact_is_null(tmp_path):
    ctx = _build(tmp_path, "")
    assert errors(ctx) == []
    assert ctx.link == {
        "idle": None,
        "ping": None,
        "resume": None,
        "idle_attempts": {"count": 3, "sources": []},
        "baud_settle": None,
        "baud_rates": [],
        "bandwidth": None,
    }


def test_errors_are_located(tmp_path):
    bad = """\
link:
  idle: {command: sleep, sources: [{manual: a.txt, line: 5}]}
  ping: {command: speed, sources: [{manual: c.txt, line: 4}]}
  idle_attempts: {count: 2}
  baud_rates:
    - {device: dev_c, rates: [9600], sources: [{manual: a.txt, line: 8}]}
    - {device: dev_a, rates: [115200, 9600], default: 19200, sources: [{manual: a.txt, line: 8}]}
    - {device: dev_a, rates: [9600], sources: [{manual: a.txt, line: 8}]}
  bandwidth: {uart_word_bits: 10, packet_overhead: 8, field_overhead: 3, sources: [{manual: a.txt, line: 9}]}
"""
    ctx = _build(tmp_path, bad)
    assert ctx.link["idle_attempts"]["count"] == 2
    got = errors(ctx)
    expected = [
        "link idle: 'sleep' is not a command of the protocol",
        "link ping: speed has parameters; a session sends it as it is",
        "unknown manual 'c.txt'",
        "link baud_rates: 'dev_c' is not a device of the protocol",
        "link baud_rates: the rates of dev_a are not ascending and distinct",
        "link baud_rates: default 19200 of dev_a is not one of its rates",
        "link baud_rates: dev_a is listed twice",
        "link bandwidth: packet_overhead 8 is not the framing's 6 bytes (sync, header, checksum)",
        "link bandwidth: field_overhead 3 is not the framing's field header size 2",
    ]
    for text in expected:
        assert any(text in e for e in got), (text, got)
    assert len(got) == len(expected), got
    # located at the offending value, file:line:column
    assert any(e.startswith("protocol.yaml:") and "'sleep'" in e for e in got)


def test_the_schema_refuses_unknown_keys(tmp_path):
    import pytest

    with pytest.raises(AssertionError, match="malformed"):
        _build(tmp_path, "link:\n  idel: {command: set_to_idle, sources: [{manual: a.txt, line: 5}]}\n")
