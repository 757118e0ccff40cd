"""simulation: the protocol file's `simulation` section, checked against the spec's commands,
parameters, data sets, devices and enums, and exported with its sources resolved."""

import pytest
from test_session_rule import ACK
from tiny_spec import PROTOCOL, build, command_set, data_set, errors

COMMANDS = """\
  - id: 0x01
    name: message_format
    role: command
    title: Message format
    functions: [write]
    sources: [{manual: a.txt, line: 4}]
    params:
      - {name: desc_set, type: u8, functions: [write], plausible: {why: "zero, the fixture's start"}}
      - {name: count, type: u8, functions: [write], plausible: {why: "zero, the fixture's start"}}
      - {name: entries, type: Rate, count: count, functions: [write], plausible: {why: "zero, the fixture's start"}}
  - id: 0x02
    name: stream_control
    role: command
    title: Stream control
    functions: [write]
    sources: [{manual: a.txt, line: 5}]
    params:
      - {name: selector, type: u8, functions: [write], plausible: {why: "zero, the fixture's start"}}
      - {name: enable, type: bool, functions: [write], plausible: {why: "zero, the fixture's start"}}
"""
TYPES = """\
structs:
  - name: Rate
    params:
      - {name: descriptor, type: u8}
      - {name: decimation, type: u16}
  - name: Unused
    params: [{name: x, type: u8}]
"""
STATES = """\
  - name: FilterState
    type: u8
    values:
      - {name: init, value: 1}
      - {name: navigating, value: 2}
"""
SIMULATION = """\
simulation:
  nack: {unknown_descriptor: failed, unknown_set: failed, invalid_parameter: failed, failed: failed}
  formats:
    - {command: message_format, set_param: desc_set, list: entries, descriptor: descriptor, decimation: decimation}
  enables:
    - command: stream_control
      selector: {param: selector, sets: [{value: 1, set: 0x80}]}
      flag: enable
  base_rates:
    - {device: dev_a, rates: [{set: 0x80, hz: 100}], sources: [{manual: a.txt, line: 6}]}
  filters:
    - device: dev_b
      aiding: external
      states: {enum: FilterState, members: [init, navigating]}
      fix: {enum: FilterState, fix: navigating, none: init}
      sources: [{manual: b.txt, line: 7}]
"""


def _files(simulation: str) -> dict[str, str]:
    ack = ACK.replace("enums:\n", "enums:\n" + STATES, 1)
    return {
        "protocol.yaml": PROTOCOL + ack + TYPES + simulation,
        "base.yaml": command_set(COMMANDS),
        "sensor.yaml": data_set(
            "  - {id: 0x04, name: accel, role: data, title: Accel, sources: [{manual: a.txt, line: 8}], params: []}\n"
        ),
    }


def test_the_section_is_checked_and_exported(tmp_path):
    ctx = build(tmp_path, _files(SIMULATION), "simulation")
    assert errors(ctx) == []
    sim = ctx.simulation
    assert sim["nack"]["failed"] == "failed"
    assert sim["formats"][0]["list"] == "entries" and sim["rates"] == [] and sim["decimation"] is None
    assert sim["base_rates"][0]["rates"] == [{"set": 0x80, "hz": 100}]
    assert sim["filters"][0]["states"]["members"] == ["init", "navigating"]


def test_no_section_no_simulation(tmp_path):
    ctx = build(tmp_path, _files(""), "simulation")
    assert errors(ctx) == [] and ctx.simulation is None


