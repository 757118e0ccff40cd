"""capabilities: per device, the commands and data the manuals document for it (the fields'
`devices`), ascending; the simulation section's descriptor lists (their reply capacity) and
identity, checked against the spec."""

from test_session_rule import ACK
from tiny_spec import PROTOCOL, build, command_set, data_set, errors

COMMANDS = """\
  - id: 0x03
    name: get_info
    role: command
    title: Get info
    response: 0x81
    sources: [{manual: a.txt, line: 4}, {manual: b.txt, line: 4}]
    params: []
  - id: 0x81
    name: info
    role: response
    title: Info
    sources: [{manual: a.txt, line: 5}, {manual: b.txt, line: 5}]
    params:
      - {name: info, type: Identity}
  - id: 0x04
    name: get_list
    role: command
    title: Get list
    response: 0x82
    sources: [{manual: a.txt, line: 6}, {manual: b.txt, line: 6}]
    params: []
  - id: 0x82
    name: list
    role: response
    title: List
    sources: [{manual: a.txt, line: 7}, {manual: b.txt, line: 7}]
    params:
      - {name: entries, type: u16, count: remaining}
  - id: 0x07
    name: get_more
    role: command
    title: Get more
    response: 0x86
    sources: [{manual: a.txt, line: 8}]
    params: []
  - id: 0x86
    name: more
    role: response
    title: More
    sources: [{manual: a.txt, line: 9}]
    params:
      - {name: entries, type: u16, count: remaining}
"""
DATA = """\
  - {id: 0x06, name: mag, role: data, title: Mag, sources: [{manual: b.txt, line: 10}], params: []}
  - {id: 0x04, name: accel, role: data, title: Accel, sources: [{manual: a.txt, line: 11}], params: []}
"""
TYPES = """\
structs:
  - name: Identity
    params:
      - {name: firmware, type: u16}
      - {name: serial, type: string, length: 4}
"""
SIMULATION = """\
simulation:
  nack: {unknown_descriptor: failed, unknown_set: failed, invalid_parameter: failed, failed: failed}
  descriptor_lists:
    lists:
      - {command: get_list, reply: list, param: entries}
      - {command: get_more, reply: more, param: entries}
    contents: [command, data]
    sources: [{manual: a.txt, line: 12}]
  identity:
    reports:
      - {reply: info, param: info.firmware, item: firmware}
      - {reply: info, param: info.serial, item: serial_number}
    devices:
      - {device: dev_a, values: {firmware: 1201, serial_number: "A-1"}, sources: [{manual: a.txt, line: 13}]}
"""


def _files(simulation: str, data: str = DATA) -> dict[str, str]:
    # 12 payload bytes: 2 + 4 for the ack field, 2 for the list field's header, 6 for 3 entries
    protocol = PROTOCOL.replace("max_payload: 255", "max_payload: 12")
    return {
        "protocol.yaml": protocol + ACK + TYPES + simulation,
        "base.yaml": command_set(COMMANDS),
        "sensor.yaml": data_set(data),
    }


def test_per_device_lists_follow_the_manuals(tmp_path):
    ctx = build(tmp_path, _files(SIMULATION), "capabilities")
    assert errors(ctx) == []
    by = {d["device"]: d for d in ctx.capabilities["devices"]}
    assert list(by) == ["dev_a", "dev_b"]  # the protocol file's order
    # responses are not listed; get_more is documented in a.txt only, mag in b.txt only
    assert by["dev_a"]["commands"] == [[1, 3], [1, 4], [1, 7]] and by["dev_a"]["data"] == [[0x80, 4]]
    assert by["dev_b"]["commands"] == [[1, 3], [1, 4]] and by["dev_b"]["data"] == [[0x80, 6]]


def test_descriptor_lists_get_their_capacity_and_the_identity_its_items(tmp_path):
    sim = build(tmp_path, _files(SIMULATION), "capabilities").simulation
    lists = sim["descriptor_lists"]["lists"]
    assert [(x["set"], x["command_descriptor"], x["reply_descriptor"], x["capacity"]) for x in lists] == [
        (1, 4, 0x82, 3),
        (1, 7, 0x86, 3),
    ]
    assert sim["identity"]["items"] == {
        "firmware": {"kind": "integer", "max": 65535},
        "serial_number": {"kind": "string", "max": 4},
    }
    report = dict(sim["identity"]["reports"][1])
    t = report.pop("type")  # the reported parameter's type: info.serial is `string, length: 4` (TYPES)
    assert report == {
        "reply": "info", "param": "info.serial", "item": "serial_number", "set": 1, "descriptor": 0x81,
    }  # fmt: skip
    assert (t["kind"], t["length"]) == ("string", 4)
    assert sim["identity"]["reports"][0]["type"]["name"] == "u16"  # info.firmware


def test_a_list_longer_than_the_first_reply_needs_the_extended_command(tmp_path):
    # dev_b gains two data quantities: 2 commands + 3 data > 3 entries, and it lacks get_more
    more = DATA + (
        "  - {id: 0x07, name: gyro, role: data, title: Gyro, sources: [{manual: b.txt, line: 14}], params: []}\n"
        "  - {id: 0x08, name: baro, role: data, title: Baro, sources: [{manual: b.txt, line: 15}], params: []}\n"
    )
    got = errors(build(tmp_path, _files(SIMULATION, more), "capabilities"))
    assert any(
        "dev_b lists 5 entries, more than its first reply holds (3), but does not support get_more" in e for e in got
    ), got


def test_a_list_longer_than_both_replies_is_an_error(tmp_path):
    more = DATA + "".join(
        f"  - {{id: 0x{10 + i:02X}, name: q{i}, role: data, title: Q, sources: [{{manual: a.txt, line: 20}}], params: []}}\n"
        for i in range(3)
    )
    got = errors(build(tmp_path, _files(SIMULATION, more), "capabilities"))
    assert any("dev_a lists 7 entries, more than the replies hold (6)" in e for e in got), got


def test_bad_lists_and_identity_are_located_errors(tmp_path):
    bad = (
        SIMULATION.replace("reply: more,", "reply: list,")
        .replace(
            "reply: list, param: entries}\n      - {command: get_more",
            "reply: list, param: items}\n      - {command: get_more",
        )
        .replace("param: info.serial,", "param: info.serial_no,")
        .replace("firmware: 1201", "firmware: 70000")
        .replace('serial_number: "A-1"}', 'serial_number: "A-1", lot: "x"}')
    )
    got = errors(build(tmp_path, _files(bad), "capabilities"))
    expected = [
        "'list' is not a reply of get_more",
        "'items' is not a list of list running to the end of the field",
        "'info.serial_no' is not a string or unsigned integer parameter of info",
        "dev_a gives no fitting 'firmware'",
        "'lot' is reported by no reply",
    ]
    for message in expected:
        assert any(message in e for e in got), (message, got)
    assert all("protocol.yaml" in e for e in got), got
