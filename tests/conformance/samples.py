"""Values generated from the spec: for every field layout in the IR, a set of packets that
together exercise every function selector, every enum value, every union member, every
optional parameter (present and absent) and every counted array at length 0, 1 and maximum.

This module reads only `generated/ir.json` (through the loader) and writes canonical JSON lines
(docs/conformance.md §4) by its own rules; it never calls generated code. The round-trip test
feeds these lines to every language's `encode`, then the bytes to every `decode`.

Sample values are chosen so that their canonical text is unambiguous: floats are small dyadic
fractions (exact in float32, printed identically by Python's repr), strings are printable
ASCII, bitfields set every defined member bit, integers are distinct per position so that a
swapped or misplaced parameter shows up as different bytes.
"""

from __future__ import annotations

import json
from dataclasses import dataclass

INT_RANGES = ("u8", "u16", "u32", "u64", "s8", "s16", "s32", "s64")
FLOATS = [1.5, -0.25, 3.0, 1024.125, -7.5, 0.0625]


@dataclass
class Sample:
    """One packet: set id, one field, the device to decode it for (None: any)."""

    set_id: int
    descriptor: int
    name: str
    device: str | None
    print_device: bool
    values: dict
    what: str  # which variation this is, for failure messages

    def json_line(self, offset: int) -> str:
        field = {"descriptor": self.descriptor, "name": self.name}
        if self.print_device:
            field["device"] = self.device
        field["values"] = self.values
        packet = {"offset": offset, "set": self.set_id, "fields": [field]}
        return json.dumps(packet, separators=(",", ":"), ensure_ascii=True)


class Values:
    """Builds values for parameters of one protocol's IR."""

    def __init__(self, protocol: dict):
        self.types = {t["name"]: t for t in protocol["types"]}
        self.protocol = protocol
        self.counter = 0

    # -- scalars -----------------------------------------------------------------------------

    def _next(self) -> int:
        self.counter += 1
        return self.counter

    def integer(self, base: str) -> int:
        """Distinct per position; varies the high bytes of wide types and the sign of signed ones."""
        bits = int(base[1:])
        raw = (self._next() * 0x9E3779B97F4A7C15) & ((1 << bits) - 1)
        if base.startswith("s") and raw >= 1 << (bits - 1):
            raw -= 1 << bits
        return raw

    def enum_values(self, name: str, device: str | None) -> list[int]:
        t = self.types[name]
        return [v["value"] for v in t["values"] if device is None or not v["devices"] or device in v["devices"]]

    def bitfield(self, name: str) -> int:
        mask = 0
        for m in self.types[name]["members"]:
            if not m.get("reserved"):
                mask |= m["mask"]
        return mask

    # -- one value of a type reference --------------------------------------------------------

    def value(self, tref: dict, device: str | None, enum_pick: int = 0):
        kind = tref["kind"]
        if kind == "primitive":
            name = tref["name"]
            if name in INT_RANGES:
                return self.integer(name)
            if name == "bool":
                return bool(self._next() % 2)
            if name == "char":
                return chr(ord("A") + self._next() % 26)
            if name in ("float", "double"):
                return FLOATS[self._next() % len(FLOATS)]
            raise ValueError(f"unknown primitive {name}")
        if kind == "string":
            n = tref["length"]
            start = self._next()
            return "".join(chr(ord("a") + (start + i) % 26) for i in range(n))
        if kind == "enum":
            vals = self.enum_values(tref["name"], device)
            return vals[enum_pick % len(vals)]
        if kind == "bitfield":
            return self.bitfield(tref["name"])
        if kind == "struct":
            return self.params_base(self.types[tref["name"]]["params"], device, None)
        raise ValueError(f"value() does not build {kind}")

    # -- a parameter list ---------------------------------------------------------------------

    def params_base(self, params: list[dict], device: str | None, function: str | None, counts=None) -> dict:
        """The baseline values of a parameter list: every optional parameter present, counted
        arrays of length 1 unless `counts` says otherwise ({param name: length})."""
        counts = counts or {}
        out: dict = {}
        selectors: dict[str, str] = {}
        for p in params:
            if function is not None and p["functions"] is not None and function not in p["functions"]:
                continue
            t = p["type"]
            if t["kind"] == "union":
                selectors[t["selector"]] = p["name"]
        for p in params:
            if function is not None and p["functions"] is not None and function not in p["functions"]:
                continue
            out[p["name"]] = self.param_value(p, params, device, counts, out)
        # A union follows its selector: pick the first member with data when there is one.
        for sel, uname in selectors.items():
            union = self.types[next(p for p in params if p["name"] == uname)["type"]["name"]]
            member = next((m for m in union["members"] if m["type"]), union["members"][0])
            out[sel] = member["value"]
            out[uname] = self.union_member(member, device)
        return out

    def union_member(self, member: dict, device: str | None):
        if member["type"] is None:
            return None
        return self.params_base(self.types[member["type"]]["params"], device, None)

    def param_value(self, p: dict, params: list[dict], device: str | None, counts: dict, sofar: dict):
        c = p["count"]
        t = p["type"]
        if t["kind"] == "union":
            return None  # filled in by params_base
        if c is None:
            return self.value(t, device)
        if c["kind"] == "fixed":
            n = c["value"]
        else:
            n = counts.get(p["name"], 1)
        items = [self.value(t, device, enum_pick=i) for i in range(n)]
        if c["kind"] == "param":
            sofar[c["param"]] = n
        return items


