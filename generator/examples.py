"""The "getting started" example program every language back end renders into its package.

Each package gets `examples/getting_started.<ext>`: run as `getting_started FILE`, it builds the
example command with the packet builder and its typed value and prints `command <hex>`, then
feeds FILE to the stream parser in blocks of `BLOCK_SIZE` bytes, flushes it at the end, and
prints `packet set=0xSS fields=NAME,...` (`?` for an entry that is not a decoded field) for
every packet and `skipped N` for every skip run. The documentation quotes the parts between the
marker comments `[build-command]`, `[parse-stream]`, `[read-file]` and `[end]`.

The example command is chosen from the IR by a data rule, never by name (see example_command);
the back ends only map it to their own names (their `api_names`).
"""

from __future__ import annotations

from typing import Callable

from . import model
from .commands import Call, commands
from .passes.session_example import CALLS as SESSION_CALLS
from .passes.session_example import STEPS as SESSION_STEPS
from .render import ToolError

# The source file of the example in each package, without its extension, and the block size the
# program reads its input in.
PROGRAM = "getting_started"
BLOCK_SIZE = 4096
# Comment lines that mark the parts the documentation cuts out (each part is closed by END).
PARTS = ("build-command", "parse-stream", "read-file")
END = "end"


class ExampleError(ToolError):
    """The spec has no command the example can send (reported like a tool error, no traceback)."""


def _is_plain_command(field: dict) -> bool:
    """A command without parameters, function selector or per-device layouts."""
    return (
        field["role"] == "command"
        and field["params"] == []
        and field["functions"] is None
        and not model.per_device(field)
    )


def example_command(protocol: dict) -> tuple[dict, dict]:
    """(set, field) of the example command: in the command set with the lowest id, the first
    field (in spec order) with role "command", no parameters, one variant and no function
    selector. Raises ExampleError when no command set has one."""
    command_sets = sorted((s for s in protocol["sets"] if s["kind"] == "command"), key=lambda s: s["id"])
    if not command_sets:
        raise ExampleError(f"protocol {protocol['name']} has no command set for the getting-started example")
    first = command_sets[0]
    for field in first["fields"]:
        if _is_plain_command(field):
            return first, field
    raise ExampleError(
        f"protocol {protocol['name']}: command set {first['name']} (0x{first['id']:02X}) has no command without"
        " parameters for the getting-started example"
    )


def typed_field_example(protocol: dict) -> tuple[dict, dict] | None:
    """(set, field) of the typed one-field example (decode a received field's data, put it in a
    packet): in the data set with the lowest id, the first field (in spec order) with role "data",
    one variant (no per-device layouts) and a fixed, non-zero size; None when there is none (the
    example is then left out)."""
    for s in sorted((s for s in protocol["sets"] if s["kind"] == "data"), key=lambda s: s["id"]):
        for field in s["fields"]:
            if field["role"] == "data" and not model.per_device(field):
                size = field["variants"][0]["size"]
                if size["fixed"] and size["min"] > 0:
                    return s, field
    return None


def example_context(protocol: dict, api_names: Callable[[dict, dict, dict], dict]) -> dict:
    """What an example template prints besides the back end's own context: the chosen command
    (set and field of the IR, and the back end's names for it) and the block size."""
    set_, field = example_command(protocol)
    return {
        "program": PROGRAM,
        "block_size": BLOCK_SIZE,
        "set": set_,
        "field": field,
        "api": api_names(protocol, set_, field),
    }


# ---------------------------------------------------------------------------------------------
# The "configure the device and stream data" example (issue 20): examples/configure_and_stream.<ext>,
# run as `configure_and_stream ADDRESS [COUNT]` (ADDRESS tcp:HOST:PORT or a serial device path).
# It connects with the session's blocking API, pings, reads the device information, writes then
# reads one setting, sets the data message format, enables the stream and prints COUNT data
# packets through one handler per data descriptor. The documentation quotes the parts between
# the marker comments `[connect]`, `[configure]`, `[stream]` and `[end]`.
#
# The commands are the protocol file's `session_example` (the IR's `session_example`, checked by
# generator/passes/session_example.py); session_example() resolves them against the IR into the
# calls each step makes, so every back end prints the same program.
SESSION_PROGRAM = "configure_and_stream"
SESSION_PARTS = ("connect", "configure", "stream")
SESSION_COUNT = 5  # data packets printed when COUNT is not given
_WHERE = "the protocol file's session_example"


def _find(protocol: dict, set_name: str, field_name: str) -> tuple[dict, dict]:
    for s in protocol["sets"]:
        if s["name"] == set_name:
            for f in s["fields"]:
                if f["name"] == field_name:
                    return s, f
    raise ExampleError(
        f"protocol {protocol['name']}: the configure-and-stream example uses {set_name}.{field_name},"
        f" which the spec does not have ({_WHERE})"
    )


def device_variant(protocol: dict, field: dict, device: str) -> dict:
    """The layout of field for device (a per-device variant, or the one shared by all)."""
    for v in field["variants"]:
        if v["device"] is None or v["device"] == device:
            return v
    raise ExampleError(f"protocol {protocol['name']}: {field['name']} has no layout for {device}")


