"""C++17 back end: one header-only library per protocol at generated/cpp/<package>/.

All naming and type mapping happens here; the templates in templates/cpp/ only loop and print.
Layout of a package (namespace = protocols[].package):

  include/<pkg>/framing.hpp          framing constants (from protocols[].framing) and limits
  include/<pkg>/wire.hpp             Reader/Writer, DecodeError, BoundedVector, Codec<T> for primitives
  include/<pkg>/checksum.hpp         Fletcher-16
  include/<pkg>/packet.hpp           PacketBuilder, PacketView, FieldIterator
  include/<pkg>/parser.hpp           StreamParser (docs/conformance.md section 1)
  include/<pkg>/samples.hpp          SampleTracker, SampleGrouper (continuation packets, section 6)
  include/<pkg>/devices.hpp          Device enum, set kinds
  include/<pkg>/types.hpp            <pkg>::types: enums, bitfields, structs, unions (+ Codec)
  include/<pkg>/fields/<set>.hpp     <pkg>::<set>: one struct per layout (+ Codec)
  include/<pkg>/lookup.hpp           (set, descriptor) -> layouts, with reserved and shared fields
  include/<pkg>/dispatch.hpp         decode_field(): variants, raw fallback
  include/<pkg>/json_*.hpp           canonical JSON writer, JSON reader, Json<T> codecs
  include/<pkg>/json_lines.hpp       stream -> JSON lines, JSON line -> bytes (what the CLIs do)
  tools/decode.cpp, tools/encode.cpp, tests/*.cpp, CMakeLists.txt
"""

from __future__ import annotations

import re

from generator import model
from generator.examples import example_context
from generator.naming import camel
from generator.passes.lookup_order import entries as lookup_entries
from generator.passes.lookup_order import set_kind
from generator.render import environment
from generator.testcases import bitfield_cases, canonical_cases, vector_cases

OUTPUT_DIRS = ["cpp"]

CPP_KEYWORDS = set(
    """
    alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t char16_t char32_t class
    compl concept const consteval constexpr constinit const_cast continue co_await co_return co_yield decltype
    default delete do double dynamic_cast else enum explicit export extern false float for friend goto if inline
    int long mutable namespace new noexcept not not_eq nullptr operator or or_eq private protected public register
    reinterpret_cast requires return short signed sizeof static static_assert static_cast struct switch template
    this thread_local throw true try typedef typeid typename union unsigned using virtual void volatile wchar_t
    while xor xor_eq
    std NULL assert errno stdin stdout stderr EOF
    """.split()
)  # C++ keywords, and names (std, common macros) a member must not shadow

# Sub-namespaces of a package that the runtime uses; a set with one of these names gets a suffix.
RUNTIME_NAMESPACES = {
    "types",
    "detail",
    "json",
    "decode",
    "encode",
    "decode_field",
    "lookup_field",
    "set_kind",
    "device_name",
    "device_from_name",
    "fletcher16",
    "format_double",
    "string_sink",
    "to_string",
    "from_string",
    "write_packet_json",
    "write_skip_json",
    "decode_to_json_lines",
    "encode_json_line",
    "no_union_member_error",
    "read_value",
    "write_value",
    "read_string",
    "write_string",
    "read_fixed",
    "write_fixed",
    "read_counted",
    "write_counted",
    "read_remaining",
    "write_remaining",
    "json_write_value",
    "json_read_value",
    "json_write_string",
    "json_read_string",
    "json_write_array",
    "json_read_fixed",
    "json_read_counted",
    "json_read_remaining",
    "json_check_object",
}  # namespace-scope names of the runtime; a set with one of these names gets a "_set" suffix

PRIM_CPP = {
    "bool": "bool",
    "char": "char",
    "u8": "std::uint8_t",
    "u16": "std::uint16_t",
    "u32": "std::uint32_t",
    "u64": "std::uint64_t",
    "s8": "std::int8_t",
    "s16": "std::int16_t",
    "s32": "std::int32_t",
    "s64": "std::int64_t",
    "float": "float",
    "double": "double",
}


