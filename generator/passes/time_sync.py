"""The protocol file's `time.sync` entries (part of the time_facts pass): per device, how its
external (GPS) time is synchronized, for the simulated clocks (runtime sim/clocks.py) and
`device timesync` (runtime device/timesync.py, docs/timesync.md).

An entry names its `device` (at most one entry each); `update`: the GPS Time Update command, its
selector and value parameters and the selector's week and time-of-week members; `window_ms`; `pps`:
where a PPS can come from (input, receiver, generated); optionally `pps_source` (the setting choosing
the PPS: command, parameter, each member of the parameter's enum mapped to none, input, receiver or
generated, every member covered), `status` (a data field with the synced and last-PPS parameters),
`external` (data fields carrying the external time as a GPS time: `flags` a bitfield parameter, and
the `tow` and `week` parameters, each with the flag member of its name) and `correlation` (a data
field whose bitfield parameter `flags` has the `pps`, `refresh` and `initialized` members). Every
check gives one located error. The IR entry resolves names to numbers: set and descriptor of each
field and command, enum values, flag masks; notes and sources kept.

The external time as a count (the CV7's External Timestamp, 0xFF,0xD7) is named once, in the time
section's `external` entries (the log time model's, time_facts.py): the IR entry's `external` list
gets, after its own fields, each of those whose field the device has, with `ns` (the parameter),
`ns_mask` (the valid members' mask), `per_second` (its units a second) and `flags`.
"""

from __future__ import annotations

from .context import Context

KINDS = ("none", "input", "receiver", "generated")


def check(ctx: Context, entries: list[dict], external: list[dict]) -> list[dict]:
    """The IR entries of `time.sync`; `external`: the IR's `time.external` entries (time_facts.py)."""
    out: list[dict] = []
    seen: set[str] = set()
    for i, e in enumerate(entries):
        r = _Sync(ctx, ("time", "sync", i)).entry(e, seen, external)
        if r is not None:
            out.append(r)
    return out


