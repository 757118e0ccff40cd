"""Pass: each field's layouts ("variants"): one per device when the spec gives `variants`,
otherwise one from the field's own `params` or a shared `layout`. A layout checks its function
selector names, parameters, response conditions, ack suppression and that a device's variant
cites that device's manual. The field then gets its sources, devices and the convenience copies
of its first variant (docs/ir.md).
"""

from __future__ import annotations

from .context import Context, SpecFile
from .params import build_params, check_starting_values
from .sizes import layout_size


def run(ctx: Context) -> None:
    for s in ctx.sets:
        for f in s["fields"]:
            _field_variants(ctx, f)


def _field_variants(ctx: Context, field: dict) -> None:
    f, sf, fp, set_name = field["_spec"], field["_sf"], field["_path"], field["_set"]
    if "variants" in f:
        variants = []
        seen_dev: set[str] = set()
        for j, v in enumerate(f["variants"]):
            if v["device"] not in ctx.device_ids:
                ctx.err(
                    sf,
                    fp + ("variants", j, "device"),
                    f"unknown device '{v['device']}'",
                    "one of " + ", ".join(ctx.device_ids),
                )
            if v["device"] in seen_dev:
                ctx.err(
                    sf,
                    fp + ("variants", j, "device"),
                    f"{set_name}.{f['name']}: two variants for device '{v['device']}'",
                    "one variant per device",
                )
            seen_dev.add(v["device"])
            if ("params" in v) == ("layout" in v):
                ctx.err(
                    sf,
                    fp + ("variants", j),
                    f"{set_name}.{f['name']} ({v['device']}): needs exactly one of params or layout",
                    "params: [...] or layout: <FieldLayout>",
                )
            variants.append(_layout(ctx, sf, fp + ("variants", j), v, set_name, f, v["device"]))
        if f.get("functions") or f.get("response") or f.get("responses"):
            ctx.err(
                sf,
                fp,
                f"{set_name}.{f['name']}: with variants, functions/responses go in each variant",
                "per-variant functions/responses",
            )
        sources = [s for v in variants for s in v["sources"]]
    else:
        variants = [_layout(ctx, sf, fp, f, set_name, f, None)]
        sources = variants[0]["sources"]
    field["sources"] = sources
    field["devices"] = [x for x in ctx.device_ids if any(x in v["devices"] for v in variants)]
    field["variants"] = variants
    # Top-level convenience copies required by the exported IR contract.
    field["params"] = variants[0]["params"]
    field["size"] = variants[0]["size"]
    field["functions"] = variants[0]["functions"]
    field["responses"] = [r["id"] for v in variants for r in v["responses"]]
    field["response"] = field["responses"][0] if field["responses"] else None
    field["stated_lengths"] = [
        {"manual": src["manual"], "line": src.get("line"), "stated": src["stated_length"]}
        for src in sources
        if "stated_length" in src
    ]


def _layout(ctx: Context, sf: SpecFile, path: tuple, src: dict, set_name: str, field: dict, device: str | None) -> dict:
    """One layout of a field (docs/ir.md "variant") from src: the field's spec entry, or one entry
    of its `variants` for device."""
    owner = f"{set_name}.{field['name']}" + (f" ({device})" if device else "")
    functions = src.get("functions")
    if functions is not None:
        for j, fn in enumerate(functions):
            if ctx.function_values and fn not in ctx.function_values:
                ctx.err(
                    sf,
                    path + ("functions", j),
                    f"{owner}: unknown function '{fn}'",
                    "one of " + ", ".join(ctx.function_values),
                )
        if field["role"] != "command":
            ctx.err(
                sf,
                path + ("functions",),
                f"{owner}: only commands take a function selector",
                "no functions on responses and data",
            )
    layout_name = src.get("layout")
    if layout_name is not None:
        shared = ctx.field_layouts.get(layout_name)
        if shared is None:
            known = ", ".join(sorted(ctx.field_layouts)) or "none defined"
            ctx.err(
                sf,
                path + ("layout",),
                f"{owner}: unknown field layout '{layout_name}'",
                f"a name under field_layouts: ({known})",
            )
            params = []
        else:
            t, lsf, lpath = shared
            params = build_params(ctx, lsf, lpath + ("params",), t["params"], functions, f"field layout {layout_name}")
    else:
        params = build_params(ctx, sf, path + ("params",), src.get("params", []), functions, owner)
    responses = _responses(ctx, sf, path, src, owner, field, functions, params)
    ack = _ack_suppression(ctx, sf, path, src, owner, functions, params)
    sources = ctx.check_sources(sf, path + ("sources",), src.get("sources", []))
    if device is not None:
        devs = ctx.devices_of(sources)
        if devs and device not in devs:
            ctx.err(
                sf,
                path + ("device",),
                f"{owner}: variant for device '{device}' cites only manuals of {', '.join(devs)}",
                "sources from that device's manual",
            )
    devices = [device] if device else ctx.devices_of(sources)
    if layout_name is None:
        check_starting_values(ctx, sf, path + ("params",), functions, params, devices, owner)
    elif shared is not None:
        check_starting_values(ctx, lsf, lpath + ("params",), functions, params, devices, owner)
    return {
        "device": device,
        "devices": devices,
        "sources": sources,
        "notes": src.get("notes", []) if device else [],
        "functions": functions,
        "responses": responses,
        "ack_suppressed_by": ack,
        "params": params,
        "size": layout_size(params, selector=functions is not None),
        "layout": layout_name,
    }


