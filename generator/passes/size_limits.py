"""Pass: every layout fits the protocol's limits. A field's data (after its header, with the
function selector byte) can be at most the framing's `max_field_data` bytes (MIP: 253, the length
byte counting the two header bytes; MS-CIP: what its protocol file's `max_payload` leaves beside
the field header), so a layout whose largest encoding is longer (`u8[300]`, a `char[300]` string,
four 3x3 double matrices, a counted array whose `max_count` is too large) can never be sent and is
an error at the layout, with the sizes that make it up.

A counted or `remaining` array without `max_count` is elastic: its capacity is what fits beside the
smallest size of every other parameter (passes/sizes.py fill_capacities), so it counts here with its
smallest size (0) and the rest of the layout must fit on its own.
"""

from __future__ import annotations

from .context import Context, SpecFile


def run(ctx: Context) -> None:
    limit = ctx.framing["max_field_data"]
    for i, r in enumerate(ctx.reserved):
        spec = ctx.pf.data["reserved_fields"][i]["params"]
        path = ("reserved_fields", i, "params")
        _check(ctx, ctx.pf, path, f"reserved field {r['name']}", r["variants"][0], spec, limit)
    for s in ctx.sets:
        for f in s["fields"]:
            spec, sf, fp = f["_spec"], f["_sf"], f["_path"]
            for j, v in enumerate(f["variants"]):
                src = spec["variants"][j] if "variants" in spec else spec
                path = fp + ("variants", j) if "variants" in spec else fp
                if "layout" in src:
                    path += ("layout",)
                    shared = ctx.field_layouts.get(src["layout"])
                    params = shared[0]["params"] if shared else []
                else:
                    path += ("params",)
                    params = src.get("params", [])
                owner = f"{s['name']}.{f['name']}" + (f" ({v['device']})" if v["device"] else "")
                _check(ctx, sf, path, owner, v, params, limit)


def _check(ctx: Context, sf: SpecFile, path: tuple, owner: str, variant: dict, spec_params: list, limit: int) -> None:
    if len(spec_params) != len(variant["params"]):  # an unknown layout, reported by `variants`
        return
    size = 1 if variant["functions"] is not None else 0
    parts = ["function selector 1"] if size else []
    for q, p in zip(variant["params"], spec_params):
        if q["max_count"] is not None and "max_count" not in p:
            size += q["size"]["min"]
            parts.append(f"{q['name']} {q['size']['min']}+ (elastic)")
        else:
            size += q["size"]["max"]
            parts.append(f"{q['name']} {q['size']['max']}")
    if size <= limit:
        return
    ctx.err(
        sf,
        path,
        f"{owner}: the largest encoding is {size} bytes of field data ({', '.join(parts)}),"
        f" more than one field can carry",
        f"at most {limit} bytes of field data: {_why(ctx.framing)}",
    )


def _why(fr: dict) -> str:
    hdr = fr["field_header_size"]
    why = f"a payload holds at most {fr['max_payload']} bytes, {hdr} of them the field header"
    if fr["field_length_counts_header"]:
        why += ", and the length byte (at most 255) counts the header too"
    return why
