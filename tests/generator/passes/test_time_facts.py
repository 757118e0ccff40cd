"""time_facts: the protocol file's `time` section (which fields give a packet its GPS time, its
device clock and the GPS - UTC leap seconds), checked against the fields, parameters and flags."""

from tiny_spec import PROTOCOL, build, command_set, data_set, errors

FLAGS = """\
bitfields:
  - name: TimeFlags
    type: u16
    title: F
    sources: [{manual: a.txt, line: 3}]
    members:
      - {name: tow_ok, bits: 0, description: d}
      - {name: week_ok, bits: 1, description: d}
      - {name: not_set, bits: 2, description: d}
      - {name: reserved, bits: [3, 15], reserved: true, description: d}
"""

FIELDS = (
    "  - {id: 0x12, name: gps_time, role: data, title: G, sources: [{manual: a.txt, line: 5}], params: ["
    "{name: tow, type: double, units: s}, {name: week, type: u16, units: weeks}, {name: flags, type: TimeFlags},"
    " {name: plain, type: u16}]}\n"
    "  - {id: 0x13, name: clock, role: data, title: C, sources: [{manual: a.txt, line: 6}], params: ["
    "{name: us, type: u64, units: us}, {name: secs, type: double, units: s}]}\n"
    "  - {id: 0x14, name: leap, role: data, title: L, sources: [{manual: a.txt, line: 7}], params: ["
    "{name: seconds, type: u8, units: s}, {name: flags, type: TimeFlags}]}\n"
)

GOOD = """\
time:
  gps_time:
    - {field: sensor.gps_time, tow: tow, week: week, valid_flags: flags, valid: [tow_ok, week_ok], sources: [{manual: a.txt, line: 5}]}
    - {field: sensor.gps_time, tow: tow, week: week, valid_flags: flags, invalid: [not_set], sources: [{manual: b.txt, line: 9}]}
  device_clock:
    - {field: sensor.clock, param: us, sources: [{manual: a.txt, line: 6}]}
  leap_seconds:
    - {field: sensor.leap, param: seconds, valid_flags: flags, valid: [week_ok], sources: [{manual: a.txt, line: 7}]}
"""


def _build(tmp_path, time: str):
    return build(tmp_path, {"protocol.yaml": PROTOCOL + time, "sensor.yaml": data_set(FIELDS, FLAGS)}, "time_facts")


def test_the_tables(tmp_path):
    ctx = _build(tmp_path, GOOD)
    assert errors(ctx) == []
    gps = ctx.time["gps_time"]
    # valid members tow_ok (bit 0) and week_ok (bit 1): mask 0b11; the second entry needs bit 2 clear
    assert [
        (g["set"], g["descriptor"], g["tow"], g["week"], g["valid_flags"], g["mask"], g["inverted"]) for g in gps
    ] == [
        (0x80, 0x12, "tow", "week", "flags", 0b011, 0),
        (0x80, 0x12, "tow", "week", "flags", 0, 0b100),
    ]
    assert [(c["set"], c["descriptor"], c["param"], c["per_second"]) for c in ctx.time["device_clock"]] == [
        (0x80, 0x13, "us", 1_000_000)
    ]
    assert [(e["descriptor"], e["param"], e["mask"]) for e in ctx.time["leap_seconds"]] == [(0x14, "seconds", 0b010)]
    assert gps[1]["sources"] == [{"manual": "b.txt", "line": 9}]


def test_without_the_section_the_tables_are_empty(tmp_path):
    ctx = _build(tmp_path, "")
    assert ctx.time == {
        "gps_time": [],
        "device_clock": [],
        "leap_seconds": [],
        "reference_time": [],
        "external": [],
        "sync_health": [],
        "sync": [],
        "clock_model": None,
    }


def _at(text: str, line_text: str, value: str) -> str:
    """'protocol.yaml:LINE:COL' of `value` on the line of the time section holding `line_text`
    (1-based; the section starts after PROTOCOL's lines)."""
    lines = (PROTOCOL + text).splitlines()
    n = next(i for i, line in enumerate(lines) if line_text in line)
    return f"protocol.yaml:{n + 1}:{lines[n].index(value, lines[n].index(line_text)) + 1}"


def test_an_unknown_field(tmp_path):
    text = "time:\n  device_clock:\n    - {field: sensor.nothing, param: us, sources: [{manual: a.txt, line: 6}]}\n"
    ctx = _build(tmp_path, text)
    assert errors(ctx) == [
        f"{_at(text, 'field:', 'sensor.nothing')}: error: time: 'sensor.nothing' is not a data field"
        " (expected set.field of a data set)"
    ]
    assert ctx.time["device_clock"] == []


