"""Pass: the protocol file's `session_example` section, the configure-and-stream example program of
every package (docs/spec-format.md `session_example`; generator/examples.py session_example builds
the program's steps from it), checked against the rest of the spec and exported as the protocol's
`session_example` entry (null without the section).

Checked: the protocol has a session (an ack field: the session_rule pass); the device is one of
the protocol's; each step's set is a command set and its command a command of that set with a
layout for the device (its sources cite the device's manual); every value names a parameter of that layout; a step that writes (setting,
format, enable) and whose command has a function selector has `write` for the device, and the
setting `read` too; a command without function selector cannot be the setting (it is written and
read back). The data step's set is a data set and its fields are fields of that set. The values'
types are the back ends' to spell (generator/examples.py example_literal names a value it cannot
write).
"""

from __future__ import annotations

from .context import Context

# The steps, in the program's order, and the functions each calls (None: the plain command, or
# "write" when the command has a function selector); values go to the calls that send them (None
# and "write"). generator/examples.py builds each step's calls from these.
CALLS: dict[str, tuple[str | None, ...]] = {
    "ping": (None,),
    "info": (None,),
    "setting": ("write", "read"),
    "format": ("write",),
    "enable": ("write",),
}
STEPS = tuple(CALLS)


def run(ctx: Context) -> None:
    spec = ctx.pf.data.get("session_example")
    ctx.session_example = None
    if spec is None:
        return
    sf = ctx.pf
    n_errors = len(ctx.errors)

    def err(path: tuple, message: str, expected: str) -> None:
        ctx.err(sf, ("session_example",) + path, "session_example: " + message, expected)

    if ctx.session is None:
        err(
            (),
            "the protocol has no session (no reserved field of role ack)",
            "a session_example only with an ack field",
        )
    device = spec["device"]
    if device not in ctx.device_ids:
        err(("device",), f"unknown device '{device}'", "one of " + ", ".join(ctx.device_ids))
        device = None  # no layout to check the steps against
    sets = {s["name"]: s for s in ctx.sets}
    out: dict = {"device": spec["device"]}
    for step in STEPS:
        entry = spec[step]
        out[step] = {"set": entry["set"], "command": entry["command"], "values": dict(entry.get("values") or {})}
        s = sets.get(entry["set"])
        if s is None or s["kind"] != "command":
            err((step, "set"), f"{step}: '{entry['set']}' is not a command set", "the name of a command set")
            continue
        f = next((f for f in s["fields"] if f["name"] == entry["command"] and f["role"] == "command"), None)
        if f is None:
            err((step, "command"), f"{step}: '{entry['command']}' is not a command of {s['name']}", "a command name")
            continue
        if device is None:
            continue
        v = next((v for v in f["variants"] if device in v["devices"]), None)
        if v is None:
            err(
                (step, "command"),
                f"{step}: {s['name']}.{f['name']} has no layout for {device}",
                "a command the device has",
            )
            continue
        names = [q["name"] for q in v["params"]]
        for k in entry.get("values") or {}:
            if k not in names:
                err(
                    (step, "values", k),
                    f"{step}: {f['name']} has no parameter '{k}'",
                    "one of: " + (", ".join(names) or "none (no values)"),
                )
        functions = v["functions"]
        if functions is None and step == "setting":
            err(
                (step, "command"),
                f"setting: {f['name']} has no function selector to write and read it",
                "a command with write and read",
            )
        for fn in CALLS[step] if functions is not None else ():
            if fn is not None and fn not in functions:
                err((step, "command"), f"{step}: {f['name']} has no {fn} function for {device}", f"a command with {fn}")
    data = spec["data"]
    out["data"] = {"set": data["set"], "fields": list(data["fields"])}
    ds = sets.get(data["set"])
    if ds is None or ds["kind"] != "data":
        err(("data", "set"), f"data: '{data['set']}' is not a data set", "the name of a data set")
    else:
        have = {f["name"] for f in ds["fields"]}
        for i, name in enumerate(data["fields"]):
            if name not in have:
                err(("data", "fields", i), f"data: '{name}' is not a field of {ds['name']}", "a field of the data set")
    if len(ctx.errors) == n_errors:
        ctx.session_example = out
