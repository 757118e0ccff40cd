"""Pass: each named field layout once, with its documentation and the fields that use it. A
layout no field uses is an error (it would be documented but never decoded)."""

from __future__ import annotations

from .context import Context
from .sizes import layout_size


def run(ctx: Context) -> None:
    out = []
    for name in sorted(ctx.field_layouts):
        t, lsf, lpath = ctx.field_layouts[name]
        users = [(s, f, v) for s in ctx.sets for f in s["fields"] for v in f["variants"] if v["layout"] == name]
        if not users:
            ctx.err(
                lsf,
                lpath + ("name",),
                f"field layout '{name}' is not used by any field",
                "layout: <name> on a field",
            )
            continue
        used_by = [
            {"set": s["id"], "field": f["id"], "name": f"{s['name']}.{f['name']}", "device": v["device"]}
            for s, f, v in users
        ]
        params = users[0][2]["params"]
        out.append(
            {
                "name": name,
                "title": t.get("title", ""),
                "description": t.get("description", ""),
                "sources": ctx.check_sources(lsf, lpath + ("sources",), t.get("sources", [])),
                "notes": t.get("notes", []),
                "params": params,
                "size": layout_size(params),
                "used_by": used_by,
            }
        )
    ctx.layouts = out
