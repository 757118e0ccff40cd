"""Pass: the protocol file's `time` section, which fields give a packet its time (the time model
of the Python tools, generator/targets/python/runtime/timebase.py; docs/log-to-csv.md "Time").

- `gps_time`: fields carrying a GPS time of their own, in order of preference: `field`
  (`set.field`), the parameters `tow` (a double in s), `week` (an unsigned integer in weeks) and
  `valid_flags` (a bitfield), `valid` (members that must all be set for the time to be valid) and
  optionally `invalid` (members that must all be clear);
- `device_clock`: fields carrying the device's own monotonic clock: `field`, `param` (an unsigned
  integer in ns, us, ms or s);
- `leap_seconds`: fields reporting GPS - UTC: `field`, `param` (an unsigned integer in s),
  `valid_flags` and `valid` as above;
- `reference_time`: per device (`device`, at most one entry each), the field carrying the device's
  own reference time for the sessions' host clock model (docs/time.md): either `param` (an
  unsigned integer in ns, us, ms or s) or `tow` and `week` as in `gps_time`, and `monotonic`
  (whether the manual promises it never jumps);
- `external`: fields carrying the device's external time as an unsigned count (ns, us, ms or s) on
  the GPS time scale: `field`, `param`, `valid_flags` and `valid` (the log time model's second
  choice, after a valid GPS time);
- `sync_health`: fields saying whether a PPS is present (`info`'s synchronization section): `field`
  and either `param` (a bool) or `valid_flags` and `valid`.
- `sync`: per device, how its external time is synchronized (time_sync.py).
- `clock_model`: the host clock model's parameters, the project's own (no manual line: `basis`
  says why): `bucket_ns`, `buckets`, `min_buckets` (at most `buckets`), `restart_ns`; required
  with `reference_time` (the model the sessions feed from it). The IR entry: the four numbers, or
  None without it (the packages then carry the model unused, generator/clock_model.py).

Each entry cites its manual lines. Every check gives one located error. The IR entry `time` holds
per entry the set and descriptor, the parameter names, and the flag masks (`mask`: bits that must
be set, `inverted`: bits that must be clear); a `reference_time` entry its `device`, `kind`
(`count`: `param`, `per_second`, its `offset` and `size` in the field data; `gps`: `tow`, `week`,
`tow_offset`, `week_offset`, `week_size`) and `monotonic`; an `external` entry `param`, `per_second`, `valid_flags`, `mask`; a
`sync_health` entry `kind` (`bool`: `param`; `flags`: `valid_flags`, `mask`); without the section
it is empty lists (and `clock_model` None).
"""

from __future__ import annotations

from . import time_sync
from .context import Context

_UNSIGNED = {"u8", "u16", "u32", "u64"}
_CLOCK_UNITS = {"ns": 1_000_000_000, "us": 1_000_000, "ms": 1000, "s": 1}


def run(ctx: Context) -> None:
    spec = ctx.pf.data.get("time")
    ctx.time = {"gps_time": [], "device_clock": [], "leap_seconds": [], "reference_time": [], "sync": []}
    ctx.time.update(external=[], sync_health=[], clock_model=None)
    if spec is None:
        return
    check = _Check(ctx)
    _log_sync(ctx, spec, check)
    # after `external`: a sync entry's external times in ns are the `external` entries of its device
    ctx.time["sync"] = time_sync.check(ctx, spec.get("sync") or [], ctx.time["external"])
    seen: set[str] = set()
    for i, entry in enumerate(spec.get("reference_time") or []):
        out = check.reference(("time", "reference_time", i), entry, seen)
        if out is not None:
            ctx.time["reference_time"].append(out)
    ctx.time["clock_model"] = _clock_model(ctx, spec)
    for kind in ("gps_time", "device_clock", "leap_seconds"):
        for i, entry in enumerate(spec.get(kind) or []):
            out = check.entry(kind, ("time", kind, i), entry)
            if out is not None:
                ctx.time[kind].append(out)


