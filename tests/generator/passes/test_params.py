"""passes/params.py and passes/sizes.py (called by several passes): parameter checks, the default
capacity of a counted array and the fixed offsets."""

from tiny_spec import build, command_set, errors


def _layout(tmp_path, params: str, extra: str = ""):
    field = (
        "  - id: 0x01\n    name: cmd\n    role: command\n    title: Cmd\n"
        "    sources: [{manual: a.txt, line: 4}]\n" + extra + "    params:\n" + params
    )
    ctx = build(tmp_path, {"base.yaml": command_set(field)}, "variants")
    return ctx, ctx.sets[0]["fields"][0]["variants"][0]


def test_counted_array_capacity_is_what_fits_beside_the_others(tmp_path):
    ctx, v = _layout(
        tmp_path,
        "      - {name: n, type: u8}\n      - {name: values, type: u32, count: n}\n      - {name: tail, type: u16}\n",
    )
    assert errors(ctx) == []
    n, values, tail = v["params"]
    # Field data holds at most 253 bytes (MIP: 255 - 2 for the field header); 1 + 2 are taken.
    assert values["max_count"] == (253 - 3) // 4
    assert values["size"] == {"min": 0, "max": 4 * values["max_count"], "fixed": False}
    assert [q["offset"] for q in (n, values, tail)] == [0, 1, None]
    assert v["size"] == {"min": 3, "max": 3 + 4 * values["max_count"], "fixed": False}


def test_count_must_name_an_earlier_integer(tmp_path):
    ctx, _ = _layout(
        tmp_path,
        "      - {name: values, type: u8, count: n}\n      - {name: n, type: u8}\n"
        "      - {name: f, type: float}\n      - {name: more, type: u8, count: f}\n",
    )
    assert errors(ctx) == [
        "base.yaml:13:41: error: base.cmd: count of values refers to 'n', which is a later parameter"
        " (expected the name of an earlier integer parameter)",
        "base.yaml:16:39: error: base.cmd: count of more refers to 'f', which is not a single integer"
        " (expected an earlier u8/u16/u32 parameter)",
    ]


def test_remaining_must_be_last_and_optional_params_must_come_last(tmp_path):
    ctx, v = _layout(
        tmp_path,
        "      - {name: rest, type: u8, count: remaining}\n"
        "      - {name: opt, type: u8, optional: true}\n      - {name: req, type: u8}\n",
    )
    assert errors(ctx) == [
        "base.yaml:13:39: error: base.cmd: parameter rest runs to the end of the field but is not the last parameter"
        " (expected count: remaining only on the last parameter)",
        "base.yaml:15:9: error: base.cmd: required parameter req follows optional parameter opt"
        " (expected optional parameters (not sent for every function) at the end)",
    ]
    assert [q["optional"] for q in v["params"]] == [False, True, False]


def test_vector_aliases_are_fixed_arrays_of_their_element(tmp_path):
    ctx, v = _layout(tmp_path, "      - {name: accel, type: vector3f}\n")
    (q,) = v["params"]
    assert (q["alias"], q["type"]["name"], q["count"], q["size"]["max"]) == (
        "vector3f",
        "float",
        {"kind": "fixed", "value": 3},
        12,
    )


def test_optional_for_makes_a_parameter_optional_for_those_functions(tmp_path):
    ctx, v = _layout(
        tmp_path,
        "      - {name: n, type: u8, functions: [write, read], optional_for: [read]}\n"
        "      - {name: values, type: u8, count: n, functions: [write, read], optional_for: [read]}\n",
        "    functions: [write, read]\n",
    )
    assert errors(ctx) == []
    n, values = v["params"]
    assert (n["optional"], n["optional_for"]) == (True, ["read"])
    assert (values["optional"], values["optional_for"]) == (True, ["read"])


def test_optional_for_names_functions_the_parameter_is_sent_for(tmp_path):
    ctx, _ = _layout(
        tmp_path,
        "      - {name: a, type: u8, functions: [write, read], optional_for: [save]}\n"
        "      - {name: b, type: u8, functions: [write, read]}\n",
        "    functions: [write, read]\n",
    )
    assert errors(ctx) == [
        "base.yaml:14:69: error: base.cmd: parameter a may be left out by function 'save', which it is not sent for"
        " (expected a subset of the parameter's functions: write, read)",
        "base.yaml:15:9: error: base.cmd: required parameter b follows optional parameter a"
        " (expected optional parameters (not sent for every function) at the end)",
    ]


def test_default_values_are_checked_against_the_type_and_exported(tmp_path):
    src = "source: {manual: a.txt, line: 9}"
    ctx, v = _layout(
        tmp_path,
        f"      - {{name: flag, type: bool, functions: [write], default: {{value: true, {src}}}}}\n"
        f"      - {{name: rate, type: u16, functions: [write], default: {{value: 400, {src}}}}}\n"
        f"      - {{name: axes, type: vector3f, functions: [write], default: {{value: [0, 0, 1], {src}}}}}\n",
        "    functions: [write, read]\n",
    )
    assert errors(ctx) == []
    src9 = {"source": {"manual": "a.txt", "line": 9}, "also": [], "devices": ["dev_a"]}
    assert [q["default"] for q in v["params"]] == [
        {"value": True, **src9},
        {"value": 400, **src9},
        {"value": [0.0, 0.0, 1.0], **src9},
    ]


