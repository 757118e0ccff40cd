"""Pass: the sample-grouping rule of docs/conformance.md section 6, derived from the spec.

`data_sets`: the data sets that group continuation packets (one tracker slot each);
`first_shared`: shared descriptors start here (256: the protocol has none); `timestamps`: the
shared fields whose value identifies a sample, with their fixed data size; `max_key`: bytes of
the largest key. A sample timestamp needs one fixed-size layout (the `sets` pass already
requires it to be a shared data field).
"""

from __future__ import annotations

from .context import Context


def run(ctx: Context) -> None:
    for s in ctx.sets:
        for f in s["fields"]:
            if f["sample_timestamp"] and (len(f["variants"]) != 1 or not f["size"]["fixed"]):
                ctx.err(
                    f["_sf"],
                    f["_path"] + ("sample_timestamp",),
                    f"{s['name']}.{f['name']}: a sample timestamp needs one fixed-size layout",
                    "fixed-size parameters, no variants",
                )
    shared = ctx.pf.data.get("shared_data")
    if not shared:
        ctx.samples = {"data_sets": [], "first_shared": 256, "timestamps": [], "max_key": 0}
        return
    stamps = []
    for s in ctx.sets:
        for f in s["fields"]:
            if f["sample_timestamp"] and len(f["variants"]) == 1 and f["size"]["fixed"]:
                stamps.append({"descriptor": f["id"], "size": f["size"]["min"]})
    data = [s["id"] for s in ctx.sets if s["kind"] == "data" and not s["shared"]]
    ctx.samples = {
        "data_sets": data,
        "first_shared": shared["first_descriptor"],
        "timestamps": stamps,
        "max_key": sum(ctx.framing["field_header_size"] + t["size"] for t in stamps),
    }
