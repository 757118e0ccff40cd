"""The language-neutral layout model (generator/model.py): hand-built IR snippets, then the real IR."""

import json
from pathlib import Path

import pytest

from generator import model
from generator.spec import load_spec

ROOT = Path(__file__).resolve().parents[2]
FIXTURE = Path(__file__).parent / "fixtures" / "everything"


def _size(n_min, n_max=None):
    n_max = n_min if n_max is None else n_max
    return {"min": n_min, "max": n_max, "fixed": n_min == n_max}


def _prim(name, size):
    return {"kind": "primitive", "name": name, "size": _size(size)}


def _q(name, tref, count=None, optional=False, max_count=None, size=None, **extra):
    return {
        "name": name,
        "type": tref,
        "count": count,
        "optional": optional,
        "max_count": max_count,
        "size": size or tref["size"],
        "functions": None,
        **extra,
    }


# A protocol with just what the snippets below refer to.
PROTO = {
    "function_selector": {"enum": "Function"},
    "types": [
        {"kind": "enum", "name": "Function", "base": "u8", "values": []},
        {"kind": "enum", "name": "Mode", "base": "u8", "values": []},
        {"kind": "struct", "name": "Pair", "params": [_q("a", _prim("u8", 1)), _q("b", _prim("s16", 2))]},
        {"kind": "struct", "name": "Flagged", "params": [_q("on", _prim("bool", 1))]},
        {
            "kind": "union",
            "name": "Choice",
            "selector_enum": "Mode",
            "members": [
                {"when": "none", "value": 0, "type": None},
                {"when": "pair", "value": 1, "type": "Pair"},
            ],
        },
    ],
}
MODE = {"kind": "enum", "name": "Mode", "base": "u8", "size": _size(1)}
PAIR = {"kind": "struct", "name": "Pair", "size": _size(3)}


def test_each_kind_is_classified_once():
    ps = model.params(
        PROTO,
        [
            _q("x", _prim("u16", 2)),
            _q("v", _prim("float", 4), count={"kind": "fixed", "value": 3}, size=_size(12)),
            _q("n", _prim("u8", 1)),
            _q("items", PAIR, count={"kind": "param", "param": "n"}, max_count=10, size=_size(0, 30)),
            _q("label", {"kind": "string", "length": 8, "padding": "space", "justify": "right", "size": _size(8)}),
            _q("mode", MODE),
            _q("choice", {"kind": "union", "name": "Choice", "selector": "mode", "size": _size(0, 3)}),
            _q("rest", _prim("u16", 2), count={"kind": "remaining"}, max_count=100, size=_size(0, 200)),
        ],
    )
    assert [p.kind for p in ps] == ["scalar", "fixed", "scalar", "counted", "string", "scalar", "union", "remaining"]
    x, v, _, items, label, _, choice, rest = ps
    assert x.elem == model.Elem("primitive", "u16", "u16", model.Size(2, 2, True))
    assert v.count == 3 and v.elem.name == "float" and v.array and v.size == model.Size(12, 12, True)
    assert items.count_param == "n" and items.max_count == 10 and not items.count_optional
    assert items.elem.kind == "struct" and items.elem.name == "Pair" and items.elem.primitive is None
    # A u8 count can say 255 > 10 elements, so decoders must check it.
    assert items.count_check
    assert (label.elem.length, label.elem.padding, label.elem.justify) == (8, "space", "right")
    assert choice.selector == "mode" and choice.selector_enum == "Mode" and not choice.selector_optional
    assert choice.members == (model.UnionMember("none", 0, None), model.UnionMember("pair", 1, "Pair"))
    assert rest.max_count == 100 and rest.count_check and rest.count_param is None
    assert not ps.has_optional and ps.has_array and ps.functions is None


def test_count_check_only_when_the_count_can_exceed_the_maximum():
    ps = model.params(
        PROTO,
        [_q("n", _prim("u8", 1)), _q("xs", _prim("u8", 1), count={"kind": "param", "param": "n"}, max_count=255)],
    )
    assert ps.params[1].count_check is False


