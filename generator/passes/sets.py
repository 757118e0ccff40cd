"""Pass: the descriptor sets and their fields, without their layouts (the `variants` pass adds
those). A set may be split over several files ("parts") that agree on its name and kind; its
fields are checked for unique descriptors and names, reserved descriptors, roles that fit the set
kind, the shared data range, and the keys a field must or must not have.
"""

from __future__ import annotations

from .context import Context, SpecFile


def run(ctx: Context) -> None:
    sets = []
    by_name: dict[str, SpecFile] = {}
    kinds = ctx.pf.data["set_kinds"]
    shared = ctx.pf.data.get("shared_data")
    groups: dict[int, list[SpecFile]] = {}
    for sf in ctx.set_files:
        groups.setdefault(sf.data["set"], []).append(sf)
    for set_id, parts in groups.items():
        sf = parts[0]
        d = sf.data
        for other in parts[1:]:
            for key in ("name", "kind"):
                if other.data[key] != d[key]:
                    ctx.err(
                        other,
                        (key,),
                        f"descriptor set 0x{set_id:02X} has {key} '{other.data[key]}' here but '{d[key]}' in {sf.path}",
                        f"every file of set 0x{set_id:02X} with {key} '{d[key]}'",
                    )
        if d["name"] in by_name:
            ctx.err(
                sf,
                ("name",),
                f"descriptor set name '{d['name']}' is used twice (also in {by_name[d['name']].path})",
                "unique set names",
            )
        by_name[d["name"]] = sf
        rng = kinds.get(d["kind"])
        if rng and not rng["first"] <= d["set"] <= rng["last"]:
            ctx.err(
                sf,
                ("set",),
                f"{d['kind']} set 0x{d['set']:02X} is outside the {d['kind']} range",
                f"0x{rng['first']:02X}..0x{rng['last']:02X}",
            )
        is_shared = bool(shared and d["set"] == shared["set"])
        sets.append(
            {
                "id": d["set"],
                "name": d["name"],
                "title": d["title"],
                "kind": d["kind"],
                "shared": is_shared,
                "description": d.get("description", ""),
                "sources": _unique(
                    [s for part in parts for s in ctx.check_sources(part, ("sources",), part.data["sources"])]
                ),
                "notes": [n for part in parts for n in part.data.get("notes", [])],
                "fields": _fields(ctx, d, parts, is_shared),
            }
        )
    sets.sort(key=lambda s: s["id"])
    ctx.sets = sets


def _fields(ctx: Context, d: dict, parts: list[SpecFile], is_shared: bool) -> list[dict]:
    """The fields of all parts of set d, in file order, each checked on its own and against the
    others. `sources`, `devices` and `variants` are filled in by the variants pass."""
    shared = ctx.pf.data.get("shared_data")
    fields = []
    ids: dict[int, tuple[str, SpecFile, tuple]] = {}
    fnames: set[str] = set()
    for sf, i, f in [(part, i, f) for part in parts for i, f in enumerate(part.data["fields"])]:
        fp = ("fields", i)
        if f["id"] in ids:
            first, first_sf, first_path = ids[f["id"]]
            ctx.err(
                sf,
                fp + ("id",),
                f"{d['name']}: descriptor 0x{f['id']:02X} is used by both '{first}' and '{f['name']}'"
                f" (the first at {first_sf.locate(first_path)})",
                "unique descriptors within a set",
            )
        else:
            ids[f["id"]] = (f["name"], sf, fp + ("id",))
        if f["name"] in fnames:
            ctx.err(
                sf,
                fp + ("name",),
                f"{d['name']}: two fields named '{f['name']}'",
                "unique field names within a set",
            )
        fnames.add(f["name"])
        for r in ctx.reserved:
            if r["applies_to"] == d["kind"] and r["id"] == f["id"]:
                ctx.err(
                    sf,
                    fp + ("id",),
                    f"{d['name']}.{f['name']}: descriptor 0x{f['id']:02X} is reserved for {r['name']}",
                    "another descriptor",
                )
        if d["kind"] == "command" and f["role"] == "data" or d["kind"] == "data" and f["role"] != "data":
            ctx.err(
                sf,
                fp + ("role",),
                f"{d['name']}.{f['name']}: role {f['role']} in a {d['kind']} set",
                "command/response in command sets, data in data sets",
            )
        if is_shared and f["id"] < shared["first_descriptor"]:
            ctx.err(
                sf,
                fp + ("id",),
                f"shared descriptor 0x{f['id']:02X} is below 0x{shared['first_descriptor']:02X}",
                f">= 0x{shared['first_descriptor']:02X}",
            )
        if f.get("sample_timestamp") and not is_shared:
            ctx.err(
                sf,
                fp + ("sample_timestamp",),
                f"{d['name']}.{f['name']}: only a shared data field can identify a sample",
                "sample_timestamp only in the shared data set",
            )
        if f.get("repeats") and f["role"] != "data":
            ctx.err(sf, fp + ("repeats",), f"{d['name']}.{f['name']}: only data fields repeat", "no repeats")
        given = [k for k in ("params", "layout", "variants") if k in f]
        if len(given) != 1:
            what = " and ".join(given) if given else "none of them"
            ctx.err(
                sf,
                fp + ((given[1],) if len(given) > 1 else ()),
                f"{d['name']}.{f['name']}: has {what}",
                "exactly one of params (its own parameters), layout (a shared field layout) or variants (per-device layouts)",
            )
        if "variants" in f and "sources" in f:
            ctx.err(
                sf,
                fp + ("sources",),
                f"{d['name']}.{f['name']}: with variants, sources go in each variant",
                "sources under each variant",
            )
        if "variants" not in f and "sources" not in f:
            ctx.err(sf, fp, f"{d['name']}.{f['name']}: missing sources", "sources: [{manual, line, title}]")
        fields.append(
            {
                "id": f["id"],
                "name": f["name"],
                "role": f["role"],
                "title": f["title"],
                "description": f.get("description", ""),
                "sources": None,
                "devices": None,
                "notes": f.get("notes", []),
                "repeats": bool(f.get("repeats")),
                "manual_name": f.get("manual_name"),
                "sample_timestamp": bool(f.get("sample_timestamp")),
                "length_byte_adjust": f.get("length_byte_adjust", 0),
                "variants": None,
                # Until `assemble`: the spec entry, where it is, and its set's name (for messages).
                "_spec": f,
                "_sf": sf,
                "_path": fp,
                "_set": d["name"],
            }
        )
    return fields


def _unique(items: list[dict]) -> list[dict]:
    """Items in order, without repeats (parts of a set may cite the same set-level source)."""
    out: list[dict] = []
    for x in items:
        if x not in out:
            out.append(x)
    return out
