"""Rust back end: one `no_std` crate (optional `std` feature) per protocol at generated/rust/<package>/.

All naming and type mapping happens here (the language's keywords and type table are data, in
facts.py); the templates in templates/rust/ only loop and print. The runtime, the code that does
not depend on the spec (parser, checksum, builder, JSON, errors, the command-line tools), is plain
Rust in runtime/, copied verbatim into each crate: its only protocol input is the generated
`crate::framing` constants module (templates/rust/framing.rs.j2).
"""

from __future__ import annotations

import re

from generator import commands, examples, model, naming, packet_plan
from generator.clock_model import clock_model
from generator.examples import ExampleError
from generator.linkfacts import link_facts
from generator.naming import upper
from generator.primitives import PRIMITIVES
from generator.release import Release, load_release
from generator.render import ToolError, copy_runtime, environment
from generator.testcases import bitfield_cases, canonical_literals, layout_error_cases, vector_cases

from .facts import (
    CATEGORIES,
    DEVICE_METHODS,
    INCLUDE,
    KEYWORDS,
    KEYWORDS_COMMON,
    LICENSE,
    NOT_RAW,
    PRIMITIVE_TYPES,
    RESERVED_MODULES,
    RUST_VERSION,
)

OUTPUT_DIRS = ["rust"]


# ---------------------------------------------------------------------------------------- naming
def camel(name: str) -> str:
    """snake_case -> CamelCase with Rust's options (generator/naming.py): a `_` between digit words,
    `T` before a leading digit."""
    return naming.camel(name, digit_break="_", leading_digit="T")


def ident(name: str) -> str:
    """A snake_case Rust identifier for a spec name (keywords escaped)."""
    if name in NOT_RAW:
        return name + "_"
    if name in KEYWORDS:
        return "r#" + name
    return name


def rust_str(s: str) -> str:
    """A Rust string literal for ASCII text."""
    out = ['"']
    for ch in s:
        if ch == "\\":
            out.append("\\\\")
        elif ch == '"':
            out.append('\\"')
        elif 0x20 <= ord(ch) < 0x7F:
            out.append(ch)
        else:
            out.append("\\u{%x}" % ord(ch))
    out.append('"')
    return "".join(out)


def toml_str(s: str) -> str:
    """A TOML basic string for any text (control and non-ASCII characters escaped)."""
    out = ['"']
    for ch in s:
        if ch in '"\\':
            out.append("\\" + ch)
        elif 0x20 <= ord(ch) < 0x7F:
            out.append(ch)
        else:
            out.append("\\u%04X" % ord(ch) if ord(ch) <= 0xFFFF else "\\U%08X" % ord(ch))
    out.append('"')
    return "".join(out)


_CRATE_KEYWORD = re.compile(r"[a-z][a-z0-9_-]{0,19}")


def cargo_metadata(proto: dict) -> dict:
    """The [package] metadata of a protocol's crate (facts.py): TOML values, ready to print.
    Keywords are the protocol's name, its vendor (the first word of its title) and the common
    ones, as far as crates.io accepts them (a word it would refuse is left out)."""
    words = [proto["name"], *proto["title"].split()[:1], *KEYWORDS_COMMON]
    keywords: list[str] = []
    for word in (w.lower() for w in words):
        if _CRATE_KEYWORD.fullmatch(word) and word not in keywords:
            keywords.append(word)
    description = (
        f"{proto['title']}: stream parser, typed encoders and decoders of every field, canonical "
        "JSON; no_std, no allocation, no dependencies. Generated from the protocol spec."
    )
    return {
        "rust_version": toml_str(RUST_VERSION),
        "license": toml_str(LICENSE),
        "description": toml_str(description),
        "keywords": ", ".join(toml_str(k) for k in keywords[:5]),
        "categories": ", ".join(toml_str(c) for c in CATEGORIES[:5]),
        "include": ", ".join(toml_str(i) for i in INCLUDE),
    }


def doc_line(*texts: str | None) -> str:
    """One line of documentation text (whitespace folded), or ''."""
    parts = [" ".join(str(t).split()) for t in texts if t and str(t).strip()]
    text = ". ".join(p.rstrip(".") for p in parts)
    if text and not text.endswith("."):
        text += "."
    # Brackets would read as intra-doc links.
    return text.replace("[", "\\[").replace("]", "\\]")


def _int_rust(name: str) -> str:
    return PRIMITIVE_TYPES[name]


# The cargo feature that every set feature turns on: with it, the dispatch holds only the
# selected sets (without it, every set).
SELECT_SETS = "select-sets"


def set_feature(module: str) -> str:
    """The cargo feature that selects a set for the dispatch: `set-` and the set's module name
    with dashes (`filter_data` -> `set-filter-data`)."""
    return "set-" + module.replace("_", "-")


def _hex(v: int, width: int = 2) -> str:
    return "0x%0*X" % (width, v)


