"""JSON Schemas of the data fields as JSON messages (the MCAP export's `<protocol>/<set>/<field>`
topics; docs/mcap.md), computed from the IR alone (the same columns as generator/columns.py).

A field's JSON message is an object: `t_ns` (UTC ns, null when unknown), `log_offset` (the
packet's offset in the log), then the field's values nested as its column paths are (a parameter, an
element of a fixed array, a member of a struct): `scaled_accel` is `[x, y, z]`,
`gps_timestamp` is `{"tow": .., "week_number": .., "valid_flags": ..}`. The leaves are the CSV
export's cells: numbers (null for NaN or infinity, which JSON cannot hold), integers, booleans,
enum names (or the number of a value the spec does not name), and the values without a fixed
shape as JSON. Every leaf's schema has the parameter's description with its units, and `units`.
"""

from __future__ import annotations

import json

from generator import columns

DRAFT = "http://json-schema.org/draft-07/schema#"
ENVELOPE = ("t_ns", "log_offset")  # the message's own keys before the field's parameters


def _leaf(c: columns.Column, enums: dict) -> dict:
    out: dict
    if c.kind in ("float32", "float64"):
        out = {"type": ["number", "null"]}
    elif c.kind in ("int", "bits"):
        out = {"type": ["integer", "null"]}
    elif c.kind == "bool":
        out = {"type": ["boolean", "null"]}
    elif c.kind == "enum":
        names = sorted(set(enums.get(c.enum, {}).values()))
        out = {"anyOf": [{"enum": names}, {"type": "integer"}, {"type": "null"}]}
    else:
        out = {}
    text = c.description + (f" [{c.units}]" if c.units else "")
    if text:
        out["description"] = text
    if c.units:
        out["units"] = c.units
    if c.frame:
        out["frame"] = c.frame
    return out


def _insert(tree: dict, path: tuple, leaf: dict) -> None:
    node = tree
    for step in path[:-1]:
        node = node.setdefault(step, {})
    node[path[-1]] = leaf


def _render(node) -> dict:
    if not isinstance(node, dict) or "\0leaf" in node:
        return node["\0leaf"]
    keys = list(node)
    if keys and all(isinstance(k, int) for k in keys):
        return {"type": "array", "items": _render(node[keys[0]]), "minItems": len(keys), "maxItems": len(keys)}
    return {
        "type": "object",
        "properties": {k: _render(v) for k, v in node.items()},
        "required": list(node),
        "additionalProperties": False,
    }


def layout_schema(proto: dict, field: dict, variant: dict, set_name: str, attr=lambda name: name) -> dict:
    """The JSON Schema of one data field layout's messages (parameter names through `attr`, the
    back end's attribute naming, which the runtime's column paths use)."""
    enums = columns.enums(proto)
    tree: dict = {}
    for c in columns.layout_columns(proto, field, variant):
        path = tuple(x if isinstance(x, int) else attr(x) for x in c.path)
        _insert(tree, path, {"\0leaf": _leaf(c, enums)})
    body = _render(tree)
    clash = set(body["properties"]) & set(ENVELOPE)
    if clash:
        raise ValueError(
            f"{set_name}.{field['name']}: parameter {sorted(clash)[0]!r} is a key of the message's envelope"
        )
    device = f" ({variant['device']})" if variant.get("device") else ""
    schema = {
        "$schema": DRAFT,
        "title": f"{proto['name']}.{set_name}.{field['name']}{device}: {field['title']}",
        "description": " ".join((field.get("description") or field["title"]).split()),
        "type": "object",
        "properties": {
            "t_ns": {
                "type": ["integer", "null"],
                "description": "UTC time of the packet in ns since the Unix epoch (the time model); null when unknown",
                "units": "ns",
            },
            "log_offset": {"type": "integer", "description": "the packet's offset in the log [bytes]"},
            **body["properties"],
        },
        "required": ["t_ns", "log_offset", *body["required"]],
        "additionalProperties": False,
    }
    return schema


def schemas(proto: dict, attr=lambda name: name) -> list[tuple[int, int, str | None, str]]:
    """(set id, descriptor, device, schema JSON text) of every data field layout."""
    out = []
    for s, f, v in columns.data_layouts(proto):
        text = json.dumps(layout_schema(proto, f, v, s["name"], attr), sort_keys=True, separators=(",", ":"))
        out.append((s["id"], f["id"], v.get("device"), text))
    return out