def test_every_name_is_checked(tmp_path):
    bad = (
        SIMULATION.replace("failed: failed}", "failed: broken}")
        .replace("command: stream_control", "command: stream_ctl")
        .replace("list: entries", "list: entry")
        .replace("decimation: decimation}", "decimation: rate}")
        .replace("set: 0x80, hz", "set: 0x81, hz")
        .replace("device: dev_b", "device: dev_c")
        .replace("members: [init, navigating]", "members: [init, full]")
        .replace("fix: {enum: FilterState", "fix: {enum: FixType")
    )
    got = errors(build(tmp_path, _files(bad), "simulation"))
    expected = [
        "'broken' is not a member of the ack code enum AckCode",
        "'stream_ctl' is not a command of the protocol",
        "'entry' is not a parameter of message_format",
        "0x81 is not a data set of the protocol",
        "'dev_c' is not a device of the protocol",
        "'full' is not a member of FilterState",
        "'FixType' is not an enum of the protocol",
    ]
    for message in expected:
        assert any(message in e for e in got), (message, got)
    assert any("simulation" in e and "protocol.yaml" in e for e in got), got  # located in the protocol file


AIDING = """\
      flags: {type: Flags, members: {heading_warning: heading}}
      internal:
        command: stream_control
        param: selector
        enable: enable
        enum: FilterState
        members: {navigating: magnetometer}
      antennas: {command: stream_control, receiver: selector, offset: enable}
      alignment: {command: stream_control, param: selector, type: Flags, members: {magnetometer: gnss_velocity}}
      dual_antenna:
        fix: {enum: FilterState, fix: navigating, none: init}
        flags: {type: Flags, members: {offsets: offsets}}
      heading:
        command: stream_control
        param: selector
        enum: FilterState
        members: {init: [], navigating: [magnetometer]}
        in_use: Flags
"""
FLAGS = """\
bitfields:
  - name: Flags
    type: u8
    members:
      - {name: heading, bits: 0}
      - {name: offsets, bits: 1}
      - {name: magnetometer, bits: 2}
"""


def _aiding(text: str) -> dict[str, str]:
    files = _files(
        SIMULATION.replace(
            "      sources: [{manual: b.txt, line: 7}]\n", text + "      sources: [{manual: b.txt, line: 7}]\n"
        )
    )
    files["protocol.yaml"] = files["protocol.yaml"].replace("structs:\n", FLAGS + "structs:\n", 1)
    return files


def test_internal_aiding_is_checked_and_exported(tmp_path):
    ctx = build(tmp_path, _aiding(AIDING), "simulation")
    assert errors(ctx) == []
    f = ctx.simulation["filters"][0]
    assert f["internal"]["members"] == {"navigating": "magnetometer"} and f["flags"]["type"] == "Flags"


def test_internal_aiding_names_are_checked(tmp_path):
    bad = (
        AIDING.replace("members: {heading_warning: heading}", "members: {heading_warning: heading_bit}")
        .replace("enable: enable", "enable: switch")
        .replace("members: {navigating: magnetometer}", "members: {full: magnetometer}")
        .replace("receiver: selector", "receiver: receiver_id")
        .replace("members: {magnetometer: gnss_velocity}", "members: {kinematic: gnss_velocity}")
        .replace("fix: navigating, none: init}", "fix: fixed, none: init}")
        .replace("in_use: Flags", "in_use: Missing\n        external: [no_such_command, message_format]")
    )
    got = errors(build(tmp_path, _aiding(bad), "simulation"))
    expected = [
        "'heading_bit' is not a member of Flags",
        "'switch' is not a parameter of stream_control",
        "'full' is not a member of FilterState",
        "'receiver_id' is not a parameter of stream_control",
        "'kinematic' is not a member of Flags",
        "'fixed' is not a member of FilterState",
        "'Missing' is not a bitfield of the protocol",
        "'no_such_command' is not a command of the protocol",
        "'heading' is not a parameter of message_format",  # an external heading command sends a heading
    ]
    for message in expected:
        assert any(message in e for e in got), (message, got)


RTK = """\
      rtk:
        fix: {enum: FilterState, float: init, fixed: navigating}
        aiding_status: {type: Flags, members: {corrections: heading, integer_fix: offsets, no_fix: magnetometer}}
        uncertainty: {single: 1.5, float: 0.5, fixed: 0.02}
"""


