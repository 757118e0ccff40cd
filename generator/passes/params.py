"""Parameter lists (of structs, reserved fields, field layouts): each parameter's type
reference, count, union selector, functions and optionality checked, with its size, the capacity
of a counted array and its fixed offset. Not a pass: the passes that build types and layouts
call build_params."""

from __future__ import annotations

import difflib

from ..primitives import ALIASES, PRIMITIVES, int_range
from .context import Context, SpecFile
from .sizes import fill_capacities, fill_offsets, fixed, max_field_data, param_size


def typeref(ctx: Context, sf: SpecFile, path: tuple, p: dict) -> tuple[dict, str | None, int | None]:
    """Returns (type ref, alias name, implicit fixed count)."""
    tname = p["type"]
    if tname in ALIASES:
        elem, n = ALIASES[tname]
        return {"kind": "primitive", "name": elem, "size": fixed(PRIMITIVES[elem][0])}, tname, n
    if tname in PRIMITIVES:
        return {"kind": "primitive", "name": tname, "size": fixed(PRIMITIVES[tname][0])}, None, None
    if tname == "string":
        length = p.get("length")
        if length is None:
            ctx.err(
                sf,
                path + ("type",),
                f"parameter {p['name']}: string needs a length",
                "length: N (bytes on the wire)",
            )
            length = 1
        return (
            {
                "kind": "string",
                "length": length,
                "padding": p.get("padding", ctx.string_defaults.get("padding", "nul")),
                "justify": p.get("justify", ctx.string_defaults.get("justify", "left")),
                "size": fixed(length),
            },
            None,
            None,
        )
    t = ctx.types.get(tname)
    if t is None:
        known = sorted(list(PRIMITIVES) + list(ALIASES) + ["string"] + list(ctx.types))
        near = difflib.get_close_matches(str(tname), known, n=3, cutoff=0.6)
        ctx.err(
            sf,
            path + ("type",),
            f"parameter {p['name']}: unknown type '{tname}'"
            + (" (did you mean " + " or ".join(f"'{x}'" for x in near) + "?)" if near else ""),
            f"a primitive, vector type, string or a type defined in the spec ({len(known)} names; docs/spec-format.md)",
        )
        return {"kind": "primitive", "name": "u8", "size": fixed(1)}, None, None
    ref = {"kind": t["kind"], "name": tname, "size": t["size"]}
    if t["kind"] in ("enum", "bitfield"):
        ref["base"] = t["base"]
    return ref, None, None


