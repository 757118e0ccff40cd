"""Pass: the protocol's IR entry in its exported shape (docs/ir.md), with the passes' location
notes (keys starting with `_`) dropped so only plain data reaches generated/ir.json."""

from __future__ import annotations

from .context import Context


def run(ctx: Context) -> None:
    for s in ctx.sets:
        for f in s["fields"]:
            for v in f["variants"]:
                for r in v["responses"]:
                    _drop_notes(r)
            _drop_notes(f)
    p = ctx.pf.data
    ctx.ir = {
        "name": p["protocol"],
        "title": p["title"],
        "package": p["package"],
        "byte_order": p["byte_order"],
        "sources": ctx.sources,
        "devices": p["devices"],
        "response_descriptor": p.get("response_descriptor"),
        "strings": {"padding": "nul", "justify": "left", **ctx.string_defaults},
        "framing": ctx.framing,
        "set_kinds": p["set_kinds"],
        "shared_data": p.get("shared_data"),
        "samples": ctx.samples,
        "session": ctx.session,
        "session_example": ctx.session_example,
        "time": ctx.time,
        "simulation": ctx.simulation,
        "settings": ctx.settings,
        "capabilities": ctx.capabilities,
        "link": ctx.link,
        "function_selector": p.get("function_selector"),
        "reserved_fields": ctx.reserved,
        "types": [ctx.types[n] for n in sorted(ctx.types)],
        "field_layouts": ctx.layouts,
        "sets": ctx.sets,
        "lookup": ctx.lookup,
        "value_paths": ctx.value_paths,
    }


def _drop_notes(d: dict) -> None:
    for k in [k for k in d if k.startswith("_")]:
        del d[k]
