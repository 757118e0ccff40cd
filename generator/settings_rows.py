"""The settings of the device command lines, language-neutral (docs/configure-a-device.md): which
commands are settings, the parameters a file entry holds, their keyed reads and the largest size of
every data field (the link budget). One derivation from the IR for every wing: the Python back end
renders it as `_settings.py` and `settings.schema.json`, the C back end as the device tool's tables
(`tools/device_facts.h`).

A setting is a command layout with the write and read functions that the spec's `settings` section
does not exclude and whose read has a reply. Names are the spec's (each wing maps them).
"""

from __future__ import annotations

import json

from generator import model
from generator.primitives import PRIMITIVES


def setting_rows(proto: dict, sets: list[dict]) -> tuple[list[dict], dict[str, dict]]:
    """(rows, sizes): one row per settings command layout, in the spec's order, and per device
    {(set, descriptor): largest data size without header} of every data field.

    A row: set (the IR set), field, variant, dev (the layout's device when the field has several
    layouts, else None), reply_field, reply_variant, reply_dev (likewise), keyed (the parameter
    names its read sends), attrs [(param, reply param, units, param dict)] the file entry holds,
    counts {count param: list param} set from the lists, fill [(param, is list)] written but not
    read back (sent as zero), held (the param dicts of attrs), keys {device: [{param: value}]} the
    key combinations read (the spec's `settings: keys`; [{}] when not keyed)."""
    spec = proto.get("settings") or {"not_settings": [], "keys": []}
    excluded = {e["command"] for e in spec["not_settings"]}
    fsel = (proto.get("function_selector") or {}).get("enum")
    sizes: dict[str, dict] = {d["id"]: {} for d in proto["devices"]}
    rows: list[dict] = []
    for s in sets:
        by_id = {f["id"]: f for f in s["fields"]}
        for f, v, dev in model.layouts_of(s["fields"]):
            if s["kind"] == "data" and f["role"] == "data":
                for d in v["devices"]:
                    sizes[d][(s["id"], f["id"])] = v["size"]["max"]
                continue
            fns = v["functions"] or []
            if f["role"] != "command" or f["name"] in excluded or "read" not in fns or "write" not in fns:
                continue
            reply = next((r for r in v["responses"] if (r.get("when") or {}).get("function") == "read"), None)
            if reply is None:
                continue
            rf = by_id[reply["id"]]
            rvariant, rdev = next(
                (rv, model.layout_device(rf, rv)) for rv in rf["variants"] if set(rv["devices"]) & set(v["devices"])
            )
            params = [q for q in v["params"] if q["type"].get("name") != fsel]
            written = [q for q in params if "write" in (q["functions"] or [])]
            counts = {q["count"]["param"]: q["name"] for q in written if (q.get("count") or {}).get("kind") == "param"}
            rparams = [q["name"] for q in rvariant["params"]]
            attrs = []
            held_names: set[str] = set()
            for i, q in enumerate(written):
                if q["name"] in counts:
                    continue
                # the reply's parameter of that name, else of that place when the lists match in length
                # (data_stream_control: enable -> enabled); else none: not read back, not in a file
                same = len(rparams) == len(written)
                r = q["name"] if q["name"] in rparams else (rparams[i] if same else None)
                if r is None:
                    continue
                attrs.append((q["name"], r, q.get("units"), q))
                held_names.add(q["name"])
            keyed = [q["name"] for q in params if not q["optional"] and "read" in (q["functions"] or [])]
            fill = [
                (q["name"], bool(q.get("count")))
                for q in written
                if q["name"] not in held_names and q["name"] not in counts
            ]
            keys: dict[str, list[dict]] = {}
            for d in v["devices"]:
                keys[d] = [{}]
                if keyed:
                    entry = next(
                        (
                            k
                            for k in spec["keys"]
                            if k["command"] == f["name"] and set(k["values"]) == set(keyed) and d in k["resolved"]
                        ),
                        None,
                    )
                    keys[d] = [dict(combo) for combo in entry["resolved"][d]] if entry else []
            rows.append(
                {
                    "set": s,
                    "field": f,
                    "variant": v,
                    "dev": dev,
                    "reply_field": rf,
                    "reply_variant": rvariant,
                    "reply_dev": rdev,
                    "keyed": keyed,
                    "attrs": attrs,
                    "counts": counts,
                    "fill": fill,
                    "held": [q for q in written if q["name"] in held_names],
                    "keys": keys,
                }
            )
    return rows, sizes


