"""Pass: build every named type in IR form: enums and bitfields first (they depend on nothing),
then structs and unions in dependency order, with their sizes. A type that contains itself, or
types nested more than MAX_NESTING deep, are reported and replaced by an empty one so the passes
after this one still run.
"""

from __future__ import annotations

from ..primitives import PRIMITIVES, int_range
from .context import Context, SpecFile
from .params import build_params
from .sizes import fixed, layout_size

# Structs and unions nest a few levels in real specs (a MIP value's path has at most 3 names); every back end
# and pass walks them recursively, so a chain of thousands (a generated or hostile spec) is refused.
MAX_NESTING = 32


def run(ctx: Context) -> None:
    # Enums and bitfields first (no dependencies), then structs/unions in dependency order.
    for name, (kind, t, sf, path) in ctx.raw_types.items():
        if kind == "enum":
            ctx.types[name] = _enum(ctx, sf, path, t)
        elif kind == "bitfield":
            ctx.types[name] = _bitfield(ctx, sf, path, t)
    visiting: list[str] = []  # the chain of types being resolved, outermost first
    too_deep: list[str] = []  # the first chain found nested deeper than MAX_NESTING (reported once)

    def placeholder(name: str, kind: str) -> None:
        ctx.types[name] = {"kind": kind, "name": name, "params": [], "members": [], "size": fixed(0)}

    def resolve(name: str) -> None:
        if name in ctx.types:
            return
        kind, t, sf, path = ctx.raw_types[name]
        if name in visiting:
            ctx.err(sf, path + ("name",), f"type '{name}' contains itself", "a finite, non-recursive layout")
            placeholder(name, kind)
            return
        if len(visiting) >= MAX_NESTING:
            if not too_deep:
                too_deep.append(name)
                ctx.err(
                    sf,
                    path + ("name",),
                    f"type '{name}' is nested more than {MAX_NESTING} types deep ({visiting[0]} > {visiting[1]} > ...)",
                    f"structs and unions nested at most {MAX_NESTING} deep",
                )
            placeholder(name, kind)
            return
        visiting.append(name)
        for ref in _type_refs(t):
            if ref in ctx.raw_types:
                resolve(ref)
        visiting.pop()
        if name in ctx.types:  # part of a cycle, already reported and replaced by an empty type
            return
        if kind == "struct":
            ctx.types[name] = _struct(ctx, sf, path, t)
        else:
            ctx.types[name] = _union(ctx, sf, path, t)

    for name, (kind, _t, _sf, _p) in ctx.raw_types.items():
        if kind in ("struct", "union"):
            resolve(name)


def _common(ctx: Context, sf: SpecFile, path: tuple, t: dict) -> dict:
    sources = ctx.check_sources(sf, path + ("sources",), t.get("sources", []))
    return {
        "title": t.get("title", t["name"]),
        "description": t.get("description", ""),
        "sources": sources,
        "devices": ctx.devices_of(sources),
        "notes": t.get("notes", []),
        "defined_at": str(sf.locate(path)),
    }


def _enum(ctx: Context, sf: SpecFile, path: tuple, t: dict) -> dict:
    base = t["type"]
    lo, hi = int_range(base)
    seen_names: dict[str, int] = {}
    seen_values: dict[int, list[tuple[set, str]]] = {}
    values = []
    for i, v in enumerate(t["values"]):
        vp = path + ("values", i)
        if not lo <= v["value"] <= hi:
            ctx.err(
                sf,
                vp + ("value",),
                f"enum {t['name']} value {v['name']} = {v['value']} does not fit in {base}",
                f"{lo}..{hi}",
            )
        if v["name"] in seen_names:
            ctx.err(sf, vp + ("name",), f"enum {t['name']} has two values named '{v['name']}'", "unique value names")
        seen_names[v["name"]] = v["value"]
        devs = set(v.get("devices") or ctx.device_ids)
        for d in v.get("devices", []) or []:
            if d not in ctx.device_ids:
                ctx.err(sf, vp + ("devices",), f"unknown device '{d}'", "one of " + ", ".join(ctx.device_ids))
        for other_devs, other_name in seen_values.get(v["value"], []):
            if other_devs & devs:
                ctx.err(
                    sf,
                    vp + ("value",),
                    f"enum {t['name']} value {v['value']} is used by both '{other_name}' and '{v['name']}' for the same device",
                    "distinct values, or 'devices:' lists that do not overlap",
                )
        seen_values.setdefault(v["value"], []).append((devs, v["name"]))
        values.append(
            {
                "name": v["name"],
                "value": v["value"],
                "description": v.get("description", ""),
                "manual_name": v.get("manual_name"),
                "devices": v.get("devices"),
            }
        )
    out = {"kind": "enum", "name": t["name"], "base": base, "size": fixed(PRIMITIVES[base][0]), "values": values}
    out.update(_common(ctx, sf, path, t))
    return out