class _Check:
    def __init__(self, ctx: Context) -> None:
        self.ctx = ctx
        self.sf = ctx.pf

    def err(self, path: tuple, message: str, expected: str) -> None:
        self.ctx.err(self.sf, path, message, expected)

    def entry(self, kind: str, path: tuple, e: dict) -> dict | None:
        found = self.field(path + ("field",), e["field"])
        sources = self.ctx.check_sources(self.sf, path + ("sources",), e["sources"])
        if found is None:
            return None
        s, f = found
        out = {"field": e["field"], "set": s["id"], "descriptor": f["id"], "sources": sources}
        ok = True
        if kind == "gps_time":
            ok &= self.param(
                path + ("tow",),
                f,
                e["tow"],
                lambda q: _prim(q) in ("double", "f64") and q["units"] == "s",
                "a double parameter in s",
            )
            ok &= self.param(
                path + ("week",),
                f,
                e["week"],
                lambda q: _prim(q) in _UNSIGNED and q["units"] == "weeks",
                "an unsigned integer parameter in weeks",
            )
            masks = self.flags(path, f, e)
            if masks is None:
                return None
            out.update(tow=e["tow"], week=e["week"], valid_flags=e["valid_flags"], mask=masks[0], inverted=masks[1])
        elif kind == "device_clock":
            ok &= self.param(
                path + ("param",),
                f,
                e["param"],
                lambda q: _prim(q) in _UNSIGNED and q["units"] in _CLOCK_UNITS,
                "an unsigned integer parameter in ns, us, ms or s",
            )
            if ok:
                q = _params(f, e["param"])[0]
                out.update(param=e["param"], per_second=_CLOCK_UNITS[q["units"]])
        else:
            ok &= self.param(
                path + ("param",),
                f,
                e["param"],
                lambda q: _prim(q) in _UNSIGNED and q["units"] == "s",
                "an unsigned integer parameter in s",
            )
            masks = self.flags(path, f, e)
            if masks is None or masks[1]:
                if masks is not None:
                    self.err(
                        path + ("invalid",), "time leap_seconds: 'invalid' is not supported here", "valid members only"
                    )
                return None
            out.update(param=e["param"], valid_flags=e["valid_flags"], mask=masks[0])
        return out if ok else None

    def reference(self, path: tuple, e: dict, seen: set[str]) -> dict | None:
        device = e["device"]
        if device not in self.ctx.device_ids:
            self.err(
                path + ("device",), f"time reference_time: unknown device '{device}'", "a device of the protocol file"
            )
            return None
        if device in seen:
            self.err(path + ("device",), f"time reference_time: a second entry for '{device}'", "one entry per device")
            return None
        seen.add(device)
        found = self.field(path + ("field",), e["field"])
        sources = self.ctx.check_sources(self.sf, path + ("sources",), e["sources"])
        if found is None:
            return None
        s, f = found
        out = {"device": device, "field": e["field"], "set": s["id"], "descriptor": f["id"], "sources": sources}
        if ("param" in e) == ("tow" in e or "week" in e) or ("tow" in e) != ("week" in e):
            self.err(path, "time reference_time: give either param or both tow and week", "param, or tow and week")
            return None
        if "param" in e:
            if not self.param(
                path + ("param",),
                f,
                e["param"],
                lambda q: _prim(q) in _UNSIGNED and q["units"] in _CLOCK_UNITS,
                "an unsigned integer parameter in ns, us, ms or s",
            ):
                return None
            q = _params(f, e["param"])[0]
            at = self.fixed(path + ("param",), f, e["param"])
            if at is None:
                return None
            out.update(kind="count", param=e["param"], per_second=_CLOCK_UNITS[q["units"]], offset=at[0], size=at[1])
        else:
            ok = self.param(
                path + ("tow",),
                f,
                e["tow"],
                lambda q: _prim(q) in ("double", "f64") and q["units"] == "s",
                "a double parameter in s",
            )
            ok &= self.param(
                path + ("week",),
                f,
                e["week"],
                lambda q: _prim(q) in _UNSIGNED and q["units"] == "weeks",
                "an unsigned integer parameter in weeks",
            )
            tow_at = self.fixed(path + ("tow",), f, e["tow"]) if ok else None
            week_at = self.fixed(path + ("week",), f, e["week"]) if ok else None
            if tow_at is None or week_at is None:
                return None
            out.update(
                kind="gps",
                tow=e["tow"],
                week=e["week"],
                tow_offset=tow_at[0],
                week_offset=week_at[0],
                week_size=week_at[1],
            )
        out["monotonic"] = e["monotonic"]
        return out

    def fixed(self, path: tuple, f: dict, name: str) -> tuple[int, int] | None:
        """(offset, size) of parameter `name`, the same in every layout of the field (for readers of
        the raw field data: the C session), else an error."""
        places = {(q.get("offset"), q["size"]["max"] if q["size"]["fixed"] else None) for q in _params(f, name)}
        place = places.pop() if len(places) == 1 else (None, None)
        if place[0] is None or place[1] is None:
            self.err(
                path, f"time: '{name}' of {f['name']} is not at one fixed offset", "a fixed offset in every layout"
            )
            return None
        return place

    def field(self, path: tuple, ref: str) -> tuple[dict, dict] | None:
        set_name, _, field_name = ref.partition(".")
        for s in self.ctx.sets:
            if s["name"] != set_name or s["kind"] != "data":
                continue
            for f in s["fields"]:
                if f["name"] == field_name and f["role"] == "data":
                    return s, f
        self.err(path, f"time: '{ref}' is not a data field", "set.field of a data set")
        return None

    def param(self, path: tuple, f: dict, name: str, fits, what: str) -> bool:
        qs = _params(f, name)
        if not qs or any(q is None or q["count"] is not None or q["optional"] or not fits(q) for q in qs):
            self.err(path, f"time: '{name}' of {f['name']} is not {what} (in every layout)", what)
            return False
        return True

    def flags(self, path: tuple, f: dict, e: dict) -> tuple[int, int] | None:
        name = e["valid_flags"]
        qs = _params(f, name)
        if not qs or any(q is None or q["type"]["kind"] != "bitfield" for q in qs):
            self.err(
                path + ("valid_flags",),
                f"time: '{name}' of {f['name']} is not a bitfield parameter",
                "a bitfield parameter",
            )
            return None
        types = {q["type"]["name"] for q in qs}
        if len(types) != 1:
            self.err(
                path + ("valid_flags",),
                f"time: '{name}' of {f['name']} has different types in its layouts",
                "one bitfield type",
            )
            return None
        members = {m["name"]: m for m in self.ctx.types[types.pop()]["members"]}
        masks = []
        for key in ("valid", "invalid"):
            mask = 0
            for j, m in enumerate(e.get(key) or []):
                if m not in members or members[m]["reserved"]:
                    self.err(
                        path + (key, j), f"time: '{m}' is not a member of {name}", "a named member of the bitfield"
                    )
                    return None
                mask |= members[m]["mask"]
            masks.append(mask)
        if not masks[0] and not masks[1]:
            self.err(path + ("valid",), "time: no valid flag member given", "the members that say the value is valid")
            return None
        return masks[0], masks[1]


