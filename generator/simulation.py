"""The simulated device's protocol tables with the spec's names resolved, decided once.

The IR's `simulation` entry (generator/passes/simulation.py, checked against the rest of the spec)
names what the manuals name: the ack code of each refusal as a member of the code enum, the
navigation filter's status flags, heading sources and alignment methods as enum and bitfield
members. A simulator needs numbers: this module resolves the names to values and masks, with no
target syntax; the only naming it leaves to the back end is a parameter's attribute (`param`,
the language's name of a layout parameter). The Python back end prints the result into `_sim.py`
(templates/python/package/_sim.py.j2).
"""

from __future__ import annotations

import math
from typing import Callable

# The refusals of the simulated device (runtime sim.py), each answered with an ack code.
NACK_ROLES = ("unknown_descriptor", "unknown_set", "invalid_parameter", "failed")


def nack_codes(proto: dict) -> dict[str, int]:
    """The ack code of each refusal role: the code enum's member the simulation section names,
    else the first code that is not the OK code (1 without a code enum)."""
    rule = proto["session"]
    types = {t["name"]: t for t in proto["types"]}
    codes = {v["name"]: v["value"] for v in types[rule["code_enum"]]["values"]} if rule and rule["code_enum"] else {}
    ok = rule["ok"] if rule else 0
    fallback = next((v for v in codes.values() if v != ok), 1)
    named = (proto["simulation"] or {}).get("nack", {})
    return {role: codes.get(named.get(role, ""), fallback) for role in NACK_ROLES}


def filters(proto: dict, param: Callable[[str], str]) -> dict[str, dict]:
    """The navigation filter per device (sim_world.NavFilter): its state enum's members in order,
    what aids it, its GNSS fix type members (fix, no fix) and its internal aiding, with status flag
    roles resolved to masks, enum members to values and parameters named by `param`."""
    types = {t["name"]: t for t in proto["types"]}

    def value(enum: str, name: str) -> int:
        return int(next(v["value"] for v in types[enum]["values"] if v["name"] == name))

    def masks(flags: dict) -> dict:
        bits = {m["name"]: m["mask"] for m in types[flags["type"]]["members"]}
        return {role: bits[name] for role, name in flags["members"].items()}

    out = {}
    for e in (proto["simulation"] or {}).get("filters", []):
        f: dict = {
            "aiding": e["aiding"],
            "states": list(e["states"]["members"]),
            "fix": [e["fix"]["fix"], e["fix"]["none"]],
        }
        if "flags" in e:
            f["flags"] = masks(e["flags"])
        if "heading" in e:
            h = e["heading"]
            used = {"type": h["in_use"], "members": {s: s for v in h["members"].values() for s in v}}
            f["heading"] = {
                "command": h["command"],
                "param": param(h["param"]),
                "sources": {value(h["enum"], n): list(s) for n, s in h["members"].items()},
                "in_use": masks(used) if "in_use" in h else {},
                "external": list(h.get("external", [])),
            }
            if "without_aids" in h:  # note 3: the velocity vector's turns observe the heading
                w = h["without_aids"]
                f["heading"]["without_aids"] = {
                    "source": value(h["enum"], w["member"]),
                    "min_speed": float(w["min_speed"]),
                    "turn_rate": math.radians(w["turn_rate"]),
                    "converge_turn": math.radians(w["converge_turn"]),
                    "drift": math.radians(w["drift"]),
                }
        if "internal" in e:
            i = e["internal"]
            f["internal"] = {
                "command": i["command"],
                "param": param(i["param"]),
                "enable": param(i["enable"]),
                "all": value(i["enum"], i["all"]) if "all" in i else None,
                "sources": {value(i["enum"], n): s for n, s in i["members"].items()},
            }
        if "alignment" in e:
            a = e["alignment"]
            f["alignment"] = {
                "command": a["command"],
                "param": param(a["param"]),
                "sources": masks({"type": a["type"], "members": {s: n for n, s in a["members"].items()}}),
            }
        if "antennas" in e:
            a = e["antennas"]
            f["antennas"] = {"command": a["command"], "receiver": param(a["receiver"]), "offset": param(a["offset"])}
        if "dual_antenna" in e:
            d = e["dual_antenna"]
            f["dual_antenna"] = {"fix": [d["fix"]["fix"], d["fix"]["none"]], "flags": masks(d["flags"])}
        if "rtk" in e:
            r = e["rtk"]
            f["rtk"] = {
                "fix": [r["fix"]["float"], r["fix"]["fixed"]],
                "aiding_status": masks(r["aiding_status"]),
                "uncertainty": dict(r["uncertainty"]),
            }
            if "corrections" in r:
                c = r["corrections"]
                f["rtk"]["corrections"] = {
                    "types": sorted(c["types"]),
                    "station": sorted(c["station"]),
                    "observations": sorted(c["observations"]),
                    "max_age": float(c["max_age"]),
                    "spartn": (c["spartn"]["command"], param(c["spartn"]["param"])) if "spartn" in c else None,
                }
        out[e["device"]] = f
    return out