def _responses(
    ctx: Context,
    sf: SpecFile,
    path: tuple,
    src: dict,
    owner: str,
    field: dict,
    functions: list[str] | None,
    params: list[dict],
) -> list[dict]:
    """A command layout's responses with their conditions checked (linked by link_responses)."""
    responses = []
    if "response" in src and "responses" in src:
        ctx.err(sf, path + ("response",), f"{owner}: both 'response' and 'responses'", "one of them")
    for j, r in enumerate(
        src.get("responses", []) if "responses" in src else ([src["response"]] if "response" in src else [])
    ):
        rp = path + (("responses", j) if "responses" in src else ("response",))
        if isinstance(r, int):
            r = {"id": r}
        when = r.get("when")
        if when:
            if "function" in when and functions is not None and when["function"] not in functions:
                ctx.err(
                    sf,
                    rp + ("when", "function"),
                    f"{owner}: response condition names function '{when['function']}', which the command does not support",
                    "one of " + ", ".join(functions),
                )
            if "param" in when:
                match = [q for q in params if q["name"] == when["param"]]
                if not match:
                    ctx.err(
                        sf,
                        rp + ("when", "param"),
                        f"{owner}: response condition names parameter '{when['param']}', which does not exist",
                        "a parameter of this command",
                    )
                elif "value" in when and isinstance(when["value"], str):
                    t = ctx.types.get(match[0]["type"].get("name", ""))
                    if not t or t["kind"] != "enum" or when["value"] not in {v["name"] for v in t["values"]}:
                        ctx.err(
                            sf,
                            rp + ("when", "value"),
                            f"{owner}: '{when['value']}' is not a value of parameter {when['param']}",
                            "an enum value name",
                        )
        responses.append({"id": r["id"], "when": when, "_loc": rp})
    if responses and field["role"] != "command":
        ctx.err(sf, path + ("response",), f"{owner}: only commands have responses", "no response on responses and data")
    return responses


def _ack_suppression(
    ctx: Context, sf: SpecFile, path: tuple, src: dict, owner: str, functions: list[str] | None, params: list[dict]
) -> dict | None:
    """What suppresses a command's ack (a function or a parameter value), checked; an enum value
    name becomes its integer."""
    ack = src.get("ack_suppressed_by")
    if ack:
        if "function" in ack and (functions is None or ack["function"] not in functions):
            ctx.err(
                sf,
                path + ("ack_suppressed_by", "function"),
                f"{owner}: ack suppression by function '{ack['function']}', which the command does not support",
                "one of the command's functions",
            )
        target = next((q for q in params if q["name"] == ack.get("param")), None)
        if "param" in ack and target is None:
            ctx.err(
                sf,
                path + ("ack_suppressed_by", "param"),
                f"{owner}: ack suppression by parameter '{ack['param']}', which does not exist",
                "a parameter of this command",
            )
        if "value" in ack:
            ack = dict(ack)
            enum = ctx.types.get(target["type"].get("name")) if target and target["type"]["kind"] == "enum" else None
            if "param" not in ack:
                ctx.err(sf, path + ("ack_suppressed_by", "value"), f"{owner}: value without param", "param: <name>")
            elif isinstance(ack["value"], str):
                names = {v["name"]: v["value"] for v in enum["values"]} if enum else {}
                if ack["value"] not in names:
                    ctx.err(
                        sf,
                        path + ("ack_suppressed_by", "value"),
                        f"{owner}: ack suppression value '{ack['value']}' is not a value of parameter {ack['param']}",
                        "one of " + ", ".join(names) if names else "an integer (the parameter is not an enum)",
                    )
                else:
                    ack["value"] = names[ack["value"]]
    return ack
