"""resolve_types: enums, bitfields, structs and unions in IR form, in dependency order, with sizes."""

from tiny_spec import build, command_set, errors

FIELD = "  - {id: 0x01, name: ping, role: command, title: Ping, sources: [{manual: a.txt, line: 4}], params: []}\n"


def _types(tmp_path, types: str):
    return build(tmp_path, {"base.yaml": command_set(FIELD, types)}, "resolve_types")


def test_a_struct_may_use_a_struct_defined_after_it(tmp_path):
    ctx = _types(
        tmp_path,
        "structs:\n"
        "  - name: Outer\n    params: [{name: inner, type: Inner}, {name: n, type: u16}]\n"
        "  - name: Inner\n    params: [{name: a, type: u8, count: 3}]\n",
    )
    assert errors(ctx) == []
    outer = ctx.types["Outer"]
    assert outer["size"] == {"min": 5, "max": 5, "fixed": True}
    assert [(q["name"], q["offset"]) for q in outer["params"]] == [("inner", 0), ("n", 3)]
    assert outer["params"][0]["type"] == {"kind": "struct", "name": "Inner", "size": ctx.types["Inner"]["size"]}


def test_a_type_that_contains_itself_is_reported_once(tmp_path):
    ctx = _types(
        tmp_path,
        "structs:\n  - name: A\n    params: [{name: b, type: B}]\n  - name: B\n    params: [{name: a, type: A}]\n",
    )
    assert [e for e in errors(ctx) if "contains itself" in e] == [
        "base.yaml:7:11: error: type 'A' contains itself (expected a finite, non-recursive layout)"
    ]
    assert set(ctx.types) == {"A", "B"}  # later passes still find both


def test_enum_values_must_fit_and_not_clash_per_device(tmp_path):
    ctx = _types(
        tmp_path,
        "enums:\n  - name: Mode\n    type: u8\n    values:\n"
        "      - {name: big, value: 300}\n"
        "      - {name: one, value: 1, devices: [dev_a]}\n"
        "      - {name: uno, value: 1, devices: [dev_b]}\n"
        "      - {name: ein, value: 1}\n",
    )
    assert errors(ctx) == [
        "base.yaml:10:28: error: enum Mode value big = 300 does not fit in u8 (expected 0..255)",
        # 'one' and 'uno' are for different devices; 'ein' (every device) clashes with both.
        "base.yaml:13:28: error: enum Mode value 1 is used by both 'one' and 'ein' for the same device"
        " (expected distinct values, or 'devices:' lists that do not overlap)",
        "base.yaml:13:28: error: enum Mode value 1 is used by both 'uno' and 'ein' for the same device"
        " (expected distinct values, or 'devices:' lists that do not overlap)",
    ]
    assert ctx.types["Mode"]["size"] == {"min": 1, "max": 1, "fixed": True}


def test_bitfield_members_get_masks_and_overlaps_are_reported(tmp_path):
    ctx = _types(
        tmp_path,
        "bitfields:\n  - name: Flags\n    type: u8\n    members:\n"
        "      - {name: low, bits: [0, 3]}\n"
        "      - {name: mid, bits: [3, 4]}\n"
        "      - {name: all, bits: [0, 7], alias: true}\n",
    )
    assert [(m["name"], m["mask"], m["width"]) for m in ctx.types["Flags"]["members"]] == [
        ("low", 0x0F, 4),
        ("mid", 0x18, 2),
        ("all", 0xFF, 8),
    ]
    assert errors(ctx) == [
        "base.yaml:11:27: error: bitfield Flags member mid overlaps 'low' at bit 3"
        " (expected non-overlapping members (mark deliberate multi-bit masks with alias: true))"
    ]


def test_union_size_spans_its_members_and_its_selector_must_be_an_enum(tmp_path):
    types = (
        "enums:\n  - name: Kind\n    type: u8\n    values: [{name: none, value: 0}, {name: pair, value: 1}]\n"
        "structs:\n  - name: Pair\n    params: [{name: a, type: u16}, {name: b, type: u16}]\n"
        "unions:\n  - name: Payload\n    selector_enum: Kind\n    members: [{when: none}, {when: pair, type: Pair}]\n"
        "  - name: Bad\n    selector_enum: Pair\n    members: [{when: none}]\n"
    )
    ctx = _types(tmp_path, types)
    u = ctx.types["Payload"]
    assert u["size"] == {"min": 0, "max": 4, "fixed": False}
    assert [(m["when"], m["value"], m["type"]) for m in u["members"]] == [("none", 0, None), ("pair", 1, "Pair")]
    assert errors(ctx) == [
        "base.yaml:18:20: error: union Bad: selector type 'Pair' is a struct, not an enum (expected the name of an enum)"
    ]
