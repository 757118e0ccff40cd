"""Rust back end: one `no_std` crate (optional `std` feature) per protocol at generated/rust/<package>/.

All naming and type mapping happens here (the language's keywords and type table are data, in
facts.py); the templates in templates/rust/ only loop and print. The runtime, the code that does
not depend on the spec (parser, checksum, builder, JSON, errors, the command-line tools), is plain
Rust in runtime/, copied verbatim into each crate: its only protocol input is the generated
`crate::framing` constants module (templates/rust/framing.rs.j2).
"""

from __future__ import annotations

import re

from generator import model, naming
from generator.examples import ExampleError, example_context, session_example
from generator.naming import upper
from generator.primitives import PRIMITIVES
from generator.release import Release, load_release
from generator.render import ToolError, copy_runtime, environment
from generator.testcases import bitfield_cases, canonical_cases, layout_error_cases, vector_cases

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
        if len(f["variants"]) == 1:
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
        if len(f["variants"]) == 1:
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
        }

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
            if len(r["variants"]) != 1:
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
            }
            for d in proto["devices"]
        ]
        reserved = self.reserved_model()
        groups = [s["variant"] for s in sets] + (["Reserved"] if reserved else [])
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
            "first_set": sets[0]["id"] if sets else "0x00",
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

    def float_cases(self) -> dict:
        cases = canonical_cases()
        return {
            "doubles": [{"bits": "0x%016X" % c.bits, "text": rust_str(c.text)} for c in cases.doubles],
            "floats": [{"bits": "0x%08X" % c.bits, "text": rust_str(c.text)} for c in cases.floats],
            "all_bytes": rust_str(cases.all_bytes),
        }

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
                multi = len(c.field["variants"]) > 1
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