def test_wrong_parameters(tmp_path):
    text = (
        "time:\n"
        "  gps_time:\n"
        "    - {field: sensor.gps_time, tow: week, week: tow, valid_flags: plain, valid: [tow_ok], sources: [{manual: a.txt, line: 5}]}\n"
        "  device_clock:\n"
        "    - {field: sensor.clock, param: secs, sources: [{manual: a.txt, line: 6}]}\n"
        "  leap_seconds:\n"
        "    - {field: sensor.leap, param: seconds, valid_flags: flags, valid: [reserved], sources: [{manual: c.txt, line: 7}]}\n"
    )
    ctx = _build(tmp_path, text)
    assert errors(ctx) == [
        f"{_at(text, 'tow: week', 'week')}: error: time: 'week' of gps_time is not a double parameter in s"
        " (in every layout) (expected a double parameter in s)",
        f"{_at(text, 'week: tow', 'tow')}: error: time: 'tow' of gps_time is not an unsigned integer parameter in"
        " weeks (in every layout) (expected an unsigned integer parameter in weeks)",
        f"{_at(text, 'valid_flags: plain', 'plain')}: error: time: 'plain' of gps_time is not a bitfield parameter"
        " (expected a bitfield parameter)",
        f"{_at(text, 'param: secs', 'secs')}: error: time: 'secs' of clock is not an unsigned integer parameter in"
        " ns, us, ms or s (in every layout) (expected an unsigned integer parameter in ns, us, ms or s)",
        f"{_at(text, 'manual: c.txt', 'c.txt')}: error: unknown manual 'c.txt' (expected one of the manuals listed"
        " under devices in the protocol file: a.txt, b.txt)",
        f"{_at(text, 'valid: [reserved]', 'reserved')}: error: time: 'reserved' is not a member of flags"
        " (expected a named member of the bitfield)",
    ]
    assert ctx.time == {
        "gps_time": [],
        "device_clock": [],
        "leap_seconds": [],
        "reference_time": [],
        "external": [],
        "sync_health": [],
        "sync": [],
        "clock_model": None,
    }


def test_a_flag_rule_is_needed(tmp_path):
    ctx = _build(
        tmp_path,
        "time:\n  gps_time:\n"
        "    - {field: sensor.gps_time, tow: tow, week: week, valid_flags: flags, sources: [{manual: a.txt, line: 5}]}\n",
    )
    assert [e.split(": error: ")[1] for e in errors(ctx)] == [
        "time: no valid flag member given (expected the members that say the value is valid)"
    ]


CLOCK = "  clock_model: {bucket_ns: 500000000, buckets: 32, min_buckets: 3, restart_ns: 2000000000, basis: b}\n"


def test_reference_time_per_device(tmp_path):
    text = (
        "time:\n" + CLOCK + "  reference_time:\n"
        "    - {device: dev_a, field: sensor.clock, param: us, monotonic: true, sources: [{manual: a.txt, line: 6}]}\n"
        "    - {device: dev_b, field: sensor.gps_time, tow: tow, week: week, monotonic: false, sources: [{manual: b.txt, line: 2}]}\n"
    )
    ctx = _build(tmp_path, text)
    assert errors(ctx) == []
    # the host clock model's parameters, carried as they are (the project's own, no manual line)
    assert ctx.time["clock_model"] == {
        "bucket_ns": 500_000_000,
        "buckets": 32,
        "min_buckets": 3,
        "restart_ns": 2_000_000_000,
    }
    rows = [{k: v for k, v in r.items() if k not in ("sources", "field")} for r in ctx.time["reference_time"]]
    assert rows == [
        {
            "device": "dev_a",
            "set": 0x80,
            "descriptor": 0x13,
            "kind": "count",
            "param": "us",
            "per_second": 1_000_000,
            "offset": 0,
            "size": 8,
            "monotonic": True,
        },
        {
            "device": "dev_b",
            "set": 0x80,
            "descriptor": 0x12,
            "kind": "gps",
            "tow": "tow",
            "week": "week",
            "tow_offset": 0,
            "week_offset": 8,
            "week_size": 2,
            "monotonic": False,
        },
    ]