def test_rtk_is_checked_and_exported(tmp_path):
    ctx = build(tmp_path, _aiding(AIDING + RTK), "simulation")
    assert errors(ctx) == []
    rtk = ctx.simulation["filters"][0]["rtk"]
    assert rtk["fix"] == {"enum": "FilterState", "float": "init", "fixed": "navigating"}
    assert rtk["uncertainty"]["fixed"] == 0.02


def test_rtk_names_and_uncertainties_are_checked(tmp_path):
    bad = (
        RTK.replace("float: init", "float: rtk_float")
        .replace("integer_fix: offsets", "integer_fix: integer")
        .replace("float: 0.5, fixed: 0.02", "float: 0.01, fixed: 0.02")
    )
    got = errors(build(tmp_path, _aiding(AIDING + bad), "simulation"))
    expected = [
        "'rtk_float' is not a member of FilterState",
        "'integer' is not a member of Flags",
        "the position uncertainties must shrink from single point to RTK float to RTK fixed",
    ]
    for message in expected:
        assert any(message in e for e in got), (message, got)
    other = RTK.replace("enum: FilterState, float", "enum: AckCode, float")
    got = errors(build(tmp_path, _aiding(AIDING + other), "simulation"))
    assert any("is not the filter's fix enum 'FilterState'" in e for e in got), got


CORRECTIONS = """\
        corrections:
          types: [1005, 1077, 1087, 1230]
          station: [1005]
          observations: [1077, 1087]
          max_age: 10.0
          spartn: {command: stream_control, param: enable}
"""


def test_rtcm_corrections_are_checked_and_exported(tmp_path):
    ctx = build(tmp_path, _aiding(AIDING + RTK + CORRECTIONS), "simulation")
    assert errors(ctx) == []
    assert ctx.simulation["filters"][0]["rtk"]["corrections"]["observations"] == [1077, 1087]
    bad = (
        CORRECTIONS.replace("station: [1005]", "station: [1006, 1077]")
        .replace("observations: [1077, 1087]", "observations: [1077, 1097]")
        .replace("param: enable}", "param: spartn_enable}")
    )
    got = errors(build(tmp_path, _aiding(AIDING + RTK + bad), "simulation"))
    expected = [
        "RTCM message types [1006] of `station` are not among the supported `types`",
        "RTCM message types [1097] of `observations` are not among the supported `types`",
        "an RTCM message type is both a station position and an observation",
        "'spartn_enable' is not a parameter of stream_control",
    ]
    for message in expected:
        assert any(message in e for e in got), (message, got)
    negative = CORRECTIONS.replace("max_age: 10.0", "max_age: 0")
    with pytest.raises(AssertionError, match="max_age: 0 is less than or equal to the minimum of 0"):
        build(tmp_path, _aiding(AIDING + RTK + negative), "simulation")  # the schema refuses it


AIDING_COMMAND = """\
  - id: 0x03
    name: aiding_control
    role: command
    title: Aiding control
    functions: [write]
    sources: [{manual: a.txt, line: 9}]
    params:
      - {name: source, type: FilterState, functions: [write], plausible: {why: "zero, the fixture's start"}}
      - {name: enable, type: bool, functions: [write], plausible: {why: "zero, the fixture's start"}}
"""
ACTIONS = """\
  actions:
    - {command: aiding_control, action: enable, param: source, flag: enable}
    - {command: message_format, action: aid, kind: heading, enabled_by: [navigating, init], values: [desc_set]}
    - {command: stream_control, action: reset}
"""


def _actions(text: str) -> dict[str, str]:
    files = _files(SIMULATION + text)
    files["base.yaml"] = command_set(COMMANDS + AIDING_COMMAND)
    return files