class _Session:
    """What commands.rs.j2 (the spec facts of every command layout, docs/conformance.md section 8)
    and command_api.rs.j2 (the typed command API) print, computed from the IR."""

    def __init__(self, m: _Protocol):
        self.m = m
        self.proto = m.proto
        fs = self.proto.get("function_selector") or {}
        self.function_enum = fs.get("enum")
        self.fvalues: dict[str, int] = {}
        if self.function_enum:
            for v in m.types[self.function_enum]["values"]:
                self.fvalues[v["name"]] = v["value"]

    def _int_value(self, tref: dict, value) -> int | None:
        if value is None or isinstance(value, int):
            return value
        if isinstance(value, bool):
            return int(value)
        t = self.m.types[tref["name"]]
        return next(v["value"] for v in t["values"] if v["name"] == value)

    def _pattern(self, s: dict, f: dict, v: dict, bind: str) -> str:
        """The match pattern of a FieldValue holding layout v of field f (binding it to `bind`)."""
        module = self.m.set_module(s)
        variant = camel(module)
        rust = camel(f["name"])
        if len(f["variants"]) > 1:
            inner = f"crate::{module}::{rust}::{self.m.device_variant(v['device'])}({bind})"
        else:
            inner = bind
        return f"FieldValue::{variant}(crate::{module}::SetField::{rust}({inner}))"

    def _constructor(self, s: dict, f: dict, v: dict, value: str) -> tuple[str, str]:
        """(struct path of layout v, the FieldValue expression wrapping `value`)."""
        module = self.m.set_module(s)
        rust = camel(f["name"])
        if len(f["variants"]) > 1:
            dv = self.m.device_variant(v["device"])
            struct = f"crate::{module}::{rust}{camel(v['device'])}"
            inner = f"crate::{module}::{rust}::{dv}({value})"
        else:
            struct = f"crate::{module}::{rust}"
            inner = value
        return struct, f"FieldValue::{camel(module)}(crate::{module}::SetField::{rust}({inner}))"

    def _to_int(self, q: model.Param, x: str) -> str:
        """A Rust expression of type i64 for the value `x` of a scalar parameter (bool, integer, enum)."""
        e = q.elem
        if e.kind == "primitive" and e.name == "bool":
            return f"i64::from({x})"
        if e.kind == "primitive":
            return f"{x} as i64"
        return f"{x}.0 as i64"

    def context(self) -> dict:
        proto = self.proto
        rule = proto.get("session")
        if rule is None:
            raise ToolError(f"{proto['name']}: the Rust session layer needs the protocol's ack rule (session)")
        ack_rust = camel(rule["ack_name"])
        code_t = self.m.types.get(rule["code_enum"]) if rule.get("code_enum") else None
        code_expr = "a.{}.0".format(ident(rule["code"])) if code_t else "a.{}".format(ident(rule["code"]))
        rows = []
        facts_match = []
        function_match = []
        param_match = []
        for s in proto["sets"]:
            if s["kind"] != "command":
                continue
            for f in s["fields"]:
                if f["role"] != "command":
                    continue
                for v in f["variants"]:
                    index = len(rows)
                    pm = model.layout(proto, v)
                    by_name = {q.name: q for q in pm.params}
                    used: list[str] = []
                    replies = []
                    for r in v["responses"]:
                        w = r["when"] or {}
                        fn = self.fvalues.get(w["function"]) if "function" in w else None
                        param = w.get("param")
                        value = self._int_value(by_name[param].ir["type"], w.get("value")) if param else None
                        if param:
                            used.append(param)
                        replies.append(
                            "ReplyFacts { descriptor: %s, function: %s, param: %s, value: %s }"
                            % (
                                _hex(r["id"]),
                                _opt(fn),
                                _opt(rust_str(param) if param else None),
                                _opt(value),
                            )
                        )
                    if len(replies) > _MAX_EXPECT:
                        raise ToolError(f"{f['name']}: more than {_MAX_EXPECT} reply fields")
                    ack = v["ack_suppressed_by"]
                    if ack is None:
                        ack_text = "AckSuppression::Never"
                    elif "function" in ack:
                        ack_text = f"AckSuppression::Function({self.fvalues[ack['function']]})"
                    else:
                        used.append(ack["param"])
                        val = self._int_value(by_name[ack["param"]].ir["type"], ack.get("value"))
                        ack_text = "AckSuppression::Param { param: %s, value: %s }" % (
                            rust_str(ack["param"]),
                            _opt(val),
                        )
                    t = v.get("timeout")
                    if t is None:
                        timeout = "None"
                    else:
                        fns = [str(self.fvalues[x]) for x in t["functions"]] if t["functions"] else None
                        if t["param"]:
                            used.append(t["param"])
                        timeout = "Some(Allowance { ms: %d, param: %s, functions: %s })" % (
                            t["ms"],
                            _opt(rust_str(t["param"]) if t["param"] else None),
                            "Some(&[%s])" % ", ".join(fns) if fns else "None",
                        )
                    functions = (
                        "Some(&[%s])" % ", ".join(str(self.fvalues[x]) for x in v["functions"])
                        if v["functions"] is not None
                        else "None"
                    )
                    devices = ", ".join(f"Device::{self.m.device_variant(d)}" for d in v["devices"])
                    device = f"Some(Device::{self.m.device_variant(v['device'])})" if v["device"] else "None"
                    rows.append(
                        {
                            "set": _hex(s["id"]),
                            "descriptor": _hex(f["id"]),
                            "name": rust_str(f["name"]),
                            "device": device,
                            "devices": devices,
                            "functions": functions,
                            "replies": replies,
                            "ack": ack_text,
                            "timeout": timeout,
                        }
                    )
                    facts_match.append({"pattern": self._pattern(s, f, v, "_"), "index": index})
                    fq = next((q for q in pm.params if q.function), None)
                    if fq is not None:
                        function_match.append({"pattern": self._pattern(s, f, v, "v"), "expr": f"v.{ident(fq.name)}.0"})
                    for name in dict.fromkeys(used):
                        q = by_name[name]
                        x = ident(q.name)
                        if q.optional:
                            expr = f"v.{x}.map(|x| {self._to_int(q, 'x')})"
                        else:
                            expr = f"Some({self._to_int(q, 'v.' + x)})"
                        param_match.append(
                            {"pattern": self._pattern(s, f, v, "v"), "name": rust_str(name), "expr": expr}
                        )
        fdevices = []
        if self.function_enum:
            for v in self.m.types[self.function_enum]["values"]:
                if v.get("devices"):
                    fdevices.append(
                        {
                            "value": v["value"],
                            "devices": ", ".join(f"Device::{self.m.device_variant(d)}" for d in v["devices"]),
                        }
                    )
        uses = ["CommandFacts"] + [
            name
            for name, used in (
                ("AckSuppression", rows),
                ("Allowance", any(r["timeout"] != "None" for r in rows)),
                ("ReplyFacts", any(r["replies"] for r in rows)),
            )
            if used
        ]
        return {
            "session_imports": ", ".join(sorted(uses)),
            "session_rule": {
                "ack": _hex(rule["ack"]),
                "ok": rule["ok"],
                "pattern": f"FieldValue::Reserved(crate::reserved::ReservedField::{ack_rust}(a))",
                "echo": f"a.{ident(rule['echo'])}",
                "code": f"u32::from({code_expr})",
            },
            "function_names": [{"value": v, "name": rust_str(n)} for n, v in self.fvalues.items()],
            "function_devices": fdevices,
            "command_rows": rows,
            "facts_match": facts_match,
            "function_match": function_match,
            "param_match": param_match,
            "api_sets": self.api_sets(),
        }

    # ------------------------------------------------------------ typed API
    def api_sets(self) -> list[dict]:
        out = []
        for s in self.proto["sets"]:
            if s["kind"] != "command":
                continue
            by_id = {f["id"]: f for f in s["fields"]}
            commands = [self._command(s, f, by_id) for f in s["fields"] if f["role"] == "command"]
            if commands:
                module = self.m.set_module(s)
                out.append(
                    {
                        "method": _set_method(module),
                        "struct": camel(module) + "Commands",
                        "title": s["title"],
                        "set": _hex(s["id"]),
                        "commands": commands,
                    }
                )
        return out

    def _command(self, s: dict, f: dict, by_id: dict) -> dict:
        variants = f["variants"]
        plain = variants[0]["functions"] is None
        functions: list[str] = []
        for v in variants:
            for fn in v["functions"] or []:
                if fn not in functions:
                    functions.append(fn)
        methods = []
        for fn in [None] if plain else functions:
            groups: dict[tuple, list[dict]] = {}
            for v in variants:
                if fn is not None and fn not in (v["functions"] or []):
                    continue
                sig = self._signature(v, fn)
                groups.setdefault(tuple((a["name"], a["type"]) for a in sig["args"]), []).append({"v": v, "sig": sig})
            split = len(groups) > 1
            for group in groups.values():
                base = ident(f["name"]) if fn is None else ident(fn)
                name = f"{base}_{group[0]['v']['device']}" if split else base
                builds = []
                for g in group:
                    v = g["v"]
                    struct, wrap = self._constructor(s, f, v, "command")
                    assign = list(g["sig"]["assign"])
                    if len(assign) < len(model.layout(self.proto, v).params):
                        assign.append(f"..<{struct} as crate::wire::Wire>::ZERO")
                    builds.append(
                        {
                            "device": f"Model::{self.m.device_variant(v['device'])}" if v["device"] else None,
                            "struct": struct,
                            "wrap": wrap,
                            "assign": assign,
                        }
                    )
                reply = self._reply(s, f, [g["v"] for g in group], fn, by_id)
                methods.append(
                    {
                        "name": name,
                        "args": group[0]["sig"]["args"],
                        "builds": builds,
                        "returns": reply["type"],
                        "extract": reply["extract"],
                        "doc": (f"Function `{fn}`" if fn else f"Sends `{f['name']}`")
                        + (f" (layout for {', '.join(g['v']['device'] for g in group)})" if split else "")
                        + (": returns the reply field." if reply["type"] != "()" else "."),
                    }
                )
        return {
            "method": ident(f["name"]),
            "struct": camel(f["name"]) + "Command",
            "title": f["title"],
            "plain": plain,
            "methods": methods,
            "descriptor": _hex(f["id"]),
        }

    def _signature(self, v: dict, fn: str | None) -> dict:
        """The arguments of function fn of layout v, and the struct fields they set (count
        parameters of counted arrays are set from the array)."""
        pm = model.layout(self.proto, v)
        counted = {q.count_param: q for q in pm.params if q.count_param}
        args, assign = [], []
        arg_optional: dict[str, bool] = {}
        counts = []
        for q in pm.params:
            x = ident(q.name)
            if q.function:
                assign.append(f"{x}: crate::types::{camel(self.function_enum)}({self.fvalues[fn]})")
                continue
            qfns = q.ir.get("functions")
            if qfns is not None and fn not in qfns:
                continue
            if q.name in counted:
                counts.append(q)
                continue
            inner = self._inner(q)
            required = (qfns is not None and fn not in (q.ir.get("optional_for") or [])) or not q.ir.get("optional")
            arg_optional[q.name] = not required
            if required:
                args.append({"name": x, "type": inner})
                assign.append(f"{x}: Some({x})" if q.optional else x)
            else:
                args.append({"name": x, "type": f"Option<{inner}>"})
                assign.append(x)
        for q in counts:
            arr = counted[q.name]
            a = ident(arr.name)
            length = f"{a}.as_ref().map_or(0, |a| a.len())" if arg_optional.get(arr.name) else f"{a}.len()"
            cast = f"{length} as {self.m.elem_type(q.elem)}"
            assign.append(f"{ident(q.name)}: Some({cast})" if q.optional else f"{ident(q.name)}: {cast}")
        args = [a for a in args if not a["type"].startswith("Option<")] + [
            a for a in args if a["type"].startswith("Option<")
        ]
        return {"args": args, "assign": assign}

    def _inner(self, q: model.Param) -> str:
        elem = self.m.elem_type(q.elem)
        if q.kind == "fixed":
            return f"[{elem}; {q.count}]"
        if q.kind in ("counted", "remaining"):
            return f"crate::bounded::BoundedVec<{elem}, {q.max_count}>"
        return elem

    def _reply(self, s: dict, f: dict, variants: list[dict], fn: str | None, by_id: dict) -> dict:
        ids: list[int] = []
        for v in variants:
            for r in v["responses"]:
                w = r["when"] or {}
                if "function" in w and w["function"] != fn:
                    continue
                if r["id"] not in ids:
                    ids.append(r["id"])
        if not ids:
            return {"type": "()", "extract": None}
        if len(ids) > 1:
            return {"type": "Option<FieldValue>", "extract": "any"}
        rf = by_id[ids[0]]
        module = self.m.set_module(s)
        rust = camel(rf["name"])
        return {
            "type": f"crate::{module}::{rust}",
            "extract": f"FieldValue::{camel(module)}(crate::{module}::SetField::{rust}(r))",
        }


