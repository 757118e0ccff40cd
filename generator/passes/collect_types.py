"""Pass: collect every named type and field layout from the protocol, type and set files.

Names are unique across the protocol (and may not shadow a built-in type); each is recorded with
its spec data, file and path so `resolve_types` and `sets` can build and locate them.
"""

from __future__ import annotations

from ..primitives import ALIASES, PRIMITIVES
from .context import Context, SpecFile

KINDS = (("enums", "enum"), ("bitfields", "bitfield"), ("structs", "struct"), ("unions", "union"))


def run(ctx: Context) -> None:
    for sf in [ctx.pf, *ctx.type_files, *ctx.set_files]:
        _collect(ctx, sf)


def _collect(ctx: Context, sf: SpecFile) -> None:
    for kind_key, kind in KINDS:
        for i, t in enumerate(sf.data.get(kind_key, []) or []):
            name = t["name"]
            path = (kind_key, i)
            if name in ctx.raw_types or name in PRIMITIVES or name in ALIASES or name == "string":
                prev = ctx.type_locs.get(name)
                where = f" (first defined at {prev})" if prev else " (a built-in type)"
                ctx.err(
                    sf,
                    path + ("name",),
                    f"type '{name}' is defined twice{where}",
                    "unique type names across the protocol",
                )
                continue
            ctx.raw_types[name] = (kind, t, sf, path)
            ctx.type_locs[name] = sf.locate(path)
    for i, t in enumerate(sf.data.get("field_layouts", []) or []):
        path = ("field_layouts", i)
        if t["name"] in ctx.field_layouts:
            prev = ctx.field_layouts[t["name"]][1].locate(ctx.field_layouts[t["name"]][2])
            ctx.err(
                sf,
                path + ("name",),
                f"field layout '{t['name']}' is defined twice (first defined at {prev})",
                "unique field layout names across the protocol",
            )
            continue
        ctx.field_layouts[t["name"]] = (t, sf, path)