# ---------------------------------------------------------------------------------------- model
class _Protocol:
    """Everything the templates need for one protocol, computed from the IR."""

    def __init__(self, proto: dict, vectors: list[dict]):
        self.proto = proto
        self.package = proto["package"]
        self.types = {t["name"]: t for t in proto["types"]}
        self.vectors = vectors
        self._check_names()
        self._plans: dict | None = None  # packet_model: computed when rendering (api_names needs none)

    # ---------------------------------------------------------------- names
    def set_module(self, s: dict) -> str:
        return self._set_modules[s["id"]]

    def _check_names(self) -> None:
        proto = self.proto
        self._set_modules: dict[int, str] = {}
        used = set(RESERVED_MODULES) | {self.package}
        for s in proto["sets"]:
            m = s["name"]
            if m in used or m in KEYWORDS or m in NOT_RAW:
                m = m + "_set"
            if m in used:
                raise ToolError(f"rust back end: set {s['name']} (0x{s['id']:02X}) has no free module name")
            used.add(m)
            self._set_modules[s["id"]] = m
        # Type names are unique in the IR; check what camel() makes of them and of field names.
        seen: dict[str, str] = {}
        for t in proto["types"]:
            n = camel(t["name"])
            if n in seen:
                raise ToolError(f"rust back end: types {seen[n]} and {t['name']} both map to {n}")
            seen[n] = t["name"]
        for s in proto["sets"]:
            names: dict[str, str] = {"SetField": "(the set's field enum)"}
            for f in s["fields"]:
                for tn in self._field_type_names(f):
                    if tn in names:
                        raise ToolError(
                            f"rust back end: in set {s['name']}, {f['name']} and {names[tn]} both map to Rust type {tn}"
                        )
                    names[tn] = f["name"]
        names = {"ReservedField": "(the reserved field enum)"}
        for r in proto["reserved_fields"]:
            tn = camel(r["name"])
            if tn in names:
                raise ToolError(f"rust back end: reserved fields {r['name']} and {names[tn]} both map to {tn}")
            names[tn] = r["name"]
        variants = [camel(self._set_modules[s["id"]]) for s in proto["sets"]] + (
            ["Reserved"] if proto["reserved_fields"] else []
        )
        if len(set(variants)) != len(variants):
            raise ToolError(
                "rust back end: two descriptor sets map to the same FieldValue variant: " + ", ".join(variants)
            )

    def _field_type_names(self, f: dict) -> list[str]:
        base = camel(f["name"])
        if not model.per_device(f):
            return [base]
        return [base] + [base + camel(v["device"]) for v in f["variants"]]

    def device_variant(self, device_id: str) -> str:
        return camel(device_id)

    # ---------------------------------------------------------------- types
    def elem_type(self, e: model.Elem) -> str:
        """The Rust type of one value."""
        if e.kind == "primitive":
            return PRIMITIVE_TYPES[e.name]
        if e.kind == "string":
            return f"crate::wire::Str<{e.length}>"
        return f"crate::types::{camel(e.name)}"

    def enum_base(self, enum_name: str) -> str:
        return _int_rust(self.types[enum_name]["base"])

    def param(self, p: model.Param) -> dict:
        """Names and types of one parameter of the layout model; layout_macros.j2 writes the Rust."""
        if p.function:
            doc = "Function selector (sent first)."
        else:
            units = f" Units: {p.units}." if p.units else ""
            doc = doc_line(p.description) + units
            if p.functions is not None:
                doc = (doc + " Sent for: " + ", ".join(p.functions) + ".").strip()
        view = {
            "name": p.name,
            "kind": p.kind,
            "field": ident(p.name),
            "local": f"p_{p.name}",
            "optional": p.optional,
            "elem": self.elem_type(p.elem),
            "count": p.count,
            "max_count": p.max_count,
            "doc": doc.strip(),
        }
        if p.count_param is not None:
            view.update(
                count_field=ident(p.count_param), count_local=f"p_{p.count_param}", count_optional=p.count_optional
            )
        if p.selector is not None:
            view.update(sel_field=ident(p.selector), sel_local=f"p_{p.selector}", sel_optional=p.selector_optional)
        return view

    def params_model(self, params: list[dict], functions: list[str] | None) -> list[dict]:
        return [self.param(p) for p in model.params(self.proto, params, functions)]

    def type_model(self, t: dict) -> dict:
        kind = t["kind"]
        m = {
            "kind": kind,
            "name": t["name"],
            "rust": camel(t["name"]),
            "doc": doc_line(t.get("title"), t.get("description")),
        }
        if kind == "enum":
            m["base"] = _int_rust(t["base"])
            seen: set[int] = set()
            values = []
            for v in t["values"]:
                first = v["value"] not in seen
                seen.add(v["value"])
                devs = f" Devices: {', '.join(v['devices'])}." if v.get("devices") else ""
                values.append(
                    {
                        "name": v["name"],
                        "const": upper(v["name"]),
                        "value": v["value"],
                        "first": first,
                        "doc": (doc_line(v.get("description")) + devs).strip(),
                    }
                )
            m["enum_values"] = values
        elif kind == "bitfield":
            base = _int_rust(t["base"])
            nbits = PRIMITIVES[t["base"]][0] * 8
            full = (1 << nbits) - 1
            m["base"] = base
            members = []
            names: set[str] = set()
            for b in t["members"]:
                getter = ident(b["name"])
                setter = f"set_{b['name']}"
                for n in (b["name"], setter):
                    if n in names:
                        raise ToolError(f"rust back end: bitfield {t['name']}: accessor {n} is defined twice")
                names.update((b["name"], setter))
                mask = b["mask"]
                width = b["width"]
                first = b["first_bit"]
                if mask == full:
                    get = "self.0" if first == 0 else f"self.0 >> {first}"
                else:
                    get = (
                        f"self.0 & Self::{upper(b['name'])}"
                        if first == 0
                        else f"(self.0 & Self::{upper(b['name'])}) >> {first}"
                    )
                shifted = "v" if first == 0 else f"(v << {first})"
                if mask == full:
                    set_expr = "v"
                else:
                    set_expr = f"(self.0 & !Self::{upper(b['name'])}) | ({shifted} & Self::{upper(b['name'])})"
                members.append(
                    {
                        "name": b["name"],
                        "const": upper(b["name"]),
                        "getter": getter,
                        "setter": setter,
                        "mask": _hex(mask, 2 * PRIMITIVES[t["base"]][0]),
                        "bool": width == 1,
                        "get_expr": get,
                        "set_expr": set_expr,
                        "bits": f"bit {first}" if width == 1 else f"bits {first}..={b['last_bit']}",
                        "doc": doc_line(b.get("description")) + (" Reserved." if b.get("reserved") else ""),
                        "width": width,
                        "first": first,
                        "mask_int": mask,
                    }
                )
            m["members"] = members
        elif kind == "struct":
            m["params"] = self.params_model(t["params"], None)
            m["has_optional"] = False
            m["fixed_size"] = t["size"]["min"] if t["size"]["fixed"] else None
        elif kind == "union":
            m["base"] = self.enum_base(t["selector_enum"])
            seen = set()
            members = []
            for mem in t["members"]:
                first = mem["value"] not in seen
                seen.add(mem["value"])
                members.append(
                    {
                        "variant": camel(mem["when"]),
                        "when": mem["when"],
                        "value": mem["value"],
                        "first": first,
                        "type": f"crate::types::{camel(mem['type'])}" if mem["type"] else None,
                        "doc": doc_line(mem.get("description")) or f"Selected by {mem['when']} ({mem['value']}).",
                    }
                )
            if not members:
                raise ToolError(f"rust back end: union {t['name']} has no members")
            m["members"] = members
        return m

    def typed_example(self) -> dict | None:
        """Names of the crate documentation's one-field example (examples.typed_field_example)."""
        found = examples.typed_field_example(self.proto)
        if found is None:
            return None
        s, f = found
        size = f["variants"][0]["size"]["min"]
        return {
            "module": self.set_module(s),
            "type": camel(f["name"]),
            "set": _hex(s["id"]),
            "descriptor": _hex(f["id"]),
            "size": size,
        }

    # ---------------------------------------------------------------- fields
    def layout_model(self, name: str, rust: str, layout: dict, descriptor: int, set_id: int | None, doc: str) -> dict:
        params = self.params_model(layout["params"], layout["functions"])
        return {
            "name": name,
            "rust": rust,
            "descriptor": _hex(descriptor),
            "set": _hex(set_id) if set_id is not None else None,
            "params": params,
            "has_optional": any(p["optional"] for p in params),
            "fixed_size": layout["size"]["min"] if layout["size"]["fixed"] else None,
            "doc": doc,
            "device": layout["device"],
        }

    def field_model(self, s: dict, f: dict) -> dict:
        base = camel(f["name"])
        doc = doc_line(f.get("title"), f.get("description"))
        if not model.per_device(f):
            layouts = [self.layout_model(f["name"], base, f["variants"][0], f["id"], s["id"], doc)]
            return {
                "name": f["name"],
                "rust": base,
                "descriptor": _hex(f["id"]),
                "multi": False,
                "layouts": layouts,
                "doc": doc,
            }
        layouts = []
        for v in f["variants"]:
            lm = self.layout_model(
                f["name"],
                base + camel(v["device"]),
                v,
                f["id"],
                s["id"],
                doc_line(f.get("title"), f"Layout for device {v['device']}"),
            )
            lm["device_variant"] = self.device_variant(v["device"])
            layouts.append(lm)
        devices = {v["device"] for v in f["variants"]}
        covers_all = all(d["id"] in devices for d in self.proto["devices"])
        return {
            "name": f["name"],
            "rust": base,
            "descriptor": _hex(f["id"]),
            "multi": True,
            "layouts": layouts,
            "doc": doc,
            "covers_all": covers_all,
            "devices": ", ".join(v["device"] for v in f["variants"]),
        }

    def set_model(self, s: dict) -> dict:
        fields = [self.field_model(s, f) for f in s["fields"]]
        return {
            "id": _hex(s["id"]),
            "name": s["name"],
            "module": self.set_module(s),
            "variant": camel(self.set_module(s)),
            "kind": s["kind"],
            "doc": doc_line(s.get("title"), s.get("description")),
            "fields": fields,
            "has_multi": any(f["multi"] for f in fields),
            "shared": s["shared"],
            "decoders": self.set_decoders(s),
            "feature": set_feature(self.set_module(s)),
            "packet": self.packet_model(s),
        }

    def packet_model(self, s: dict) -> dict | None:
        """Set s's straight-line packet decoder (set.rs.j2 `Packet`, `decode_packet`; issue 38),
        None for a set that is not a data set. The members are the packet plan's
        (generator/packet_plan.py, shared with C and C++): one per entry of the set's lookup whose
        field has one layout. Each member is a value of the field's struct, named after the field
        (with the defining module's name before it when two entries would share a name)."""
        if self._plans is None:
            self._plans = packet_plan.packet_plans(self.proto)
        plan = self._plans[s["id"]]
        if plan is None:
            return None
        sets = {x["id"]: x for x in self.proto["sets"]}
        names = [m.field["name"] for m in plan.members]
        members = []
        for m in plan.members:
            fname = m.field["name"]
            module = "reserved" if m.field_set is None else self.set_module(sets[m.field_set])
            name = ident(fname if names.count(fname) == 1 else f"{module}_{fname}")
            if m.field_set is None:
                value = f"crate::FieldValue::Reserved(crate::reserved::ReservedField::{camel(fname)}(self.{name}))"
            else:
                value = f"crate::FieldValue::{camel(module)}(crate::{module}::SetField::{camel(fname)}(self.{name}))"
            fast = None
            if m.fast is not None:
                fast = {
                    "size": m.fast.size,
                    "loads": [
                        {"path": ident(x.param) + ("" if x.index is None else f"[{x.index}]"), "off": x.off}
                        for x in m.fast.loads
                    ],
                    "bools": list(m.fast.bools),
                }
            members.append(
                {
                    "descriptor": _hex(m.descriptor),
                    "member": name,
                    "type": f"crate::{module}::{camel(fname)}",
                    "value": value,
                    "source": m.source,
                    "fast": fast,
                }
            )
        return {"members": members}

    def set_decoders(self, s: dict) -> list[dict]:
        """The entries of set s's decoder table: every descriptor that the IR's `lookup` resolves
        to a field of a set (its own, or a shared data field it does not define). Descriptors
        that resolve to a reserved field stay out: decode_other_field decodes those."""
        sets = {x["id"]: x for x in self.proto["sets"]}
        table = next(t["fields"] for t in self.proto["lookup"]["sets"] if t["set"] == s["id"])
        return [
            {"descriptor": _hex(e["descriptor"]), "fn": f"{self.set_module(sets[e['set']])}_{e['name']}"}
            for e in table
            if e["source"] != "reserved"
        ]

    def reserved_model(self) -> list[dict]:
        out = []
        for r in self.proto["reserved_fields"]:
            if model.per_device(r):
                raise ToolError(f"rust back end: reserved field {r['name']} has several variants")
            doc = doc_line(r.get("title"), r.get("description")) + f" Reserved in every {r['applies_to']} set."
            lm = self.layout_model(r["name"], camel(r["name"]), r["variants"][0], r["id"], None, doc)
            out.append(
                {
                    "name": r["name"],
                    "rust": camel(r["name"]),
                    "descriptor": _hex(r["id"]),
                    "kind": camel(r["applies_to"]),
                    "layouts": [lm],
                    "doc": doc,
                    "multi": False,
                }
            )
        return out

    # ---------------------------------------------------------------- context
    def context(self) -> dict:
        proto = self.proto
        f = proto["framing"]
        sets = [self.set_model(s) for s in proto["sets"]]
        shared = None
        sd = proto.get("shared_data")
        if sd:
            shared = next((s for s in sets if s["id"] == _hex(sd["set"])), None)
        kinds = [
            {"variant": camel(k), "name": k, "first": _hex(r["first"]), "last": _hex(r["last"])}
            for k, r in proto["set_kinds"].items()
        ]
        caps = {c["device"]: c for c in proto.get("capabilities", {}).get("devices", [])}
        devices = [
            {
                "id": d["id"],
                "variant": self.device_variant(d["id"]),
                "title": d["title"],
                "title_lit": rust_str(d["title"]),
                "manual_lit": rust_str(d["manual"]),
                "commands": [f"0x{s:02X}{x:02X}" for s, x in caps.get(d["id"], {}).get("commands", [])],
                "data": [f"0x{s:02X}{x:02X}" for s, x in caps.get(d["id"], {}).get("data", [])],
                "baud_rates": [str(r) for r in lf["rates"]],
                "default_baud": lf["default"],
            }
            for d, lf in zip(proto["devices"], link_facts(proto)["devices"])
        ]
        reserved = self.reserved_model()
        groups = [s["variant"] for s in sets] + (["Reserved"] if reserved else [])
        # Cargo features that select the sets of the dispatch (firmware size, issue 38): a set is
        # in decode_field's tables when its feature is on or when no set feature is on at all.
        # Every set feature turns on SELECT_SETS.
        selecting = f'feature = "{SELECT_SETS}"'
        for s in sets:
            s["cfg"] = f'any(feature = "{s["feature"]}", not({selecting}))'
        types = [self.type_model(t) for t in proto["types"]]
        return {
            "package": self.package,
            "protocol": proto["name"],
            "title": proto["title"],
            "framing": {
                "sync": ", ".join(_hex(b) for b in f["sync"]),
                "sync_len": len(f["sync"]),
                "sync_text": " ".join("%02X" % b for b in f["sync"]),
                "header_size": f["header_size"],
                "set_offset": f["set_offset"],
                "length_offset": f["length_offset"],
                "max_payload": f["max_payload"],
                "max_packet": f["max_packet"],
                "nmea": f["nmea"],
                "rtcm3": f["rtcm3"],
                "nmea_max": f["nmea_max"],
                "parser_capacity": f["parser_capacity"],
                "checksum_size": f["checksum_size"],
                "field_header_size": f["field_header_size"],
                "field_length_offset": f["field_length_offset"],
                "field_descriptor_offset": f["field_descriptor_offset"],
                "counts_header": "true" if f["field_length_counts_header"] else "false",
                "field_length_adjust": f["field_length_adjust"],
                "irregular_lengths": f["irregular_lengths"],
                "max_field_data": f["max_field_data"],
                "big_endian": "true" if proto["byte_order"] == "big" else "false",
                "sum1_first": "true" if f["checksum"]["order"][0] == "sum1" else "false",
                "header": ", ".join(f["header"]),
                "field_header": ", ".join(f["field_header"]),
                "byte_order": proto["byte_order"],
            },
            "path_depth": self.proto["value_paths"]["depth"],  # a name or an index: one step each
            "kinds": kinds,
            "devices": devices,
            "types": types,
            "sets": sets,
            "reserved": reserved,
            "groups": groups,
            "shared": shared,
            "shared_rule": bool(shared) and "data" in proto["set_kinds"],
            "selecting": selecting,
            "select_sets": SELECT_SETS,
            "data_set": next((s for s in sets if s["kind"] == "data"), None),
            "first_set": sets[0]["id"] if sets else "0x00",
            "typed_example": self.typed_example(),
            "cargo": cargo_metadata(proto),
            "rust_version": RUST_VERSION,
        }

    # ---------------------------------------------------------------- tests (cases from generator/testcases.py)
    def vector_cases(self) -> list[dict]:
        out = []
        used: set[str] = set()
        for c in vector_cases(self.vectors, self.proto):
            prefix = "stream_" if c.corpus == "streams" else "case_"
            fn = prefix + re.sub(r"[^a-z0-9_]", "_", c.name.lower())
            while fn in used:
                fn += "_"
            used.add(fn)
            out.append(
                {
                    "fn": fn,
                    "name": c.name,
                    "hex": rust_str(c.hex),
                    "device": f"Some({rust_str(c.device)})" if c.device else "None",
                    "expect": [rust_str(line) for line in c.expect],
                    "rejected": "true" if c.rejected else "false",
                    "source": c.source,
                }
            )
        return out

    def bitfield_cases(self) -> list[dict]:
        out = []
        for b in bitfield_cases(self.proto):
            members = []
            for m in b.members:
                getter = ident(m.name)
                if m.flag:
                    maxv, zero = "true", "false"
                    check_max, check_zero = f"assert!(v.{getter}());", f"assert!(!v.{getter}());"
                else:
                    maxv, zero = _hex(m.max), "0"
                    check_max, check_zero = f"assert_eq!(v.{getter}(), {maxv});", f"assert_eq!(v.{getter}(), 0);"
                members.append(
                    {
                        "getter": getter,
                        "setter": f"set_{m.name}",
                        "max": maxv,
                        "zero": zero,
                        "mask": _hex(m.mask),
                        "check_max": check_max,
                        "check_zero": check_zero,
                    }
                )
            out.append({"rust": camel(b.name), "base": _int_rust(b.base), "members": members})
        return out

    def short_cases(self) -> list[dict]:
        """Per layout: the result of decoding empty data and one byte too many (docs/conformance.md §3)."""
        out = []
        for c in layout_error_cases(self.proto):
            if c.set is None:
                module, rust = "reserved", camel(c.field["name"])
            else:
                module = self.set_module(c.set)
                multi = model.per_device(c.field)
                rust = camel(c.field["name"]) + (camel(c.layout["device"]) if multi else "")
            case = {"module": module, "rust": rust, "empty": None, "extra_len": None}
            if c.empty == "":
                case["empty"] = "Ok(())"
            elif c.empty is not None:
                case["empty"] = f"Err({rust_str(c.empty)}.to_string())"
            if c.extra_len is not None:
                case["extra_len"] = c.extra_len
                case["extra"] = rust_str(c.extra)
            case["zero_safe"] = c.zero_safe
            case["set"] = "0x00" if module == "reserved" else f"{self.package}::{module}::{rust}::SET"
            out.append(case)
        return out