def _session_cases(proto: dict, sessions: list[dict]) -> list[dict]:
    """The session corpus cases of the protocol (generator/sessions.py) as Rust literals."""
    out = []
    used: set[str] = set()
    for c in sessions:
        if c["protocol"] != proto["name"]:
            continue
        fn = "session_" + re.sub(r"[^a-z0-9_]", "_", c["name"].lower())
        while fn in used:
            fn += "_"
        used.add(fn)
        steps = []
        for st in c["steps"]:
            if "send" in st:
                steps.append(
                    "Step::Send { at: %d, line: %s, bytes: %s }"
                    % (st["at"], rust_str(st["send"]), _opt(rust_str(st["bytes"]) if st["bytes"] else None))
                )
            else:
                steps.append("Step::Receive { at: %d, hex: %s }" % (st["at"], rust_str(st["receive"])))
        out.append(
            {
                "fn": fn,
                "name": c["name"],
                "device": _opt(rust_str(c["device"]) if c["device"] else None),
                "timeout_ms": c["timeout_ms"],
                "inter_packet_timeout_ms": c["inter_packet_timeout_ms"],
                "steps": steps,
                "expect": [rust_str(line) for line in c["expect"]],
            }
        )
    return out


def _session_example(m: _Protocol, api_sets: list[dict]) -> dict | None:
    """The context of examples/configure_and_stream.rs (generator/examples.py session_example) as
    calls of the typed command API (command_api.rs.j2) with literal arguments, or None for a
    protocol without the example."""
    ex = session_example(m.proto)
    if ex is None:
        return None
    pkg = m.package
    device = ex["device"]

    def literal(tref: dict, value, top: bool = True) -> str:
        kind = tref["kind"]
        if kind == "struct":
            t = m.types[tref["name"]]
            qs = {q["name"]: q["type"] for q in t["params"]}
            if set(value) != set(qs):
                raise ExampleError(f"Rust back end: the example gives {sorted(value)} of {tref['name']} ({sorted(qs)})")
            inner = ", ".join(f"{ident(k)}: {literal(qs[k], v, False)}" for k, v in value.items())
            return f"{pkg}::types::{camel(tref['name'])} {{ {inner} }}"
        if kind == "enum":
            t = m.types[tref["name"]]
            number = value if isinstance(value, int) else next(x["value"] for x in t["values"] if x["name"] == value)
            name = next((x["name"] for x in t["values"] if x["value"] == number), None)
            enum = f"{pkg}::types::{camel(tref['name'])}"
            return f"{enum}::{upper(name)}" if name is not None else f"{enum}({number})"
        if kind == "primitive" and tref["name"] == "bool":
            return "true" if value else "false"
        if kind == "primitive" and tref["name"] in ("float", "double"):
            return repr(float(value))
        if kind in ("primitive", "bitfield") and isinstance(value, int) and not isinstance(value, bool):
            return f"0x{value:02X}" if value >= 0x10 and top else str(value)
        raise ExampleError(f"Rust back end: the configure-and-stream example cannot write a {kind} value {value!r}")

    def call(step: str, fn: str | None) -> dict:
        """`device.<set>().<command>()[.<function>](args)` and the `let`s of its bounded arrays."""
        st = ex[step]
        api = next(a for a in api_sets if a["method"] == _set_method(m.set_module(st["set"])))
        command = next(c for c in api["commands"] if c["method"] == ident(st["field"]["name"]))
        names = {x["name"]: x for x in command["methods"]}
        base = ident(st["field"]["name"]) if fn is None else ident(fn)
        method = names.get(f"{base}_{device}") or names.get(base)
        if method is None:
            raise ExampleError(f"Rust back end: {st['field']['name']} has no method {base} for {device}")
        params = {ident(q.name): q for q in model.layout(m.proto, st["variant"]).params}
        values = {ident(k): v for k, v in st["values"].items()} if fn in (None, "write") else {}
        args, lets = [], []
        for a in method["args"]:
            q = params[a["name"]]
            if a["name"] not in values:
                if a["type"].startswith("Option<"):
                    args.append("None")
                    continue
                raise ExampleError(
                    f"Rust back end: the configure-and-stream example gives no value for {q.name} of"
                    f" {st['field']['name']} (generator/examples.py SESSION_EXAMPLES)"
                )
            value, tref = values[a["name"]], q.ir["type"]
            if q.kind == "fixed":
                text = "[" + ", ".join(literal(tref, v) for v in value) + "]"
            elif q.kind in ("counted", "remaining"):
                items = ", ".join(literal(tref, v) for v in value)
                lets.append(
                    f'let {a["name"]} = {pkg}::bounded::BoundedVec::from_slice(&[{items}]).ok_or("too many {q.name}")?;'
                )
                text = a["name"]
            else:
                text = literal(tref, value)
            args.append(f"Some({text})" if a["type"].startswith("Option<") else text)
        head = f"device.{api['method']}()"
        target = f"{head}.{method['name']}" if command["plain"] else f"{head}.{command['method']}().{method['name']}"
        returns = method["returns"].rsplit("::", 1)[-1]
        return {"call": f"{target}({', '.join(args)})", "lets": lets, "returns": returns}

    def fn_of(step: str) -> str | None:
        return "write" if ex[step]["field"]["functions"] else None

    data_set = ex["data"]["set"]
    module = m.set_module(data_set)
    fields = []
    for f in ex["data"]["fields"]:
        if len(f["variants"]) > 1:
            raise ExampleError(f"Rust back end: the example's data field {f['name']} has per-device layouts")
        fields.append(
            {
                "name": f["name"],
                "descriptor": _hex(f["id"]),
                "pattern": f"FieldValue::{camel(module)}({pkg}::{module}::SetField::{camel(f['name'])}(v))",
            }
        )
    setting_write, setting_read = call("setting", "write"), call("setting", "read")
    titles = {d["id"]: d["title"] for d in m.proto["devices"]}
    return {
        "program": ex["program"],
        "count": ex["count"],
        "title": titles.get(device, device),
        "model": m.device_variant(device),
        "ping": call("ping", None),
        "info": call("info", None),
        "info_title": ex["info"]["field"]["title"],
        "setting_title": ex["setting"]["field"]["title"],
        "setting_write": setting_write,
        "setting_read": setting_read,
        "format_title": ex["format"]["field"]["title"],
        "format": call("format", fn_of("format")),
        "enable_title": ex["enable"]["field"]["title"],
        "enable": call("enable", fn_of("enable")),
        "data_set": _hex(data_set["id"]),
        "data_set_title": data_set["title"],
        "data_fields": fields,
        "readme": [
            *setting_write["lets"],
            setting_write["call"] + "?;",
            f"let setting = {setting_read['call']}?; // {setting_read['returns']}",
        ],
    }


