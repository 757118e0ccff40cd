"""The identifiers the Rust back end gives to spec elements, for the shared name check
(generator/name_check.py), spelled with the back end's own functions (backend.py)."""

from __future__ import annotations

from generator import model
from generator import name_check as nc
from generator.name_check import Name, calls, layouts, param_element, taken
from generator.naming import upper

from .backend import camel, ident, set_method
from .facts import DEVICE_METHODS, KEYWORDS, NOT_RAW, RESERVED_MODULES


def reserved(name: str) -> str | None:
    """Why name is still reserved in Rust (after ident()'s escaping: `r#type`, `self_`), or None."""
    if name in NOT_RAW:
        return "is a Rust keyword that cannot be a raw identifier"
    if name in KEYWORDS:
        return "is a Rust keyword"
    if "#" in name[2 if name.startswith("r#") else 0 :]:
        return "is no Rust identifier (a raw identifier `r#...` inside a longer name)"
    return None


def set_modules(proto: dict) -> dict[int, str]:
    """Set id -> module, as backend._Protocol._check_names names them (a `_set` suffix for a set
    whose name is taken or a keyword)."""
    used = set(RESERVED_MODULES) | {proto["package"]}
    out = {}
    for s in proto["sets"]:
        m = s["name"]
        if m in used or m in KEYWORDS or m in NOT_RAW:
            m = m + "_set"
        used.add(m)
        out[s["id"]] = m
    return out


def names(proto: dict) -> list[Name]:
    pkg = proto["package"]
    out: list[Name] = []
    top = f"crate {pkg}"
    out.extend(taken(top, RESERVED_MODULES | {pkg}, "a module of the crate,"))
    modules = set_modules(proto)
    variants = f"enum {pkg}::FieldValue"
    if proto["reserved_fields"]:
        out.append(Name(variants, "Reserved", "the variant of the reserved fields", (), False))
    for s in proto["sets"]:
        out.append(Name(top, modules[s["id"]], f"the module of set {s['name']}", (s["name"],)))
        out.append(Name(variants, camel(modules[s["id"]]), f"the FieldValue variant of set {s['name']}", (s["name"],)))
    for t, owner in nc.types(out, f"module {pkg}::types", proto, camel):
        scope = f"{t['kind']} {pkg}::types::{camel(t['name'])}"
        if t["kind"] == "enum":
            out.extend(nc.enum_values(scope, owner, t, upper))
        elif t["kind"] == "bitfield":
            for b, bw, element in nc.each_member(t, owner):
                out.append(Name(scope, ident(b["name"]), element, bw, owner=owner))
                out.append(Name(scope, f"set_{b['name']}", f"the setter of {element}", bw, False, owner))
                out.append(Name(scope + " (constants)", upper(b["name"]), f"the mask of {element}", bw, False, owner))
        elif t["kind"] == "struct":
            out.extend(nc.struct_members(scope, owner, proto, t, ident))
        else:
            for m in t["members"]:
                out.append(Name(scope, camel(m["when"]), f"member {m['when']} of {owner}", (t["name"],), owner=owner))
    for lay in layouts(proto):
        module = "reserved" if lay.set is None else modules[lay.set["id"]]
        scope = f"module {pkg}::{module}"
        out.extend(taken(scope, ["ReservedField" if lay.set is None else "SetField"], "the field enum,"))
        base = camel(lay.field["name"])
        struct = base + (camel(lay.device) if lay.device else "")
        out.append(Name(scope, struct, lay.what, lay.where))
        if lay.device:  # a field with per-device layouts: an enum of them, named as the field
            out.append(Name(scope, base, lay.what.split(" (device")[0], lay.where))
        for q in model.layout(proto, lay.variant):
            pw = lay.where if q.function else lay.params_where + (q.name,)
            out.append(
                Name(f"struct {pkg}::{module}::{struct}", ident(q.name), param_element(q, lay.what), pw, owner=lay.what)
            )
    out += _command_api(proto, modules)
    return out


def _command_api(proto: dict, modules: dict[int, str]) -> list[Name]:
    """The typed command API (backend.session_context, command_api.rs.j2): device.<set>()
    .<command>().<function>(arguments) (a plain command: device.<set>().<command>(arguments)), and
    one `send_<command>_<call>` function per call, all in one module."""
    pkg = proto["package"]
    module = f"module {pkg}::command_api"
    device = f"impl {pkg}::device::Device"
    out = taken(module, ["reply"], "a function of the module,") + taken(device, DEVICE_METHODS, "a method of Device,")
    for s, f, c in calls(proto):
        sw, fw = (s["name"],), (s["name"], f["name"])
        set_struct = camel(modules[s["id"]]) + "Commands"
        out.append(Name(device, set_method(modules[s["id"]]), f"the command set {s['name']}", sw))
        out.append(Name(module, set_struct, f"the command struct of set {s['name']}", sw))
        what = f"the command {s['name']}.{f['name']}"
        base = ident(f["name"]) if c.function is None else ident(c.function)
        method = f"{base}_{c.device}" if c.device is not None else base
        call = f"the method of {what} for {c.function or 'the command'}" + (f" on {c.device}" if c.device else "")
        if f["variants"][0]["functions"] is None:  # plain: the call is a method of the set's struct
            out.append(Name(f"struct {set_struct}", method, call, fw, owner=s["name"]))
        else:
            cmd_struct = camel(f["name"]) + "Command"
            out.append(Name(f"struct {set_struct}", ident(f["name"]), what, fw, owner=s["name"]))
            out.append(Name(module, cmd_struct, f"the command struct of {what}", fw))
            out.append(Name(f"struct {cmd_struct}", method, call, fw, owner=what))
        send = f"send_{ident(f['name'])}_{method}"
        out.append(Name(module, send, f"the function sending {what} for {c.function or 'the command'}", fw))
        scope, owner = f"fn {send}", f"{what} {method}"
        out.extend(taken(scope, ["device"], "the function's parameter", owner))
        out.extend(nc.call_arguments(scope, owner, what, s, f, c, ident))
    return out
