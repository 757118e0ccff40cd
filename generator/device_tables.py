"""The tables a device tool needs, language-neutral (docs/configure-a-device.md "The C tool"):
the settings per device (generator/settings_rows.py, the derivation the Python package's
_settings.py comes from), the enums their parameters name, the largest data size of every data
field (the link budget), and the facts of the spec's simulation and link sections the tool uses
(identity, descriptor lists, base rates, message formats, stream control, baud rate commands,
save-all). Names are the spec's; the C back end spells them as C literals in
templates/c/tools/device_facts.h.j2.
"""

from __future__ import annotations

from generator.linkfacts import bandwidth_sources
from generator.naming import camel, upper
from generator.settings_rows import setting_rows


def device_tables(proto: dict) -> dict:
    """The tables of a device tool (the C package's tools/device/, docs/configure-a-device.md):
    every setting per device (generator/settings_rows.py, the same derivation as the Python
    package's _settings.py), the enums their parameters name, the largest data size of every data
    field, and the facts of the spec's simulation section the tool uses (identity, descriptor
    lists, base rates, message formats, stream control, baud rate commands, save-all)."""
    types = {t["name"]: t for t in proto["types"]}
    by_name: dict[str, list[tuple[int, int]]] = {}
    for s in proto["sets"]:
        for f in s["fields"]:
            by_name.setdefault(f["name"], []).append((s["id"], f["id"]))
    enums: list[dict] = []
    enum_index: dict[str, int] = {}

    def enum_of(type_name: str) -> int:
        if type_name not in enum_index:
            enum_index[type_name] = len(enums)
            enums.append(
                {
                    "name": camel(type_name),
                    "members": [(upper(v["name"]).lower(), int(v["value"])) for v in types[type_name]["values"]],
                }
            )
        return enum_index[type_name]

    rows, sizes = setting_rows(proto, proto["sets"])
    settings: dict[str, list[dict]] = {d["id"]: [] for d in proto["devices"]}
    for r in rows:
        attrs = []
        for q, rq, units, qd in r["attrs"]:
            t = qd["type"]
            e = enum_of(t["name"]) if t["kind"] == "enum" and qd.get("count") is None else -1
            attrs.append({"name": q, "reply": rq, "units": units, "enum": e})
        for d in r["variant"]["devices"]:
            settings[d].append(
                {
                    "name": r["field"]["name"],
                    "set": r["set"]["id"],
                    "descriptor": r["field"]["id"],
                    "device": r["dev"],
                    "reply": r["reply_field"]["name"],
                    "keyed": r["keyed"],
                    "attrs": attrs,
                    "counts": list(r["counts"].items()),
                    "fill": r["fill"],
                    "keys": [[combo[k] for k in r["keyed"]] for combo in r["keys"][d]],
                }
            )
    ack = next((f for f in proto["reserved_fields"] if f["role"] == "ack"), None)
    ack_enum = -1
    if ack is not None:
        for q in ack["variants"][0]["params"]:
            if q["type"]["kind"] == "enum":
                ack_enum = enum_of(q["type"]["name"])
    sim = proto.get("simulation") or {}

    def cmd(name: str) -> list[tuple[int, int]]:
        return by_name.get(name, [])

    formats = [
        {
            "set": e.get("set", -1),
            "param": e.get("set_param"),
            "list": e["list"],
            "descriptor": e.get("descriptor"),
            "decimation": e.get("decimation"),
            "at": at,
        }
        for e in sim.get("formats", [])
        for at in cmd(e["command"])
    ]
    rates = [
        {"set": e.get("set", -1), "param": e.get("set_param"), "at": at}
        for e in sim.get("rates", [])
        for at in cmd(e["command"])
    ]
    enables = []
    for e in sim.get("enables", []):
        for at in cmd(e["command"]):
            sel = e.get("selector")
            enables.append(
                {
                    "at": at,
                    "flag": e["flag"],
                    "selector": sel["param"] if sel else None,
                    "map": [(x["value"], x["set"]) for x in sel["sets"]] if sel else [],
                    "set_param": e.get("set_param"),
                }
            )
    baud = [{"at": at, "param": e["param"]} for e in sim.get("baud", []) for at in cmd(e["command"])]
    all_settings = [at for n in sim.get("all_settings", []) for at in cmd(n)]
    base_rates = {e["device"]: [(r["set"], r["hz"]) for r in e["rates"]] for e in sim.get("base_rates", [])}
    unaddressed = {e["device"]: list(e["sets"]) for e in sim.get("unaddressed", [])}
    lists = [
        {
            "at": (e["set"], e["command_descriptor"]),
            "reply": e["reply_descriptor"],
            "param": e["param"],
            "u16": e["item"] == "u16",
        }
        for e in (sim.get("descriptor_lists") or {}).get("lists", [])
    ]
    ident = sim.get("identity") or {"reports": [], "devices": []}
    reports = [
        {"at": (r["set"], r["descriptor"]), "path": r["param"].split("."), "item": r["item"]} for r in ident["reports"]
    ]
    models = {d["device"]: d["values"].get("model_name", "") for d in ident["devices"]}
    fs = proto.get("function_selector") or {}
    functions = []
    if fs.get("enum") in types:
        functions = [(v["name"], int(v["value"])) for v in types[fs["enum"]]["values"]]
    return {
        "dev_timesync": _timesync(proto, types),
        "dev_settings": settings,
        "dev_enums": enums,
        "dev_ack_enum": ack_enum,
        "dev_sizes": {d: sorted(v.items()) for d, v in sizes.items()},
        "dev_formats": formats,
        "dev_rates": rates,
        "dev_enables": enables,
        "dev_baud": baud,
        "dev_all_settings": all_settings,
        "dev_base_rates": base_rates,
        "dev_unaddressed": unaddressed,
        "dev_lists": lists,
        "dev_reports": reports,
        "dev_models": models,
        "dev_functions": functions,
        "dev_bandwidth_sources": bandwidth_sources(proto),
        "dev_shared_set": (proto.get("shared_data") or {}).get("set"),
        "dev_set_names": [(s["id"], s["name"]) for s in proto["sets"]],
        "dev_devices": proto["devices"],
        "dev_identity": next(
            (
                (s["id"], f["id"])
                for r in ident["reports"][:1]
                for s in proto["sets"]
                if s["id"] == r["set"]
                for f in s["fields"]
                if f["role"] == "command"
                and any(x["id"] == r["descriptor"] for v in f["variants"] for x in v["responses"])
            ),
            None,
        ),
    }