def session_example(protocol: dict) -> dict | None:
    """The configure-and-stream example of a protocol, resolved against the IR (None when the
    protocol has none): device, and per step (ping, info, setting, format, enable) the set, field,
    layout variant for the device, the values written and `calls`: per function the step calls
    (SESSION_CALLS; None for a command without function selector) the generator/commands.py
    Call the program makes for the device; data: the set and its fields."""
    table = protocol.get("session_example")
    if table is None or not protocol.get("session"):
        return None
    device = table["device"]
    if device not in [d["id"] if isinstance(d, dict) else d for d in protocol["devices"]]:
        raise ExampleError(f"protocol {protocol['name']}: the example's device {device} is not in the spec")
    out: dict = {"program": SESSION_PROGRAM, "count": SESSION_COUNT, "device": device}
    cmds = commands(protocol)
    for step in SESSION_STEPS:
        set_name, field_name, values = table[step]["set"], table[step]["command"], table[step]["values"]
        s, f = _find(protocol, set_name, field_name)
        v = device_variant(protocol, f, device)
        names = {q["name"] for q in v["params"]}
        unknown = sorted(set(values) - names)
        if unknown:
            raise ExampleError(f"protocol {protocol['name']}: {field_name} has no parameter {', '.join(unknown)}")
        calls: dict[str | None, Call] = {}
        for fn in SESSION_CALLS[step]:
            fn = fn if f["functions"] else None
            call = cmds.call(s["id"], f["name"], fn, device)
            if call is None:
                raise ExampleError(
                    f"protocol {protocol['name']}: {field_name} has no {fn or 'plain'} call for {device} ({_WHERE})"
                )
            calls[fn] = call
        out[step] = {"set": s, "field": f, "variant": v, "values": values, "calls": calls}
    data_set, data_names = table["data"]["set"], table["data"]["fields"]
    fields = [_find(protocol, data_set, n) for n in data_names]
    out["data"] = {"set": fields[0][0], "fields": [f for _s, f in fields]}
    return out


def session_example_context(ex: dict, call: Callable[[str, str | None], dict]) -> dict:
    """What every language's configure-and-stream template prints besides its own names: the
    program, the count, the titles, the data set, and per step the back end's `call(step,
    function)` for each function the step calls (session_example's `calls`)."""

    def fns(step: str) -> list[str | None]:
        return list(ex[step]["calls"])

    data_set = ex["data"]["set"]
    return {
        "program": ex["program"],
        "count": ex["count"],
        "ping": call("ping", fns("ping")[0]),
        "info": call("info", fns("info")[0]),
        "info_title": ex["info"]["field"]["title"],
        "setting_title": ex["setting"]["field"]["title"],
        "setting_write": call("setting", fns("setting")[0]),
        "setting_read": call("setting", fns("setting")[-1]),
        "format_title": ex["format"]["field"]["title"],
        "format": call("format", fns("format")[0]),
        "enable_title": ex["enable"]["field"]["title"],
        "enable": call("enable", fns("enable")[0]),
        "data_set": data_set["id"],
        "data_set_title": data_set["title"],
    }


def example_literal(
    types: dict[str, dict],
    tref: dict,
    value,
    lang: str,
    names: Callable[[str, str], str],
    float_suffix: str = "",
    top: bool = True,
) -> dict:
    """One value of the configure-and-stream example as a record a back end's session_macros.j2
    `literal` spells: a struct (`type`; `fields`, each `field` and `value`, in the spec's member
    order), an enum (`type`; `member`, None for a number the spec does not name; `number`), a
    bool, a float (`text`: its shortest repr, `float_suffix` after a single), an int (`hex` for a
    top-level value of 0x10 or more). `names(kind, spec_name)` spells a "type", "field" or
    "member" (enum value) in the language `lang` (named in the error a value it cannot write
    gives)."""
    kind = tref["kind"]
    if kind == "struct":
        t = types[tref["name"]]
        qs = {q["name"]: q["type"] for q in t["params"]}
        if set(value) != set(qs):
            raise ExampleError(f"{lang} back end: the example gives {sorted(value)} of {tref['name']} ({sorted(qs)})")
        fields = [
            {"field": names("field", k), "value": example_literal(types, q, value[k], lang, names, float_suffix, False)}
            for k, q in qs.items()
        ]
        return {"kind": "struct", "type": names("type", tref["name"]), "fields": fields}
    if kind == "enum":
        values = types[tref["name"]]["values"]
        number = value if isinstance(value, int) else next(x["value"] for x in values if x["name"] == value)
        name = next((x["name"] for x in values if x["value"] == number), None)
        member = names("member", name) if name else None
        return {"kind": "enum", "type": names("type", tref["name"]), "member": member, "number": number}
    if kind == "primitive" and tref["name"] == "bool":
        return {"kind": "bool", "value": bool(value)}
    if kind == "primitive" and tref["name"] in ("float", "double"):
        return {"kind": "text", "text": repr(float(value)) + (float_suffix if tref["name"] == "float" else "")}
    if kind in ("primitive", "bitfield") and isinstance(value, int) and not isinstance(value, bool):
        return {"kind": "int", "value": value, "hex": value >= 0x10 and top}
    raise ExampleError(f"{lang} back end: the configure-and-stream example cannot write a {kind} value {value!r}")


def example_arguments(protocol: dict, ex: dict, step: str, fn: str | None, lang: str) -> list[tuple]:
    """The arguments of one call of session_example `ex` (its step `step`, function `fn`), in the
    call's order: (argument, its layout-model parameter, the example's value or None for an
    optional argument the example leaves out). A required argument without a value is an
    ExampleError of the back end `lang`."""
    st = ex[step]
    values = st["values"] if fn in (None, "write") else {}
    params = {q.name: q for q in model.layout(protocol, st["variant"]).params}
    out = []
    for a in st["calls"][fn].arguments:
        if a.name not in values and a.required:
            raise ExampleError(
                f"{lang} back end: the configure-and-stream example gives no value for {a.name} of"
                f" {st['field']['name']} ({_WHERE})"
            )
        out.append((a, params[a.name], values.get(a.name)))
    return out