# ---------------------------------------------------------------------------------------- session
# The most reply descriptors one command may expect (MAX_EXPECT of runtime/src/session.rs).
_MAX_EXPECT = 4


def session_context(m: _Protocol) -> dict:
    """What commands.rs.j2 (the spec facts of every command layout, docs/conformance.md section 8)
    and command_api.rs.j2 (the typed command API) print: the command model of generator/commands.py
    with Rust's names and types; session_macros.j2 spells the rows, patterns and calls."""
    proto = m.proto
    rule = proto.get("session")
    if rule is None:
        raise ToolError(f"{proto['name']}: the Rust session layer needs the protocol's ack rule (session)")
    cm = commands.commands(proto)
    sets = {s["id"]: s for s in proto["sets"]}
    fields = {(s["id"], f["name"]): f for s in proto["sets"] for f in s["fields"]}
    rows = []
    for lay in cm.layouts:
        if len(lay.replies) > _MAX_EXPECT:
            raise ToolError(f"{lay.field}: more than {_MAX_EXPECT} reply fields")
        pm = {q.name: q for q in model.layout(proto, fields[(lay.set, lay.field)]["variants"][lay.variant]).params}
        rows.append(
            {
                "layout": lay,
                "names": _names(m, sets[lay.set], fields[(lay.set, lay.field)], lay.device),
                "device": m.device_variant(lay.device) if lay.device else None,
                "devices": [m.device_variant(d) for d in lay.devices],
                "reads": [
                    {"name": q, "field": ident(q), "optional": pm[q].optional, "to_int": _to_int(pm[q].elem)}
                    for q in lay.reads
                ],
            }
        )
    uses = ["CommandFacts"] + [
        name
        for name, used in (
            ("AckSuppression", rows),
            ("Allowance", any(r["layout"].timeout for r in rows)),
            ("ReplyFacts", any(r["layout"].replies for r in rows)),
        )
        if used
    ]
    code_enum = rule.get("code_enum")
    methods: dict[commands.Call, dict] = {}
    api_sets: list[dict] = []
    for g in cm.api_sets():
        s, module = sets[g.set], m.set_module(sets[g.set])
        api_set = {
            "id": g.set,
            "method": set_method(module),
            "struct": camel(module) + "Commands",
            "title": s["title"],
            "set": _hex(s["id"]),
            "commands": [],
        }
        api_sets.append(api_set)
        for cmd in g.commands:
            f = fields[(g.set, cmd.field)]
            command = {
                "id": cmd.descriptor,
                "method": ident(f["name"]),
                "struct": camel(f["name"]) + "Command",
                "title": f["title"],
                "plain": f["variants"][0]["functions"] is None,
                "methods": [_method(m, cm, s, f, c) for c in cmd.calls],
                "descriptor": _hex(f["id"]),
            }
            api_set["commands"].append(command)
            for c, method in zip(cmd.calls, command["methods"]):
                methods[c] = {"set": api_set, "command": command, "method": method}
    shared = (proto.get("shared_data") or {}).get("set")
    reference_times = []
    for e in (proto.get("time") or {}).get("reference_time", []):
        gps = e["kind"] == "gps"
        reference_times.append(
            {
                "device": m.device_variant(e["device"]),
                "set": f"0x{e['set']:02X}",
                "shared": "true" if e["set"] == shared else "false",
                "descriptor": f"0x{e['descriptor']:02X}",
                "gps": "true" if gps else "false",
                "offset": e["tow_offset"] if gps else e["offset"],
                "size": 8 if gps else e["size"],
                "week_offset": e["week_offset"] if gps else 0,
                "week_size": e["week_size"] if gps else 0,
                "ns_per_unit": 1 if gps else 1_000_000_000 // e["per_second"],
                "field": e["field"],
            }
        )
    return {
        "reference_times": reference_times,
        "session_imports": sorted(uses),
        "session_rule": {
            "ack": rule["ack"],
            "ok": rule["ok"],
            "ack_type": camel(rule["ack_name"]),
            "echo": ident(rule["echo"]),
            "code": ident(rule["code"]),
            "code_newtype": bool(code_enum and code_enum in m.types),
        },
        "functions": [
            {"value": x.value, "name": x.name, "devices": [m.device_variant(d) for d in x.devices]}
            for x in cm.functions
        ],
        "command_rows": rows,
        "api_sets": api_sets,
        "methods": methods,
    }