def ident(name: str, extra: set[str] | frozenset = frozenset()) -> str:
    return name + "_" if name in CPP_KEYWORDS or name in extra else name


def int_literal(v: int) -> str:
    if v >= 0:
        return str(v) if v < 2**31 else f"{v}ULL"
    if v >= -(2**31):
        return str(v)
    return f"({v + 1}LL - 1)"


def cpp_string(s: str) -> str:
    """A C++ string literal for ASCII-ish text (octal escapes for anything unusual)."""
    out = ['"']
    for ch in s:
        o = ord(ch)
        if ch == '"':
            out.append('\\"')
        elif ch == "\\":
            out.append("\\\\")
        elif ch == "?":
            out.append("\\?")  # no trigraphs
        elif 0x20 <= o < 0x7F:
            out.append(ch)
        elif o < 0x100:
            out.append("\\%03o" % o)
        else:
            raise ValueError(f"non-Latin-1 character in {s!r}")
    out.append('"')
    return "".join(out)


def _reserved_ns(proto: dict) -> str:
    names = {s["name"] for s in proto["sets"]}
    return "reserved" if "reserved" not in names else "reserved_fields"


def _set_ns(set_: dict) -> str:
    n = ident(set_["name"])
    return n + "_set" if n in RUNTIME_NAMESPACES or n == "reserved" else n


def _layout_names(fields: list[dict]) -> dict[tuple[str, str | None], str]:
    """(field name, device) -> C++ struct name, unique within a set."""
    taken = {camel(f["name"]) for f in fields}
    out: dict[tuple[str, str | None], str] = {}
    for f in fields:
        if len(f["variants"]) == 1:
            out[(f["name"], None)] = camel(f["name"])
            continue
        for v in f["variants"]:
            name = camel(f["name"]) + camel(v["device"])
            if name in taken:
                name = camel(f["name"]) + "For" + camel(v["device"])
            taken.add(name)
            out[(f["name"], v["device"])] = name
    return out


def api_names(protocol: dict, set_: dict | None, field: dict) -> dict[str, str]:
    """The names a C++ user types for a field (documentation back end)."""
    pkg = protocol["package"]
    is_reserved = set_ is None or field.get("role") == "ack"
    ns = _reserved_ns(protocol) if is_reserved else _set_ns(set_)
    names = _layout_names(protocol["reserved_fields"] if is_reserved else set_["fields"])
    types = [
        f"{pkg}::{ns}::{names[(field['name'], v['device'] if len(field['variants']) > 1 else None)]}"
        for v in field["variants"]
    ]
    out = {
        "type": types[0],
        "header": f"{pkg}/fields/{ns}.hpp",
        "namespace": f"{pkg}::{ns}",
        "decode": f"{pkg}::decode(data, size, value, error)",
        "encode": f"{pkg}::encode(value, buffer, capacity, written)",
        "packet": f"{pkg}::PacketBuilder(set).add(value)",
    }
    if len(types) > 1:
        out["variants"] = ", ".join(types)
        for v, t in zip(field["variants"], types):
            out[f"type_{v['device']}"] = t
    return out


