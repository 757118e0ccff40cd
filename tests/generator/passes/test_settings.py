"""settings: the protocol file's `settings` section (the device command line's settings files),
checked against the commands, their read parameters, enums and the simulation's base rates, and
exported with every keyed read's key combinations resolved per device."""

from test_session_rule import ACK
from tiny_spec import PROTOCOL, build, command_set, errors

COMMANDS = """\
  - id: 0x01
    name: port_speed
    role: command
    title: Port speed
    functions: [write, read]
    sources: [{manual: a.txt, line: 4}]
    params:
      - {name: port, type: u8, functions: [write, read]}
      - {name: baud, type: u32, functions: [write]}
  - id: 0x02
    name: range
    role: command
    title: Range
    functions: [write, read]
    sources: [{manual: a.txt, line: 5}]
    params:
      - {name: sensor, type: Sensor, functions: [write, read]}
      - {name: value, type: u8, functions: [write]}
  - id: 0x03
    name: clock
    role: command
    title: Clock
    functions: [write, read]
    sources: [{manual: a.txt, line: 6}]
    params:
      - {name: seconds, type: u32, functions: [write]}
"""
ENUMS = """\
  - name: Sensor
    type: u8
    values:
      - {name: all, value: 0}
      - {name: accel, value: 1}
      - {name: gyro, value: 2}
"""
SETTINGS = """\
settings:
  not_settings:
    - {command: clock, why: "a clock, not a setting"}
  keys:
    - {command: port_speed, values: {port: [1, 2]}, decision: both ports, sources: [{manual: a.txt, line: 7}]}
    - {command: range, values: {sensor: [accel, gyro]}, decision: not all, sources: [{manual: b.txt, line: 8}]}
"""


def _files(settings: str) -> dict[str, str]:
    ack = ACK.replace("enums:\n", "enums:\n" + ENUMS, 1).replace(
        "{name: save, value: 3}", "{name: read, value: 2}\n      - {name: save, value: 3}"
    )
    return {"protocol.yaml": PROTOCOL + ack + settings, "base.yaml": command_set(COMMANDS)}


def test_the_section_is_checked_and_exported(tmp_path):
    ctx = build(tmp_path, _files(SETTINGS), "settings")
    assert errors(ctx) == []
    s = ctx.settings
    assert s["not_settings"] == [{"command": "clock", "why": "a clock, not a setting"}]
    port, rng = s["keys"]
    assert port["resolved"] == {"dev_a": [{"port": 1}, {"port": 2}]}  # the devices of its manual (a.txt)
    assert rng["resolved"]["dev_a"] == [{"sensor": 1}, {"sensor": 2}]  # enum members by value
    assert rng["sources"][0]["manual"] == "b.txt"


def test_no_section_no_settings(tmp_path):
    ctx = build(tmp_path, _files(""), "settings")
    assert errors(ctx) == [] and ctx.settings is None


def test_every_name_and_value_is_checked(tmp_path):
    bad = (
        SETTINGS.replace("command: clock", "command: clok")
        .replace("values: {port: [1, 2]}", "values: {port: [1, 300]}")
        .replace("[accel, gyro]", "[accel, wind]")
    )
    got = errors(build(tmp_path, _files(bad), "settings"))
    for message in (
        "'clok' is not a command with a read function",
        "300 does not fit port (u8)",
        "'wind' is not a member of Sensor",
    ):
        assert any(message in e for e in got), (message, got)
    assert all("protocol.yaml" in e for e in got), got


def test_key_parameters_are_parameters_read_sends(tmp_path):
    wrong = SETTINGS.replace("values: {port: [1, 2]}", "values: {baud: [1]}")
    got = errors(build(tmp_path, _files(wrong), "settings"))
    assert any("port_speed does not send 'baud' with read" in e for e in got), got