def _params(f: dict, name: str) -> list[dict | None]:
    """The parameter `name` in each layout of the field (None where a layout lacks it)."""
    return [next((q for q in v["params"] if q["name"] == name), None) for v in f["variants"]]


def _prim(q: dict) -> str | None:
    return q["type"]["name"] if q["type"]["kind"] == "primitive" else None


def _log_sync(ctx: Context, spec: dict, check: _Check) -> None:
    """The `external` and `sync_health` entries (the log time model and `info`, docs/time.md)."""
    for i, e in enumerate(spec.get("external") or []):
        path = ("time", "external", i)
        found = check.field(path + ("field",), e["field"])
        sources = ctx.check_sources(ctx.pf, path + ("sources",), e["sources"])
        if found is None:
            continue
        s, f = found
        ok = check.param(
            path + ("param",),
            f,
            e["param"],
            lambda q: _prim(q) in _UNSIGNED and q["units"] in _CLOCK_UNITS,
            "an unsigned integer parameter in ns, us, ms or s",
        )
        masks = check.flags(path, f, e)
        if not ok or masks is None:
            continue
        if masks[1]:
            check.err(path + ("invalid",), "time external: 'invalid' is not supported here", "valid members only")
            continue
        q = _params(f, e["param"])[0]
        ctx.time["external"].append(
            {
                "field": e["field"],
                "set": s["id"],
                "descriptor": f["id"],
                "param": e["param"],
                "per_second": _CLOCK_UNITS[q["units"]],
                "valid_flags": e["valid_flags"],
                "mask": masks[0],
                "sources": sources,
            }
        )
    for i, e in enumerate(spec.get("sync_health") or []):
        path = ("time", "sync_health", i)
        found = check.field(path + ("field",), e["field"])
        sources = ctx.check_sources(ctx.pf, path + ("sources",), e["sources"])
        if found is None:
            continue
        s, f = found
        out = {"field": e["field"], "set": s["id"], "descriptor": f["id"], "sources": sources}
        if ("param" in e) == ("valid_flags" in e):
            check.err(path, "time sync_health: give either param or valid_flags", "param, or valid_flags and valid")
            continue
        if "param" in e:
            if not check.param(path + ("param",), f, e["param"], lambda q: _prim(q) == "bool", "a bool parameter"):
                continue
            out.update(kind="bool", param=e["param"])
        else:
            masks = check.flags(path, f, e)
            if masks is None:
                continue
            if masks[1]:
                check.err(
                    path + ("invalid",), "time sync_health: 'invalid' is not supported here", "valid members only"
                )
                continue
            out.update(kind="flags", valid_flags=e["valid_flags"], mask=masks[0])
        ctx.time["sync_health"].append(out)


def _clock_model(ctx: Context, spec: dict) -> dict | None:
    """`clock_model`: the host clock model's parameters (the project's own, docs/time.md), required
    where the sessions run the model (the protocol file has `reference_time` entries); the IR entry
    is the four numbers, or None without the section."""
    m = spec.get("clock_model")
    if m is None:
        if spec.get("reference_time"):
            ctx.err(
                ctx.pf,
                ("time",),
                "time: reference_time without clock_model (the host clock model it feeds needs its parameters)",
                "clock_model: {bucket_ns, buckets, min_buckets, restart_ns, basis}",
            )
        return None
    if m["min_buckets"] > m["buckets"]:
        ctx.err(
            ctx.pf,
            ("time", "clock_model", "min_buckets"),
            f"time clock_model: min_buckets {m['min_buckets']} above buckets {m['buckets']} (never an estimate)",
            "at most buckets",
        )
        return None
    return {k: m[k] for k in ("bucket_ns", "buckets", "min_buckets", "restart_ns")}
