"""value_paths: how deep (in steps and in names) and how long a value path can get."""

from tiny_spec import PROTOCOL, build, command_set, errors

TYPES = """\
structs:
  - name: Inner
    params: [{name: a, type: u8, count: 3}]
  - name: Outer
    params: [{name: inner, type: Inner}, {name: name_long, type: u16}]
"""


def _paths(tmp_path, params: str, types: str = TYPES, extra: str = "", protocol: str = PROTOCOL):
    field = (
        "  - id: 0x01\n    name: cmd\n    role: command\n    title: C\n    sources: [{manual: a.txt, line: 4}]\n"
        + extra
        + f"    params: {params}\n"
    )
    ctx = build(tmp_path, {"protocol.yaml": protocol, "base.yaml": command_set(field, types)}, "value_paths")
    assert errors(ctx) == []
    return ctx.value_paths


def test_names_indexes_and_text(tmp_path):
    # The deepest path is list[i].inner.a[j]: 5 steps, 3 names; its text at most
    # "list[13].inner.a[3]" (a counted array's index counted with the digits of capacity + 1).
    params = "[{name: outer, type: Outer}, {name: n, type: u8}, {name: list, type: Outer, count: n, max_count: 12}]"
    assert _paths(tmp_path, params) == {"depth": 5, "names": 3, "length": len("list[13].inner.a[3]")}


def test_a_union_path_goes_through_the_struct_it_selects(tmp_path):
    types = TYPES + (
        "enums:\n  - name: Kind\n    type: u8\n    values: [{name: none, value: 0}, {name: outer, value: 1}]\n"
        "unions:\n  - name: Choice\n    selector_enum: Kind\n    members: [{when: none}, {when: outer, type: Outer}]\n"
    )
    params = "[{name: k, type: Kind}, {name: c, type: Choice, selector: k}]"
    # c.inner.a[j]: the union's member struct adds no step of its own.
    assert _paths(tmp_path, params, types) == {"depth": 4, "names": 3, "length": len("c.inner.a[3]")}


def test_a_function_selector_and_an_empty_layout_count_as_one_step(tmp_path):
    protocol = PROTOCOL + "function_selector: {enum: Function}\n"
    types = "enums:\n  - name: Function\n    type: u8\n    values: [{name: write, value: 1}]\n"
    got = _paths(tmp_path, "[]", types, extra="    functions: [write]\n", protocol=protocol)
    assert got == {"depth": 1, "names": 1, "length": len("function")}


def test_struct_types_count_even_when_no_layout_uses_them(tmp_path):
    # Outer alone: inner.a[j] (3 steps, 2 names), deeper than the layout's one-step x.
    assert _paths(tmp_path, "[{name: x, type: u8}]") == {"depth": 3, "names": 2, "length": len("inner.a[3]")}