def _names(m: _Protocol, s: dict, f: dict, device: str | None) -> dict:
    """The Rust names of field f's layout for device (None: its only layout): module, the set's
    FieldValue variant, the field's SetField variant, its per-device variant and struct."""
    module = m.set_module(s)
    rust = camel(f["name"])
    per_device = model.per_device(f) and device is not None
    return {
        "module": module,
        "set_variant": camel(module),
        "type": rust,
        "device_variant": m.device_variant(device) if per_device else None,
        "struct": f"{rust}{camel(device)}" if per_device else rust,
    }


def _to_int(e: model.Elem) -> str:
    """How a scalar parameter's value becomes an i64 (session_macros.j2 `to_int`)."""
    if e.kind == "primitive":
        return "bool" if e.name == "bool" else "primitive"
    return "newtype"


def _method(m: _Protocol, cm: commands.Commands, s: dict, f: dict, c: commands.Call) -> dict:
    """One call of the typed API: its name, arguments (types through layout_macros.j2 `inner`),
    the layout it builds per device and what it returns."""
    base = ident(f["name"]) if c.function is None else ident(c.function)
    name = f"{base}_{c.device}" if c.device is not None else base
    required = {a.name: a.required for a in c.arguments}
    builds = []
    for i in c.variants:
        v = f["variants"][i]
        pm = model.layout(m.proto, v)
        assign: list[dict] = []
        for q in pm.params:
            if q.function:
                assign.append(
                    {
                        "kind": "function",
                        "field": ident(q.name),
                        "enum": camel(cm.function_enum),
                        "value": c.function_value,
                    }
                )
            elif q.name in required:
                some = required[q.name] and q.optional
                assign.append({"kind": "some" if some else "plain", "field": ident(q.name)})
        for k in c.counts:
            q = next(x for x in pm.params if x.name == k.param)
            assign.append(
                {
                    "kind": "count",
                    "field": ident(k.param),
                    "array": ident(k.array),
                    "array_optional": not k.array_required,
                    "type": m.elem_type(q.elem),
                    "optional": q.optional,
                }
            )
        names = _names(m, s, f, model.layout_device(f, v))
        builds.append(
            {
                "device": m.device_variant(v["device"]) if v["device"] else None,
                "names": names,
                "assign": assign,
                "zero": len(assign) < len(pm.params),
            }
        )
    v0 = model.layout(m.proto, f["variants"][c.variants[0]])
    params = {q.name: q for q in v0.params}
    args = [{"name": ident(a.name), "required": a.required, "p": m.param(params[a.name])} for a in c.arguments]
    reply = None
    if c.reply_kind == commands.FIELD:
        reply = _names(m, s, next(x for x in s["fields"] if x["id"] == c.reply.descriptor), None)
    returns = c.reply_kind != commands.NO_REPLY
    return {
        "name": name,
        "args": args,
        "builds": builds,
        "reply_kind": c.reply_kind,
        "reply": reply,
        "doc": (f"Function `{c.function}`" if c.function else f"Sends `{f['name']}`")
        + (f" (layout for {', '.join(d for d in c.devices if d)})" if c.device is not None else "")
        + (": returns the reply field." if returns else "."),
    }