def build_params(
    ctx: Context,
    sf: SpecFile,
    path: tuple,
    params: list[dict],
    functions: list[str] | None,
    owner: str,
    allow_optional: bool = True,
) -> list[dict]:
    """The IR parameters (docs/ir.md) of one parameter list at `path` in sf. `functions` are the
    selector names of a command with a function selector (None otherwise); `owner` names the
    list in messages; struct parameters may not be optional (allow_optional False)."""
    out: list[dict] = []
    names: dict[str, dict] = {}
    optional_seen: str | None = None
    max_data = max_field_data(ctx.pf.data["framing"])
    for i, p in enumerate(params):
        pp = path + (i,)
        name = p["name"]
        if name in names:
            ctx.err(sf, pp + ("name",), f"{owner}: two parameters named '{name}'", "unique parameter names")
        if name == "function" and functions is not None:
            ctx.err(sf, pp + ("name",), f"{owner}: 'function' is reserved for the function selector", "another name")
        tref, alias, implicit_count = typeref(ctx, sf, pp, p)
        count = _count(ctx, sf, pp, p, owner, alias, implicit_count, names, params[i + 1 :])
        if tref["kind"] == "string" and count is not None:
            ctx.err(sf, pp + ("count",), f"{owner}: arrays of strings are not supported", "a struct holding the string")
        if tref["kind"] != "string" and ("length" in p or "padding" in p or "justify" in p):
            ctx.err(
                sf,
                pp,
                f"{owner}: parameter {name}: length/padding/justify apply only to type string",
                "type: string",
            )
        tref = _selector(ctx, sf, pp, p, owner, tref, count, names)
        pf = _functions(ctx, sf, pp, p, owner, functions)
        optional_for = _optional_for(ctx, sf, pp, p, owner, pf)
        optional = (
            bool(p.get("optional"))
            or bool(optional_for)
            or (functions is not None and pf is not None and set(pf) != set(functions))
        )
        if functions is not None and pf is None:
            ctx.err(
                sf,
                pp,
                f"{owner}: parameter {name} does not say which functions it is sent for",
                "functions: [...] on every parameter of a command with a function selector",
            )
        if optional and not allow_optional:
            ctx.err(
                sf, pp, f"{owner}: parameter {name} cannot be optional here", "optional parameters only in commands"
            )
        if optional:
            optional_seen = optional_seen or name
        elif optional_seen:
            ctx.err(
                sf,
                pp,
                f"{owner}: required parameter {name} follows optional parameter {optional_seen}",
                "optional parameters (not sent for every function) at the end",
            )
        max_count = None
        if count is not None and count["kind"] != "fixed":
            max_count = p.get("max_count") or -1  # default: what fits beside the others (fill_capacities)
        elif "max_count" in p:
            ctx.err(
                sf,
                pp + ("max_count",),
                f"{owner}: max_count applies only to counted arrays",
                "count: <param> or remaining",
            )
        q = {
            "name": name,
            "description": p.get("description", ""),
            "units": p.get("units"),
            "frame": _frame(ctx, sf, pp, p, owner),
            "manual_name": p.get("manual_name"),
            "type": tref,
            "alias": alias,
            "count": count,
            "max_count": max_count,
            "functions": pf,
            "optional": optional,
            "optional_for": optional_for,
            "notes": p.get("notes", []),
            "default": _default(ctx, sf, pp, p, owner, tref, count, pf),
            "ignored": _ignored(ctx, sf, pp, p, owner, functions, pf, optional_for),
            "plausible": _plausible(ctx, sf, pp, p, owner, tref, count, pf),
        }
        q["size"] = param_size(q)
        names[name] = q
        out.append(q)
    fill_capacities(out, max_data, selector=functions is not None)
    fill_offsets(out)
    return out


def _count(
    ctx: Context,
    sf: SpecFile,
    pp: tuple,
    p: dict,
    owner: str,
    alias: str | None,
    implicit_count: int | None,
    names: dict[str, dict],
    after: list[dict],
) -> dict | None:
    """The parameter's count (null, fixed, param or remaining; docs/ir.md), checked against the
    parameters before it (`names`) and after it."""
    name = p["name"]
    count = None
    if implicit_count is not None:
        count = {"kind": "fixed", "value": implicit_count}
        if "count" in p:
            ctx.err(
                sf,
                pp + ("count",),
                f"{owner}: parameter {name} has type {alias}, which already has {implicit_count} elements",
                "no count on vector/matrix types (use the element type with count)",
            )
    elif "count" in p:
        c = p["count"]
        if isinstance(c, int):
            count = {"kind": "fixed", "value": c}
        elif c == "remaining":
            count = {"kind": "remaining"}
            if after:
                ctx.err(
                    sf,
                    pp + ("count",),
                    f"{owner}: parameter {name} runs to the end of the field but is not the last parameter",
                    "count: remaining only on the last parameter",
                )
        else:
            ref = names.get(c)
            if ref is None:
                later = any(q["name"] == c for q in after)
                why = "a later parameter" if later else "not a parameter"
                ctx.err(
                    sf,
                    pp + ("count",),
                    f"{owner}: count of {name} refers to '{c}', which is {why}",
                    "the name of an earlier integer parameter",
                )
            elif not _is_integer(ref["type"]) or ref["count"] is not None:
                ctx.err(
                    sf,
                    pp + ("count",),
                    f"{owner}: count of {name} refers to '{c}', which is not a single integer",
                    "an earlier u8/u16/u32 parameter",
                )
            count = {"kind": "param", "param": c}
    return count