def _set_method(module: str) -> str:
    """The method of `device::Device` that gives a set's typed commands (`device.threedm()`)."""
    return ident(module + "_set" if module in DEVICE_METHODS else module)


def _opt(v) -> str:
    return "None" if v is None else f"Some({v})"


# ---------------------------------------------------------------------------------------- entry points
_TEMPLATES = [
    ("Cargo.toml.j2", "Cargo.toml"),
    ("README.md.j2", "README.md"),
    ("lib.rs.j2", "src/lib.rs"),
    ("types.rs.j2", "src/types.rs"),
    ("reserved.rs.j2", "src/reserved.rs"),
    ("dispatch.rs.j2", "src/dispatch.rs"),
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
    checksum = copy_runtime("rust", {_RUNTIME_CHECKSUM: "src/framing.rs"})["src/framing.rs"]
    files: dict[str, str] = {}
    for proto in ir["protocols"]:
        model = _Protocol(proto, vectors)
        ctx = {**model.context(), **release.stamp(proto)}
        ctx["cases"] = model.vector_cases()
        ctx["floats"] = model.float_cases()
        ctx["bitfields"] = model.bitfield_cases()
        ctx["short_cases"] = model.short_cases()
        ctx["sample_rule"] = proto["samples"]
        ctx["example"] = _example(proto)
        ctx.update(_Session(model).context())
        ctx["session_cases"] = _session_cases(proto, list(sessions))
        ctx["session_example"] = _session_example(model, ctx["api_sets"])
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
    example = example_context(proto, api_names)
    example["type_name"] = example["api"]["type"].rsplit("::", 1)[1]
    return example


def api_names(protocol: dict, set_: dict | None, field: dict) -> dict[str, str]:
    """Names a Rust user types for a field: its type (per device when it has variants) and module."""
    model = _Protocol(protocol, [])
    pkg = protocol["package"]
    if set_ is None or "applies_to" in field:
        module = f"{pkg}::reserved"
        return {
            "type": f"{module}::{camel(field['name'])}",
            "module": module,
            "enum": f"{module}::ReservedField",
            "decode": f"{pkg}::decode_field",
        }
    module = f"{pkg}::{model.set_module(set_)}"
    out = {
        "type": f"{module}::{camel(field['name'])}",
        "module": module,
        "enum": f"{module}::SetField",
        "decode": f"{pkg}::decode_field",
    }
    if len(field["variants"]) > 1:
        out["variants"] = ", ".join(
            f"{v['device']}: {module}::{camel(field['name'])}{camel(v['device'])}" for v in field["variants"]
        )
    if field.get("role") == "command" and set_["kind"] == "command":
        # The typed command API (command_api.rs.j2): device.<set>().<command>().<function>(...).
        call = f"device.{_set_method(model.set_module(set_))}()"
        functions = list(dict.fromkeys(fn for v in field["variants"] for fn in v["functions"] or []))
        if len(functions) > 1:
            out["session"] = f"{call}.{ident(field['name'])}().{{{','.join(ident(fn) for fn in functions)}}}(...)"
        elif functions:
            out["session"] = f"{call}.{ident(field['name'])}().{ident(functions[0])}(...)"
        else:
            out["session"] = f"{call}.{ident(field['name'])}(...)"
    return out


def public_name(protocol: dict, kind: str, *path) -> str:
    """The Rust name(s) of a spec element, for `mipgen diff` (generator/wirediff.py); the kinds of
    generator/targets/c/backend.py public_name."""
    pkg = protocol["package"]
    if kind == "set":
        return f"{pkg}::{_Protocol(protocol, []).set_module(path[0])}"
    if kind == "field":
        names = api_names(protocol, path[0], path[1])
        return names.get("variants", names["type"])
    if kind == "value":
        return f"{pkg}::{path[0]['name']}::{path[1]['name'].upper()}"
    return f"{path[0]}.{path[1]}"
