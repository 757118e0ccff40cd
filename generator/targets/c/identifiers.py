"""The identifiers the C back end gives to spec elements, for the shared name check
(generator/name_check.py), spelled with the back end's own functions (backend.py)."""

from __future__ import annotations

from generator import model
from generator.name_check import Name, calls, layouts, param_element, params_where, taken
from generator.naming import snake

from .backend import member, prefix_of
from .facts import KEYWORDS, RESERVED


def reserved(ident: str) -> str | None:
    """Why ident is still reserved in C (after member's escaping), or None."""
    if ident in KEYWORDS:
        return "is a C or C++ keyword (the headers are compiled as C++ too)"
    if ident in RESERVED:
        return "is a macro of the C library or of the compiler (facts.RESERVED)"
    return None


def names(proto: dict) -> list[Name]:
    p = prefix_of(proto)
    P = p.upper()
    pkg = proto["package"]
    file_scope = f"the C file scope of {pkg}"
    out: list[Name] = []

    def glob(ident: str, element: str, where: tuple[str, ...]) -> None:
        # Prefixed with the package's prefix: never a keyword or macro of the language.
        out.append(Name(file_scope, ident, element, where, checked=False))

    def members(scope: str, plist: model.ParamList, owner: str, where: tuple[str, ...], fwhere: tuple[str, ...]):
        for q in plist:
            pw = fwhere if q.function else where + (q.name,)
            element = param_element(q, owner)
            out.append(Name(scope, member(q.name), element, pw, owner=owner))
            if q.optional:
                out.append(Name(scope, f"has_{q.name}", f"the presence flag of {element}", pw, False, owner))
            if q.kind == model.REMAINING:
                out.append(Name(scope, f"{q.name}_count", f"the element count of {element}", pw, False, owner))

    for t in proto["types"]:
        tw = (t["name"],)
        ctype = f"{p}_{snake(t['name'])}_t"
        macro = f"{P}_{snake(t['name']).upper()}"
        glob(ctype, f"type {t['name']}", tw)
        if t["kind"] == "enum":
            for v in t["values"]:
                glob(f"{macro}_{v['name'].upper()}", f"value {v['name']} of enum {t['name']}", tw + (v["name"],))
        elif t["kind"] == "bitfield":
            for m in t["members"]:
                for suffix in ("MASK", "SHIFT"):
                    glob(
                        f"{macro}_{m['name'].upper()}_{suffix}",
                        f"member {m['name']} of bitfield {t['name']}",
                        tw + (m["name"],),
                    )
        elif t["kind"] == "struct":
            members(f"struct {ctype}", model.struct(proto, t), f"struct {t['name']}", tw, tw)
        else:
            scope = f"union {ctype}"
            owner = f"union {t['name']}"
            out.extend(taken(scope, ["none_"], "the member for selector values without data,", owner))
            values: set[int] = set()
            for m in t["members"]:
                if m["value"] in values:
                    continue  # per-device values sharing a number: one member (backend.py)
                values.add(m["value"])
                out.append(Name(scope, member(m["when"]), f"member {m['when']} of {owner}", tw, owner=owner))
    for s in proto["sets"]:
        glob(f"{P}_{s['name'].upper()}_SET", f"set {s['name']}", (s["name"],))
    for lay in layouts(proto):
        s, f = lay.set, lay.field
        base = f"{p}_{s['name']}_{f['name']}" if s else f"{p}_{f['name']}"
        lbase = base + (f"_{lay.variant['device']}" if lay.variant["device"] else "")
        what = f"field {s['name']}.{f['name']}" if s else f"reserved field {f['name']}"
        glob(f"{base.upper()}_DESCRIPTOR", what, lay.where)
        for ident in (f"{lbase}_t", f"{P}_FIELD_{lbase[len(p) + 1 :].upper()}", f"{lbase}_encode", f"{lbase}_decode"):
            glob(ident, what, lay.where)
        plist = model.layout(proto, lay.variant)
        members(f"struct {lbase}_t", plist, lay.what, lay.params_where, lay.where)
    # The typed command API (backend.command_api, commands.h.j2): one function per call, whose
    # parameters are the link, the arguments (`link` and `reply` get a "_"), an array's count and
    # the reply.
    for s, f, c in calls(proto):
        name = (
            f"{p}_{s['name']}_{f['name']}"
            + (f"_{c.function}" if c.function else "")
            + (f"_{c.device}" if c.device else "")
        )
        what = f"the command function of field {s['name']}.{f['name']}"
        glob(name, what, (s["name"], f["name"]))
        scope, owner = f"the parameters of {name}", f"{what} {c.function} {c.device}"
        out.extend(taken(scope, ["link", "reply"], "the function's parameter", owner))
        v = f["variants"][c.variants[0]]
        kinds = {q.name: q.kind for q in model.layout(proto, v)}
        for a in c.arguments:
            arg = member(a.name)
            arg = arg + "_" if arg in ("link", "reply") else arg
            element = f"parameter {a.name} of {what}"
            w = params_where(s, f, v) + (a.name,)
            out.append(Name(scope, arg, element, w, owner=owner))
            if kinds[a.name] in (model.COUNTED, model.REMAINING):
                out.append(Name(scope, f"{a.name}_count", f"the element count of {element}", w, False, owner))
    for d in proto["devices"]:
        glob(f"{P}_DEVICE_{d['id'].upper()}", f"device {d['id']}", (d["id"],))
    return out
