"""The identifiers the Python back end gives to spec elements, for the shared name check
(generator/name_check.py), spelled with the back end's own functions (backend.py)."""

from __future__ import annotations

from generator import model
from generator import name_check as nc
from generator.name_check import Name, calls, layouts, param_element, taken
from generator.naming import camel

from . import facts
from .backend import (
    BITFIELD_RESERVED,
    DEVICE_ATTRIBUTES,
    EXPORTED,
    RUNTIME_MODULES,
    const_name,
    py_attr,
    set_module,
)


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
    for t, owner in nc.types(out, f"module {pkg}.types", proto, str):
        scope = f"class {pkg}.types.{t['name']}"
        if t["kind"] == "enum":
            out.extend(nc.enum_values(scope, owner, t, const_name))
        elif t["kind"] == "bitfield":
            for b, bw, element in nc.each_member(t, owner):
                out.append(Name(scope, py_attr(b["name"], BITFIELD_RESERVED), element, bw, owner=owner))
                out.append(Name(scope, const_name(b["name"]), f"the mask of {element}", bw, False, owner))
        elif t["kind"] == "struct":
            out.extend(nc.struct_members(scope, owner, proto, t, py_attr))
    for lay in layouts(proto):
        module = f"{pkg}.reserved" if lay.set is None else f"{pkg}.{set_module(lay.set)}"
        cls = camel(lay.field["name"]) + (f"_{lay.device}" if lay.device else "")
        out.append(Name(f"module {module}", cls, lay.what, lay.where))
        for q in model.layout(proto, lay.variant):
            pw = lay.where if q.function else lay.params_where + (q.name,)
            out.append(Name(f"class {module}.{cls}", py_attr(q.name), param_element(q, lay.what), pw, owner=lay.what))
    out += _command_api(proto)
    return out


# What templates/python/package/command_api.py.j2 defines besides the spec's names.
API_OWN = ("_Command", "DeviceCommands", "bind")
COMMAND_OWN = ("__init__", "_pick", "_call", "device")
# A method's own parameters and locals: an argument with one of these names would shadow them.
METHOD_OWN = ("self", "timeout_ms", "check_device", "cls", "command")


def _command_api(proto: dict) -> list[Name]:
    """The typed command API (backend.session_context, command_api.py.j2): device.<set>.<command>
    .<method>(arguments), a class per set and per command in one module."""
    pkg = proto["package"]
    module = f"module {pkg}.command_api"
    device = f"class {pkg}.session.Device"
    out = taken(module, API_OWN, "a name of the module,") + taken(device, DEVICE_ATTRIBUTES, "an attribute of Device,")
    seen_sets: set[int] = set()
    seen_commands: set[tuple[int, str]] = set()
    for s, f, c in calls(proto):
        sw, fw = (s["name"],), (s["name"], f["name"])
        set_cls = camel(s["name"]) + "Commands"
        if s["id"] not in seen_sets:
            seen_sets.add(s["id"])
            attr = set_module(s)
            attr = attr + "_set" if attr in DEVICE_ATTRIBUTES else attr
            out.append(Name(device, attr, f"the command set {s['name']}", sw))
            out.append(Name(module, set_cls, f"the command class of set {s['name']}", sw))
        cmd_cls = camel(f["name"])
        what = f"the command class of field {s['name']}.{f['name']}"
        if (s["id"], f["name"]) not in seen_commands:
            seen_commands.add((s["id"], f["name"]))
            out.append(Name(module, cmd_cls, what, fw))
            out.append(
                Name(
                    f"class {set_cls}", py_attr(f["name"]), f"the command {s['name']}.{f['name']}", fw, owner=s["name"]
                )
            )
            out.extend(taken(f"class {cmd_cls}", COMMAND_OWN, "a member of every command class,", what))
        method = _method_name(c)
        out.append(
            Name(
                f"class {cmd_cls}",
                method,
                f"the method of {what} for {c.function or 'the command'}" + (f" on {c.device}" if c.device else ""),
                fw,
                False,
                what,
            )
        )
        scope, owner = f"method {cmd_cls}.{method}", f"{what} {method}"
        out.extend(taken(scope, METHOD_OWN, "a parameter or variable of the method,", owner))
        out.extend(nc.call_arguments(scope, owner, what, s, f, c, py_attr))
    return out


def _method_name(c) -> str:
    """backend._method's name of a call."""
    name = "__call__" if c.function is None else py_attr(c.function)
    if c.device is not None:
        name = f"{name}_{c.device}" if c.function is not None else f"call_{c.device}"
    return name
