"""The identifiers the Python back end gives to spec elements, for the shared name check
(generator/name_check.py), spelled with the back end's own functions (backend.py)."""

from __future__ import annotations

from generator import model
from generator.name_check import Name, layouts, param_element, taken
from generator.naming import camel

from . import facts
from .backend import BITFIELD_RESERVED, EXPORTED, RUNTIME_MODULES, const_name, py_attr, set_module


def reserved(ident: str) -> str | None:
    """Why ident is still reserved in Python (after py_attr's escaping), or None."""
    if ident in facts.KEYWORDS:
        return "is a Python keyword"
    if ident in facts.AMBIGUOUS_NAMES:
        return "is an ambiguous name (pycodestyle E741/E742)"
    return None


def names(proto: dict) -> list[Name]:
    pkg = proto["package"]
    out: list[Name] = []
    top = f"package {pkg}"
    out.extend(taken(top, RUNTIME_MODULES | EXPORTED, "a module or name of the package,"))
    for s in proto["sets"]:
        out.append(Name(top, set_module(s), f"the module of set {s['name']}", (s["name"],)))
    types = f"module {pkg}.types"
    for t in proto["types"]:
        tw = (t["name"],)
        out.append(Name(types, t["name"], f"type {t['name']}", tw))
        scope = f"class {pkg}.types.{t['name']}"
        owner = f"{t['kind']} {t['name']}"
        if t["kind"] == "enum":
            for v in t["values"]:
                out.append(
                    Name(scope, const_name(v["name"]), f"value {v['name']} of {owner}", tw + (v["name"],), owner=owner)
                )
        elif t["kind"] == "bitfield":
            for b in t["members"]:
                bw = tw + (b["name"],)
                element = f"member {b['name']} of {owner}"
                out.append(Name(scope, py_attr(b["name"], BITFIELD_RESERVED), element, bw, owner=owner))
                out.append(Name(scope, const_name(b["name"]), f"the mask of {element}", bw, False, owner))
        elif t["kind"] == "struct":
            for q in model.struct(proto, t):
                out.append(Name(scope, py_attr(q.name), param_element(q, owner), tw + (q.name,), owner=owner))
    for lay in layouts(proto):
        module = f"{pkg}.reserved" if lay.set is None else f"{pkg}.{set_module(lay.set)}"
        cls = camel(lay.field["name"]) + (f"_{lay.device}" if lay.device else "")
        out.append(Name(f"module {module}", cls, lay.what, lay.where))
        for q in model.layout(proto, lay.variant):
            pw = lay.where if q.function else lay.params_where + (q.name,)
            out.append(Name(f"class {module}.{cls}", py_attr(q.name), param_element(q, lay.what), pw, owner=lay.what))
    return out
