"""The identifiers the C++ back end gives to spec elements, for the shared name check
(generator/name_check.py), spelled with the back end's own functions (backend.py)."""

from __future__ import annotations

from generator import model
from generator import name_check as nc
from generator.name_check import Name, calls, layouts, param_element, taken

from .backend import RUNTIME_NAMESPACES, call_name, ident, layout_names, reserved_namespace, set_namespace
from .facts import KEYWORDS, RESERVED

# What the bitfield classes of templates/cpp/include/types.hpp.j2 define besides their members.
BITFIELD_OWN = ("Raw", "raw", "set_raw", "raw_")


def reserved(ident: str) -> str | None:
    """Why ident is still reserved in C++ (after ident()'s escaping), or None."""
    if ident in KEYWORDS:
        return "is a C++ keyword or a name of the standard library (facts.KEYWORDS)"
    if ident in RESERVED:
        return "is a macro of the C++ library or of the compiler (facts.RESERVED)"
    if "__" in ident:
        return "contains a double underscore (reserved to the implementation: C++ [lex.name])"
    return None


def names(proto: dict) -> list[Name]:
    ns = ident(proto["package"])
    out: list[Name] = []
    top = f"namespace {ns}"
    out.extend(taken(top, RUNTIME_NAMESPACES, "a name of the runtime,"))
    for s in proto["sets"]:
        out.append(Name(top, set_namespace(s), f"the namespace of set {s['name']}", (s["name"],)))
    if proto["reserved_fields"]:
        out.append(Name(top, reserved_namespace(proto), "the namespace of the reserved fields", (), False))
    for t, owner in nc.types(out, f"namespace {ns}::types", proto, str):
        scope = f"{t['kind']} {ns}::types::{t['name']}"
        if t["kind"] == "enum":
            out.extend(nc.enum_values(scope, owner, t, ident))
        elif t["kind"] == "bitfield":
            out.extend(taken(scope, BITFIELD_OWN, "a member every bitfield class has,", owner))
            for b, bw, element in nc.each_member(t, owner):
                getter = ident(b["name"], frozenset({"raw", "set_raw", "Raw"}))
                out.append(Name(scope, getter, element, bw, owner=owner))
                out.append(Name(scope, "set_" + b["name"], f"the setter of {element}", bw, False, owner))
                out.append(Name(scope, b["name"] + "_mask", f"the mask of {element}", bw, False, owner))
        elif t["kind"] == "struct":
            out.extend(nc.struct_members(scope, owner, proto, t, ident))
    for s in [None, *proto["sets"]]:
        fields = proto["reserved_fields"] if s is None else s["fields"]
        set_ns = reserved_namespace(proto) if s is None else set_namespace(s)
        structs = layout_names(fields)
        for lay in (x for x in layouts(proto) if x.set is s):
            scope = f"namespace {ns}::{set_ns}"
            struct = structs[(lay.field["name"], lay.device)]
            out.append(Name(scope, struct, lay.what, lay.where))
            members = f"struct {ns}::{set_ns}::{struct}"
            for q in model.layout(proto, lay.variant):
                pw = lay.where if q.function else lay.params_where + (q.name,)
                out.append(Name(members, ident(q.name), param_element(q, lay.what), pw, owner=lay.what))
    out += _command_api(proto, ns)
    return out


# A typed command function's own parameters and local (templates/cpp/include/commands.hpp.j2).
FUNCTION_OWN = ("connection", "options", "v")


def _command_api(proto: dict, ns: str) -> list[Name]:
    """The typed command API (backend.session_context, commands.hpp.j2):
    <ns>::api::<set>::<command>::<function>(connection, arguments..., options)."""
    out: list[Name] = []
    for s, f, c in calls(proto):
        set_ns = f"namespace {ns}::api::{set_namespace(s)}"
        what = f"the command namespace of field {s['name']}.{f['name']}"
        fw = (s["name"], f["name"])
        out.append(Name(set_ns, ident(f["name"]), what, fw, owner=s["name"]))
        name = call_name(c)
        cmd_ns = f"{set_ns[len('namespace ') :]}::{ident(f['name'])}"
        out.append(
            Name(
                f"namespace {cmd_ns}", name, f"the function of {what} for {c.function or 'the command'}", fw, owner=what
            )
        )
        scope, owner = f"function {cmd_ns}::{name}", f"{what} {name}"
        out.extend(taken(scope, FUNCTION_OWN, "a parameter or variable of the function,", owner))
        out.extend(nc.call_arguments(scope, owner, what, s, f, c, ident))
    return out
