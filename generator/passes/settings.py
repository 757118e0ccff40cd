"""Pass: the protocol file's `settings` section, what the device command line's settings files
hold (docs/spec-format.md "Settings"; docs/configure-a-device.md), checked against the rest of the
spec and exported as the protocol's `settings` entry (null without the section).

A setting is a command layout with the write and read functions whose command is not named in
`not_settings`. Checked: every command named is a command of the protocol with a read function;
every key parameter is a parameter that the command's read sends (a layout has it, not optional,
`read` among its functions); every key value is an integer that fits the parameter's type or, for
an enum parameter, one of its members' names; `base_rates` is the model's data sets with a base
rate (the `simulation` section's `base_rates`). A keyed setting (a read that sends a parameter
besides the function selector) without a `keys` entry is not read by `dump` (a file may still
write it: its entries carry their keys). Exported: `not_settings` as written and
`keys` with, per entry, `resolved`: device -> the list of key combinations (parameter -> integer),
for each device whose layout has the key parameters.
"""

from __future__ import annotations

import itertools

from .context import Context

_LIMITS = {"u8": 0xFF, "u16": 0xFFFF, "u32": 0xFFFFFFFF}


def run(ctx: Context) -> None:
    spec = ctx.pf.data.get("settings")
    ctx.settings = None
    if spec is None:
        return
    sf = ctx.pf
    commands: dict[str, dict] = {}
    for s in ctx.sets:
        for f in s["fields"]:
            if f["role"] == "command":
                commands[f["name"]] = f

    def err(path: tuple, message: str, expected: str) -> None:
        ctx.err(sf, ("settings",) + path, message, expected)

    def readable(name: str) -> list[dict]:
        f = commands.get(name)
        return [v for v in (f or {}).get("variants", []) if "read" in (v["functions"] or [])]

    excluded = set()
    for i, entry in enumerate(spec.get("not_settings", [])):
        if not readable(entry["command"]):
            err(
                ("not_settings", i, "command"),
                f"settings: '{entry['command']}' is not a command with a read function",
                "a command name",
            )
        excluded.add(entry["command"])
    rates = {r["device"]: [x["set"] for x in r["rates"]] for r in ((ctx.simulation or {}).get("base_rates") or [])}
    keys = []
    for i, entry in enumerate(spec.get("keys", [])):
        path = ("keys", i)
        variants = readable(entry["command"])
        if not variants:
            err(
                path + ("command",),
                f"settings: '{entry['command']}' is not a command with a read function",
                "a command name",
            )
            continue
        names = tuple(entry["values"])
        resolved: dict[str, list[dict]] = {}
        for v in variants:
            params = {q["name"]: q for q in v["params"]}
            if not all(n in params for n in names):
                continue
            per_param = []
            for n in names:
                q = params[n]
                if q["optional"] or "read" not in (q["functions"] or []):
                    err(
                        path + ("values", n),
                        f"settings: {entry['command']} does not send '{n}' with read",
                        "a parameter read sends",
                    )
                    per_param.append([])
                    continue
                per_param.append(None)
            for dev in v["devices"]:
                lists = []
                for n in names:
                    lists.append(
                        _values(
                            ctx,
                            err,
                            path + ("values", n),
                            entry["command"],
                            params[n],
                            entry["values"][n],
                            rates.get(dev),
                        )
                    )
                resolved[dev] = [dict(zip(names, combo)) for combo in itertools.product(*lists)]
        if not resolved:
            err(
                path + ("values",),
                f"settings: no layout of {entry['command']} has the parameters {', '.join(names)}",
                "the parameters read sends",
            )
        keys.append(
            {
                "command": entry["command"],
                "values": entry["values"],
                "decision": entry["decision"],
                "sources": ctx.check_sources(sf, ("settings",) + path + ("sources",), entry["sources"]),
                "resolved": resolved,
            }
        )
    ctx.settings = {"not_settings": list(spec.get("not_settings", [])), "keys": keys}


def _values(ctx: Context, err, path: tuple, command: str, param: dict, values, rates: list[int] | None) -> list[int]:
    t = param["type"]
    if values == "base_rates":
        if rates is None:
            err(
                path,
                f"settings: base_rates for {command}, but the simulation section gives no base rates",
                "base_rates under simulation",
            )
            return []
        return list(rates)
    out = []
    members = {}
    if t["kind"] == "enum":
        members = {m["name"]: m["value"] for m in ctx.types[t["name"]]["values"]}
    for j, x in enumerate(values):
        if isinstance(x, str):
            if x not in members:
                err(
                    path + (j,),
                    f"settings: '{x}' is not a member of {t.get('name')}",
                    "an enum member name or an integer",
                )
                continue
            out.append(members[x])
        else:
            limit = _LIMITS.get(t.get("name") or "", None)
            if limit is None and t["kind"] == "enum":
                limit = _LIMITS.get(ctx.types[t["name"]].get("base", "u8"), 0xFF)
            if limit is not None and not 0 <= x <= limit:
                err(path + (j,), f"settings: {x} does not fit {param['name']} ({t.get('name')})", f"0..{limit}")
                continue
            out.append(x)
    return out