def test_optional_count_and_selector_are_reported():
    ps = model.params(
        PROTO,
        [
            _q("n", _prim("u8", 1), optional=True),
            _q("mode", MODE, optional=True),
            _q("xs", _prim("u8", 1), count={"kind": "param", "param": "n"}, max_count=4, optional=True),
            _q("c", {"kind": "union", "name": "Choice", "selector": "mode", "size": _size(0, 3)}, optional=True),
        ],
    )
    assert ps.params[2].count_optional and ps.params[3].selector_optional
    assert ps.has_optional and all(p.optional for p in ps)


def test_function_selector_comes_first():
    ps = model.params(PROTO, [_q("x", _prim("u8", 1))], ["write", "read"])
    f = ps.params[0]
    assert f.function and f.name == "function" and f.kind == "scalar"
    assert f.elem == model.Elem("enum", "Function", "u8", model.Size(1, 1, True))
    assert f.functions == ("write", "read") and ps.functions == ("write", "read")
    assert [p.name for p in ps] == ["function", "x"]


def test_plain_means_every_byte_pattern_decodes():
    flagged = {"kind": "struct", "name": "Flagged", "size": _size(1)}
    ps = model.params(
        PROTO,
        [
            _q("pair", PAIR),
            _q("pairs", PAIR, count={"kind": "fixed", "value": 2}, size=_size(6)),
            _q("b", _prim("bool", 1)),
            _q("f", flagged),
            _q("o", _prim("u8", 1), optional=True),
        ],
    )
    assert [p.plain for p in ps] == [True, True, False, False, False]
    assert not ps.plain


def test_unknown_count_kind_is_refused():
    with pytest.raises(ValueError, match="unknown count kind"):
        model.params(PROTO, [_q("x", _prim("u8", 1), count={"kind": "sometimes"})])


def _all_lists(proto):
    for s in proto["sets"]:
        for f in s["fields"]:
            for v in f["variants"]:
                yield v, model.layout(proto, v)
    for r in proto["reserved_fields"]:
        for v in r["variants"]:
            yield v, model.layout(proto, v)
    for t in proto["types"]:
        if t["kind"] == "struct":
            yield t, model.struct(proto, t)


def _check_against_ir(proto):
    kinds = set()
    for owner, ps in _all_lists(proto):
        ir_params = owner["params"]
        offset = 1 if owner.get("functions") is not None else 0
        assert len(ps) == len(ir_params) + offset
        for p, q in zip(ps.params[offset:], ir_params):
            kinds.add(p.kind)
            assert p.name == q["name"] and p.optional == q["optional"] and p.ir is q
            assert p.kind in model.KINDS
            count = q["count"]
            if p.kind == "fixed":
                assert p.count == count["value"]
            elif p.kind == "counted":
                assert p.count_param == count["param"] and p.max_count == q["max_count"]
                assert p.count_param in [e.name for e in ps.params[: ps.params.index(p)]]
            elif p.kind == "union":
                assert p.selector == q["type"]["selector"] and p.members
            elif p.kind == "string":
                assert count is None and p.elem.length == q["type"]["length"]
    return kinds


def test_real_ir_every_parameter_is_classified():
    ir = json.loads((ROOT / "generated" / "ir.json").read_text())
    kinds = set()
    for proto in ir["protocols"]:
        kinds |= _check_against_ir(proto)
    assert kinds == set(model.KINDS)


def test_everything_fixture_is_classified():
    proto = load_spec(FIXTURE, root=FIXTURE)["protocols"][0]
    assert _check_against_ir(proto) == set(model.KINDS)


def test_type_order_declares_what_a_type_contains_before_it():
    # The rule: enums and bitfields first (IR order), then each struct or union after the structs
    # and unions it contains, depth first in IR order; primitives and enums are no dependency.
    def ref(kind, name):
        return {"type": {"kind": kind, "name": name}}

    types = [
        {
            "kind": "struct",
            "name": "Alpha",
            "params": [ref("primitive", "u8"), ref("union", "Choice"), ref("enum", "Mode")],
        },
        {"kind": "struct", "name": "Beta", "params": [ref("struct", "Gamma")]},
        {"kind": "union", "name": "Choice", "members": [{"type": "Gamma"}, {"type": None}]},
        {"kind": "struct", "name": "Gamma", "params": [ref("bitfield", "Flags")]},
        {"kind": "bitfield", "name": "Flags"},
        {"kind": "enum", "name": "Mode"},
    ]
    order = [t["name"] for t in model.type_order({"types": types})]
    assert order == ["Flags", "Mode", "Gamma", "Choice", "Alpha", "Beta"]
