"""Pass: what a command session needs beyond the layouts (docs/conformance.md section 8).

Per command layout (variant): `timeout`, the extra time the manuals give a long command before
its reply (`{ms, param, functions, sources}` or null; the allowance is `ms` plus the value of the
integer parameter `param`, in milliseconds, and applies to the listed functions only when
`functions` is given), checked against the layout's parameters and functions.

Per protocol: `session`, how a reply is matched: the reserved field of role `ack` (its
descriptor), which of its two parameters echoes the command descriptor and which carries the
code, the code's enum (null when the code is a plain u8) and the value that means success (0). The
ack field must be exactly two one-byte parameters, the echo first, so every runtime reads it as
two bytes.
"""

from __future__ import annotations

from .context import Context

_INTEGER = {"u8", "u16", "u32", "u64"}


def run(ctx: Context) -> None:
    for s in ctx.sets:
        for f in s["fields"]:
            spec = f["_spec"]
            sources = spec["variants"] if "variants" in spec else [spec]
            for j, (v, src) in enumerate(zip(f["variants"], sources)):
                path = f["_path"] + (("variants", j) if "variants" in spec else ())
                v["timeout"] = _timeout(ctx, f, v, src, path, f"{s['name']}.{f['name']}")
    ctx.session = _session(ctx)


def _timeout(ctx: Context, f: dict, v: dict, src: dict, path: tuple, owner: str) -> dict | None:
    t = src.get("timeout")
    if t is None:
        return None
    sf = f["_sf"]
    if f["role"] != "command":
        ctx.err(sf, path + ("timeout",), f"{owner}: only commands have a reply timeout", "no timeout here")
    param = t.get("param")
    if param is not None:
        target = next((q for q in v["params"] if q["name"] == param), None)
        if target is None or target["type"]["kind"] != "primitive" or target["type"]["name"] not in _INTEGER:
            ctx.err(
                sf,
                path + ("timeout", "param"),
                f"{owner}: timeout parameter '{param}' is not an unsigned integer parameter of the command",
                "the name of a u8/u16/u32 parameter giving milliseconds",
            )
        elif target["count"] is not None or target["optional"]:
            ctx.err(
                sf,
                path + ("timeout", "param"),
                f"{owner}: timeout parameter '{param}' must be a required scalar",
                "a required u8/u16/u32 parameter",
            )
    functions = t.get("functions")
    for k, fn in enumerate(functions or []):
        if v["functions"] is None or fn not in v["functions"]:
            ctx.err(
                sf,
                path + ("timeout", "functions", k),
                f"{owner}: timeout for function '{fn}', which the command does not support",
                "one of the command's functions",
            )
    return {
        "ms": t["ms"],
        "param": param,
        "functions": list(functions) if functions else None,
        "sources": ctx.check_sources(sf, path + ("timeout", "sources"), t["sources"]),
    }


def _session(ctx: Context) -> dict | None:
    acks = [r for r in ctx.reserved if r["role"] == "ack"]
    if not acks:
        return None
    ack = acks[0]
    params = ack["params"]
    ok = (
        len(params) == 2
        and all(p["count"] is None and p["size"] == {"min": 1, "max": 1, "fixed": True} for p in params)
        and params[0]["type"]["kind"] == "primitive"
        and params[1]["type"]["kind"] in ("primitive", "enum")
    )
    if not ok:
        ctx.err(
            ctx.pf,
            ("reserved_fields",),
            f"ack field {ack['name']}: a session needs two one-byte parameters, the echoed descriptor then the code",
            "params: [{name: ..., type: u8}, {name: ..., type: u8 or a u8 enum}]",
        )
        return None
    enum = ctx.types.get(params[1]["type"]["name"], {}) if params[1]["type"]["kind"] == "enum" else None
    if enum is not None and not any(v["value"] == 0 for v in enum.get("values", [])):
        ctx.err(
            ctx.pf,
            ("reserved_fields",),
            f"ack field {ack['name']}: code enum {enum.get('name')} has no value 0 (success)",
            "a value 0 meaning the command was accepted",
        )
    return {
        "ack": ack["id"],
        "ack_name": ack["name"],
        "echo": params[0]["name"],
        "code": params[1]["name"],
        "code_enum": enum["name"] if enum else None,
        "ok": 0,
    }