class _Proto:
    def __init__(self, proto: dict):
        self.p = proto
        self.ns = ident(proto["package"])
        self.types = {t["name"]: t for t in proto["types"]}
        self.reserved_ns = _reserved_ns(proto)

    # ------------------------------------------------------------ type mapping
    def type_name(self, name: str) -> str:
        return f"::{self.ns}::types::{name}"

    def elem_cpp(self, e: model.Elem) -> str:
        """The C++ type of one value."""
        if e.kind == "primitive":
            return PRIM_CPP[e.name]
        if e.kind == "string":
            return f"std::array<char, {e.length}>"
        return self.type_name(e.name)

    def param(self, p: model.Param) -> dict:
        """Names and types of one parameter of the layout model (struct member or layout
        parameter); include/macros.j2 writes the C++ for its kind."""
        if p.function:
            doc = "Function selector."
        else:
            doc = " ".join(p.description.split()) + (f" [{p.units}]" if p.units else "")
        view = {
            "json": p.name,
            "member": ident(p.name),
            "kind": p.kind,
            "optional": p.optional,
            "elem": self.elem_cpp(p.elem),
            "ns": self.ns,
            "count": p.count,
            "max_count": p.max_count,
            "plain": p.plain,
            "doc": doc,
        }
        if p.count_param is not None:
            view.update(count_member=ident(p.count_param), count_optional=p.count_optional)
        if p.selector is not None:
            view.update(
                sel_member=ident(p.selector), sel_optional=p.selector_optional, sel_type=self.type_name(p.selector_enum)
            )
        return view

    def params(self, params: list[dict], functions: list[str] | None = None) -> list[dict]:
        return [self.param(p) for p in model.params(self.p, params, functions)]

    # ------------------------------------------------------------ types
    def ordered_types(self) -> list[dict]:
        """Enums and bitfields first, then structs and unions after what they contain."""
        done: set[str] = set()
        order: list[dict] = []

        def deps(t: dict) -> list[str]:
            if t["kind"] == "struct":
                return [q["type"]["name"] for q in t["params"] if q["type"]["kind"] in ("struct", "union")]
            if t["kind"] == "union":
                return [m["type"] for m in t["members"] if m["type"]]
            return []

        def visit(name: str) -> None:
            if name in done:
                return
            done.add(name)
            t = self.types[name]
            for d in deps(t):
                visit(d)
            order.append(t)

        for t in self.p["types"]:
            if t["kind"] in ("enum", "bitfield"):
                done.add(t["name"])
                order.append(t)
        for t in self.p["types"]:
            visit(t["name"])
        return order

    def type_model(self, t: dict) -> dict:
        m = {
            "kind": t["kind"],
            "name": t["name"],
            "cpp": t["name"],
            "full": self.type_name(t["name"]),
            "title": " ".join(t.get("title", t["name"]).split()),
        }
        if t["kind"] == "enum":
            m["base"] = PRIM_CPP[t["base"]]
            m["enumerators"] = [
                {"name": v["name"], "cpp": ident(v["name"]), "literal": int_literal(v["value"])} for v in t["values"]
            ]
        elif t["kind"] == "bitfield":
            m["base"] = PRIM_CPP[t["base"]]
            taken = {"raw", "set_raw", "Raw"}
            members = []
            for b in t["members"]:
                getter = ident(b["name"], frozenset(taken))
                members.append(
                    {
                        "name": b["name"],
                        "getter": getter,
                        "setter": "set_" + b["name"],
                        "mask_name": b["name"] + "_mask",
                        "mask": f"0x{b['mask']:X}ULL",
                        "shift": b["first_bit"],
                        "width": b["width"],
                        "flag": b["width"] == 1,
                    }
                )
            m["members"] = members
        elif t["kind"] == "struct":
            m["params"] = self.params(t["params"])
            m["fixed"] = "true" if t["size"]["fixed"] else "false"
            m["size"] = t["size"]["min"] if t["size"]["fixed"] else 0
            m["plain"] = all(p["plain"] for p in m["params"])
        else:
            sel = self.types[t["selector_enum"]]
            alts = ["std::monostate"]
            members = []
            for mem in t["members"]:
                if mem["type"]:
                    alts.append(self.type_name(mem["type"]))
                    index = len(alts) - 1
                else:
                    index = 0
                members.append(
                    {
                        "when": mem["when"],
                        "literal": int_literal(mem["value"]),
                        "index": index,
                        "type": self.type_name(mem["type"]) if mem["type"] else None,
                    }
                )
            m["alternatives"] = alts
            m["members"] = members
            m["selector"] = self.type_name(sel["name"])
            m["selector_base"] = PRIM_CPP[sel["base"]]
            m["selector_signed"] = sel["base"].startswith("s")
        return m

    # ------------------------------------------------------------ fields
    def layouts(self, fields: list[dict], set_: dict | None) -> list[dict]:
        names = _layout_names(fields)
        out = []
        for f in fields:
            multi = len(f["variants"]) > 1
            for v in f["variants"]:
                params = self.params(v["params"], v["functions"])
                out.append(
                    {
                        "cpp": names[(f["name"], v["device"] if multi else None)],
                        "name": f["name"],
                        "title": " ".join(f["title"].split()),
                        "set": set_["id"] if set_ else None,
                        "descriptor": f["id"],
                        "device": v["device"] if multi else None,
                        "device_cpp": ident(v["device"]) if multi else None,
                        "params": params,
                        "has_optional": any(q["optional"] for q in v["params"]),
                        "plain": all(q["plain"] for q in params),
                        "role": f["role"],
                    }
                )
        return out

    def set_models(self) -> list[dict]:
        out = []
        for s in self.p["sets"]:
            ns = _set_ns(s)
            out.append(
                {
                    "ns": ns,
                    "file": ns,
                    "title": s["title"],
                    "id": s["id"],
                    "kind": s["kind"],
                    "layouts": self.layouts(s["fields"], s),
                }
            )
        if self.p["reserved_fields"]:
            out.append(
                {
                    "ns": self.reserved_ns,
                    "file": self.reserved_ns,
                    "title": "Reserved fields",
                    "id": None,
                    "kind": None,
                    "layouts": self.layouts(self.p["reserved_fields"], None),
                }
            )
        return out

    def lookup_cases(self, fields: list[dict], ns: str) -> list[dict]:
        names = _layout_names(fields)
        cases = []
        for f in fields:
            multi = len(f["variants"]) > 1
            cases.append(
                {
                    "descriptor": f["id"],
                    "types": [
                        f"::{self.ns}::{ns}::{names[(f['name'], v['device'] if multi else None)]}"
                        for v in f["variants"]
                    ],
                }
            )
        return cases

    def lookup(self) -> dict:
        sets = [{"id": s["id"], "cases": self.lookup_cases(s["fields"], _set_ns(s))} for s in self.p["sets"]]
        kinds = []
        for k, r in self.p["set_kinds"].items():
            conds = ([f"set >= {r['first']}"] if r["first"] > 0 else []) + (
                [f"set <= {r['last']}"] if r["last"] < 255 else []
            )
            kinds.append({"name": k, "cpp": ident(k), "cond": " && ".join(conds) or "true"})
        reserved = []
        for k in kinds:
            rf = [f for f in self.p["reserved_fields"] if f["applies_to"] == k["name"]]
            if rf:
                reserved.append({"kind": k["cpp"], "cases": self.lookup_cases(rf, self.reserved_ns)})
        shared = None
        sd = self.p.get("shared_data")
        if sd:
            sset = next((s for s in self.p["sets"] if s["id"] == sd["set"]), None)
            if sset and any(k["name"] == "data" for k in kinds):
                shared = {"kind": ident("data"), "cases": self.lookup_cases(sset["fields"], _set_ns(sset))}
        return {
            "sets": sets,
            "kinds": kinds,
            "reserved": reserved,
            "shared": shared,
            **self.lookup_table(sets, reserved),
        }

    def lookup_table(self, sets: list[dict], reserved: list[dict]) -> dict:
        """The (set, descriptor) -> case table of lookup.hpp: the answers of the search order of
        docs/conformance.md section 2 (set fields, reserved fields of the set's kind, shared data
        fields) as the IR's `lookup` resolves it. Case 0 is an unknown set, 1 an unknown descriptor,
        2.. a field."""
        cases: list[list[str]] = []
        index: dict[tuple, int] = {}

        def case(c: dict) -> int:
            key = tuple(c["types"])
            if key not in index:
                index[key] = len(cases) + 2
                cases.append(c["types"])
            return index[key]

        # Each field's case: a set's cases, the reserved cases of each kind (names are unique
        # within those lists), found by where the IR's `lookup` resolves (set, descriptor) to.
        by_owner: dict[tuple, dict] = {("set", st["id"]): st["cases"] for st in sets}
        by_owner.update({("reserved", r["kind"]): r["cases"] for r in reserved})
        by_owner = {k: {c["descriptor"]: c for c in v} for k, v in by_owner.items()}

        defined = {st["id"] for st in sets}

        def row(set_id: int) -> list[int]:
            kind = set_kind(self.p, set_id)
            found = {e["descriptor"]: e for e in lookup_entries(self.p, set_id)}
            miss = 1 if set_id in defined else 0
            out = []
            for d in range(256):
                if d not in found:
                    out.append(miss)
                    continue
                e = found[d]
                key = ("reserved", ident(kind)) if e["source"] == "reserved" else ("set", e["set"])
                out.append(case(by_owner[key][d]))
            return out

        rows: list[list[int]] = []
        row_of: dict[tuple, int] = {}

        def add(r: list[int]) -> int:
            key = tuple(r)
            if key not in row_of:
                row_of[key] = len(rows)
                rows.append(r)
            return row_of[key]

        # Undefined sets of one kind resolve alike: their row is shared through add().
        set_row = [add(row(i)) for i in range(256)]
        return {
            "cases": [{"index": i + 2, "types": t} for i, t in enumerate(cases)],
            "set_row": set_row,
            "rows": rows,
            "case_type": "std::uint8_t" if len(cases) + 2 <= 256 else "std::uint16_t",
        }

    # ------------------------------------------------------------ limits
    def limits(self) -> dict:
        """Buffer limits from the IR's value_paths, with slack: the error path text and the JSON
        nesting (every step of a path but its last opens an object or array)."""
        vp = self.p["value_paths"]
        return {"max_error_path": vp["length"] + 8, "max_json_depth": vp["depth"] - 1 + 8}

    # ------------------------------------------------------------ framing
    def framing(self) -> dict:
        f = self.p["framing"]
        order = f["checksum"]["order"]
        return {
            "sync": ", ".join(f"0x{b:02X}" for b in f["sync"]),
            "sync_size": len(f["sync"]),
            "header_size": f["header_size"],
            "set_offset": f["set_offset"],
            "length_offset": f["length_offset"],
            "field_header_size": f["field_header_size"],
            "field_length_offset": f["field_length_offset"],
            "field_descriptor_offset": f["field_descriptor_offset"],
            "field_length_counts_header": "true" if f["field_length_counts_header"] else "false",
            "field_length_adjust": f["field_length_adjust"],
            "irregular_lengths": f["irregular_lengths"],
            "max_payload": f["max_payload"],
            "checksum_size": f["checksum_size"],
            "sum1_index": order.index("sum1"),
            "sum2_index": order.index("sum2"),
            "max_packet": f["max_packet"],
            "max_field_data": f["max_field_data"],
            "big_endian": "true" if self.p["byte_order"] == "big" else "false",
        }

    # ------------------------------------------------------------ tests (cases from generator/testcases.py)
    def bitfield_test(self) -> dict | None:
        """The accessor round trip of the first bitfield type: its first member wider than a bit
        (or its first member) and its first flag."""
        cases = bitfield_cases(self.p)
        if not cases:
            return None
        b = cases[0]
        m = self.type_model(self.types[b.name])
        members = {x["name"]: x for x in m["members"]}
        mem = b.wide_member()
        flag = b.first_flag()
        return {
            "type": m["full"],
            "base": m["base"],
            "member": members[mem.name],
            "flag": members[flag.name] if flag else None,
            "value": mem.value,
            "raw": f"0x{mem.raw:X}ULL",
        }

    def vector_cases(self, vectors: list[dict]) -> list[dict]:
        out = []
        used: set[str] = set()
        for c in vector_cases(vectors, self.p):
            name = re.sub(r"[^A-Za-z0-9]", "_", c.name).strip("_") or "case"
            name = camel(name.lower()) if name[0].isdigit() else name
            base, i = name, 2
            while name in used:
                name, i = f"{base}_{i}", i + 1
            used.add(name)
            out.append(
                {
                    "name": name,
                    "suite": c.corpus.capitalize(),
                    "source": c.name,
                    "hex": cpp_string(c.hex),
                    "device": cpp_string(c.device) if c.device else "nullptr",
                    "rejected": c.rejected,
                    "expect": [cpp_string(line) for line in c.expect],
                }
            )
        return out


