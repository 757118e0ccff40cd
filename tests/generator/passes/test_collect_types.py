"""collect_types: every named type and field layout is recorded once, with where it is defined."""

from tiny_spec import build, command_set, errors

ENUM = "enums:\n  - name: Mode\n    type: u8\n    values: [{name: idle, value: 0}]\n"
FIELD = "  - {id: 0x01, name: ping, role: command, title: Ping, sources: [{manual: a.txt, line: 4}], params: []}\n"


def test_types_from_every_file_are_recorded(tmp_path):
    types = "types: shared\n" + ENUM.replace("Mode", "Shared")
    ctx = build(tmp_path, {"base.yaml": command_set(FIELD, ENUM), "types.yaml": types}, "collect_types")
    assert errors(ctx) == []
    assert sorted(ctx.raw_types) == ["Mode", "Shared"]
    kind, _t, sf, path = ctx.raw_types["Mode"]
    assert (kind, sf.path, path) == ("enum", "base.yaml", ("enums", 0))
    assert str(ctx.type_locs["Shared"]) == "types.yaml:3:5"


def test_a_name_defined_twice_points_at_the_first(tmp_path):
    types = "types: shared\n" + ENUM
    ctx = build(tmp_path, {"base.yaml": command_set(FIELD, ENUM), "types.yaml": types}, "collect_types")
    # Type files are collected before set files: the set file's Mode is the second one.
    assert errors(ctx) == [
        "base.yaml:7:11: error: type 'Mode' is defined twice (first defined at types.yaml:3:5)"
        " (expected unique type names across the protocol)"
    ]


def test_field_layouts_are_unique(tmp_path):
    layout = "field_layouts:\n  - name: Pos\n    params: [{name: x, type: float}]\n"
    ctx = build(
        tmp_path, {"base.yaml": command_set(FIELD, layout + layout.replace("field_layouts:\n", ""))}, "collect_types"
    )
    assert list(ctx.field_layouts) == ["Pos"]
    assert errors(ctx) == [
        "base.yaml:9:11: error: field layout 'Pos' is defined twice (first defined at base.yaml:7:5)"
        " (expected unique field layout names across the protocol)"
    ]
