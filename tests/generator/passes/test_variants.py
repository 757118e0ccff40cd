"""variants: each field's layouts (one per device with `variants:`), and the field's sources,
devices and the convenience copies of its first layout."""

from tiny_spec import build, command_set, errors

PER_DEVICE = """\
  - id: 0x01
    name: status
    role: command
    title: Status
    variants:
      - device: dev_a
        sources: [{manual: a.txt, line: 4, stated_length: 3}]
        params: [{name: x, type: u8}]
      - device: dev_b
        sources: [{manual: b.txt, line: 8}]
        params: [{name: x, type: u16}]
"""


def test_one_layout_per_device(tmp_path):
    ctx = build(tmp_path, {"base.yaml": command_set(PER_DEVICE)}, "variants")
    assert errors(ctx) == []
    (f,) = ctx.sets[0]["fields"]
    assert [(v["device"], v["devices"], v["size"]["max"]) for v in f["variants"]] == [
        ("dev_a", ["dev_a"], 1),
        ("dev_b", ["dev_b"], 2),
    ]
    assert f["devices"] == ["dev_a", "dev_b"]
    assert [s["line"] for s in f["sources"]] == [4, 8]
    # Convenience copies from the first layout; stated lengths from every source.
    assert f["params"] is f["variants"][0]["params"] and f["size"] == {"min": 1, "max": 1, "fixed": True}
    assert f["stated_lengths"] == [{"manual": "a.txt", "line": 4, "stated": 3}]


def test_a_variant_cites_its_own_device_and_devices_are_unique(tmp_path):
    spec = PER_DEVICE.replace("manual: a.txt, line: 4", "manual: b.txt, line: 4").replace(
        "device: dev_b", "device: dev_a"
    )
    assert errors(build(tmp_path, {"base.yaml": command_set(spec)}, "variants")) == [
        "base.yaml:12:17: error: base.status (dev_a): variant for device 'dev_a' cites only manuals of dev_b"
        " (expected sources from that device's manual)",
        "base.yaml:15:17: error: base.status: two variants for device 'dev_a' (expected one variant per device)",
        "base.yaml:15:17: error: base.status (dev_a): variant for device 'dev_a' cites only manuals of dev_b"
        " (expected sources from that device's manual)",
    ]


def test_functions_and_responses_are_checked_per_layout(tmp_path):
    field = (
        "  - {id: 0x01, name: cmd, role: command, title: C, sources: [{manual: a.txt, line: 4}],"
        " functions: [write], response: 0x81, params: []}\n"
    )
    ctx = build(tmp_path, {"base.yaml": command_set(field)}, "variants")
    assert errors(ctx) == []  # no function selector enum in the protocol: nothing to check names against
    (f,) = ctx.sets[0]["fields"]
    assert (f["functions"], f["responses"], f["response"]) == (["write"], [0x81], 0x81)
    assert f["size"] == {"min": 1, "max": 1, "fixed": True}  # the selector byte