# ------------------------------------------------------------------------------ the file's schema
def _value_schema(types: dict, q: dict) -> dict:
    """The JSON Schema of one parameter's value in a settings file (runtime settings.py)."""
    t = q["type"]
    kind = t["kind"]
    if kind == "primitive":
        size, k, signed = PRIMITIVES[t["name"]]
        if k == "int":
            lo, hi = (-(1 << (size * 8 - 1)), (1 << (size * 8 - 1)) - 1) if signed else (0, (1 << (size * 8)) - 1)
            one: dict = {"type": "integer", "minimum": lo, "maximum": hi}
        elif k == "float":
            one = {"type": "number"}
        elif k == "bool":
            one = {"type": "boolean"}
        else:
            one = {"type": "string", "maxLength": 1}
    elif kind == "enum":
        names = [v["name"] for v in types[t["name"]]["values"]]
        one = {"anyOf": [{"enum": names}, {"type": "integer", "minimum": 0}]}
    elif kind == "bitfield":
        one = {"type": "integer", "minimum": 0}
    elif kind == "string":
        one = {"type": "string", "maxLength": t.get("length", 0)}
    elif kind == "struct":
        members = list(types[t["name"]]["params"])
        one = {
            "type": "object",
            "additionalProperties": False,
            "properties": {p["name"]: _value_schema(types, p) for p in members},
        }
    else:  # a union: its canonical JSON form (docs/conformance.md section 5)
        one = {"type": ["object", "null"]}
    count = q.get("count")
    if count is not None:
        arr: dict = {"type": "array", "items": one}
        if count.get("kind") == "fixed":
            arr["minItems"] = arr["maxItems"] = count["value"]
        elif q.get("max_count"):
            arr["maxItems"] = q["max_count"]
        one = arr
    desc = q.get("description") or ""
    if q.get("units"):
        desc = f"{desc} [{q['units']}]".strip()
    return {**one, "description": desc} if desc else one


def settings_schema(proto: dict, package: str, rows: list[dict]) -> str:
    """The settings file format as a JSON Schema (settings.schema.json, docs/configure-a-device.md):
    per setting of `rows` (setting_rows) an object of the parameters a file entry holds, a list of
    them when the setting is read per key."""
    types = {t["name"]: t for t in proto["types"]}
    props: dict[str, list[dict]] = {}
    for r in rows:
        f, v, held, keyed = r["field"], r["variant"], r["held"], r["keyed"]
        obj = {
            "type": "object",
            "additionalProperties": False,
            "properties": {q["name"]: _value_schema(types, q) for q in held},
            "required": [q["name"] for q in held if q["name"] in keyed],
        }
        if not obj["required"]:
            del obj["required"]
        one = {"type": "array", "items": obj} if keyed else obj
        title = f"{f['title']} (0x{r['set']['id']:02X},0x{f['id']:02X}); {', '.join(v['devices'])}"
        props.setdefault(f["name"], []).append({**one, "description": title})
    schema = {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": f"{package}-settings.schema.json",
        "title": f"{proto['title']} settings file ({package}-device settings dump|apply|diff)",
        "description": "Keyed by command name; each value the parameters of its write (enum members by name, "
        "numbers in the units of the description); a setting read per key parameter is a list of entries. "
        "Generated from the spec: do not edit.",
        "type": "object",
        "additionalProperties": False,
        "properties": {
            "device": {"type": "string", "description": "The model the file was dumped from (informative)."},
            **{name: (alts[0] if len(alts) == 1 else {"anyOf": alts}) for name, alts in sorted(props.items())},
        },
    }
    return json.dumps(schema, indent=2) + "\n"