def _selector_values(protocol: dict, function: str) -> int:
    enum = next(t for t in protocol["types"] if t["name"] == protocol["function_selector"]["enum"])
    return next(v["value"] for v in enum["values"] if v["name"] == function)


def _with_function(values: dict, protocol: dict, function: str | None) -> dict:
    if function is None:
        return values
    return {"function": _selector_values(protocol, function), **values}


def _walk_variations(vals: Values, params: list[dict], device: str | None, function: str | None):
    """Yield (what, values) variations of one parameter list."""
    base = vals.params_base(params, device, function)
    yield "baseline", base
    present = [p for p in params if function is None or p["functions"] is None or function in p["functions"]]
    for p in present:
        t = p["type"]
        # Every enum value (top-level enum parameters, and enum arrays through enum_pick).
        if t["kind"] == "enum" and p["count"] is None and not _is_selector(p, present):
            for v in vals.enum_values(t["name"], device):
                yield f"{p['name']}={v}", {**base, p["name"]: v}
        # Every union member.
        if t["kind"] == "union":
            union = vals.types[t["name"]]
            for m in union["members"]:
                vv = dict(base)
                vv[t["selector"]] = m["value"]
                vv[p["name"]] = vals.union_member(m, device)
                yield f"{p['name']}={m['when']}", vv
        # Counted and remaining arrays at 0, 1 and their maximum.
        if p["count"] is not None and p["count"]["kind"] in ("param", "remaining"):
            for n in sorted({0, 1, p["max_count"]}):
                yield f"{p['name']}[{n}]", vals.params_base(params, device, function, counts={p["name"]: n})
        # Enums, bitfields and arrays nested in a struct parameter: every enum value inside it.
        if t["kind"] == "struct" and p["count"] is None:
            for what, sv in _walk_variations(vals, vals.types[t["name"]]["params"], device, None):
                if what != "baseline":
                    yield f"{p['name']}.{what}", {**base, p["name"]: sv}
    # Optional trailing parameters left out, one more at a time from the end.
    optional = [p for p in present if p["optional"] and (function is None or p["functions"] is None)]
    for k in range(1, len(optional) + 1):
        drop = {p["name"] for p in optional[-k:]}
        yield f"without {','.join(sorted(drop))}", {n: v for n, v in base.items() if n not in drop}


def _drop_empty_trailing(values: dict, params: list[dict]) -> dict:
    """An optional union parameter whose member carries no data, or an optional counted array of
    length 0, occupies no bytes; when it is the last value, a decoder cannot tell it from
    absent, and docs/conformance.md §4 prints absent optional parameters by leaving them out."""
    optional = {p["name"] for p in params if p["optional"]}
    names = list(values)
    while names and names[-1] in optional and values[names[-1]] in (None, []):
        names.pop()
    return {n: values[n] for n in names}


def _is_selector(p: dict, params: list[dict]) -> bool:
    return any(q["type"]["kind"] == "union" and q["type"]["selector"] == p["name"] for q in params)


def field_samples(protocol: dict) -> list[Sample]:
    """Every variation of every field layout of the protocol (reserved fields included)."""
    vals = Values(protocol)
    out: list[Sample] = []
    sets = protocol["sets"]
    fields = [(s, f) for s in sets if not s.get("shared") for f in s["fields"]]
    # Shared descriptors (set 0xFF, 0xD0 and up) travel inside every data set: test them in each.
    data_sets = [s for s in sets if s["kind"] == "data" and not s.get("shared")]
    fields += [(d, f) for s in sets if s.get("shared") for f in s["fields"] for d in data_sets]
    command_sets = [s for s in sets if s["kind"] == "command"]
    for r in protocol["reserved_fields"]:
        if command_sets and r["applies_to"] == "command":
            fields.append((command_sets[0], r))
    for s, f in fields:
        for v in f["variants"]:
            devices = [v["device"]] if v["device"] else [None]
            for device in devices:
                functions = v["functions"] or [None]
                for function in functions:
                    for what, values in _walk_variations(vals, v["params"], device, function):
                        values = _drop_empty_trailing(values, v["params"])
                        out.append(
                            Sample(
                                set_id=s["id"],
                                descriptor=f["id"],
                                name=f["name"],
                                device=device,
                                print_device=len(f["variants"]) > 1,
                                values=_with_function(values, protocol, function),
                                what=f"{s['name']}.{f['name']}"
                                + (f" ({device})" if device else "")
                                + (f" {function}" if function else "")
                                + f": {what}",
                            )
                        )
    return out
