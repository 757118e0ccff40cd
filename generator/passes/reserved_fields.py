"""Pass: the reserved fields of the protocol file (descriptors every set of a kind answers, e.g.
MIP's ack/nack), in the same shape as a set's field with one variant."""

from __future__ import annotations

from .context import Context, SpecFile
from .params import build_params
from .sizes import layout_size


def run(ctx: Context) -> None:
    ctx.reserved = [_reserved_field(ctx, ctx.pf, i, f) for i, f in enumerate(ctx.pf.data.get("reserved_fields", []))]


def _reserved_field(ctx: Context, sf: SpecFile, i: int, f: dict) -> dict:
    path = ("reserved_fields", i)
    params = build_params(ctx, sf, path + ("params",), f["params"], None, f"reserved field {f['name']}")
    sources = ctx.check_sources(sf, path + ("sources",), f["sources"])
    return {
        "id": f["id"],
        "name": f["name"],
        "title": f["title"],
        "role": f["role"],
        "applies_to": f["applies_to"],
        "description": f.get("description", ""),
        "sources": sources,
        "devices": ctx.devices_of(sources),
        "notes": f.get("notes", []),
        "stated_length": f.get("stated_length"),
        "variants": [
            {
                "device": None,
                "devices": ctx.devices_of(sources),
                "sources": sources,
                "notes": [],
                "functions": None,
                "responses": [],
                "ack_suppressed_by": None,
                "params": params,
                "size": layout_size(params),
                "layout": None,
            }
        ],
        "params": params,
        "size": layout_size(params),
    }