def _selector(
    ctx: Context, sf: SpecFile, pp: tuple, p: dict, owner: str, tref: dict, count: dict | None, names: dict[str, dict]
) -> dict:
    """A union parameter's type reference with its selector (an earlier parameter of the union's
    enum); any other parameter must not have one."""
    name = p["name"]
    if tref["kind"] == "union":
        sel = p.get("selector")
        ut = ctx.types[tref["name"]]
        if sel is None:
            ctx.err(
                sf,
                pp,
                f"{owner}: union parameter {name} needs 'selector'",
                "selector: <earlier enum parameter>",
            )
        elif sel not in names:
            ctx.err(
                sf,
                pp + ("selector",),
                f"{owner}: selector of {name} refers to '{sel}', which is not an earlier parameter",
                "the name of an earlier enum parameter",
            )
        elif names[sel]["type"]["kind"] != "enum":
            ctx.err(
                sf,
                pp + ("selector",),
                f"{owner}: selector '{sel}' of union {name} is not an enum (it is {names[sel]['type']['kind']})",
                f"a parameter of enum type {ut['selector_enum']}",
            )
        elif names[sel]["type"]["name"] != ut["selector_enum"]:
            ctx.err(
                sf,
                pp + ("selector",),
                f"{owner}: selector '{sel}' has type {names[sel]['type']['name']}, union {tref['name']} is selected by {ut['selector_enum']}",
                f"a parameter of enum type {ut['selector_enum']}",
            )
        tref = dict(tref, selector=sel)
        if count is not None:
            ctx.err(sf, pp + ("count",), f"{owner}: arrays of unions are not supported", "a single union")
    elif "selector" in p:
        ctx.err(
            sf,
            pp + ("selector",),
            f"{owner}: parameter {name} is not a union; 'selector' does not apply",
            "no selector",
        )
    return tref


def _functions(ctx: Context, sf: SpecFile, pp: tuple, p: dict, owner: str, functions: list[str] | None) -> list | None:
    """The functions a command parameter is sent for: a subset of its command's."""
    name = p["name"]
    pf = p.get("functions")
    if pf is not None:
        if functions is None:
            ctx.err(
                sf,
                pp + ("functions",),
                f"{owner}: parameter {name} lists functions but the command has no function selector",
                "functions: on the command first",
            )
        else:
            for fn in pf:
                if fn not in functions:
                    ctx.err(
                        sf,
                        pp + ("functions",),
                        f"{owner}: parameter {name} is marked for function '{fn}', which the command does not support",
                        "a subset of the command's functions: " + ", ".join(functions),
                    )
    return pf


def _optional_for(ctx: Context, sf: SpecFile, pp: tuple, p: dict, owner: str, pf: list | None) -> list | None:
    """The functions that may leave a parameter out although the manual prints it for them (host
    software in the field sends e.g. a READ as the function byte alone): a subset of the
    parameter's functions. Such a parameter is optional: decoders accept both forms."""
    of = p.get("optional_for")
    if of is None:
        return None
    if pf is None:
        ctx.err(
            sf,
            pp + ("optional_for",),
            f"{owner}: parameter {p['name']} has optional_for but no functions",
            "functions: [...] on the parameter first",
        )
        return None
    for fn in of:
        if fn not in pf:
            ctx.err(
                sf,
                pp + ("optional_for",),
                f"{owner}: parameter {p['name']} may be left out by function '{fn}', which it is not sent for",
                "a subset of the parameter's functions: " + ", ".join(pf),
            )
    return list(of)


def _is_integer(tref: dict) -> bool:
    return tref["kind"] == "primitive" and PRIMITIVES[tref["name"]][1] == "int" and not PRIMITIVES[tref["name"]][2]