def test_actions_are_checked_and_exported(tmp_path):
    ctx = build(tmp_path, _actions(ACTIONS), "simulation")
    assert errors(ctx) == []
    enable, aid, reset = ctx.simulation["actions"]
    assert enable == {"command": "aiding_control", "action": "enable", "param": "source", "flag": "enable"}
    # FilterState: init = 1, navigating = 2 (STATES above), in the order the action names them
    assert aid["enabled_by_values"] == [2, 1] and aid["values"] == ["desc_set"]
    assert reset == {"command": "stream_control", "action": "reset"}
    (tmp_path / "none").mkdir()
    assert build(tmp_path / "none", _files(SIMULATION), "simulation").simulation["actions"] == []


def test_action_names_are_checked(tmp_path):
    bad = (
        ACTIONS.replace("[navigating, init]", "[navigating, full]")
        .replace("values: [desc_set]", "values: [nope]")
        .replace("command: stream_control, action: reset", "command: stream_ctl, action: reset")
        + "    - {command: stream_control, action: capture}\n"
    )
    got = errors(build(tmp_path, _actions(bad), "simulation"))
    expected = [
        "'full' is not a member of FilterState",
        "'nope' is not a parameter of message_format",
        "'stream_ctl' is not a command of the protocol",
        "the capture action of stream_control needs `param`",
    ]
    for message in expected:
        assert any(message in e for e in got), (message, got)
    # enabled_by needs the enable action's parameter to be an enum (stream_control's selector is a u8)
    on_u8 = ACTIONS.replace(
        "command: aiding_control, action: enable, param: source",
        "command: stream_control, action: enable, param: selector",
    )
    (tmp_path / "u8").mkdir()
    got = errors(build(tmp_path / "u8", _actions(on_u8), "simulation"))
    assert any("`enabled_by` needs an enable action whose `param` is an enum" in e for e in got), got


WORLD = """\
  world:
    - sets: [sensor]
      fields:
        accel: {}
"""


def test_world_names_are_checked(tmp_path):
    ctx = build(tmp_path, _files(SIMULATION + WORLD), "simulation")
    assert errors(ctx) == [] and ctx.simulation["world"][0]["sets"] == ["sensor"]
    bad = WORLD.replace("sets: [sensor]", "sets: [sensor, base, nowhere]") + "        gyro: {}\n"
    (tmp_path / "bad").mkdir()
    got = errors(build(tmp_path / "bad", _files(SIMULATION + bad), "simulation"))
    expected = [
        "'base' is not a data set of the protocol",  # a command set
        "'nowhere' is not a data set of the protocol",
        "'gyro' is not a field of",
    ]
    for message in expected:
        assert any(message in e for e in got), (message, got)
    (tmp_path / "param").mkdir()
    param = WORLD.replace("accel: {}", "accel: {x: specific_force}")
    got = errors(build(tmp_path / "param", _files(SIMULATION + param), "simulation"))
    assert any("'x' is not a parameter of accel" in e for e in got), got


WITHOUT_AIDS = (
    "        without_aids: {member: init, min_speed: 1.0, turn_rate: 2.0, converge_turn: 90.0, drift: 0.05}\n"
)


def test_heading_without_aids_is_checked_and_exported(tmp_path):
    ctx = build(tmp_path, _aiding(AIDING + WITHOUT_AIDS), "simulation")
    assert errors(ctx) == []
    assert ctx.simulation["filters"][0]["heading"]["without_aids"]["member"] == "init"
    for i, (member, message) in enumerate(
        [
            ("full", "'full' is not a member of FilterState"),
            ("navigating", "'navigating' enables heading sources: not without aids"),  # it enables the magnetometer
        ]
    ):
        (tmp_path / str(i)).mkdir()
        got = errors(build(tmp_path / str(i), _aiding(AIDING + WITHOUT_AIDS.replace("init", member)), "simulation"))
        assert any(message in e for e in got), (message, got)