class _Sync:
    def __init__(self, ctx: Context, path: tuple) -> None:
        self.ctx = ctx
        self.path = path
        self.ok = True

    def err(self, sub: tuple, message: str, expected: str) -> None:
        self.ok = False
        self.ctx.err(self.ctx.pf, self.path + sub, f"time sync: {message}", expected)

    def entry(self, e: dict, seen: set[str], external: list[dict]) -> dict | None:
        device = e["device"]
        if device not in self.ctx.device_ids:
            self.err(("device",), f"unknown device '{device}'", "a device of the protocol file")
            return None
        if device in seen:
            self.err(("device",), f"a second entry for '{device}'", "one entry per device")
            return None
        seen.add(device)
        out: dict = {"device": device, "window_ms": e["window_ms"], "pps": list(e["pps"])}
        out["update"] = self.update(e["update"])
        if "pps_source" in e:
            out["pps_source"] = self.pps_source(e["pps_source"])
        if "status" in e:
            st = e["status"]
            f = self.data_field(("status", "field"), st["field"])
            if f is not None:
                names = {q["name"] for v in f[1]["variants"] for q in v["params"]}
                for key in ("synced", "last_pps"):
                    if st[key] not in names:
                        self.err(("status", key), f"'{st[key]}' is not a parameter of {st['field']}", "a parameter")
                out["status"] = {
                    "field": st["field"],
                    "set": f[0]["id"],
                    "descriptor": f[1]["id"],
                    "synced": st["synced"],
                    "last_pps": st["last_pps"],
                    "last_pps_max": st["last_pps_max"],
                }
        out["external"] = []
        for j, x in enumerate(e.get("external") or []):
            r = self.external(("external", j), x)
            if r is not None:
                out["external"].append(r)
        out["external"] += [self.count_view(x) for x in external if self.has_field(device, x)]
        if "correlation" in e:
            c = e["correlation"]
            f = self.data_field(("correlation", "field"), c["field"])
            masks = self.masks(("correlation",), f, c["flags"], [c["pps"], c["refresh"], c["initialized"]])
            if f is not None and masks is not None:
                out["correlation"] = {
                    "field": c["field"],
                    "set": f[0]["id"],
                    "descriptor": f[1]["id"],
                    "flags": c["flags"],
                    "pps": masks[0],
                    "refresh": masks[1],
                    "initialized": masks[2],
                }
        out["notes"] = e.get("notes", [])
        out["sources"] = self.ctx.check_sources(self.ctx.pf, self.path + ("sources",), e["sources"])
        return out if self.ok else None

    def command(self, sub: tuple, name: str) -> list[dict]:
        for s in self.ctx.sets:
            for f in s["fields"]:
                if f["role"] == "command" and f["name"] == name:
                    return [{**v, "_set": s["id"], "_descriptor": f["id"]} for v in f["variants"]]
        self.err(sub, f"'{name}' is not a command of the protocol", "the name of a command field")
        return []

    def enum_of(self, sub: tuple, variants: list[dict], param: str, command: str) -> dict | None:
        types = {q["type"]["name"] for v in variants for q in v["params"] if q["name"] == param}
        t = self.ctx.types.get(next(iter(types))) if len(types) == 1 else None
        if t is None or t["kind"] != "enum":
            self.err(sub, f"'{param}' is not an enum parameter of {command}", "an enum parameter (one type)")
            return None
        return {v["name"]: v["value"] for v in t["values"]}

    def update(self, u: dict) -> dict:
        variants = self.command(("update", "command"), u["command"])
        out = {"command": u["command"], "selector": u["selector"], "value": u["value"]}
        if not variants:
            return out
        out.update(set=variants[0]["_set"], descriptor=variants[0]["_descriptor"])
        if not any(q["name"] == u["value"] for v in variants for q in v["params"]):
            self.err(("update", "value"), f"'{u['value']}' is not a parameter of {u['command']}", "a parameter")
        values = self.enum_of(("update", "selector"), variants, u["selector"], u["command"])
        for key in ("week", "tow"):
            if values is not None and u[key] not in values:
                self.err(("update", key), f"'{u[key]}' is not a member of the selector's enum", "an enum member")
            elif values is not None:
                out[key] = values[u[key]]
        return out

    def pps_source(self, p: dict) -> dict:
        variants = self.command(("pps_source", "command"), p["command"])
        out = {"command": p["command"], "param": p["param"], "kinds": {}}
        values = self.enum_of(("pps_source", "param"), variants, p["param"], p["command"]) if variants else None
        if values is None:
            return out
        for name, kind in p["kinds"].items():
            if name not in values:
                self.err(("pps_source", "kinds", name), f"'{name}' is not a member of the source enum", "a member")
            else:
                out["kinds"][values[name]] = kind
        missing = sorted(set(values) - set(p["kinds"]))
        if missing:
            self.err(("pps_source", "kinds"), f"no kind for {', '.join(missing)}", "a kind for every member")
        return out

    def has_field(self, device: str, x: dict) -> bool:
        """Whether the device has the field of a `time.external` entry."""
        for s in self.ctx.sets:
            for f in s["fields"] if s["id"] == x["set"] else []:
                if f["id"] == x["descriptor"]:
                    return not f.get("devices") or device in f["devices"]
        return False

    @staticmethod
    def count_view(x: dict) -> dict:
        """A `time.external` entry as a sync entry's external time in ns."""
        return {
            "field": x["field"],
            "set": x["set"],
            "descriptor": x["descriptor"],
            "flags": x["valid_flags"],
            "ns": x["param"],
            "ns_mask": x["mask"],
            "per_second": x["per_second"],
        }

    def external(self, sub: tuple, x: dict) -> dict | None:
        f = self.data_field(sub + ("field",), x["field"])
        if f is None:
            return None
        params = [x["tow"], x["week"]]
        names = {q["name"] for v in f[1]["variants"] for q in v["params"]}
        for k in ("tow", "week"):
            if x[k] not in names:
                self.err(sub + (k,), f"'{x[k]}' is not a parameter of {x['field']}", "a parameter")
                return None
        masks = self.masks(sub, f, x["flags"], params)
        if masks is None:
            return None
        out = {"field": x["field"], "set": f[0]["id"], "descriptor": f[1]["id"], "flags": x["flags"]}
        for k in ("tow", "week"):
            out[k] = x[k]
            out[f"{k}_mask"] = masks[params.index(x[k])]
        return out

    def masks(self, sub: tuple, f: tuple | None, flags: str, members: list[str]) -> list[int] | None:
        """The masks of `members` of the bitfield parameter `flags` of field `f`."""
        if f is None:
            return None
        types = {q["type"]["name"] for v in f[1]["variants"] for q in v["params"] if q["name"] == flags}
        t = self.ctx.types.get(next(iter(types))) if len(types) == 1 else None
        if t is None or t["kind"] != "bitfield":
            self.err(sub + ("flags",), f"'{flags}' is not a bitfield parameter of {f[1]['name']}", "a bitfield")
            return None
        by_name = {m["name"]: m for m in t["members"] if not m["reserved"]}
        out = []
        for m in members:
            if m not in by_name:
                self.err(sub, f"'{m}' is not a member of {t['name']}", f"a member of {t['name']}")
                return None
            out.append(by_name[m]["mask"])
        return out

    def data_field(self, sub: tuple, ref: str) -> tuple[dict, dict] | None:
        set_name, _, field_name = ref.partition(".")
        for s in self.ctx.sets:
            if s["name"] == set_name and s["kind"] == "data":
                for f in s["fields"]:
                    if f["name"] == field_name and f["role"] == "data":
                        return s, f
        self.err(sub, f"'{ref}' is not a data field", "set.field of a data set")
        return None
