"""size_limits: every layout's largest encoding fits one field of the protocol (issue 28): MIP
carries at most 253 bytes of field data, a protocol whose length byte counts only the data (MS-CIP)
what its max_payload leaves beside the field header."""

from tiny_spec import PROTOCOL, build, command_set, data_set, errors


def _field(fid: int, name: str, params: str, role: str = "data", extra: str = "") -> str:
    """One field, six lines (seven with extra): its params at column 13 of the last line."""
    return (
        f"  - id: 0x{fid:02X}\n    name: {name}\n    role: {role}\n    title: T\n"
        f"    sources: [{{manual: a.txt, line: 4}}]\n{extra}    params: {params}\n"
    )


MIP_LIMIT = (
    "at most 253 bytes of field data: a payload holds at most 255 bytes, 2 of them the field header,"
    " and the length byte (at most 255) counts the header too"
)


def _error(line: int, what: str, limit: str = MIP_LIMIT, file: str = "a.yaml", col: int = 13) -> str:
    return f"{file}:{line}:{col}: error: {what}, more than one field can carry (expected {limit})"


def test_largest_layouts_that_fit_pass(tmp_path):
    fields = _field(1, "full", "[{name: a, type: u8, count: 253}]") + _field(
        2, "counted", "[{name: n, type: u8}, {name: xs, type: u16, count: n}]"
    )
    ctx = build(tmp_path, {"a.yaml": data_set(fields)}, "size_limits")
    assert errors(ctx) == []
    # The counted array's default capacity fills the field: 1 + 2 * 126 = 253.
    assert [f["size"]["max"] for f in ctx.sets[0]["fields"]] == [253, 253]


def test_arrays_strings_and_matrices_too_large_for_a_field(tmp_path):
    mats = ", ".join(f"{{name: m{i}, type: matrix3d}}" for i in range(1, 5))
    fields = (
        _field(1, "big", "[{name: a, type: u8, count: 300}]")
        + _field(2, "text", "[{name: s, type: string, length: 300}]")
        + _field(3, "mats", f"[{mats}]")
        + _field(4, "counted", "[{name: n, type: u16}, {name: xs, type: u32, count: n, max_count: 100}]")
        + _field(5, "huge", "[{name: a, type: double, count: 1000000000000}]")
    )
    assert errors(build(tmp_path, {"a.yaml": data_set(fields)}, "size_limits")) == [
        _error(12, "sensor.big: the largest encoding is 300 bytes of field data (a 300)"),
        _error(18, "sensor.text: the largest encoding is 300 bytes of field data (s 300)"),
        _error(24, "sensor.mats: the largest encoding is 288 bytes of field data (m1 72, m2 72, m3 72, m4 72)"),
        _error(30, "sensor.counted: the largest encoding is 402 bytes of field data (n 2, xs 400)"),
        _error(36, "sensor.huge: the largest encoding is 8000000000000 bytes of field data (a 8000000000000)"),
    ]


def test_the_function_selector_byte_counts(tmp_path):
    fields = _field(
        1, "cmd", "[{name: a, type: u8, count: 253, functions: [write]}]", "command", "    functions: [write]\n"
    )
    assert errors(build(tmp_path, {"a.yaml": command_set(fields)}, "size_limits")) == [
        _error(13, "base.cmd: the largest encoding is 254 bytes of field data (function selector 1, a 253)"),
    ]


def test_structs_and_device_variants_and_shared_layouts(tmp_path):
    types = (
        "structs:\n  - {name: Block, title: B, params: [{name: x, type: float, count: 40}]}\n"
        "field_layouts:\n  - name: Two\n    title: Two blocks\n"
        "    params: [{name: a, type: Block}, {name: b, type: Block}]\n"
    )
    fields = (
        "  - id: 0x01\n    name: per_device\n    role: data\n    title: T\n    variants:\n"
        "      - device: dev_a\n        sources: [{manual: a.txt, line: 4}]\n        params: [{name: a, type: Block}]\n"
        "      - device: dev_b\n        sources: [{manual: b.txt, line: 4}]\n"
        "        params: [{name: a, type: Block}, {name: b, type: Block}]\n"
        "  - {id: 0x02, name: shared, role: data, title: T, sources: [{manual: a.txt, line: 4}], layout: Two}\n"
    )
    assert errors(build(tmp_path, {"a.yaml": data_set(fields, types)}, "size_limits")) == [
        _error(23, "sensor.per_device (dev_b): the largest encoding is 320 bytes of field data (a 160, b 160)", col=17),
        _error(24, "sensor.shared: the largest encoding is 320 bytes of field data (a 160, b 160)", col=97),
    ]


def test_a_protocol_whose_length_byte_counts_only_data_has_its_own_limit(tmp_path):
    protocol = PROTOCOL.replace("field_length_counts_header: true", "field_length_counts_header: false").replace(
        "max_payload: 255", "max_payload: 100"
    )
    fields = _field(1, "fits", "[{name: a, type: u8, count: 98}]") + _field(
        2, "over", "[{name: a, type: u8, count: 99}]"
    )
    limit = "at most 98 bytes of field data: a payload holds at most 100 bytes, 2 of them the field header"
    assert errors(build(tmp_path, {"protocol.yaml": protocol, "a.yaml": data_set(fields)}, "size_limits")) == [
        _error(18, "sensor.over: the largest encoding is 99 bytes of field data (a 99)", limit),
    ]


def test_reserved_fields_are_checked_in_the_protocol_file(tmp_path):
    protocol = PROTOCOL + (
        "reserved_fields:\n  - id: 0xF1\n    name: ack\n    title: Ack\n    role: ack\n    applies_to: command\n"
        "    sources: [{manual: a.txt, line: 5}]\n    params: [{name: junk, type: u8, count: 260}]\n"
    )
    errs = errors(build(tmp_path, {"protocol.yaml": protocol}, "size_limits"))
    assert errs == [
        _error(
            26, "reserved field ack: the largest encoding is 260 bytes of field data (junk 260)", file="protocol.yaml"
        )
    ]


def test_an_elastic_array_counts_with_its_smallest_size(tmp_path):
    # Without max_count, an array takes what the others leave (here 253 - 200 - 1 = 52 u8s): the
    # layout fits. Two elastic arrays may each fill the field alone; the encoder checks the total.
    fields = _field(1, "ok", "[{name: a, type: u8, count: 200}, {name: n, type: u8}, {name: t, type: u8, count: n}]")
    fields += _field(
        2, "two", "[{name: n, type: u8}, {name: a, type: u8, count: n}, {name: b, type: u8, count: remaining}]"
    )
    fields += _field(
        3, "over", "[{name: a, type: u8, count: 250}, {name: n, type: u32}, {name: t, type: u8, count: n}]"
    )
    ctx = build(tmp_path, {"a.yaml": data_set(fields)}, "size_limits")
    assert errors(ctx) == [
        _error(24, "sensor.over: the largest encoding is 254 bytes of field data (a 250, n 4, t 0+ (elastic))"),
    ]
    assert [q["max_count"] for q in ctx.sets[0]["fields"][0]["params"]] == [None, None, 52]
