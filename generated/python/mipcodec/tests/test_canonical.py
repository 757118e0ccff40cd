"""Canonical text (docs/conformance.md section 4) of mipcodec: the float, double and string
table of tests/canonical_cases.py (generated from generator/testcases.py) that the C, C++, Python
and Rust packages all check. Plain source, the same in every package
(generator/targets/python/runtime/package_tests/)."""

import math

from canonical_cases import ALL_BYTES, DOUBLES, FLOATS, canonical

f32_bits, f32_from_bits, f32_text = canonical.f32_bits, canonical.f32_from_bits, canonical.f32_text
f64_bits, f64_from_bits, f64_text = canonical.f64_bits, canonical.f64_from_bits, canonical.f64_text
float_from_json, loads, string_text = canonical.float_from_json, canonical.loads, canonical.string_text


def test_doubles_print_canonically_and_read_back():
    for bits, text in DOUBLES:
        assert f64_text(f64_from_bits(bits)) == text, f"bits 0x{bits:016x}"
        back = float_from_json(loads(text), 64)
        if text == '"nan"':
            assert math.isnan(back)
        else:
            assert f64_bits(back) == bits, text


def test_floats_print_canonically_and_read_back():
    for bits, text in FLOATS:
        assert f32_text(f32_from_bits(bits)) == text, f"bits 0x{bits:08x}"
        assert f32_bits(float_from_json(loads(text), 32)) == bits, text


def test_strings_escape_every_byte():
    assert string_text(bytes(range(256))) == ALL_BYTES
    assert loads(ALL_BYTES) == bytes(range(256)).decode("latin-1")
