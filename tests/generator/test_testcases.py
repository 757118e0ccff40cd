"""generator/testcases.py: the language-neutral test cases every back end renders."""

import math
import struct
from pathlib import Path

from generator.canonical import float_text
from generator.spec import load_spec
from generator.testcases import (
    EnumValue,
    Flags,
    Sampler,
    StructValue,
    bitfield_cases,
    canonical_cases,
    layout_error_cases,
    layout_sample,
    layouts,
    stable_seed,
    struct_sample,
    vector_cases,
)

FIXTURE = Path(__file__).parent / "fixtures" / "everything"


def _proto():
    return load_spec(FIXTURE, root=FIXTURE)["protocols"][0]


def _layout(p, set_name, field_name, device=None):
    return next(v for s, f, v in layouts(p) if s and s["name"] == set_name and f["name"] == field_name
                and v["device"] == device)  # fmt: skip


# ------------------------------------------------------------------------------ vectors
def test_vector_cases_keep_one_protocol_and_say_where_they_come_from():
    vectors = [
        {"protocol": "a", "name": "x", "corpus": "vectors", "hex": "01", "device": None, "rejected": False,
         "expect": ["{}"], "file": "tests/vectors/a.yaml", "line": 3},
        {"protocol": "b", "name": "y", "corpus": "vectors", "hex": "02", "device": None, "rejected": False,
         "expect": [], "file": "tests/vectors/b.yaml", "line": 1},
        {"protocol": "a", "name": "z", "corpus": "streams", "hex": "", "device": "dev", "rejected": True,
         "expect": [], "file": "tests/streams/a.yaml", "line": 9},
    ]  # fmt: skip
    cases = vector_cases(vectors, {"name": "a"})
    assert [c.name for c in cases] == ["x", "z"]
    assert cases[0].source == "tests/vectors/a.yaml:3" and cases[0].expect == ("{}",)
    assert cases[1].corpus == "streams" and cases[1].device == "dev" and cases[1].rejected is True


# ------------------------------------------------------------------------------ canonical floats
def test_canonical_cases_are_the_reference_text_of_every_case():
    cases = canonical_cases()
    assert len(cases.doubles) == 26 + 6 + 300 and len(cases.floats) == 9 + 7 + 300
    for c in cases.doubles:
        assert c.text == float_text(struct.unpack(">d", struct.pack(">Q", c.bits))[0], c.bits)
    for c in cases.floats:
        assert c.text == float_text(struct.unpack(">f", struct.pack(">I", c.bits))[0], c.bits, single=True)
    by_bits = {c.bits: c.text for c in cases.doubles}
    assert by_bits[0x8000000000000000] == "-0.0"
    assert by_bits[struct.unpack(">Q", struct.pack(">d", 1e16))[0]] == "1e+16"
    assert by_bits[0x7FF8000000000000] == '"nan"'
    assert by_bits[0xFFF8000000000000] == '"nan:0xfff8000000000000"'
    assert by_bits[0xFFF0000000000000] == '"-inf"'
    assert {c.bits: c.text for c in cases.floats}[0x7FA00000] == '"nan:0x7fa00000"'


def test_canonical_cases_do_not_change_from_run_to_run():
    assert canonical_cases() == canonical_cases()


def test_all_bytes_escapes_controls_quote_backslash_and_high_bytes():
    text = canonical_cases().all_bytes
    assert text.startswith('"\\u0000\\u0001') and text.endswith('\\u00fe\\u00ff"')
    assert ' !\\"#' in text and "[\\\\]" in text and "}~\\u007f" in text
    assert text.count("\\u") == 32 + 1 + 128  # controls, DEL, bytes 0x80..0xFF


# ------------------------------------------------------------------------------ bitfields
def test_bitfield_cases_list_every_member_with_its_bits():
    (flags,) = bitfield_cases(_proto())
    assert flags.name == "Flags" and flags.base == "u16"
    by = {m.name: m for m in flags.members}
    assert by["ok"].flag and (by["ok"].mask, by["ok"].max, by["ok"].raw) == (1, 1, 1)
    assert not by["level"].flag
    assert (by["level"].first_bit, by["level"].width, by["level"].max, by["level"].raw) == (12, 4, 15, 0xF000)
    assert by["level"].raw == by["level"].mask
    assert flags.wide_member().name == "level" and flags.first_flag().name == "ok"


def test_a_64_bit_member_writes_one():
    proto = {
        "types": [
            {"kind": "bitfield", "name": "Wide", "base": "u64",
             "members": [{"name": "all", "first_bit": 0, "width": 64, "mask": (1 << 64) - 1}]},
        ]
    }  # fmt: skip
    (case,) = bitfield_cases(proto)
    (m,) = case.members
    assert m.max == (1 << 64) - 1 and (m.value, m.raw) == (1, 1)
    assert case.first_flag() is None and case.wide_member() is m