def _default(
    ctx: Context,
    sf: SpecFile,
    pp: tuple,
    p: dict,
    owner: str,
    tref: dict,
    count: dict | None,
    pf: list | None,
    check_manual: bool = True,
) -> dict | None:
    """The `default` of a setting's parameter (docs/spec-format.md), its value checked against the
    type (an enum value by name or number, as the enum's number in the IR) and its manual against
    the protocol's; None without one."""
    d = p.get("default")
    if d is None:
        return None
    where = pp + ("default",)
    if pf is None or "write" not in pf:
        ctx.err(
            sf,
            where,
            f"{owner}: default of {p['name']}: only a setting's parameters sent for write have one",
            "no default",
        )
        return None
    cited = [("source",), *(("also", i) for i in range(len(d.get("also", []))))]
    refs = [d["source"], *d.get("also", [])]
    for at, ref in zip(cited, refs):
        if check_manual and ref["manual"] not in ctx.manual_devices:
            ctx.err(
                sf,
                where + at + ("manual",),
                f"unknown manual '{ref['manual']}'",
                "one of the manuals listed under devices in the protocol file: "
                + ", ".join(sorted(ctx.manual_devices)),
            )
    manual = d["source"]["manual"]
    value = d["value"]
    n = None
    if count is not None and count["kind"] != "fixed":
        # A counted array (a message format's list): any number of items, its count implied.
        if not isinstance(value, list):
            ctx.err(sf, where + ("value",), f"{owner}: default of {p['name']} is not a list", "a list of values")
            return None
        n = len(value)
        items = value
    elif count is not None:
        n = count["value"]
        if not isinstance(value, list) or len(value) != n:
            ctx.err(
                sf, where + ("value",), f"{owner}: default of {p['name']} is not a list of {n} values", f"{n} values"
            )
            return None
        items = value
    elif isinstance(value, list):
        ctx.err(sf, where + ("value",), f"{owner}: default of {p['name']} is a list", "one value")
        return None
    else:
        items = [value]
    out = []
    for item in items:
        v = _default_item(ctx, sf, where + ("value",), owner, p["name"], tref, item)
        if v is None:
            return None
        out.append(v)
    return {
        "value": out if n is not None else out[0],
        "source": {"manual": manual, "line": d["source"]["line"]},
        "also": [{"manual": r["manual"], "line": r["line"]} for r in d.get("also", [])],
        # The devices whose manuals state it: the simulated device's factory value on those only.
        "devices": sorted({ctx.manual_devices[r["manual"]] for r in refs if r["manual"] in ctx.manual_devices}),
    }


def _ignored(
    ctx: Context,
    sf: SpecFile,
    pp: tuple,
    p: dict,
    owner: str,
    functions: list[str] | None,
    pf: list | None,
    optional_for: list | None,
) -> dict | None:
    """The functions for which the manual says the device ignores the parameter (`ignored`,
    docs/spec-format.md): functions of the command for which the parameter is not required (not
    sent for them, or optional_for them), with the line saying so; None without one."""
    ig = p.get("ignored")
    if ig is None:
        return None
    where = pp + ("ignored",)
    for fn in ig["functions"]:
        if functions is None or fn not in functions:
            ctx.err(
                sf,
                where + ("functions",),
                f"{owner}: parameter {p['name']} is ignored for function '{fn}', which the command does not support",
                "a subset of the command's functions",
            )
        elif pf is not None and fn in pf and fn not in (optional_for or []):
            ctx.err(
                sf,
                where + ("functions",),
                f"{owner}: parameter {p['name']} is ignored for function '{fn}' but required for it",
                "leave the function out of the parameter's functions, or list it in optional_for",
            )
    if ig["source"]["manual"] not in ctx.manual_devices:
        ctx.err(sf, where + ("source", "manual"), f"unknown manual '{ig['source']['manual']}'", "a protocol manual")
    return {"functions": list(ig["functions"]), "source": dict(ig["source"])}


def _plausible(
    ctx: Context, sf: SpecFile, pp: tuple, p: dict, owner: str, tref: dict, count: dict | None, pf: list | None
) -> dict | None:
    """The value the simulated device starts with when no manual states one (`plausible`,
    docs/spec-format.md), checked against the type as a default is; None without one."""
    pl = p.get("plausible")
    if pl is None:
        return None
    where = pp + ("plausible",)
    source = pl.get("source")
    if source is not None and source["manual"] not in ctx.manual_devices:
        ctx.err(sf, where + ("source", "manual"), f"unknown manual '{source['manual']}'", "a protocol manual")
    if "value" not in pl:  # the type's zero (a union's, a string's: no value to write), for the reason given
        if pf is None or "write" not in pf:
            ctx.err(sf, where, f"{owner}: plausible value of {p['name']}: only a setting's parameters have one", "none")
            return None
        return {"value": None, "why": " ".join(pl["why"].split()), "source": source}
    # Checked as a default would be (type, count), then kept apart from it.
    shaped = _default(
        ctx,
        sf,
        pp,
        {"name": p["name"], "default": {"value": pl["value"], "source": source or {"manual": "", "line": 1}}},
        owner,
        tref,
        count,
        pf,
        check_manual=False,
    )
    if shaped is None:
        return None
    return {"value": shaped["value"], "why": " ".join(pl["why"].split()), "source": source}