def _session_cases(proto: dict, sessions: list[dict]) -> list[dict]:
    """The session corpus cases of the protocol (generator/sessions.py) with their test names;
    test_sessions.rs.j2 spells the steps."""
    out = []
    used: set[str] = set()
    for c in sessions:
        if c["protocol"] != proto["name"]:
            continue
        fn = "session_" + re.sub(r"[^a-z0-9_]", "_", c["name"].lower())
        while fn in used:
            fn += "_"
        used.add(fn)
        out.append({**c, "fn": fn})
    return out


def _session_example(m: _Protocol, session: dict) -> dict | None:
    """The context of examples/configure_and_stream.rs (generator/examples.py session_example): per
    step the call of the typed command API (command_api.rs.j2) and its arguments as values that
    session_macros.j2 spells, or None for a protocol without the example."""
    ex = examples.session_example(m.proto)
    if ex is None:
        return None
    device = ex["device"]

    def literal(tref: dict, value) -> dict:
        return examples.example_literal(
            m.types, tref, value, "Rust", lambda k, n: {"type": camel, "member": upper}.get(k, ident)(n)
        )

    def call(step: str, fn: str | None) -> dict:
        """The call, its arguments and the `let`s of its bounded arrays."""
        at = session["methods"][ex[step]["calls"][fn]]
        args, lets = [], []
        for a, q, value in examples.example_arguments(m.proto, ex, step, fn, "Rust"):
            if value is None:
                args.append({"kind": "none"})
                continue
            tref = q.ir["type"]
            if q.kind == "fixed":
                arg = {"kind": "array", "elems": [literal(tref, v) for v in value]}
            elif q.kind in ("counted", "remaining"):
                lets.append({"name": ident(a.name), "param": q.name, "elems": [literal(tref, v) for v in value]})
                arg = {"kind": "local", "name": ident(a.name)}
            else:
                arg = literal(tref, value)
            args.append({"kind": "some", "value": arg} if not a.required else arg)
        reply = at["method"]["reply"]
        return {
            "set": at["set"]["method"],
            "command": None if at["command"]["plain"] else at["command"]["method"],
            "method": at["method"]["name"],
            "args": args,
            "lets": lets,
            "returns": reply["type"] if reply else None,
            "reply_kind": at["method"]["reply_kind"],
        }

    data_set = ex["data"]["set"]
    fields = []
    for f in ex["data"]["fields"]:
        if model.per_device(f):
            raise ExampleError(f"Rust back end: the example's data field {f['name']} has per-device layouts")
        fields.append({"name": f["name"], "descriptor": f["id"], "names": _names(m, data_set, f, None)})
    titles = {d["id"]: d["title"] for d in m.proto["devices"]}
    return {
        **examples.session_example_context(ex, call),
        "title": titles.get(device, device),
        "model": m.device_variant(device),
        "data_fields": fields,
    }