def test_a_default_holds_on_the_devices_of_the_manuals_citing_it(tmp_path):
    # a.txt is dev_a's manual, b.txt dev_b's (tiny_spec): `also` cites a further line stating it.
    ctx, v = _layout(
        tmp_path,
        "      - {name: flag, type: bool, functions: [write], default: {value: true, source: {manual: b.txt, line: 7}}}\n"
        "      - {name: rate, type: u16, functions: [write], default: {value: 400, source: {manual: b.txt, line: 7},"
        " also: [{manual: a.txt, line: 12}, {manual: b.txt, line: 30}]}}\n",
        "    functions: [write, read]\n",
    )
    assert errors(ctx) == []
    flag, rate = (q["default"] for q in v["params"])
    assert flag["devices"] == ["dev_b"]
    assert rate["devices"] == ["dev_a", "dev_b"]
    assert rate["also"] == [{"manual": "a.txt", "line": 12}, {"manual": "b.txt", "line": 30}]


def test_a_counted_list_default_is_a_list_of_any_length(tmp_path):
    # A message format's list (MS-CIP select sensors): the count follows from the list.
    ctx, v = _layout(
        tmp_path,
        "      - {name: n, type: u8, functions: [write]}\n"
        "      - {name: codes, type: u8, count: n, functions: [write], default: {value: [0x81, 0x82], source: {manual: a.txt, line: 9}}}\n"
        "      - {name: rest, type: u16, count: remaining, functions: [write], default: {value: 5, source: {manual: a.txt, line: 9}}}\n",
        "    functions: [write, read]\n",
    )
    assert errors(ctx) == [
        "base.yaml:16:88: error: base.cmd: default of rest is not a list (expected a list of values)",
    ]
    assert v["params"][1]["default"]["value"] == [0x81, 0x82]


def test_default_values_that_do_not_fit_are_located_errors(tmp_path):
    src = "source: {manual: a.txt, line: 9}"
    ctx, v = _layout(
        tmp_path,
        f"      - {{name: rate, type: u8, functions: [write], default: {{value: 300, {src}}}}}\n"
        f"      - {{name: axes, type: vector3f, functions: [write], default: {{value: [1, 2], {src}}}}}\n"
        "      - {name: flag, type: bool, functions: [write], default: {value: true, source: {manual: a.txt, line: 1},"
        " also: [{manual: z.txt, line: 1}]}}\n"
        f"      - {{name: key, type: u8, functions: [read], default: {{value: 1, {src}}}}}\n",
        "    functions: [write, read]\n",
    )
    assert errors(ctx) == [
        "base.yaml:14:69: error: base.cmd: default of rate: 300 is not a value of u8 (expected a u8 value)",
        "base.yaml:15:75: error: base.cmd: default of axes is not a list of 3 values (expected 3 values)",
        "base.yaml:16:127: error: unknown manual 'z.txt' (expected one of the manuals listed under devices in the"
        " protocol file: a.txt, b.txt)",
        "base.yaml:17:59: error: base.cmd: default of key: only a setting's parameters sent for write have one"
        " (expected no default)",
    ]
    assert v["params"][0]["default"] is None


def test_frame_one_name_or_one_per_device_of_the_protocol(tmp_path):
    """`frame:` is kept as the IR's `frame` (a name, or {device: name} in device order); a device
    that is not the protocol's is a located error (the schema already refuses unknown names)."""
    ctx, v = _layout(
        tmp_path,
        "      - {name: a, type: vector3f, frame: ned}\n"
        "      - {name: b, type: vector3f, frame: {dev_b: vehicle, dev_a: sensor}}\n"
        "      - {name: c, type: float}\n",
    )
    assert errors(ctx) == []
    assert [q["frame"] for q in v["params"]] == ["ned", {"dev_a": "sensor", "dev_b": "vehicle"}, None]
    assert list(v["params"][1]["frame"]) == ["dev_a", "dev_b"]
    ctx, _ = _layout(tmp_path, "      - {name: a, type: vector3f, frame: {dev_c: sensor}}\n")
    (err,) = errors(ctx)
    assert "parameter a: frame for unknown device 'dev_c'" in err and "dev_a, dev_b" in err, err


def test_ignored_names_functions_that_do_not_require_the_parameter(tmp_path):
    # "For all functions except 0x01 ..., the new ... value is ignored" (3dm-gx5-45-dcp.txt:2005).
    src = "source: {manual: a.txt, line: 9}"
    ctx, v = _layout(
        tmp_path,
        "      - {name: key, type: u8, functions: [write, read]}\n"
        f"      - {{name: flag, type: bool, functions: [write, read], ignored: {{functions: [read, save], {src}}}}}\n"
        f"      - {{name: mode, type: u8, functions: [write], ignored: {{functions: [read], {src}}}}}\n",
        "    functions: [write, read]\n",
    )
    assert [e.split("error: ")[1] for e in errors(ctx)] == [
        "base.cmd: parameter flag is ignored for function 'read' but required for it"
        " (expected leave the function out of the parameter's functions, or list it in optional_for)",
        "base.cmd: parameter flag is ignored for function 'save', which the command does not support"
        " (expected a subset of the command's functions)",
    ]
    assert v["params"][2]["ignored"] == {"functions": ["read"], "source": {"manual": "a.txt", "line": 9}}
    assert v["params"][0]["ignored"] is None


