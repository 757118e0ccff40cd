"""sets: descriptor sets (merged from their parts) and their fields, before their layouts."""

from tiny_spec import build, command_set, data_set, errors


def _field(i: int, name: str, role: str = "command", extra: str = "") -> str:
    return (
        f"  - {{id: 0x{i:02X}, name: {name}, role: {role}, title: T, sources: [{{manual: a.txt, line: 4}}],"
        f" params: []{extra}}}\n"
    )


def test_sets_are_sorted_by_id_and_parts_merge(tmp_path):
    files = {
        "sensor.yaml": data_set(_field(0x04, "accel", "data")),
        "base.yaml": command_set(_field(0x01, "ping")),
        "base_more.yaml": command_set(_field(0x02, "reset")).replace("line: 2", "line: 9"),
    }
    ctx = build(tmp_path, files, "sets")
    assert errors(ctx) == []
    assert [(s["id"], s["name"]) for s in ctx.sets] == [(0x01, "base"), (0x80, "sensor")]
    base = ctx.sets[0]
    assert [f["name"] for f in base["fields"]] == ["ping", "reset"]
    assert [s["line"] for s in base["sources"]] == [2, 9]
    # Layouts come later (the variants pass); the field remembers its spec entry until then.
    assert base["fields"][0]["variants"] is None and base["fields"][0]["_sf"].path == "base.yaml"


def test_descriptors_and_names_are_unique_within_a_set(tmp_path):
    fields = _field(0x01, "ping") + _field(0x01, "ping")
    ctx = build(tmp_path, {"base.yaml": command_set(fields)}, "sets")
    assert errors(ctx) == [
        "base.yaml:8:10: error: base: descriptor 0x01 is used by both 'ping' and 'ping' (the first at base.yaml:7:10)"
        " (expected unique descriptors within a set)",
        "base.yaml:8:22: error: base: two fields named 'ping' (expected unique field names within a set)",
    ]


def test_roles_fit_the_set_kind_and_sets_fit_their_range(tmp_path):
    files = {
        "base.yaml": command_set(_field(0x01, "reading", "data")),
        "sensor.yaml": data_set(_field(0x04, "accel", "data"), set_id=0x20),
    }
    assert errors(build(tmp_path, files, "sets")) == [
        "base.yaml:7:37: error: base.reading: role data in a command set"
        " (expected command/response in command sets, data in data sets)",
        "sensor.yaml:1:6: error: data set 0x20 is outside the data range (expected 0x80..0xFF)",
    ]


def test_only_shared_data_fields_identify_a_sample(tmp_path):
    ctx = build(tmp_path, {"sensor.yaml": data_set(_field(0x04, "time", "data", ", sample_timestamp: true"))}, "sets")
    assert errors(ctx) == [
        "sensor.yaml:7:117: error: sensor.time: only a shared data field can identify a sample"
        " (expected sample_timestamp only in the shared data set)"
    ]