def set_method(module: str) -> str:
    """The method of `device::Device` that gives a set's typed commands (`device.threedm()`)."""
    return ident(module + "_set" if module in DEVICE_METHODS else module)


# ---------------------------------------------------------------------------------------- entry points
_TEMPLATES = [
    ("Cargo.toml.j2", "Cargo.toml"),
    ("README.md.j2", "README.md"),
    ("lib.rs.j2", "src/lib.rs"),
    ("types.rs.j2", "src/types.rs"),
    ("reserved.rs.j2", "src/reserved.rs"),
    ("dispatch.rs.j2", "src/dispatch.rs"),
    ("packets.rs.j2", "src/packets.rs"),
    ("test_vectors.rs.j2", "tests/vectors.rs"),
    ("test_spec.rs.j2", "tests/spec.rs"),
    ("example_getting_started.rs.j2", "examples/getting_started.rs"),
    ("commands.rs.j2", "src/commands.rs"),
    ("command_api.rs.j2", "src/command_api.rs"),
    ("test_sessions.rs.j2", "tests/sessions.rs"),
]

# The runtime (runtime/src/ beside this module) by name in the crate. The command-line tools
# name the crate they use; in runtime/ that is its own crate, `protocodec`.
_RUNTIME_CRATE = "protocodec"
_RUNTIME = {
    f"src/{name}.rs": f"src/{name}.rs"
    for name in (
        "error",
        "wire",
        "bounded",
        "json",
        "json_read",
        "parser",
        "fields",
        "builder",
        "samples",
        "clock",
        "text",
        "session",
        "device",
    )
}
_RUNTIME_TOOLS = [f"src/bin/{_RUNTIME_CRATE}-{tool}.rs" for tool in ("decode", "encode", "session")]
# The checksum half of `crate::framing`, after the constants rendered from framing.rs.j2.
_RUNTIME_CHECKSUM = "src/framing_checksum.rs"