_PPS_KINDS = ("none", "input", "receiver", "generated")


def _timesync(proto: dict, types: dict) -> list[dict]:
    """The spec's `time.sync` per device (the IR's, names resolved to numbers) as the rows of the
    tool's DEV_TIMESYNC (tools/device/timesync.c, docs/timesync.md): the PPS source's members in
    their enum's order with their kinds (the default is the first receiver), the status field, the
    external time fields carrying a time of week, and the correlation flags with the time of week
    parameter of its field's `time.gps_time` entry."""
    t = proto.get("time") or {}
    tows = {e["field"]: e["tow"] for e in t.get("gps_time", [])}
    by_name = {f["name"]: f for s in proto["sets"] for f in s["fields"] if f["role"] == "command"}
    out = []
    for e in t.get("sync", []):
        row: dict = {"device": e["device"], "cmd": e["update"], "members": [], "pps": None}
        p = e.get("pps_source")
        if p is not None:
            f = by_name[p["command"]]
            enum = next(q["type"]["name"] for v in f["variants"] for q in v["params"] if q["name"] == p["param"])
            kinds = {int(k): kind for k, kind in p["kinds"].items()}  # (keys are text in the exported IR)
            row["members"] = [
                (upper(v["name"]).lower(), int(v["value"]), _PPS_KINDS.index(kinds[int(v["value"])]))
                for v in types[enum]["values"]
            ]
            set_id = next(s["id"] for s in proto["sets"] if f in s["fields"])
            row["pps"] = {"at": (set_id, f["id"]), "param": p["param"]}
        row["status"] = e.get("status")
        row["external"] = [x for x in e.get("external", []) if "tow" in x]
        c = e.get("correlation")
        row["correlation"] = dict(c, tow=tows.get(c["field"], "tow")) if c is not None else None
        out.append(row)
    return out