def canonical_context() -> dict:
    """The canonical float/string table of generator/testcases.py as C++ literals."""
    cases = canonical_cases()
    return {
        "doubles": [{"bits": f"0x{c.bits:016X}ULL", "text": cpp_string(c.text)} for c in cases.doubles],
        "floats": [{"bits": f"0x{c.bits:08X}u", "text": cpp_string(c.text)} for c in cases.floats],
        "all_bytes": cpp_string(cases.all_bytes),
    }


def render(ir: dict, vectors: list[dict]) -> dict[str, str]:
    env = environment()
    files: dict[str, str] = {}
    for proto in ir["protocols"]:
        P = _Proto(proto)
        pkg = proto["package"]
        root = f"cpp/{pkg}"
        inc = f"{root}/include/{pkg}"
        sets = P.set_models()
        ctx = {
            "ns": P.ns,
            "pkg": pkg,
            "protocol": proto["name"],
            "title": proto["title"],
            "framing": P.framing(),
            "limits": P.limits(),
            "devices": [{"id": d["id"], "cpp": ident(d["id"]), "title": d["title"]} for d in proto["devices"]],
            "types": [P.type_model(t) for t in P.ordered_types()],
            "sets": sets,
            "lookup": P.lookup(),
            "vectors": P.vector_cases(vectors),
            "bitfield_test": P.bitfield_test(),
            "canonical": canonical_context(),
            "sample_rule": proto["samples"],
            "example": example_context(proto, api_names),
        }
        plain = {
            "framing.hpp": "framing.hpp.j2",
            "wire.hpp": "wire.hpp.j2",
            "checksum.hpp": "checksum.hpp.j2",
            "packet.hpp": "packet.hpp.j2",
            "parser.hpp": "parser.hpp.j2",
            "samples.hpp": "samples.hpp.j2",
            "devices.hpp": "devices.hpp.j2",
            "types.hpp": "types.hpp.j2",
            "types_json.hpp": "types_json.hpp.j2",
            "lookup.hpp": "lookup.hpp.j2",
            "dispatch.hpp": "dispatch.hpp.j2",
            "json_writer.hpp": "json_writer.hpp.j2",
            "json_reader.hpp": "json_reader.hpp.j2",
            "json_codec.hpp": "json_codec.hpp.j2",
            "json_lines.hpp": "json_lines.hpp.j2",
            f"{pkg}.hpp": "package.hpp.j2",
        }
        for out, tpl in plain.items():
            files[f"{inc}/{out}"] = env.get_template(f"cpp/include/{tpl}").render(ctx)
        for s in sets:
            files[f"{inc}/fields/{s['file']}.hpp"] = env.get_template("cpp/include/fields.hpp.j2").render(ctx, set=s)
            files[f"{inc}/fields/{s['file']}_json.hpp"] = env.get_template("cpp/include/fields_json.hpp.j2").render(
                ctx, set=s
            )
        files[f"{root}/tools/decode.cpp"] = env.get_template("cpp/tools/decode.cpp.j2").render(ctx)
        files[f"{root}/tools/encode.cpp"] = env.get_template("cpp/tools/encode.cpp.j2").render(ctx)
        files[f"{root}/examples/getting_started.cpp"] = env.get_template("cpp/examples/getting_started.cpp.j2").render(
            ctx
        )
        files[f"{root}/tests/test_support.hpp"] = env.get_template("cpp/tests/test_support.hpp.j2").render(ctx)
        files[f"{root}/tests/test_vectors.cpp"] = env.get_template("cpp/tests/test_vectors.cpp.j2").render(ctx)
        files[f"{root}/tests/test_runtime.cpp"] = env.get_template("cpp/tests/test_runtime.cpp.j2").render(ctx)
        files[f"{root}/tests/test_canonical.cpp"] = env.get_template("cpp/tests/test_canonical.cpp.j2").render(ctx)
        files[f"{root}/CMakeLists.txt"] = env.get_template("cpp/CMakeLists.txt.j2").render(ctx)
        files[f"{root}/README.md"] = env.get_template("cpp/README.md.j2").render(ctx)
    return files