def test_reference_time_errors(tmp_path):
    text = (
        "time:\n" + CLOCK + "  reference_time:\n"
        "    - {device: dev_c, field: sensor.clock, param: us, monotonic: true, sources: [{manual: a.txt, line: 6}]}\n"
        "    - {device: dev_a, field: sensor.clock, param: secs, monotonic: true, sources: [{manual: a.txt, line: 6}]}\n"
        "    - {device: dev_a, field: sensor.clock, param: us, monotonic: false, sources: [{manual: a.txt, line: 6}]}\n"
        "    - {device: dev_b, field: sensor.gps_time, tow: tow, monotonic: false, sources: [{manual: b.txt, line: 2}]}\n"
    )
    ctx = _build(tmp_path, text)
    assert errors(ctx) == [
        f"{_at(text, 'dev_c', 'dev_c')}: error: time reference_time: unknown device 'dev_c' (expected a device of the protocol file)",
        f"{_at(text, 'param: secs', 'secs')}: error: time: 'secs' of clock is not an unsigned integer parameter in"
        " ns, us, ms or s (in every layout) (expected an unsigned integer parameter in ns, us, ms or s)",
        f"{_at(text, 'dev_a, field: sensor.clock, param: us', 'dev_a')}:"
        " error: time reference_time: a second entry for 'dev_a' (expected one entry per device)",
        f"{_at(text, '{device: dev_b', '{')}: error: time reference_time: give either param or both tow and week"
        " (expected param, or tow and week)",
    ]
    assert ctx.time["reference_time"] == []


def test_clock_model_errors(tmp_path):
    ref = "  reference_time:\n    - {device: dev_a, field: sensor.clock, param: us, monotonic: true, sources: [{manual: a.txt, line: 6}]}\n"
    # the model the sessions feed from the reference time needs its parameters
    ctx = _build(tmp_path, "time:\n" + ref)
    assert [e.split(": error: ")[1] for e in errors(ctx)] == [
        "time: reference_time without clock_model (the host clock model it feeds needs its parameters)"
        " (expected clock_model: {bucket_ns, buckets, min_buckets, restart_ns, basis})"
    ]
    assert ctx.time["clock_model"] is None
    # more closed buckets needed than kept: never an estimate
    text = "time:\n" + CLOCK.replace("min_buckets: 3", "min_buckets: 33") + ref
    ctx = _build(tmp_path, text)
    assert errors(ctx) == [
        f"{_at(text, 'min_buckets', '33')}: error: time clock_model: min_buckets 33 above buckets 32 (never an estimate)"
        " (expected at most buckets)"
    ]
    # without reference_time the model is not fed: the section is optional
    ctx = _build(tmp_path, GOOD)
    assert errors(ctx) == [] and ctx.time["clock_model"] is None


SYNC_FIELDS = FIELDS + (
    "  - {id: 0x15, name: sync, role: data, title: S, sources: [{manual: a.txt, line: 8}], params: ["
    "{name: synced, type: bool}, {name: since, type: u8, units: s}]}\n"
)


def test_external_time_and_sync_health(tmp_path):
    text = (
        "time:\n"
        "  external:\n"
        "    - {field: sensor.clock, param: us, valid_flags: flags, valid: [tow_ok], sources: [{manual: a.txt, line: 6}]}\n"
        "    - {field: sensor.leap, param: seconds, valid_flags: flags, valid: [week_ok], sources: [{manual: a.txt, line: 7}]}\n"
        "  sync_health:\n"
        "    - {field: sensor.sync, param: synced, sources: [{manual: a.txt, line: 8}]}\n"
        "    - {field: sensor.gps_time, valid_flags: flags, valid: [week_ok], sources: [{manual: a.txt, line: 5}]}\n"
        "    - {field: sensor.sync, param: since, sources: [{manual: a.txt, line: 8}]}\n"
        "    - {field: sensor.sync, sources: [{manual: a.txt, line: 8}]}\n"
    )
    ctx = build(tmp_path, {"protocol.yaml": PROTOCOL + text, "sensor.yaml": data_set(SYNC_FIELDS, FLAGS)}, "time_facts")
    # sensor.clock has no valid_flags parameter: its entry is refused; the leap field's seconds
    # (u8 in s) with bit 1 is an external time in whole seconds
    assert [e.split(": error: ")[1] for e in errors(ctx)] == [
        "time: 'flags' of clock is not a bitfield parameter (expected a bitfield parameter)",
        "time: 'since' of sync is not a bool parameter (in every layout) (expected a bool parameter)",
        "time sync_health: give either param or valid_flags (expected param, or valid_flags and valid)",
    ]
    assert [
        (e["descriptor"], e["param"], e["per_second"], e["valid_flags"], e["mask"]) for e in ctx.time["external"]
    ] == [(0x14, "seconds", 1, "flags", 0b10)]
    assert [(e["descriptor"], e["kind"], e.get("param"), e.get("mask")) for e in ctx.time["sync_health"]] == [
        (0x15, "bool", "synced", None),
        (0x12, "flags", None, 0b10),
    ]


