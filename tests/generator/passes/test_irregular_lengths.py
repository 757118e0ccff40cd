"""irregular_lengths: fields with length_byte_adjust (MS-CIP) are listed in the framing, and their
size byte must stay within 0..255."""

from tiny_spec import build, data_set, errors


def _field(adjust: int, params: str = "[{name: x, type: u8}]") -> str:
    return (
        "  - {id: 0x05, name: odd, role: data, title: O, sources: [{manual: a.txt, line: 4}],"
        f" length_byte_adjust: {adjust}, params: {params}}}\n"
    )


def test_adjusted_fields_are_listed_in_the_framing(tmp_path):
    ctx = build(tmp_path, {"sensor.yaml": data_set(_field(-1))}, "irregular_lengths")
    assert errors(ctx) == []
    assert ctx.framing["irregular_lengths"] == [{"set": 0x80, "descriptor": 0x05, "adjust": -1}]


def test_the_size_byte_must_stay_in_range(tmp_path):
    ctx = build(tmp_path, {"sensor.yaml": data_set(_field(-4, "[]"))}, "irregular_lengths")
    assert errors(ctx) == [
        "sensor.yaml:7:106: error: sensor.odd: with length_byte_adjust -4 the size byte would be -2..-2"
        " (expected one layout whose size byte stays within 0..255)"
    ]