# ------------------------------------------------------------------------------ fixed-layout errors
def test_layout_error_cases_name_the_first_value_read():
    p = _proto()
    cases = layout_error_cases(p)
    assert [(c.set, c.field, c.layout) for c in cases] == list(layouts(p))
    by = {(c.field["name"], c.layout["device"]): c for c in cases}
    # a function selector is read first
    assert by[("configure", None)].empty == "function: needs 1 bytes at offset 0, 0 left"
    # a fixed array names its first element
    assert by[("sample", None)].empty == "quat[0]: needs 4 bytes at offset 0, 0 left"
    # a layout of fixed-size values: one byte too many is an error at the end
    assert by[("per_device", "dev_b")].extra_len == 10
    assert by[("per_device", "dev_b")].extra == "1 unexpected bytes at offset 9"
    # a counted array makes the length variable: no extra-byte case, zero value not round-trip safe
    conf = by[("configuration", None)]
    assert conf.extra_len is None and conf.extra is None and not conf.zero_safe
    # the reserved ack is listed without a set
    assert by[("ack", None)].set is None


def test_an_optional_first_parameter_decodes_from_nothing():
    proto = {
        "types": [],
        "framing": {"max_field_data": 253},
        "sets": [{"name": "s", "fields": [{"name": "f", "variants": [{
            "device": None, "functions": None, "size": {"min": 0, "max": 1, "fixed": False},
            "params": [{"name": "x", "optional": True, "count": None, "size": {"min": 1, "max": 1, "fixed": True},
                        "type": {"kind": "primitive", "name": "u8", "size": {"min": 1, "max": 1, "fixed": True}}}],
        }]}]}],
        "reserved_fields": [],
    }  # fmt: skip
    (case,) = layout_error_cases(proto)
    assert case.empty == "" and case.zero_safe


# ------------------------------------------------------------------------------ typed samples
def test_samples_fill_counts_selectors_and_unions_consistently():
    p = _proto()
    args = dict(Sampler(p).layout(_layout(p, "commands", "configure")["params"], ["write", "read", "save"]))
    # the last function (the one with every optional parameter), the union's first member with data
    assert args["function"] == EnumValue("Function", "save")
    assert isinstance(args["mode"], EnumValue) and args["mode"].type == "Mode"
    assert isinstance(args["params"], StructValue) and args["params"].type == "GpioParams"
    conf = dict(Sampler(p).layout(_layout(p, "commands", "configuration")["params"], None))
    assert conf["count"] == 2 and len(conf["rates"]) == 2  # the count parameter says how many
    assert len(conf["matrix"]) == 9 and len(conf["fixed"]) == 4
    assert conf["name"][:3].isalpha() and conf["name"][3:] == b"\x00" * 5  # nul padding
    assert conf["label"][3:] == b" " * 13  # space padding
    assert isinstance(conf["flags"], Flags) and conf["flags"].mask in (0x1, 0xF000, 0xFFFF)


def test_sample_values_are_in_range_and_vary():
    p = _proto()
    sampler = Sampler(p)
    values = [v for _, _, lay in layouts(p) for _, v in sampler.layout(lay["params"], lay["functions"])]
    ints = [v for v in values if type(v) is int]
    assert len(set(ints)) > len(ints) // 2
    sample = dict(Sampler(p).layout(_layout(p, "data", "sample")["params"], None))
    assert all(struct.unpack(">f", struct.pack(">f", x))[0] == x for x in sample["quat"])  # exact in binary32
    assert -128 <= sample["small"] <= 127 and not math.isnan(sample["f"])


def test_a_fields_samples_depend_on_that_field_alone():
    p = _proto()
    before = {(s and s["id"], f["name"], v["device"]): layout_sample(p, s, f, v) for s, f, v in layouts(p)}
    structs = {t["name"]: struct_sample(p, t) for t in p["types"] if t["kind"] == "struct"}
    # drop the first field of the commands set: every other field keeps its values
    commands = next(s for s in p["sets"] if s["name"] == "commands")
    dropped = commands["fields"].pop(0)
    after = {(s and s["id"], f["name"], v["device"]): layout_sample(p, s, f, v) for s, f, v in layouts(p)}
    assert (commands["id"], dropped["name"], None) not in after
    assert after == {k: v for k, v in before.items() if k != (commands["id"], dropped["name"], None)}
    assert structs == {t["name"]: struct_sample(p, t) for t in p["types"] if t["kind"] == "struct"}


def test_fields_with_the_same_shape_get_different_values():
    p = _proto()
    (a, fa, va), (b, fb, vb) = [(s, f, v) for s, f, v in layouts(p) if f["name"] == "llh_position"]
    assert a["id"] != b["id"] and layout_sample(p, a, fa, va) != layout_sample(p, b, fb, vb)


def test_stable_seed_is_a_fixed_function_of_its_parts():
    assert stable_seed("mip", 0x80, 0x04, "scaled_accel", None) == stable_seed("mip", 128, 4, "scaled_accel", None)
    assert stable_seed("mip", 0x80, 0x04) != stable_seed("mip", 0x80, 0x05)
    assert stable_seed("a", "b") == 0xC14CDDC0