def _runtime_files(package: str) -> dict[str, str]:
    """The runtime files of one crate, by path in the crate."""
    files = copy_runtime("rust", _RUNTIME)
    tools = {src: src.replace(_RUNTIME_CRATE, package) for src in _RUNTIME_TOOLS}
    files.update(copy_runtime("rust", tools, replace=[(_RUNTIME_CRATE, package)]))
    return files


def render(ir: dict, vectors: list[dict], release: Release | None = None, sessions: list[dict] = ()) -> dict[str, str]:
    release = release or load_release()
    env = environment()
    env.filters["rust_str"] = rust_str
    checksum = copy_runtime("rust", {_RUNTIME_CHECKSUM: "src/framing.rs"})["src/framing.rs"]
    files: dict[str, str] = {}
    for proto in ir["protocols"]:
        model = _Protocol(proto, vectors)
        ctx = {**model.context(), **release.stamp(proto)}
        ctx["cases"] = model.vector_cases()
        ctx["floats"] = canonical_literals(rust_str)
        ctx["bitfields"] = model.bitfield_cases()
        ctx["short_cases"] = model.short_cases()
        ctx["sample_rule"] = proto["samples"]
        ctx["link_facts"] = link_facts(proto)
        ctx["clock_model"] = clock_model(proto)
        ctx["example"] = _example(proto)
        session = session_context(model)
        ctx.update(session)
        ctx["session_cases"] = _session_cases(proto, list(sessions))
        ctx["session_example"] = _session_example(model, session)
        root = f"rust/{model.package}/"
        files[root + "LICENSE"] = release.license
        for tpl, out in _TEMPLATES:
            files[root + out] = env.get_template(f"rust/{tpl}").render(**ctx)
        if ctx["session_example"]:
            files[root + "examples/configure_and_stream.rs"] = env.get_template(
                "rust/example_configure_and_stream.rs.j2"
            ).render(**ctx)
        files[root + "src/framing.rs"] = env.get_template("rust/framing.rs.j2").render(**ctx) + "\n" + checksum
        for path, text in _runtime_files(model.package).items():
            files[root + path] = text
        set_tpl = env.get_template("rust/set.rs.j2")
        for s in ctx["sets"]:
            files[root + f"src/{s['module']}.rs"] = set_tpl.render(set=s, **ctx)
    return files


