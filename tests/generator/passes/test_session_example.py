"""session_example: the protocol file's configure-and-stream example (the device, each step's command
and values, the data fields printed), checked against the devices, sets, commands, their layouts,
parameters and functions, and exported as the protocol's `session_example` (null without it)."""

from test_session_rule import ACK
from tiny_spec import PROTOCOL, build, command_set, data_set, errors

COMMANDS = """\
  - {id: 0x01, name: ping, role: command, title: Ping, sources: [{manual: a.txt, line: 4}], params: []}
  - {id: 0x02, name: info, role: command, title: Info, sources: [{manual: a.txt, line: 5}], params: []}
  - id: 0x03
    name: rate
    role: command
    title: Rate
    functions: [write, read]
    sources: [{manual: a.txt, line: 6}]
    params: [{name: decimation, type: u16, functions: [write]}]
  - id: 0x04
    name: enable
    role: command
    title: Enable
    functions: [write]
    sources: [{manual: a.txt, line: 7}]
    params: [{name: "on", type: bool, functions: [write]}]
  - id: 0x05
    name: only_b
    role: command
    title: Only on B
    functions: [write]
    sources: [{manual: b.txt, line: 8}]
    params: []
"""
DATA = """\
  - {id: 0x01, name: accel, role: data, title: Accel, sources: [{manual: a.txt, line: 9}], params: [{name: x, type: float}]}
  - {id: 0x02, name: gyro, role: data, title: Gyro, sources: [{manual: a.txt, line: 10}], params: [{name: x, type: float}]}
"""
EXAMPLE = """\
session_example:
  device: dev_a
  ping: {set: base, command: ping}
  info: {set: base, command: info}
  setting: {set: base, command: rate, values: {decimation: 10}}
  format: {set: base, command: rate, values: {decimation: 0x20}}
  enable: {set: base, command: enable, values: {"on": true}}
  data: {set: sensor, fields: [accel, gyro]}
"""
READ = "{name: write, value: 1}\n      - {name: read, value: 2}"


def _files(example: str, ack: str = ACK) -> dict[str, str]:
    return {
        "protocol.yaml": PROTOCOL + ack.replace("{name: write, value: 1}", READ) + example,
        "base.yaml": command_set(COMMANDS),
        "sensor.yaml": data_set(DATA),
    }


def test_the_example_is_checked_and_exported(tmp_path):
    ctx = build(tmp_path, _files(EXAMPLE), "session_example")
    assert errors(ctx) == []
    ex = ctx.session_example
    assert ex["device"] == "dev_a"
    assert ex["ping"] == {"set": "base", "command": "ping", "values": {}}  # no values: an empty mapping
    assert ex["format"]["values"] == {"decimation": 0x20}
    assert ex["enable"]["values"] == {"on": True}
    assert ex["data"] == {"set": "sensor", "fields": ["accel", "gyro"]}
    assert build(tmp_path, _files(EXAMPLE), "assemble").ir["session_example"] == ex


def test_no_section_no_example(tmp_path):
    ctx = build(tmp_path, _files(""), "assemble")
    assert errors(ctx) == [] and ctx.ir["session_example"] is None


def test_every_name_is_checked_where_it_is_written(tmp_path):
    bad = (
        EXAMPLE.replace("command: info}", "command: inf}")
        .replace("{decimation: 10}", "{decimation: 10, rate: 2}")
        .replace("{set: base, command: enable", "{set: sensor, command: enable")
        .replace("fields: [accel, gyro]", "fields: [accel, gyr]")
    )
    ctx = build(tmp_path, _files(bad), "session_example")
    assert errors(ctx) == [
        "protocol.yaml:45:30: error: session_example: info: 'inf' is not a command of base (expected a command name)",
        "protocol.yaml:46:70: error: session_example: setting: rate has no parameter 'rate'"
        " (expected one of: decimation)",
        "protocol.yaml:48:17: error: session_example: enable: 'sensor' is not a command set"
        " (expected the name of a command set)",
        "protocol.yaml:49:39: error: session_example: data: 'gyr' is not a field of sensor"
        " (expected a field of the data set)",
    ]
    assert ctx.session_example is None  # nothing exported from a wrong example
    ctx = build(tmp_path, _files(EXAMPLE.replace("device: dev_a", "device: dev_c")), "session_example")
    assert errors(ctx) == [
        "protocol.yaml:43:11: error: session_example: unknown device 'dev_c' (expected one of dev_a, dev_b)"
    ]


def test_the_device_needs_a_layout_and_the_functions_each_step_calls(tmp_path):
    bad = EXAMPLE.replace("command: rate, values: {decimation: 10}", "command: enable, values: {}").replace(
        'command: enable, values: {"on": true}', "command: only_b"
    )
    ctx = build(tmp_path, _files(bad), "session_example")
    assert errors(ctx) == [
        "protocol.yaml:46:33: error: session_example: setting: enable has no read function for dev_a"
        " (expected a command with read)",
        "protocol.yaml:48:32: error: session_example: enable: base.only_b has no layout for dev_a"
        " (expected a command the device has)",
    ]
    # a plain command (no function selector) cannot be the setting written then read back
    plain = EXAMPLE.replace("command: rate, values: {decimation: 10}", "command: ping")
    assert errors(build(tmp_path, _files(plain), "session_example")) == [
        "protocol.yaml:46:33: error: session_example: setting: ping has no function selector to write and read it"
        " (expected a command with write and read)"
    ]


def test_an_example_needs_a_session(tmp_path):
    no_ack = "enums:\n  - name: Function\n    type: u8\n    values:\n      - {name: write, value: 1}\n"
    no_ack += "function_selector: {enum: Function}\n"
    ctx = build(tmp_path, _files(EXAMPLE, no_ack), "session_example")
    assert "session_example: the protocol has no session (no reserved field of role ack)" in errors(ctx)[0]
    assert errors(ctx)[0].startswith("protocol.yaml:") and ctx.session_example is None


def test_the_schema_refuses_a_step_without_its_command(tmp_path):
    import pytest

    with pytest.raises(AssertionError, match="the tiny spec itself is malformed"):
        build(tmp_path, _files(EXAMPLE.replace("{set: base, command: ping}", "{set: base}")), "session_example")