def test_plausible_values_are_checked_like_defaults_and_keep_their_reason(tmp_path):
    ctx, v = _layout(
        tmp_path,
        "      - {name: baud, type: u32, functions: [write], plausible: {value: 115200, why: 'the lowest rate\n"
        "          the port serves', source: {manual: a.txt, line: 3}}}\n"
        "      - {name: noise, type: vector3f, functions: [write], plausible: {value: [1, 2], why: x}}\n",
        "    functions: [write, read]\n",
    )
    assert [e.split("error: ")[1] for e in errors(ctx)] == [
        "base.cmd: default of noise is not a list of 3 values (expected 3 values)",
    ]
    assert v["params"][0]["plausible"] == {
        "value": 115200,
        "why": "the lowest rate the port serves",
        "source": {"manual": "a.txt", "line": 3},
    }


def test_a_counted_struct_list_default_is_records_of_every_member(tmp_path):
    # The GX5-45's factory constellations (3dm-gx5-45-dcp.txt:1106): one record per constellation.
    types = (
        "structs:\n  - name: Pair\n    title: Pair\n    sources: [{manual: a.txt, line: 5}]\n    params:\n"
        "      - {name: a, type: u8}\n      - {name: b, type: bool}\n"
    )
    field = (
        "  - id: 0x01\n    name: cmd\n    role: command\n    title: Cmd\n    functions: [write, read]\n"
        "    sources: [{manual: a.txt, line: 4}]\n    params:\n"
        "      - {name: n, type: u8, functions: [write]}\n"
        "      - {name: items, type: Pair, count: n, functions: [write], default: {value: VALUE,"
        " source: {manual: a.txt, line: 9}}}\n"
    )
    good = field.replace("VALUE", "[{a: 1, b: true}, {a: 3, b: false}]")
    (tmp_path / "good").mkdir()
    (tmp_path / "bad").mkdir()
    ctx = build(tmp_path / "good", {"base.yaml": command_set(good, types)}, "variants")
    assert errors(ctx) == []
    items = ctx.sets[0]["fields"][0]["variants"][0]["params"][1]
    assert items["default"]["value"] == [{"a": 1, "b": True}, {"a": 3, "b": False}]
    bad = field.replace("VALUE", "[{a: 1, b: true}, {a: 3}]")
    ctx = build(tmp_path / "bad", {"base.yaml": command_set(bad, types)}, "variants")
    assert [e.split("error: ")[1] for e in errors(ctx)] == [
        "base.cmd: default of items: {'a': 3} is not a value of Pair (expected a record naming every member: a, b)"
    ]


def test_a_simulated_setting_starts_from_a_default_or_a_plausible_value(tmp_path):
    # Issue 51: every value a setting holds starts from a value the spec records with its reason,
    # never from an unexplained zero; checked where the simulator serves the protocol.
    from tiny_spec import PROTOCOL

    simulated = PROTOCOL + (
        "simulation:\n  nack: {unknown_descriptor: a, unknown_set: b, invalid_parameter: c, failed: d}\n"
    )
    field = (
        "  - id: 0x01\n    name: cmd\n    role: command\n    title: Cmd\n    functions: [write, read]\n"
        "    sources: [{manual: a.txt, line: 4}, {manual: b.txt, line: 4}]\n    params:\n"
        "      - {name: key, type: u8, functions: [write, read]}\n"
        "      - {name: stated, type: u8, functions: [write], default: {value: 1, source: {manual: a.txt, line: 5}}}\n"
        "      - {name: none, type: u8, functions: [write]}\n"
        "      - {name: offset, type: float, functions: [write], plausible: {why: 'zero: no offset applied'}}\n"
    )
    (tmp_path / "sim").mkdir()
    (tmp_path / "plain").mkdir()
    ctx = build(tmp_path / "sim", {"protocol.yaml": simulated, "base.yaml": command_set(field)}, "variants")
    # `key` selects the setting (read sends it); `stated` lacks a value on dev_b only; `offset`
    # starts from its type's zero for the reason recorded.
    assert [e.split("error: ")[1].split(" (expected")[0] for e in errors(ctx)] == [
        "base.cmd: setting parameter stated has no default stated for dev_b and no plausible value",
        "base.cmd: setting parameter none has no default stated for dev_a, dev_b and no plausible value",
    ]
    offset = ctx.sets[0]["fields"][0]["variants"][0]["params"][3]
    assert offset["plausible"] == {"value": None, "why": "zero: no offset applied", "source": None}
    ctx = build(tmp_path / "plain", {"base.yaml": command_set(field)}, "variants")
    assert errors(ctx) == []
