"""Pass: fields whose size byte is irregular (`length_byte_adjust`, MS-CIP): the size byte must
stay within 0..255 for the field's one layout; framing `irregular_lengths` lists them so a
runtime can apply the adjustment per (set, descriptor)."""

from __future__ import annotations

from .context import Context


def run(ctx: Context) -> None:
    base = ctx.framing["field_length_adjust"]
    for s in ctx.sets:
        for f in s["fields"]:
            adjust = f["length_byte_adjust"]
            if not adjust:
                continue
            lo, hi = f["size"]["min"] + base + adjust, f["size"]["max"] + base + adjust
            if len(f["variants"]) != 1 or lo < 0 or hi > 255:
                ctx.err(
                    f["_sf"],
                    f["_path"] + ("length_byte_adjust",),
                    f"{s['name']}.{f['name']}: with length_byte_adjust {adjust} the size byte would be {lo}..{hi}",
                    "one layout whose size byte stays within 0..255",
                )
    ctx.framing["irregular_lengths"] = [
        {"set": s["id"], "descriptor": f["id"], "adjust": f["length_byte_adjust"]}
        for s in ctx.sets
        for f in s["fields"]
        if f["length_byte_adjust"]
    ]