def held_params(functions: list[str] | None, params: list[dict]) -> list[dict]:
    """The values a setting command's layout holds: the parameters sent for write that do not
    select which setting (a key is sent, and required, for read too), less the counts of lists."""
    if "write" not in (functions or []):
        return []
    counts = {(q.get("count") or {}).get("param") for q in params}  # follow their list's length
    return [
        q
        for q in params
        if "write" in (q.get("functions") or [])
        and not ("read" in q["functions"] and "read" not in (q.get("optional_for") or []))
        and q["name"] not in counts
    ]


def check_starting_values(
    ctx: Context, sf: SpecFile, path: tuple, functions: list[str] | None, params: list[dict], devices: list, owner: str
) -> None:
    """Every value a setting holds starts somewhere the spec records: a `default` the manual of
    each device states, else a `plausible` value with its reason (docs/spec-format.md). Checked
    for a protocol the simulator serves (one with a `simulation` section)."""
    if ctx.pf.data.get("simulation") is None:
        return
    for i, q in enumerate(params):
        if q not in held_params(functions, params) or q.get("plausible"):
            continue
        stated = (q.get("default") or {}).get("devices", [])
        missing = [d for d in devices if d not in stated]
        if missing:
            ctx.err(
                sf,
                path + (i,),
                f"{owner}: setting parameter {q['name']} has no default stated for {', '.join(missing)} "
                "and no plausible value",
                "plausible: {value, why, source} (the value the device starts with and the reason)",
            )


def _default_item(ctx: Context, sf: SpecFile, where: tuple, owner: str, name: str, tref: dict, item):
    kind = tref["kind"]
    bad = f"{owner}: default of {name}: {item!r} is not a value of {tref.get('name', kind)}"
    if kind == "struct":  # one record of a counted struct list: every member, each checked
        members = ctx.types.get(tref["name"], {}).get("params", [])
        names = [m["name"] for m in members]
        if not isinstance(item, dict) or sorted(item) != sorted(names):
            ctx.err(sf, where, bad, "a record naming every member: " + ", ".join(names))
            return None
        record = {}
        for m in members:
            v = _default_item(ctx, sf, where, owner, f"{name}.{m['name']}", m["type"], item[m["name"]])
            if v is None:
                return None
            record[m["name"]] = v
        return record
    if kind == "enum":
        values = ctx.types.get(tref["name"], {}).get("values", [])
        for v in values:
            if item == v["name"] or (isinstance(item, int) and not isinstance(item, bool) and item == v["value"]):
                return v["value"]
        ctx.err(sf, where, bad, "one of " + ", ".join(v["name"] for v in values))
        return None
    base = tref.get("base") if kind == "bitfield" else tref.get("name") if kind == "primitive" else None
    if base is None or base not in PRIMITIVES:
        ctx.err(sf, where, f"{owner}: default of {name}: not supported for a {kind}", "no default")
        return None
    _, pkind, _ = PRIMITIVES[base]
    if pkind == "bool":
        ok = isinstance(item, bool)
    elif pkind == "float":
        ok = isinstance(item, (int, float)) and not isinstance(item, bool)
    elif pkind == "int":
        lo, hi = int_range(base)
        ok = isinstance(item, int) and not isinstance(item, bool) and lo <= item <= hi
    else:
        ok = False
    if not ok:
        ctx.err(sf, where, bad, f"a {base} value")
        return None
    return float(item) if pkind == "float" else item


def _frame(ctx: Context, sf: SpecFile, pp: tuple, p: dict, owner: str) -> str | dict | None:
    """The parameter's coordinate frame (`frame:`): one frame name, or {device id: frame name}
    with device ids of the protocol (each a device whose manual the protocol lists)."""
    frame = p.get("frame")
    if not isinstance(frame, dict):
        return frame
    devices = set(ctx.manual_devices.values())
    for device in frame:
        if device not in devices:
            ctx.err(
                sf,
                pp + ("frame", device),
                f"{owner}: parameter {p['name']}: frame for unknown device {device!r}",
                "one of the protocol's devices: " + ", ".join(sorted(devices)),
            )
    return {d: frame[d] for d in sorted(frame)}
