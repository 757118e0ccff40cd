"""sample_rule: the sample-grouping rule (docs/conformance.md section 6) derived from the spec."""

from tiny_spec import PROTOCOL, build, data_set, errors

SHARED = PROTOCOL + "shared_data: {set: 0xFF, first_descriptor: 0xD0}\n"


def _stamp(i: int, name: str, params: str) -> str:
    return (
        f"  - {{id: 0x{i:02X}, name: {name}, role: data, title: T, sources: [{{manual: a.txt, line: 4}}],"
        f" sample_timestamp: true, params: {params}}}\n"
    )


def _files(stamps: str) -> dict:
    accel = "  - {id: 0x04, name: accel, role: data, title: A, sources: [{manual: a.txt, line: 5}], params: []}\n"
    return {
        "protocol.yaml": SHARED,
        "sensor.yaml": data_set(accel),
        "shared.yaml": data_set(stamps, set_id=0xFF, name="shared"),
    }


def test_timestamps_and_the_largest_key(tmp_path):
    stamps = _stamp(0xD3, "gps_time", "[{name: tow, type: double}, {name: week, type: u16}]") + _stamp(
        0xD5, "ref_time", "[{name: ns, type: u64}]"
    )
    ctx = build(tmp_path, _files(stamps), "sample_rule")
    assert errors(ctx) == []
    assert ctx.samples == {
        "data_sets": [0x80],  # the shared set itself is not a data set that groups samples
        "first_shared": 0xD0,
        "timestamps": [{"descriptor": 0xD3, "size": 10}, {"descriptor": 0xD5, "size": 8}],
        "max_key": (2 + 10) + (2 + 8),
    }


def test_a_timestamp_needs_a_fixed_size(tmp_path):
    stamps = _stamp(0xD3, "gps_time", "[{name: n, type: u8}, {name: v, type: u8, count: n}]")
    ctx = build(tmp_path, _files(stamps), "sample_rule")
    assert errors(ctx) == [
        "shared.yaml:7:109: error: shared.gps_time: a sample timestamp needs one fixed-size layout"
        " (expected fixed-size parameters, no variants)"
    ]
    assert ctx.samples["timestamps"] == []


def test_a_protocol_without_shared_data_has_no_sample_keys(tmp_path):
    accel = "  - {id: 0x04, name: accel, role: data, title: A, sources: [{manual: a.txt, line: 5}], params: []}\n"
    ctx = build(tmp_path, {"sensor.yaml": data_set(accel)}, "sample_rule")
    assert ctx.samples == {"data_sets": [], "first_shared": 256, "timestamps": [], "max_key": 0}
