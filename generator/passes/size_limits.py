"""Pass: every layout fits the protocol's limits. A field's data (after its header, with the
function selector byte) can be at most the framing's `max_field_data` bytes (MIP: 253, the length
byte counting the two header bytes; MS-CIP: what its protocol file's `max_payload` and field
header allow), so a layout whose largest encoding is longer (`u8[300]`, a `char[300]` string,
four 3x3 double matrices, a counted array whose `max_count` is too large) can never be sent and is
an error at the layout, with the sizes that make it up."""

from __future__ import annotations

from .context import Context, SpecFile


def run(ctx: Context) -> None:
    limit = ctx.framing["max_field_data"]
    for i, r in enumerate(ctx.reserved):
        _check(ctx, ctx.pf, ("reserved_fields", i, "params"), f"reserved field {r['name']}", r["variants"][0], limit)
    for s in ctx.sets:
        for f in s["fields"]:
            spec, sf, fp = f["_spec"], f["_sf"], f["_path"]
            for j, v in enumerate(f["variants"]):
                path = fp + ("variants", j) if "variants" in spec else fp
                src = spec["variants"][j] if "variants" in spec else spec
                path += ("layout",) if "layout" in src else ("params",)
                owner = f"{s['name']}.{f['name']}" + (f" ({v['device']})" if v["device"] else "")
                _check(ctx, sf, path, owner, v, limit)


def _check(ctx: Context, sf: SpecFile, path: tuple, owner: str, variant: dict, limit: int) -> None:
    size = variant["size"]["max"]
    if size <= limit:
        return
    parts = [f"{q['name']} {q['size']['max']}" for q in variant["params"]]
    if variant["functions"] is not None:
        parts.insert(0, "function selector 1")
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
