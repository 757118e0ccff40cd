"""examples.typed_field_example: the field the Rust crate documentation decodes in its typed,
firmware-ready example (issue 39 item 8)."""

from __future__ import annotations

import copy

from generator import examples
from generator.spec import load_spec


def _protocol(name: str) -> dict:
    return next(p for p in load_spec()["protocols"] if p["name"] == name)


def test_the_first_fixed_size_data_field_of_the_lowest_data_set():
    # MIP: the sensor set 0x80 is the lowest data set; its first field in spec order is fixed-size.
    s, f = examples.typed_field_example(_protocol("mip"))
    assert s["id"] == min(x["id"] for x in _protocol("mip")["sets"] if x["kind"] == "data")
    assert f["role"] == "data" and f["variants"][0]["size"]["fixed"]
    assert f is next(x for x in s["fields"] if x["role"] == "data")


def test_fields_with_per_device_layouts_or_variable_size_are_passed_over():
    p = copy.deepcopy(_protocol("mip"))
    s, first = examples.typed_field_example(p)
    first["variants"].append(copy.deepcopy(first["variants"][0]))
    s2, second = examples.typed_field_example(p)
    assert second is not first and second["id"] != first["id"]
    second["variants"][0]["size"] = {"min": 0, "max": 40, "fixed": False}
    _, third = examples.typed_field_example(p)
    assert third["id"] not in (first["id"], second["id"])


def test_no_data_set_no_example():
    p = copy.deepcopy(_protocol("mip"))
    p["sets"] = [s for s in p["sets"] if s["kind"] != "data"]
    assert examples.typed_field_example(p) is None