# --------------------------------------------------------------------------------- time.sync
SYNC_TYPES = """\
enums:
  - name: TimeField
    type: u8
    title: T
    sources: [{manual: a.txt, line: 3}]
    values:
      - {name: week_number, value: 1, description: d}
      - {name: time_of_week, value: 2, description: d}
  - name: Source
    type: u8
    title: S
    sources: [{manual: a.txt, line: 3}]
    values:
      - {name: disabled, value: 0, description: d}
      - {name: pin, value: 3, description: d}
"""
COMMANDS = (
    "  - {id: 0x72, name: time_update, role: command, title: U, sources: [{manual: a.txt, line: 8}], params: ["
    "{name: field_id, type: TimeField}, {name: value, type: u32}]}\n"
    "  - {id: 0x28, name: pps_source, role: command, title: P, sources: [{manual: a.txt, line: 9}], params: ["
    "{name: source, type: Source}]}\n"
)
SYNC = """\
time:
  sync:
    - device: dev_a
      update: {command: time_update, selector: field_id, value: value, week: week_number, tow: time_of_week}
      window_ms: 500
      pps: [input, generated]
      pps_source: {command: pps_source, param: source, kinds: {disabled: none, pin: input}}
      correlation: {field: sensor.gps_time, flags: flags, pps: tow_ok, refresh: week_ok, initialized: not_set}
      sources: [{manual: a.txt, line: 8}]
"""


def _sync(tmp_path, text: str):
    files = {
        "protocol.yaml": PROTOCOL + text,
        "sensor.yaml": data_set(FIELDS, FLAGS),
        "base.yaml": command_set(COMMANDS, SYNC_TYPES),
    }
    return build(tmp_path, files, "time_facts")


def test_sync_resolves_names_to_numbers(tmp_path):
    ctx = _sync(tmp_path, SYNC)
    assert errors(ctx) == []
    (e,) = ctx.time["sync"]
    assert e["update"] == {
        "command": "time_update", "selector": "field_id", "value": "value", "set": 0x01, "descriptor": 0x72,
        "week": 1, "tow": 2,
    }  # fmt: skip
    assert e["pps_source"]["kinds"] == {0: "none", 3: "input"}
    assert e["external"] == []
    assert (e["correlation"]["pps"], e["correlation"]["refresh"], e["correlation"]["initialized"]) == (1, 2, 4)


def test_sync_takes_the_external_count_from_the_time_section(tmp_path):
    # the external time as a count is named once, in `time.external` (the log time model's): each
    # sync entry of a device that has the field gets it, after its own GPS time fields
    text = SYNC.replace(
        "      correlation:",
        "      external: [{field: sensor.gps_time, flags: flags, tow: tow_ok, week: week_ok}]\n      correlation:",
    )
    text += (
        "  external:\n"
        "    - {field: sensor.leap, param: seconds, valid_flags: flags, valid: [week_ok], sources: [{manual: a.txt, line: 7}]}\n"
    )
    files = {
        "protocol.yaml": PROTOCOL + text,
        "sensor.yaml": data_set(
            FIELDS.replace("name: tow,", "name: tow_ok,").replace("name: week,", "name: week_ok,"), FLAGS
        ),
        "base.yaml": command_set(COMMANDS, SYNC_TYPES),
    }
    ctx = build(tmp_path, files, "time_facts")
    assert errors(ctx) == []
    (e,) = ctx.time["sync"]
    assert e["external"] == [
        {"field": "sensor.gps_time", "set": 0x80, "descriptor": 0x12, "flags": "flags", "tow": "tow_ok",
         "tow_mask": 0b01, "week": "week_ok", "week_mask": 0b10},
        {"field": "sensor.leap", "set": 0x80, "descriptor": 0x14, "flags": "flags", "ns": "seconds",
         "ns_mask": 0b10, "per_second": 1},
    ]  # fmt: skip


def test_sync_errors(tmp_path):
    # the external time's flag members are named as its parameters: tow and week are no members of
    # TimeFlags here (tow_ok, week_ok); an enum member without a PPS kind; an unknown selector value
    text = SYNC.replace("kinds: {disabled: none, pin: input}", "kinds: {disabled: none}").replace(
        "tow: time_of_week}", "tow: hour}"
    )
    text = text.replace(
        "      correlation:",
        "      external: [{field: sensor.gps_time, flags: flags, tow: tow, week: week}]\n      correlation:",
    )
    ctx = _sync(tmp_path, text)
    assert [e.split(": error: ")[1] for e in errors(ctx)] == [
        "time sync: 'hour' is not a member of the selector's enum (expected an enum member)",
        "time sync: no kind for pin (expected a kind for every member)",
        "time sync: 'tow' is not a member of TimeFlags (expected a member of TimeFlags)",
    ]
    assert ctx.time["sync"] == []