def _example(proto: dict) -> dict:
    """The getting-started example (generator/examples.py), with the type's name after its `use`."""
    example = examples.example_context(proto, api_names)
    example["type_name"] = example["api"]["type"].rsplit("::", 1)[1]
    return example


def api_names(protocol: dict, set_: dict | None, field: dict) -> dict[str, str]:
    """Names a Rust user types for a field: its type (per device when it has variants) and module."""
    m = _Protocol(protocol, [])
    pkg = protocol["package"]
    if set_ is None or "applies_to" in field:
        module = f"{pkg}::reserved"
        return {
            "type": f"{module}::{camel(field['name'])}",
            "module": module,
            "enum": f"{module}::ReservedField",
            "decode": f"{pkg}::decode_field",
        }
    module = f"{pkg}::{m.set_module(set_)}"
    out = {
        "type": f"{module}::{camel(field['name'])}",
        "module": module,
        "enum": f"{module}::SetField",
        "decode": f"{pkg}::decode_field",
    }
    if model.per_device(field):
        out["variants"] = ", ".join(
            f"{v['device']}: {module}::{camel(field['name'])}{camel(v['device'])}" for v in field["variants"]
        )
    if field.get("role") == "command" and set_["kind"] == "command":
        # The typed command API (command_api.rs.j2): device.<set>().<command>().<function>(...).
        call = f"device.{set_method(m.set_module(set_))}()"
        functions = list(dict.fromkeys(fn for v in field["variants"] for fn in v["functions"] or []))
        if len(functions) > 1:
            out["session"] = f"{call}.{ident(field['name'])}().{{{','.join(ident(fn) for fn in functions)}}}(...)"
        elif functions:
            out["session"] = f"{call}.{ident(field['name'])}().{ident(functions[0])}(...)"
        else:
            out["session"] = f"{call}.{ident(field['name'])}(...)"
    return out


def public_name(protocol: dict, kind: str, *path) -> str:
    """The Rust name of a set (`kind` "set") or enum value (kind "value": enum type, value), for
    `mipgen diff` (generator/wirediff.py public_names, which names fields and members itself)."""
    if kind == "set":
        return f"{protocol['package']}::{_Protocol(protocol, []).set_module(path[0])}"
    return f"{protocol['package']}::{path[0]['name']}::{path[1]['name'].upper()}"