def _bitfield(ctx: Context, sf: SpecFile, path: tuple, t: dict) -> dict:
    base = t["type"]
    nbits = PRIMITIVES[base][0] * 8
    members = []
    used: dict[int, str] = {}
    names: set[str] = set()
    for i, m in enumerate(t["members"]):
        mp = path + ("members", i)
        bits = m["bits"]
        first, last = (bits, bits) if isinstance(bits, int) else (bits[0], bits[1])
        if first > last:
            ctx.err(
                sf,
                mp + ("bits",),
                f"bitfield {t['name']} member {m['name']}: bit range {first}-{last} is reversed",
                "[low, high]",
            )
            first, last = last, first
        if last >= nbits:
            ctx.err(
                sf,
                mp + ("bits",),
                f"bitfield {t['name']} member {m['name']}: bit {last} is out of range for {base}",
                f"bits 0..{nbits - 1}",
            )
            last = min(last, nbits - 1)
            first = min(first, last)
        if m["name"] in names:
            ctx.err(
                sf,
                mp + ("name",),
                f"bitfield {t['name']} has two members named '{m['name']}'",
                "unique member names",
            )
        names.add(m["name"])
        if not m.get("alias"):
            for b in range(first, last + 1):
                if b in used:
                    ctx.err(
                        sf,
                        mp + ("bits",),
                        f"bitfield {t['name']} member {m['name']} overlaps '{used[b]}' at bit {b}",
                        "non-overlapping members (mark deliberate multi-bit masks with alias: true)",
                    )
                    break
            for b in range(first, last + 1):
                used.setdefault(b, m["name"])
        width = last - first + 1
        members.append(
            {
                "name": m["name"],
                "first_bit": first,
                "last_bit": last,
                "width": width,
                "mask": ((1 << width) - 1) << first,
                "reserved": bool(m.get("reserved")),
                "alias": bool(m.get("alias")),
                "description": m.get("description", ""),
                "manual_name": m.get("manual_name"),
                "devices": m.get("devices"),
            }
        )
    out = {
        "kind": "bitfield",
        "name": t["name"],
        "base": base,
        "size": fixed(PRIMITIVES[base][0]),
        "members": members,
    }
    out.update(_common(ctx, sf, path, t))
    return out


def _struct(ctx: Context, sf: SpecFile, path: tuple, t: dict) -> dict:
    params = build_params(
        ctx, sf, path + ("params",), t["params"], functions=None, owner=f"struct {t['name']}", allow_optional=False
    )
    out = {"kind": "struct", "name": t["name"], "params": params, "size": layout_size(params)}
    out.update(_common(ctx, sf, path, t))
    return out


def _union(ctx: Context, sf: SpecFile, path: tuple, t: dict) -> dict:
    sel = t["selector_enum"]
    sel_t = ctx.types.get(sel)
    if sel_t is None or sel_t["kind"] != "enum":
        what = "not defined" if sel_t is None else f"a {sel_t['kind']}, not an enum"
        ctx.err(
            sf,
            path + ("selector_enum",),
            f"union {t['name']}: selector type '{sel}' is {what}",
            "the name of an enum",
        )
        values = {}
    else:
        values = {v["name"]: v["value"] for v in sel_t["values"]}
    members = []
    seen: set[str] = set()
    for i, m in enumerate(t["members"]):
        mp = path + ("members", i)
        if values and m["when"] not in values:
            ctx.err(
                sf,
                mp + ("when",),
                f"union {t['name']}: '{m['when']}' is not a value of enum {sel}",
                "one of " + ", ".join(values),
            )
        if m["when"] in seen:
            ctx.err(
                sf,
                mp + ("when",),
                f"union {t['name']}: two members for '{m['when']}'",
                "one member per selector value",
            )
        seen.add(m["when"])
        mt = m.get("type")
        if mt is not None and (mt not in ctx.types or ctx.types[mt]["kind"] != "struct"):
            ctx.err(
                sf,
                mp + ("type",),
                f"union {t['name']} member '{m['when']}': type '{mt}' is not a defined struct",
                "a struct name",
            )
            mt = None
        members.append(
            {
                "when": m["when"],
                "value": values.get(m["when"], 0),
                "type": mt,
                "description": m.get("description", ""),
                "size": ctx.types[mt]["size"] if mt else fixed(0),
            }
        )
    sizes = [m["size"] for m in members] or [fixed(0)]
    size = {"min": min(s["min"] for s in sizes), "max": max(s["max"] for s in sizes), "fixed": False}
    out = {"kind": "union", "name": t["name"], "selector_enum": sel, "members": members, "size": size}
    out.update(_common(ctx, sf, path, t))
    return out


def _type_refs(t: dict) -> list[str]:
    """The type names a struct or union spec refers to."""
    refs = [p["type"] for p in t.get("params", [])]
    refs += [
        m["type"] for m in t.get("members", []) if isinstance(m, dict) and "type" in m and isinstance(m["type"], str)
    ]
    if "selector_enum" in t:
        refs.append(t["selector_enum"])
    return refs
