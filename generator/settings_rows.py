"""The settings of the device command lines, language-neutral (docs/configure-a-device.md): which
commands are settings, the parameters a file entry holds, their keyed reads and the largest size of
every data field (the link budget). One derivation from the IR for every wing: the Python back end
renders it as `_settings.py` and `settings.schema.json`, the C back end as the device tool's tables
(`tools/device_facts.h`).

A setting is a command layout with the write and read functions that the spec's `settings` section
does not exclude and whose read has a reply. Names are the spec's (each wing maps them).
"""

from __future__ import annotations

from generator import model


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
                (rv, (rv["device"] if len(rf["variants"]) > 1 else None))
                for rv in rf["variants"]
                if set(rv["devices"]) & set(v["devices"])
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