def command_facts(proto: dict, v: dict, param: Callable[[str], str]) -> dict:
    """What the simulated device reads of command layout v (runtime sim.py): per function value
    the parameters a request must carry (`sends`: not optional; the function selector left out),
    the scalar enum parameters it checks (`enums`), per function value the parameters the device
    ignores (`ignored`: not sent for that function, or stated ignored for it, `ignored` in the spec:
    neither required nor checked nor taken into a reply) and per device the factory values
    (`factory`: the defaults its manual states, else the spec's `plausible` value), parameters
    named by `param`."""
    fenum = (proto.get("function_selector") or {}).get("enum")
    types = {t["name"]: t for t in proto["types"]}
    fvalues = {x["name"]: x["value"] for x in types[fenum]["values"]} if fenum else {}
    qs = [q for q in v["params"] if not (fenum and q["type"].get("name") == fenum)]
    sends = {
        fvalues[fn]: tuple(
            param(q["name"]) for q in qs if (q["functions"] is None or fn in q["functions"]) and not q["optional"]
        )
        for fn in v["functions"] or []
    }
    ignored = {
        fvalues[fn]: tuple(
            param(q["name"])
            for q in qs
            if (q["functions"] is not None and fn not in q["functions"])
            or (q.get("ignored") and fn in q["ignored"]["functions"])
        )
        for fn in v["functions"] or []
    }

    def factory_value(q: dict, dev: str):
        if q.get("default") and dev in q["default"]["devices"]:
            return q["default"]["value"]
        return q["plausible"]["value"] if q.get("plausible") else None

    factory = {}
    for dev in v["devices"]:
        values = {param(q["name"]): x for q in qs if (x := factory_value(q, dev)) is not None}
        for q in qs:  # a counted list's count parameter: the number of its records
            count = q["count"] or {}
            if count.get("kind") == "param" and isinstance(values.get(param(q["name"])), list):
                values.setdefault(param(count["param"]), len(values[param(q["name"])]))
        factory[dev] = values
    return {
        "ignored": {fn: names for fn, names in ignored.items() if names},
        "sends": sends,
        "enums": tuple(param(q["name"]) for q in qs if q["type"]["kind"] == "enum" and q["count"] is None),
        "factory": {dev: values for dev, values in factory.items() if values},
    }


def nmea(proto: dict, param: Callable[[str], str]) -> dict:
    """NMEA output and input (sim/nmea.py; the simulation section's `nmea`, empty without it): the
    entry members as attributes, the NACK code of a refused entry, per origin its sets and highest
    rate, the talker IDs and sentences by code, the input's set, sentences and updates."""
    spec = (proto["simulation"] or {}).get("nmea")
    if not spec:
        return {}
    rule = proto["session"]
    types = {t["name"]: t for t in proto["types"]}
    codes = {v["name"]: v["value"] for v in types[rule["code_enum"]]["values"]} if rule and rule["code_enum"] else {}
    return {
        "entry": {role: param(name) for role, name in spec["entry"].items()},
        "nack": codes.get(spec["nack"], nack_codes(proto)["invalid_parameter"]),
        "origins": {o["kind"]: (tuple(o["sets"]), o["max_hz"]) for o in spec["origins"]},
        "talkers": {t["code"]: t["id"] for t in spec["talkers"]},
        "sentences": {s["code"]: (s["name"], s["talker"], tuple(s["sources"])) for s in spec["sentences"]},
        "input": (
            {k: (tuple(v) if isinstance(v, list) else v) for k, v in spec["input"].items()} if "input" in spec else None
        ),
    }


def nmea_commands(proto: dict, param: Callable[[str], str]) -> dict[str, tuple[str, str]]:
    """The NMEA format and poll commands by name: (role, the list attribute)."""
    spec = (proto["simulation"] or {}).get("nmea") or {}
    return {spec[k]["command"]: (k, param(spec[k]["list"])) for k in ("format", "poll") if k in spec}