STATUS_FIELDS = """\
  - id: 0x03
    name: status
    role: command
    title: Status
    response: 0x83
    sources: [{manual: a.txt, line: 9}]
    params: []
  - id: 0x83
    name: status_reply
    role: response
    title: Status reply
    sources: [{manual: a.txt, line: 9}]
    params:
      - {name: timer, type: u32}
      - {name: inner, type: Rate}
      - {name: ratio, type: float}
"""
STATUS = """\
  status:
    - reply: status_reply
      timer: [timer]
      pps: {count: decimation, last: timer}
      streams: {descriptor: 0x80}
      messages: [{set: 0x80, count: decimation, last: timer, while_fix: true}]
      sources: [{manual: a.txt, line: 9}]
"""


def test_status_is_checked_and_exported(tmp_path):
    files = _files(SIMULATION + STATUS)
    files["base.yaml"] = command_set(COMMANDS + STATUS_FIELDS)
    ctx = build(tmp_path, files, "simulation")
    assert errors(ctx) == []
    entry = ctx.simulation["status"][0]
    assert (entry["set"], entry["descriptor"]) == (0x01, 0x83) and entry["pps"]["count"] == "decimation"
    bad = STATUS.replace("timer: [timer]", "timer: [ratio, missing]").replace("descriptor: 0x80", "descriptor: 0x81")
    files["protocol.yaml"] = files["protocol.yaml"].replace(STATUS, bad)
    (tmp_path / "bad").mkdir()
    got = errors(build(tmp_path / "bad", files, "simulation"))
    expected = [
        "'ratio' is not an unsigned integer parameter of status_reply",  # a float
        "'missing' is not an unsigned integer parameter of status_reply",
        "0x81 is not a data set of the protocol",
    ]
    for message in expected:
        assert any(message in e for e in got), (message, got)
    files["protocol.yaml"] = files["protocol.yaml"].replace("reply: status_reply", "reply: status")
    (tmp_path / "command").mkdir()
    got = errors(build(tmp_path / "command", files, "simulation"))
    assert any("'status' is not a response" in e for e in got), got


NMEA = """\
  nmea:
    format: {command: message_format, list: entries}
    entry: {sentence: descriptor, talker: descriptor, source: descriptor, decimation: decimation}
    nack: failed
    origins: [{kind: imu, sets: [0x80], max_hz: 10}]
    talkers: [{code: 1, id: GN}]
    sentences: [{name: GGA, code: 1, talker: true, sources: [imu]}]
    input: {set: 0x80, sentences: [GGA], updates: 2}
    sources: [{manual: a.txt, line: 9}]
"""


def test_nmea_is_checked_and_exported(tmp_path):
    ctx = build(tmp_path, _files(SIMULATION + NMEA), "simulation")
    assert errors(ctx) == []
    nmea = ctx.simulation["nmea"]
    assert nmea["origins"] == [{"kind": "imu", "sets": [0x80], "max_hz": 10}] and nmea["input"]["updates"] == 2
    assert nmea["sources"][0]["line"] == 9
    bad = (
        NMEA.replace("list: entries", "list: desc_set")
        .replace("nack: failed", "nack: refused")
        .replace("sets: [0x80]", "sets: [0x81]")
        .replace("sources: [imu]", "sources: [gnss]")
        .replace("sentences: [GGA], updates", "sentences: [RMC], updates")
        .replace("{code: 1, id: GN}", "{code: 1, id: GN}, {code: 1, id: GP}")
    )
    (tmp_path / "bad").mkdir()
    got = errors(build(tmp_path / "bad", _files(SIMULATION + bad), "simulation"))
    expected = [
        "'desc_set' is not a struct list of message_format",
        "'refused' is not a member of the ack code enum",
        "0x81 is not a data set of the protocol",
        "'gnss' is not an origin",
        "'RMC' is not a sentence",
        "talkers code 1 twice",
    ]
    for message in expected:
        assert any(message in e for e in got), (message, got)
