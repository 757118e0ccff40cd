"""field_layouts: each shared field layout once, with the fields that use it; an unused one is an error."""

from tiny_spec import build, data_set, errors

LAYOUT = (
    "field_layouts:\n  - name: Pos\n    title: Position\n    params: [{name: x, type: float}, {name: y, type: float}]\n"
)


def _user(i: int, name: str) -> str:
    return f"  - {{id: 0x{i:02X}, name: {name}, role: data, title: T, sources: [{{manual: a.txt, line: 4}}], layout: Pos}}\n"


def test_a_layout_lists_its_users(tmp_path):
    files = {
        "a.yaml": data_set(_user(0x01, "pos"), LAYOUT),
        "b.yaml": data_set(_user(0x02, "pos2"), set_id=0x81, name="other"),
    }
    ctx = build(tmp_path, files, "field_layouts")
    assert errors(ctx) == []
    (pos,) = ctx.layouts
    assert (pos["name"], pos["title"], pos["size"]) == ("Pos", "Position", {"min": 8, "max": 8, "fixed": True})
    assert pos["used_by"] == [
        {"set": 0x80, "field": 0x01, "name": "sensor.pos", "device": None},
        {"set": 0x81, "field": 0x02, "name": "other.pos2", "device": None},
    ]
    # Users share the layout's parameters.
    assert ctx.sets[0]["fields"][0]["params"] == pos["params"]


def test_an_unused_layout_is_an_error(tmp_path):
    field = "  - {id: 0x01, name: n, role: data, title: T, sources: [{manual: a.txt, line: 4}], params: []}\n"
    ctx = build(tmp_path, {"a.yaml": data_set(field, LAYOUT)}, "field_layouts")
    assert errors(ctx) == [
        "a.yaml:7:11: error: field layout 'Pos' is not used by any field (expected layout: <name> on a field)"
    ]
    assert ctx.layouts == []
