"""Build the one intermediate representation (IR) from loaded spec files, with semantic checks.

The IR is plain JSON-compatible data (dicts, lists, ints, strings) so that it can be exported
as generated/ir.json unchanged; every back end consumes exactly that structure. docs/ir.md
documents it. All decisions (sizes, offsets, optionality, dispatch tables, response links)
are made here, so templates stay dumb.
"""

from __future__ import annotations

import re
from typing import Callable

from .diagnostics import Location, SpecError
from .primitives import ALIASES, PRIMITIVES, int_range

IR_VERSION = 1


class SpecFile:
    """A loaded spec file: its data and a function that locates any path in it."""

    def __init__(self, path: str, data: dict, locate: Callable[[tuple], Location]):
        self.path = path
        self.data = data
        self.locate = locate


class Builder:
    def __init__(self, protocol_file: SpecFile, set_files: list[SpecFile], type_files: list[SpecFile]):
        self.pf = protocol_file
        self.set_files = set_files
        self.type_files = type_files
        self.errors: list[SpecError] = []
        self.types: dict[str, dict] = {}  # name -> type definition (IR form, filled progressively)
        self.type_locs: dict[str, Location] = {}
        self.raw_types: dict[str, tuple[str, dict, SpecFile, tuple]] = {}
        # Named field layouts shared by several fields (e.g. the GNSS receiver sets).
        self.field_layouts: dict[str, tuple[dict, SpecFile, tuple]] = {}
        self.manual_devices: dict[str, str] = {}
        self.device_ids: list[str] = []
        # Protocol-wide defaults for string parameters (MS-CIP: space padding, right-justified).
        self.string_defaults: dict = protocol_file.data.get("strings", {})

    # ---------------------------------------------------------------- helpers
    def err(self, sf: SpecFile, path: tuple, message: str, expected: str | None = None) -> None:
        self.errors.append(SpecError(sf.locate(path), message, expected))

    # ---------------------------------------------------------------- entry
    def build(self) -> dict:
        p = self.pf.data
        for d in p["devices"]:
            self.manual_devices[d["manual"]] = d["id"]
            self.device_ids.append(d["id"])
        self._collect_types(self.pf, ())
        for tf in self.type_files:
            self._collect_types(tf, ())
        for sf in self.set_files:
            self._collect_types(sf, ())
        self._resolve_types()
        framing = self._framing()
        fs_enum = (p.get("function_selector") or {}).get("enum")
        if fs_enum and fs_enum not in self.types:
            self.err(
                self.pf,
                ("function_selector", "enum"),
                f"function selector enum '{fs_enum}' is not defined",
                "an enum defined in the spec",
            )
        self.function_values: dict[str, int] = {}
        if fs_enum in self.types and self.types[fs_enum]["kind"] == "enum":
            self.function_values = {v["name"]: v["value"] for v in self.types[fs_enum]["values"]}
        reserved = [self._reserved_field(self.pf, i, f) for i, f in enumerate(p.get("reserved_fields", []))]
        sets = self._sets(reserved, framing)
        framing["irregular_lengths"] = [
            {"set": s["id"], "descriptor": f["id"], "adjust": f["length_byte_adjust"]}
            for s in sets
            for f in s["fields"]
            if f["length_byte_adjust"]
        ]
        ir = {
            "ir_version": IR_VERSION,
            "protocols": [
                {
                    "name": p["protocol"],
                    "title": p["title"],
                    "package": p["package"],
                    "byte_order": p["byte_order"],
                    "sources": self._sources(self.pf, ("sources",), p["sources"]),
                    "devices": p["devices"],
                    "response_descriptor": p.get("response_descriptor"),
                    "strings": {"padding": "nul", "justify": "left", **self.string_defaults},
                    "framing": framing,
                    "set_kinds": p["set_kinds"],
                    "shared_data": p.get("shared_data"),
                    "samples": self._samples(sets, framing),
                    "function_selector": p.get("function_selector"),
                    "reserved_fields": reserved,
                    "types": [self.types[n] for n in sorted(self.types)],
                    "field_layouts": self._field_layouts(sets),
                    "sets": sets,
                }
            ],
        }
        return ir

    # ---------------------------------------------------------------- framing
    def _framing(self) -> dict:
        f = dict(self.pf.data["framing"])
        header_size = len(f["sync"]) + 2
        f["header_size"] = header_size
        f["set_offset"] = len(f["sync"]) + f["header"].index("set")
        f["length_offset"] = len(f["sync"]) + f["header"].index("payload_length")
        f["field_header_size"] = 2
        f["field_length_offset"] = f["field_header"].index("length")
        f["field_descriptor_offset"] = f["field_header"].index("descriptor")
        f["field_length_adjust"] = 2 if f["field_length_counts_header"] else 0
        f["checksum_size"] = 2
        f["max_packet"] = header_size + f["max_payload"] + 2
        # Largest data a single field can carry.
        f["max_field_data"] = min(f["max_payload"] - 2, 255 - f["field_length_adjust"])
        return f

    # ---------------------------------------------------------------- field layouts
    def _field_layouts(self, sets: list[dict]) -> list[dict]:
        """Each named field layout once, with its documentation and the fields that use it."""
        out = []
        for name in sorted(self.field_layouts):
            t, lsf, lpath = self.field_layouts[name]
            users = [(s, f, v) for s in sets for f in s["fields"] for v in f["variants"] if v["layout"] == name]
            if not users:
                self.err(
                    lsf,
                    lpath + ("name",),
                    f"field layout '{name}' is not used by any field",
                    "layout: <name> on a field",
                )
                continue
            used_by = [
                {"set": s["id"], "field": f["id"], "name": f"{s['name']}.{f['name']}", "device": v["device"]}
                for s, f, v in users
            ]
            params = users[0][2]["params"]
            out.append(
                {
                    "name": name,
                    "title": t.get("title", ""),
                    "description": t.get("description", ""),
                    "sources": self._sources(lsf, lpath + ("sources",), t.get("sources", [])),
                    "notes": t.get("notes", []),
                    "params": params,
                    "size": _layout_size(params),
                    "used_by": used_by,
                }
            )
        return out

    # ---------------------------------------------------------------- samples
    def _samples(self, sets: list[dict], framing: dict) -> dict | None:
        """The sample-grouping rule of docs/conformance.md section 6, derived from the spec.

        `data_sets`: the data sets that group continuation packets (one tracker slot each);
        `first_shared`: shared descriptors start here (256: the protocol has none); `timestamps`: the shared fields whose value
        identifies a sample, with their fixed data size; `max_key`: bytes of the largest key.
        """
        shared = self.pf.data.get("shared_data")
        if not shared:
            return {"data_sets": [], "first_shared": 256, "timestamps": [], "max_key": 0}
        stamps = []
        for s in sets:
            for f in s["fields"]:
                if not f.get("sample_timestamp"):
                    continue
                size = f["variants"][0]["size"]
                if len(f["variants"]) != 1 or not size["fixed"]:
                    continue  # reported by _sets
                stamps.append({"descriptor": f["id"], "size": size["min"]})
        data = [s["id"] for s in sets if s["kind"] == "data" and not s["shared"]]
        return {
            "data_sets": data,
            "first_shared": shared["first_descriptor"],
            "timestamps": stamps,
            "max_key": sum(framing["field_header_size"] + t["size"] for t in stamps),
        }

    # ---------------------------------------------------------------- sources & notes
    def _sources(self, sf: SpecFile, path: tuple, sources: list[dict]) -> list[dict]:
        out = []
        for i, s in enumerate(sources or []):
            if s["manual"] not in self.manual_devices and s["manual"] not in _known_manuals(self.pf):
                self.err(
                    sf,
                    path + (i, "manual"),
                    f"unknown manual '{s['manual']}'",
                    "one of the manuals listed under devices in the protocol file: "
                    + ", ".join(sorted(self.manual_devices)),
                )
            out.append(dict(s))
        return out

    def _devices_of(self, sources: list[dict]) -> list[str]:
        devs = {self.manual_devices[s["manual"]] for s in sources if s["manual"] in self.manual_devices}
        return [d for d in self.device_ids if d in devs]

    # ---------------------------------------------------------------- types
    def _collect_types(self, sf: SpecFile, base: tuple) -> None:
        for kind_key, kind in (
            ("enums", "enum"),
            ("bitfields", "bitfield"),
            ("structs", "struct"),
            ("unions", "union"),
        ):
            for i, t in enumerate(sf.data.get(kind_key, []) or []):
                name = t["name"]
                path = base + (kind_key, i)
                if name in self.raw_types or name in PRIMITIVES or name in ALIASES or name == "string":
                    prev = self.type_locs.get(name)
                    where = f" (first defined at {prev})" if prev else " (a built-in type)"
                    self.err(
                        sf,
                        path + ("name",),
                        f"type '{name}' is defined twice{where}",
                        "unique type names across the protocol",
                    )
                    continue
                self.raw_types[name] = (kind, t, sf, path)
                self.type_locs[name] = sf.locate(path)
        for i, t in enumerate(sf.data.get("field_layouts", []) or []):
            path = base + ("field_layouts", i)
            if t["name"] in self.field_layouts:
                prev = self.field_layouts[t["name"]][1].locate(self.field_layouts[t["name"]][2])
                self.err(
                    sf,
                    path + ("name",),
                    f"field layout '{t['name']}' is defined twice (first defined at {prev})",
                    "unique field layout names across the protocol",
                )
                continue
            self.field_layouts[t["name"]] = (t, sf, path)

    def _resolve_types(self) -> None:
        # Enums and bitfields first (no dependencies), then structs/unions in dependency order.
        for name, (kind, t, sf, path) in self.raw_types.items():
            if kind == "enum":
                self.types[name] = self._enum(sf, path, t)
            elif kind == "bitfield":
                self.types[name] = self._bitfield(sf, path, t)
        visiting: set[str] = set()

        def resolve(name: str) -> None:
            if name in self.types:
                return
            kind, t, sf, path = self.raw_types[name]
            if name in visiting:
                self.err(sf, path + ("name",), f"type '{name}' contains itself", "a finite, non-recursive layout")
                self.types[name] = {"kind": kind, "name": name, "params": [], "members": [], "size": _fixed(0)}
                return
            visiting.add(name)
            for ref in _type_refs(t):
                if ref in self.raw_types:
                    resolve(ref)
            if kind == "struct":
                self.types[name] = self._struct(sf, path, t)
            else:
                self.types[name] = self._union(sf, path, t)
            visiting.discard(name)

        for name, (kind, _t, _sf, _p) in self.raw_types.items():
            if kind in ("struct", "union"):
                resolve(name)

    def _common(self, sf: SpecFile, path: tuple, t: dict) -> dict:
        sources = self._sources(sf, path + ("sources",), t.get("sources", []))
        return {
            "title": t.get("title", t["name"]),
            "description": t.get("description", ""),
            "sources": sources,
            "devices": self._devices_of(sources),
            "notes": t.get("notes", []),
            "defined_at": str(sf.locate(path)),
        }

    def _enum(self, sf: SpecFile, path: tuple, t: dict) -> dict:
        base = t["type"]
        lo, hi = int_range(base)
        seen_names: dict[str, int] = {}
        seen_values: dict[int, list[tuple[set, str]]] = {}
        values = []
        for i, v in enumerate(t["values"]):
            vp = path + ("values", i)
            if not lo <= v["value"] <= hi:
                self.err(
                    sf,
                    vp + ("value",),
                    f"enum {t['name']} value {v['name']} = {v['value']} does not fit in {base}",
                    f"{lo}..{hi}",
                )
            if v["name"] in seen_names:
                self.err(
                    sf, vp + ("name",), f"enum {t['name']} has two values named '{v['name']}'", "unique value names"
                )
            seen_names[v["name"]] = v["value"]
            devs = set(v.get("devices") or self.device_ids)
            for d in v.get("devices", []) or []:
                if d not in self.device_ids:
                    self.err(sf, vp + ("devices",), f"unknown device '{d}'", "one of " + ", ".join(self.device_ids))
            for other_devs, other_name in seen_values.get(v["value"], []):
                if other_devs & devs:
                    self.err(
                        sf,
                        vp + ("value",),
                        f"enum {t['name']} value {v['value']} is used by both '{other_name}' and '{v['name']}' for the same device",
                        "distinct values, or 'devices:' lists that do not overlap",
                    )
            seen_values.setdefault(v["value"], []).append((devs, v["name"]))
            values.append(
                {
                    "name": v["name"],
                    "value": v["value"],
                    "description": v.get("description", ""),
                    "manual_name": v.get("manual_name"),
                    "devices": v.get("devices"),
                }
            )
        out = {"kind": "enum", "name": t["name"], "base": base, "size": _fixed(PRIMITIVES[base][0]), "values": values}
        out.update(self._common(sf, path, t))
        return out

    def _bitfield(self, sf: SpecFile, path: tuple, t: dict) -> dict:
        base = t["type"]
        nbits = PRIMITIVES[base][0] * 8
        members = []
        used: dict[int, str] = {}
        names: set[str] = set()
        for i, m in enumerate(t["members"]):
            mp = path + ("members", i)
            bits = m["bits"]
            first, last = (bits, bits) if isinstance(bits, int) else (bits[0], bits[1])
            if first > last:
                self.err(
                    sf,
                    mp + ("bits",),
                    f"bitfield {t['name']} member {m['name']}: bit range {first}-{last} is reversed",
                    "[low, high]",
                )
                first, last = last, first
            if last >= nbits:
                self.err(
                    sf,
                    mp + ("bits",),
                    f"bitfield {t['name']} member {m['name']}: bit {last} is out of range for {base}",
                    f"bits 0..{nbits - 1}",
                )
                last = min(last, nbits - 1)
                first = min(first, last)
            if m["name"] in names:
                self.err(
                    sf,
                    mp + ("name",),
                    f"bitfield {t['name']} has two members named '{m['name']}'",
                    "unique member names",
                )
            names.add(m["name"])
            if not m.get("alias"):
                for b in range(first, last + 1):
                    if b in used:
                        self.err(
                            sf,
                            mp + ("bits",),
                            f"bitfield {t['name']} member {m['name']} overlaps '{used[b]}' at bit {b}",
                            "non-overlapping members (mark deliberate multi-bit masks with alias: true)",
                        )
                        break
                for b in range(first, last + 1):
                    used.setdefault(b, m["name"])
            width = last - first + 1
            members.append(
                {
                    "name": m["name"],
                    "first_bit": first,
                    "last_bit": last,
                    "width": width,
                    "mask": ((1 << width) - 1) << first,
                    "reserved": bool(m.get("reserved")),
                    "alias": bool(m.get("alias")),
                    "description": m.get("description", ""),
                    "manual_name": m.get("manual_name"),
                    "devices": m.get("devices"),
                }
            )
        out = {
            "kind": "bitfield",
            "name": t["name"],
            "base": base,
            "size": _fixed(PRIMITIVES[base][0]),
            "members": members,
        }
        out.update(self._common(sf, path, t))
        return out

    def _struct(self, sf: SpecFile, path: tuple, t: dict) -> dict:
        params = self._params(
            sf, path + ("params",), t["params"], functions=None, owner=f"struct {t['name']}", allow_optional=False
        )
        out = {"kind": "struct", "name": t["name"], "params": params, "size": _layout_size(params)}
        out.update(self._common(sf, path, t))
        return out

    def _union(self, sf: SpecFile, path: tuple, t: dict) -> dict:
        sel = t["selector_enum"]
        sel_t = self.types.get(sel)
        if sel_t is None or sel_t["kind"] != "enum":
            what = "not defined" if sel_t is None else f"a {sel_t['kind']}, not an enum"
            self.err(
                sf,
                path + ("selector_enum",),
                f"union {t['name']}: selector type '{sel}' is {what}",
                "the name of an enum",
            )
            values = {}
        else:
            values = {v["name"]: v["value"] for v in sel_t["values"]}
        members = []
        seen: set[str] = set()
        for i, m in enumerate(t["members"]):
            mp = path + ("members", i)
            if values and m["when"] not in values:
                self.err(
                    sf,
                    mp + ("when",),
                    f"union {t['name']}: '{m['when']}' is not a value of enum {sel}",
                    "one of " + ", ".join(values),
                )
            if m["when"] in seen:
                self.err(
                    sf,
                    mp + ("when",),
                    f"union {t['name']}: two members for '{m['when']}'",
                    "one member per selector value",
                )
            seen.add(m["when"])
            mt = m.get("type")
            if mt is not None and (mt not in self.types or self.types[mt]["kind"] != "struct"):
                self.err(
                    sf,
                    mp + ("type",),
                    f"union {t['name']} member '{m['when']}': type '{mt}' is not a defined struct",
                    "a struct name",
                )
                mt = None
            members.append(
                {
                    "when": m["when"],
                    "value": values.get(m["when"], 0),
                    "type": mt,
                    "description": m.get("description", ""),
                    "size": self.types[mt]["size"] if mt else _fixed(0),
                }
            )
        sizes = [m["size"] for m in members] or [_fixed(0)]
        size = {"min": min(s["min"] for s in sizes), "max": max(s["max"] for s in sizes), "fixed": False}
        out = {"kind": "union", "name": t["name"], "selector_enum": sel, "members": members, "size": size}
        out.update(self._common(sf, path, t))
        return out

    # ---------------------------------------------------------------- params
    def _typeref(self, sf: SpecFile, path: tuple, p: dict) -> tuple[dict, str | None, int | None]:
        """Returns (type ref, alias name, implicit fixed count)."""
        tname = p["type"]
        if tname in ALIASES:
            elem, n = ALIASES[tname]
            return {"kind": "primitive", "name": elem, "size": _fixed(PRIMITIVES[elem][0])}, tname, n
        if tname in PRIMITIVES:
            return {"kind": "primitive", "name": tname, "size": _fixed(PRIMITIVES[tname][0])}, None, None
        if tname == "string":
            length = p.get("length")
            if length is None:
                self.err(
                    sf,
                    path + ("type",),
                    f"parameter {p['name']}: string needs a length",
                    "length: N (bytes on the wire)",
                )
                length = 1
            return (
                {
                    "kind": "string",
                    "length": length,
                    "padding": p.get("padding", self.string_defaults.get("padding", "nul")),
                    "justify": p.get("justify", self.string_defaults.get("justify", "left")),
                    "size": _fixed(length),
                },
                None,
                None,
            )
        t = self.types.get(tname)
        if t is None:
            known = sorted(list(PRIMITIVES) + list(ALIASES) + ["string"] + list(self.types))
            self.err(
                sf,
                path + ("type",),
                f"parameter {p['name']}: unknown type '{tname}'",
                "a primitive, vector type, string or defined type: " + ", ".join(known),
            )
            return {"kind": "primitive", "name": "u8", "size": _fixed(1)}, None, None
        ref = {"kind": t["kind"], "name": tname, "size": t["size"]}
        if t["kind"] in ("enum", "bitfield"):
            ref["base"] = t["base"]
        return ref, None, None

    def _params(
        self,
        sf: SpecFile,
        path: tuple,
        params: list[dict],
        functions: list[str] | None,
        owner: str,
        allow_optional: bool = True,
    ) -> list[dict]:
        out: list[dict] = []
        names: dict[str, dict] = {}
        optional_seen: str | None = None
        max_data = self._framing_max_field_data()
        for i, p in enumerate(params):
            pp = path + (i,)
            name = p["name"]
            if name in names:
                self.err(sf, pp + ("name",), f"{owner}: two parameters named '{name}'", "unique parameter names")
            if name == "function" and functions is not None:
                self.err(
                    sf, pp + ("name",), f"{owner}: 'function' is reserved for the function selector", "another name"
                )
            tref, alias, implicit_count = self._typeref(sf, pp, p)
            count = None
            if implicit_count is not None:
                count = {"kind": "fixed", "value": implicit_count}
                if "count" in p:
                    self.err(
                        sf,
                        pp + ("count",),
                        f"{owner}: parameter {name} has type {alias}, which already has {implicit_count} elements",
                        "no count on vector/matrix types (use the element type with count)",
                    )
            elif "count" in p:
                c = p["count"]
                if isinstance(c, int):
                    count = {"kind": "fixed", "value": c}
                elif c == "remaining":
                    count = {"kind": "remaining"}
                    if i != len(params) - 1:
                        self.err(
                            sf,
                            pp + ("count",),
                            f"{owner}: parameter {name} runs to the end of the field but is not the last parameter",
                            "count: remaining only on the last parameter",
                        )
                else:
                    ref = names.get(c)
                    if ref is None:
                        later = any(q["name"] == c for q in params[i + 1 :])
                        why = "a later parameter" if later else "not a parameter"
                        self.err(
                            sf,
                            pp + ("count",),
                            f"{owner}: count of {name} refers to '{c}', which is {why}",
                            "the name of an earlier integer parameter",
                        )
                    elif not _is_integer(ref["type"]) or ref["count"] is not None:
                        self.err(
                            sf,
                            pp + ("count",),
                            f"{owner}: count of {name} refers to '{c}', which is not a single integer",
                            "an earlier u8/u16/u32 parameter",
                        )
                    count = {"kind": "param", "param": c}
            if tref["kind"] == "string" and count is not None:
                self.err(
                    sf, pp + ("count",), f"{owner}: arrays of strings are not supported", "a struct holding the string"
                )
            if tref["kind"] != "string" and ("length" in p or "padding" in p or "justify" in p):
                self.err(
                    sf,
                    pp,
                    f"{owner}: parameter {name}: length/padding/justify apply only to type string",
                    "type: string",
                )
            if tref["kind"] == "union":
                sel = p.get("selector")
                ut = self.types[tref["name"]]
                if sel is None:
                    self.err(
                        sf,
                        pp,
                        f"{owner}: union parameter {name} needs 'selector'",
                        "selector: <earlier enum parameter>",
                    )
                elif sel not in names:
                    self.err(
                        sf,
                        pp + ("selector",),
                        f"{owner}: selector of {name} refers to '{sel}', which is not an earlier parameter",
                        "the name of an earlier enum parameter",
                    )
                elif names[sel]["type"]["kind"] != "enum":
                    self.err(
                        sf,
                        pp + ("selector",),
                        f"{owner}: selector '{sel}' of union {name} is not an enum (it is {names[sel]['type']['kind']})",
                        f"a parameter of enum type {ut['selector_enum']}",
                    )
                elif names[sel]["type"]["name"] != ut["selector_enum"]:
                    self.err(
                        sf,
                        pp + ("selector",),
                        f"{owner}: selector '{sel}' has type {names[sel]['type']['name']}, union {tref['name']} is selected by {ut['selector_enum']}",
                        f"a parameter of enum type {ut['selector_enum']}",
                    )
                tref = dict(tref, selector=sel)
                if count is not None:
                    self.err(sf, pp + ("count",), f"{owner}: arrays of unions are not supported", "a single union")
            elif "selector" in p:
                self.err(
                    sf,
                    pp + ("selector",),
                    f"{owner}: parameter {name} is not a union; 'selector' does not apply",
                    "no selector",
                )
            pf = p.get("functions")
            if pf is not None:
                if functions is None:
                    self.err(
                        sf,
                        pp + ("functions",),
                        f"{owner}: parameter {name} lists functions but the command has no function selector",
                        "functions: on the command first",
                    )
                else:
                    for fn in pf:
                        if fn not in functions:
                            self.err(
                                sf,
                                pp + ("functions",),
                                f"{owner}: parameter {name} is marked for function '{fn}', which the command does not support",
                                "a subset of the command's functions: " + ", ".join(functions),
                            )
            optional = bool(p.get("optional")) or (
                functions is not None and pf is not None and set(pf) != set(functions)
            )
            if functions is not None and pf is None:
                self.err(
                    sf,
                    pp,
                    f"{owner}: parameter {name} does not say which functions it is sent for",
                    "functions: [...] on every parameter of a command with a function selector",
                )
            if optional and not allow_optional:
                self.err(
                    sf, pp, f"{owner}: parameter {name} cannot be optional here", "optional parameters only in commands"
                )
            if optional:
                optional_seen = optional_seen or name
            elif optional_seen:
                self.err(
                    sf,
                    pp,
                    f"{owner}: required parameter {name} follows optional parameter {optional_seen}",
                    "optional parameters (not sent for every function) at the end",
                )
            max_count = None
            if count is not None and count["kind"] != "fixed":
                max_count = p.get("max_count") or -1  # default: what fits beside the others (below)
            elif "max_count" in p:
                self.err(
                    sf,
                    pp + ("max_count",),
                    f"{owner}: max_count applies only to counted arrays",
                    "count: <param> or remaining",
                )
            q = {
                "name": name,
                "description": p.get("description", ""),
                "units": p.get("units"),
                "manual_name": p.get("manual_name"),
                "type": tref,
                "alias": alias,
                "count": count,
                "max_count": max_count,
                "functions": pf,
                "optional": optional,
                "notes": p.get("notes", []),
            }
            q["size"] = _param_size(q)
            names[name] = q
            out.append(q)
        # Default capacity of a counted array: what fits in one field beside the selector byte and
        # the smallest size of every other parameter.
        for q in out:
            if q["max_count"] == -1:
                others = sum(o["size"]["min"] for o in out if o is not q)
                budget = max_data - (1 if functions is not None else 0) - others
                q["max_count"] = max(budget // max(q["type"]["size"]["min"], 1), 0)
                q["size"] = _param_size(q)
        # fixed offsets where known
        off: int | None = 0
        for q in out:
            q["offset"] = off
            if off is not None and q["size"]["fixed"] and not q["optional"]:
                off += q["size"]["min"]
            else:
                off = None
        return out

    def _framing_max_field_data(self) -> int:
        f = self.pf.data["framing"]
        adj = 2 if f["field_length_counts_header"] else 0
        return min(f["max_payload"] - 2, 255 - adj)

    # ---------------------------------------------------------------- fields
    def _reserved_field(self, sf: SpecFile, i: int, f: dict) -> dict:
        path = ("reserved_fields", i)
        params = self._params(sf, path + ("params",), f["params"], None, f"reserved field {f['name']}")
        sources = self._sources(sf, path + ("sources",), f["sources"])
        return {
            "id": f["id"],
            "name": f["name"],
            "title": f["title"],
            "role": f["role"],
            "applies_to": f["applies_to"],
            "description": f.get("description", ""),
            "sources": sources,
            "devices": self._devices_of(sources),
            "notes": f.get("notes", []),
            "stated_length": f.get("stated_length"),
            "variants": [
                {
                    "device": None,
                    "devices": self._devices_of(sources),
                    "sources": sources,
                    "notes": [],
                    "functions": None,
                    "responses": [],
                    "ack_suppressed_by": None,
                    "params": params,
                    "size": _layout_size(params),
                    "layout": None,
                }
            ],
            "params": params,
            "size": _layout_size(params),
        }

    def _layout(self, sf: SpecFile, path: tuple, src: dict, set_name: str, field: dict, device: str | None) -> dict:
        owner = f"{set_name}.{field['name']}" + (f" ({device})" if device else "")
        functions = src.get("functions")
        if functions is not None:
            for j, fn in enumerate(functions):
                if self.function_values and fn not in self.function_values:
                    self.err(
                        sf,
                        path + ("functions", j),
                        f"{owner}: unknown function '{fn}'",
                        "one of " + ", ".join(self.function_values),
                    )
            if field["role"] != "command":
                self.err(
                    sf,
                    path + ("functions",),
                    f"{owner}: only commands take a function selector",
                    "no functions on responses and data",
                )
        layout_name = src.get("layout")
        if layout_name is not None:
            shared = self.field_layouts.get(layout_name)
            if shared is None:
                known = ", ".join(sorted(self.field_layouts)) or "none defined"
                self.err(
                    sf,
                    path + ("layout",),
                    f"{owner}: unknown field layout '{layout_name}'",
                    f"a name under field_layouts: ({known})",
                )
                params = []
            else:
                t, lsf, lpath = shared
                params = self._params(lsf, lpath + ("params",), t["params"], functions, f"field layout {layout_name}")
        else:
            params = self._params(sf, path + ("params",), src.get("params", []), functions, owner)
        responses = []
        if "response" in src and "responses" in src:
            self.err(sf, path + ("response",), f"{owner}: both 'response' and 'responses'", "one of them")
        for j, r in enumerate(
            src.get("responses", []) if "responses" in src else ([src["response"]] if "response" in src else [])
        ):
            rp = path + (("responses", j) if "responses" in src else ("response",))
            if isinstance(r, int):
                r = {"id": r}
            when = r.get("when")
            if when:
                if "function" in when and functions is not None and when["function"] not in functions:
                    self.err(
                        sf,
                        rp + ("when", "function"),
                        f"{owner}: response condition names function '{when['function']}', which the command does not support",
                        "one of " + ", ".join(functions),
                    )
                if "param" in when:
                    match = [q for q in params if q["name"] == when["param"]]
                    if not match:
                        self.err(
                            sf,
                            rp + ("when", "param"),
                            f"{owner}: response condition names parameter '{when['param']}', which does not exist",
                            "a parameter of this command",
                        )
                    elif "value" in when and isinstance(when["value"], str):
                        t = self.types.get(match[0]["type"].get("name", ""))
                        if not t or t["kind"] != "enum" or when["value"] not in {v["name"] for v in t["values"]}:
                            self.err(
                                sf,
                                rp + ("when", "value"),
                                f"{owner}: '{when['value']}' is not a value of parameter {when['param']}",
                                "an enum value name",
                            )
            responses.append({"id": r["id"], "when": when, "_loc": rp})
        if responses and field["role"] != "command":
            self.err(
                sf, path + ("response",), f"{owner}: only commands have responses", "no response on responses and data"
            )
        ack = src.get("ack_suppressed_by")
        if ack:
            if "function" in ack and (functions is None or ack["function"] not in functions):
                self.err(
                    sf,
                    path + ("ack_suppressed_by", "function"),
                    f"{owner}: ack suppression by function '{ack['function']}', which the command does not support",
                    "one of the command's functions",
                )
            target = next((q for q in params if q["name"] == ack.get("param")), None)
            if "param" in ack and target is None:
                self.err(
                    sf,
                    path + ("ack_suppressed_by", "param"),
                    f"{owner}: ack suppression by parameter '{ack['param']}', which does not exist",
                    "a parameter of this command",
                )
            if "value" in ack:
                ack = dict(ack)
                enum = (
                    self.types.get(target["type"].get("name")) if target and target["type"]["kind"] == "enum" else None
                )
                if "param" not in ack:
                    self.err(
                        sf, path + ("ack_suppressed_by", "value"), f"{owner}: value without param", "param: <name>"
                    )
                elif isinstance(ack["value"], str):
                    names = {v["name"]: v["value"] for v in enum["values"]} if enum else {}
                    if ack["value"] not in names:
                        self.err(
                            sf,
                            path + ("ack_suppressed_by", "value"),
                            f"{owner}: ack suppression value '{ack['value']}' is not a value of parameter {ack['param']}",
                            "one of " + ", ".join(names) if names else "an integer (the parameter is not an enum)",
                        )
                    else:
                        ack["value"] = names[ack["value"]]
        sources = self._sources(sf, path + ("sources",), src.get("sources", []))
        if device is not None:
            devs = self._devices_of(sources)
            if devs and device not in devs:
                self.err(
                    sf,
                    path + ("device",),
                    f"{owner}: variant for device '{device}' cites only manuals of {', '.join(devs)}",
                    "sources from that device's manual",
                )
        return {
            "device": device,
            "devices": [device] if device else self._devices_of(sources),
            "sources": sources,
            "notes": src.get("notes", []) if device else [],
            "functions": functions,
            "responses": responses,
            "ack_suppressed_by": ack,
            "params": params,
            "size": _layout_size(params, selector=functions is not None),
            "layout": layout_name,
        }

    def _sets(self, reserved: list[dict], framing: dict) -> list[dict]:
        sets = []
        by_id: dict[int, tuple[SpecFile, dict]] = {}
        by_name: dict[str, SpecFile] = {}
        kinds = self.pf.data["set_kinds"]
        shared = self.pf.data.get("shared_data")
        # A set may be split over several files ("parts"); they must agree on name and kind.
        groups: dict[int, list[SpecFile]] = {}
        for sf in self.set_files:
            groups.setdefault(sf.data["set"], []).append(sf)
        for set_id, parts in groups.items():
            sf = parts[0]
            d = sf.data
            for other in parts[1:]:
                for key in ("name", "kind"):
                    if other.data[key] != d[key]:
                        self.err(
                            other,
                            (key,),
                            f"descriptor set 0x{set_id:02X} has {key} '{other.data[key]}' here but '{d[key]}' in {sf.path}",
                            f"every file of set 0x{set_id:02X} with {key} '{d[key]}'",
                        )
            if d["name"] in by_name:
                self.err(
                    sf,
                    ("name",),
                    f"descriptor set name '{d['name']}' is used twice (also in {by_name[d['name']].path})",
                    "unique set names",
                )
            by_id[set_id] = (sf, d)
            by_name[d["name"]] = sf
            rng = kinds.get(d["kind"])
            if rng and not rng["first"] <= d["set"] <= rng["last"]:
                self.err(
                    sf,
                    ("set",),
                    f"{d['kind']} set 0x{d['set']:02X} is outside the {d['kind']} range",
                    f"0x{rng['first']:02X}..0x{rng['last']:02X}",
                )
            is_shared = bool(shared and d["set"] == shared["set"])
            fields = []
            ids: dict[int, str] = {}
            fnames: set[str] = set()
            for sf, i, f in [(part, i, f) for part in parts for i, f in enumerate(part.data["fields"])]:
                fp = ("fields", i)
                if f["id"] in ids:
                    self.err(
                        sf,
                        fp + ("id",),
                        f"{d['name']}: descriptor 0x{f['id']:02X} is used by both '{ids[f['id']]}' and '{f['name']}'",
                        "unique descriptors within a set",
                    )
                ids[f["id"]] = f["name"]
                if f["name"] in fnames:
                    self.err(
                        sf,
                        fp + ("name",),
                        f"{d['name']}: two fields named '{f['name']}'",
                        "unique field names within a set",
                    )
                fnames.add(f["name"])
                for r in reserved:
                    if r["applies_to"] == d["kind"] and r["id"] == f["id"]:
                        self.err(
                            sf,
                            fp + ("id",),
                            f"{d['name']}.{f['name']}: descriptor 0x{f['id']:02X} is reserved for {r['name']}",
                            "another descriptor",
                        )
                if d["kind"] == "command" and f["role"] == "data" or d["kind"] == "data" and f["role"] != "data":
                    self.err(
                        sf,
                        fp + ("role",),
                        f"{d['name']}.{f['name']}: role {f['role']} in a {d['kind']} set",
                        "command/response in command sets, data in data sets",
                    )
                if is_shared and f["id"] < shared["first_descriptor"]:
                    self.err(
                        sf,
                        fp + ("id",),
                        f"shared descriptor 0x{f['id']:02X} is below 0x{shared['first_descriptor']:02X}",
                        f">= 0x{shared['first_descriptor']:02X}",
                    )
                if f.get("sample_timestamp") and not is_shared:
                    self.err(
                        sf,
                        fp + ("sample_timestamp",),
                        f"{d['name']}.{f['name']}: only a shared data field can identify a sample",
                        "sample_timestamp only in the shared data set",
                    )
                if f.get("repeats") and f["role"] != "data":
                    self.err(sf, fp + ("repeats",), f"{d['name']}.{f['name']}: only data fields repeat", "no repeats")
                given = [k for k in ("params", "layout", "variants") if k in f]
                if len(given) != 1:
                    what = " and ".join(given) if given else "none of them"
                    self.err(
                        sf,
                        fp + ((given[1],) if len(given) > 1 else ()),
                        f"{d['name']}.{f['name']}: has {what}",
                        "exactly one of params (its own parameters), layout (a shared field layout) or variants (per-device layouts)",
                    )
                if "variants" in f and "sources" in f:
                    self.err(
                        sf,
                        fp + ("sources",),
                        f"{d['name']}.{f['name']}: with variants, sources go in each variant",
                        "sources under each variant",
                    )
                if "variants" not in f and "sources" not in f:
                    self.err(sf, fp, f"{d['name']}.{f['name']}: missing sources", "sources: [{manual, line, title}]")
                if "variants" in f:
                    variants = []
                    seen_dev: set[str] = set()
                    for j, v in enumerate(f["variants"]):
                        if v["device"] not in self.device_ids:
                            self.err(
                                sf,
                                fp + ("variants", j, "device"),
                                f"unknown device '{v['device']}'",
                                "one of " + ", ".join(self.device_ids),
                            )
                        if v["device"] in seen_dev:
                            self.err(
                                sf,
                                fp + ("variants", j, "device"),
                                f"{d['name']}.{f['name']}: two variants for device '{v['device']}'",
                                "one variant per device",
                            )
                        seen_dev.add(v["device"])
                        if ("params" in v) == ("layout" in v):
                            self.err(
                                sf,
                                fp + ("variants", j),
                                f"{d['name']}.{f['name']} ({v['device']}): needs exactly one of params or layout",
                                "params: [...] or layout: <FieldLayout>",
                            )
                        variants.append(self._layout(sf, fp + ("variants", j), v, d["name"], f, v["device"]))
                    if f.get("functions") or f.get("response") or f.get("responses"):
                        self.err(
                            sf,
                            fp,
                            f"{d['name']}.{f['name']}: with variants, functions/responses go in each variant",
                            "per-variant functions/responses",
                        )
                    sources = [s for v in variants for s in v["sources"]]
                else:
                    variants = [self._layout(sf, fp, f, d["name"], f, None)]
                    sources = variants[0]["sources"]
                devices = [x for x in self.device_ids if any(x in v["devices"] for v in variants)]
                fields.append(
                    {
                        "id": f["id"],
                        "name": f["name"],
                        "role": f["role"],
                        "title": f["title"],
                        "description": f.get("description", ""),
                        "sources": sources,
                        "devices": devices,
                        "notes": f.get("notes", []),
                        "repeats": bool(f.get("repeats")),
                        "manual_name": f.get("manual_name"),
                        "sample_timestamp": bool(f.get("sample_timestamp")),
                        "length_byte_adjust": f.get("length_byte_adjust", 0),
                        "variants": variants,
                        "_sf": sf,
                        "_path": fp,
                    }
                )
            sets.append(
                {
                    "id": d["set"],
                    "name": d["name"],
                    "title": d["title"],
                    "kind": d["kind"],
                    "shared": is_shared,
                    "description": d.get("description", ""),
                    "sources": _unique(
                        [s for part in parts for s in self._sources(part, ("sources",), part.data["sources"])]
                    ),
                    "notes": [n for part in parts for n in part.data.get("notes", [])],
                    "fields": fields,
                    "_sf": parts[0],
                }
            )
        sets.sort(key=lambda s: s["id"])
        # Link responses: each must exist in the same set with role response.
        for s in sets:
            by_desc = {f["id"]: f for f in s["fields"]}
            for f in s["fields"]:
                for v in f["variants"]:
                    for r in v["responses"]:
                        target = by_desc.get(r["id"])
                        sf = f["_sf"]
                        if target is None:
                            self.err(
                                sf,
                                r["_loc"],
                                f"{s['name']}.{f['name']}: response 0x{r['id']:02X} does not exist in set 0x{s['id']:02X}",
                                "the descriptor of a field with role response in the same set",
                            )
                        elif target["role"] != "response":
                            self.err(
                                sf,
                                r["_loc"],
                                f"{s['name']}.{f['name']}: response 0x{r['id']:02X} is '{target['name']}', a {target['role']} field",
                                "a field with role response",
                            )
                        else:
                            r["name"] = target["name"]
                        rule = self.pf.data.get("response_descriptor")
                        if rule and r["id"] != f["id"] | rule["command_or"]:
                            self.err(
                                sf,
                                r["_loc"],
                                f"{s['name']}.{f['name']}: response 0x{r['id']:02X} breaks the reply code rule",
                                f"0x{f['id'] | rule['command_or']:02X} (command 0x{f['id']:02X} | 0x{rule['command_or']:02X}, protocol response_descriptor)",
                            )
                        del r["_loc"]
                    # Top-level convenience copies required by the exported IR contract.
                f["params"] = f["variants"][0]["params"]
                f["size"] = f["variants"][0]["size"]
                f["functions"] = f["variants"][0]["functions"]
                f["responses"] = [r["id"] for v in f["variants"] for r in v["responses"]]
                f["response"] = f["responses"][0] if f["responses"] else None
                f["stated_lengths"] = [
                    {"manual": src["manual"], "line": src.get("line"), "stated": src["stated_length"]}
                    for src in f["sources"]
                    if "stated_length" in src
                ]
                adjust = f["length_byte_adjust"]
                if adjust:
                    base = framing["field_length_adjust"]
                    lo, hi = f["size"]["min"] + base + adjust, f["size"]["max"] + base + adjust
                    if len(f["variants"]) != 1 or lo < 0 or hi > 255:
                        self.err(
                            f["_sf"],
                            f["_path"] + ("length_byte_adjust",),
                            f"{s['name']}.{f['name']}: with length_byte_adjust {adjust} the size byte would be "
                            f"{lo}..{hi}",
                            "one layout whose size byte stays within 0..255",
                        )
                if f.get("sample_timestamp") and (len(f["variants"]) != 1 or not f["size"]["fixed"]):
                    self.err(
                        f["_sf"],
                        f["_path"] + ("sample_timestamp",),
                        f"{s['name']}.{f['name']}: a sample timestamp needs one fixed-size layout",
                        "fixed-size parameters, no variants",
                    )
                del f["_sf"], f["_path"]
            del s["_sf"]
        return sets


def _unique(items: list[dict]) -> list[dict]:
    """Items in order, without repeats (parts of a set may cite the same set-level source)."""
    out: list[dict] = []
    for x in items:
        if x not in out:
            out.append(x)
    return out


def _known_manuals(pf: SpecFile) -> set[str]:
    return {d["manual"] for d in pf.data.get("devices", [])}


def _fixed(n: int) -> dict:
    return {"min": n, "max": n, "fixed": True}


def _is_integer(tref: dict) -> bool:
    return tref["kind"] == "primitive" and PRIMITIVES[tref["name"]][1] == "int" and not PRIMITIVES[tref["name"]][2]


def _param_size(q: dict) -> dict:
    t = q["type"]["size"]
    c = q["count"]
    if c is None:
        return dict(t)
    if c["kind"] == "fixed":
        return {"min": t["min"] * c["value"], "max": t["max"] * c["value"], "fixed": t["fixed"]}
    return {"min": 0, "max": t["max"] * q["max_count"], "fixed": False}


def _layout_size(params: list[dict], selector: bool = False) -> dict:
    """Data size of a layout (after the field header), including the function selector byte."""
    sel = 1 if selector else 0
    mn = sel + sum(q["size"]["min"] for q in params if not q["optional"])
    mx = sel + sum(q["size"]["max"] for q in params)
    fixed = all(q["size"]["fixed"] and not q["optional"] for q in params)
    return {"min": mn, "max": mx, "fixed": fixed}


def _type_refs(t: dict) -> list[str]:
    refs = [p["type"] for p in t.get("params", [])]
    refs += [
        m["type"] for m in t.get("members", []) if isinstance(m, dict) and "type" in m and isinstance(m["type"], str)
    ]
    if "selector_enum" in t:
        refs.append(t["selector_enum"])
    return refs


def lint_stated_lengths(ir: dict) -> list[dict]:
    """Every disagreement between a manual's stated field length and the computed one."""
    out = []
    for proto in ir["protocols"]:
        adj = proto["framing"]["field_length_adjust"]
        for s in proto["sets"]:
            for f in s["fields"]:
                for v in f["variants"]:
                    size = v["size"]
                    for src in v["sources"]:
                        stated = src.get("stated_length")
                        if stated is None:
                            continue
                        full_min, full_max = size["min"] + adj, size["max"] + adj
                        textual = not isinstance(stated, int)
                        if not textual:
                            # A command with optional parameters may be stated at its full length.
                            ok = stated == full_max if _all_fixed_elements(v["params"]) else False
                            if ok or (size["fixed"] and stated == full_min):
                                continue
                        item = {
                            "protocol": proto["name"],
                            "set": s["id"],
                            "descriptor": f["id"],
                            "name": f"{s['name']}.{f['name']}",
                            "manual": src["manual"],
                            "line": src.get("line"),
                            "stated": stated,
                            "computed": full_min if size["fixed"] else f"{full_min}..{full_max}",
                        }
                        if textual:
                            item["textual"] = True
                        out.append(item)
    return out


def _all_fixed_elements(params: list[dict]) -> bool:
    return all(q["size"]["fixed"] for q in params)


_IDENT = re.compile(r"^[a-z][a-z0-9_]*$")
