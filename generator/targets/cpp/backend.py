"""C++17 back end: one header-only library per protocol at generated/cpp/<package>/.

All naming and type mapping happens here (language facts in facts.py); the templates in
templates/cpp/ only loop and print, and the hand-written runtime in runtime/ is copied verbatim
(runtime/README.md). Layout of a package (namespace = protocols[].package):

  include/<pkg>/framing.hpp          framing constants, sample rule and limits (the runtime's only protocol input)
  include/<pkg>/wire.hpp             runtime: Reader/Writer, DecodeError, BoundedVector, Codec<T> for primitives
  include/<pkg>/checksum.hpp         runtime: Fletcher-16
  include/<pkg>/packet.hpp           runtime: PacketBuilder, PacketView, FieldIterator
  include/<pkg>/parser.hpp           runtime: StreamParser (docs/conformance.md section 1)
  include/<pkg>/samples.hpp          runtime: SampleTracker, SampleGrouper (continuation packets, section 6)
  include/<pkg>/clock.hpp            runtime: ClockModel (the host clock model, docs/time.md)
  include/<pkg>/json_{writer,reader,codec}.hpp  runtime: canonical JSON writer, JSON reader, Json<T> of primitives
  include/<pkg>/dispatch.hpp         runtime: decode_field(): variants, raw fallback
  include/<pkg>/json_lines.hpp       runtime: stream -> JSON lines, JSON line -> bytes (what the CLIs do)
  include/<pkg>/devices.hpp          Device enum, set kinds
  include/<pkg>/types.hpp            <pkg>::types: enums, bitfields, structs, unions (+ Codec)
  include/<pkg>/types_json.hpp       Json<T> of the types
  include/<pkg>/fields/<set>.hpp     <pkg>::<set>: one struct per layout (+ Codec), and <set>_json.hpp
  include/<pkg>/layouts_json.hpp     every set's <set>_json.hpp (for json_lines.hpp)
  include/<pkg>/lookup.hpp           runtime: (set, descriptor) -> layouts, over the tables of lookup_tables.hpp
  include/<pkg>/lookup_tables.hpp    the answers of the search (with reserved and shared fields) as tables
  include/<pkg>/version.hpp          version and spec hash (generator/release.py)
  tools/decode.cpp, tools/encode.cpp, tests/*.cpp, CMakeLists.txt, LICENSE
"""

from __future__ import annotations

import re

from generator import commands, examples, model, packet_plan
from generator.clock_model import clock_model
from generator.cmake import cmake_package_files, pkg_config
from generator.examples import ExampleError
from generator.linkfacts import link_facts
from generator.naming import camel
from generator.passes.lookup_order import entries as lookup_entries
from generator.passes.lookup_order import set_kind
from generator.release import Release, load_release
from generator.render import copy_runtime, environment
from generator.targets.cfamily import c_string, session_steps
from generator.targets.cpp.facts import KEYWORDS as CPP_KEYWORDS
from generator.targets.cpp.facts import PRIMITIVE_TYPES as PRIM_CPP
from generator.targets.cpp.facts import RESERVED as CPP_RESERVED
from generator.testcases import bitfield_cases, canonical_literals, vector_cases

OUTPUT_DIRS = ["cpp"]

# CPP_KEYWORDS and PRIM_CPP (above) are the language tables of facts.py, under this module's names.

# The hand-written runtime (generator/targets/cpp/runtime/, see its README.md): {file there: file
# in the package}. The library headers' only protocol input is the generated framing.hpp;
# dispatch.hpp, json_lines.hpp, the tools and the package tests also use the generated API
# (devices.hpp, lookup_tables.hpp, layouts_json.hpp).
RUNTIME_HEADERS = [
    "lookup_types.hpp",
    "lookup.hpp",
    "wire.hpp",
    "checksum.hpp",
    "packet.hpp",
    "parser.hpp",
    "samples.hpp",
    "clock.hpp",
    "dispatch.hpp",
    "json_writer.hpp",
    "json_reader.hpp",
    "json_codec.hpp",
    "json_lines.hpp",
    "session_types.hpp",
    "session.hpp",
    "session_json.hpp",
    "transport.hpp",
    "transport_posix.hpp",
]


# The hand-written runtime's sources (runtime/src/), compiled into the library with the generated
# ones (library_sources): the members that instantiate the field dispatch once for every program.
RUNTIME_SOURCES = ["dispatch.cpp", "json_encode.cpp", "json_lines.cpp", "transport.cpp"]


def runtime_files(pkg: str) -> dict[str, str]:
    """{runtime file: path in the package} of the hand-written runtime."""
    return {
        **{f"include/protopkg/{h}": f"include/{pkg}/{h}" for h in RUNTIME_HEADERS},
        **{f"src/{c}": f"src/{c}" for c in RUNTIME_SOURCES},
        # The Windows counterpart of transport_posix.hpp (compiles only on Windows, with MinGW-w64).
        "include/protopkg/transport_win32.hpp": f"include/{pkg}/transport_win32.hpp",
        "tools/decode.cpp": "tools/decode.cpp",
        "tools/encode.cpp": "tools/encode.cpp",
        "tools/session.cpp": "tools/session.cpp",
        "tools/tool_io.hpp": "tools/tool_io.hpp",
        "package_tests/test_support.hpp": "tests/test_support.hpp",
        "package_tests/test_package.cpp": "tests/test_package.cpp",
        "package_tests/test_canonical.cpp": "tests/test_canonical.cpp",
        "package_tests/session_runner.hpp": "tests/session_runner.hpp",
    }


# The first line of every file of a package, the copied runtime included.
GENERATED_LINE = "// Generated by the protocol code generator from generated/ir.json. Do not edit.\n"


def runtime_names(pkg: str, ns: str) -> list[tuple[str, str]]:
    """The replacements of the runtime's placeholder package "protopkg" (see runtime/README.md), in
    order: file names (include paths, the umbrella header, the tools' names) take the package
    name; code takes its namespace (the package name, with a "_" suffix if that is a C++ keyword),
    and macros the namespace in capitals."""
    return [
        ("protopkg/", pkg + "/"),
        ("protopkg.hpp", pkg + ".hpp"),
        ("protopkg-", pkg + "-"),
        ("protopkg", ns),
        ("PROTOPKG", ns.upper()),
    ]


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
    "write_field_entry_json",
    "decode_ack",
    "function_name",
    "function_devices",
    "support_error",
    "ack_suppressed",
    "allowance_ms",
    "expected_replies",
    "write_result_json",
    "session_event_line",
    "with_command_from_line",
    "parse_tcp_address",
    "open_tcp",
    "open_serial",
    "open_transport",
    "baud_speed",
    "api",
}  # namespace-scope names of the runtime; a set with one of these names gets a "_set" suffix


def ident(name: str, extra: set[str] | frozenset = frozenset()) -> str:
    return name + "_" if name in CPP_KEYWORDS or name in CPP_RESERVED or name in extra else name


def int_literal(v: int) -> str:
    if v >= 0:
        return str(v) if v < 2**31 else f"{v}ULL"
    if v >= -(2**31):
        return str(v)
    return f"({v + 1}LL - 1)"


def cpp_string(s: str) -> str:
    return c_string(s, cpp=True)


def reserved_namespace(proto: dict) -> str:
    names = {s["name"] for s in proto["sets"]}
    return "reserved" if "reserved" not in names else "reserved_fields"


def set_namespace(set_: dict) -> str:
    n = ident(set_["name"])
    return n + "_set" if n in RUNTIME_NAMESPACES or n == "reserved" else n


def layout_names(fields: list[dict]) -> dict[tuple[str, str | None], str]:
    """(field name, device) -> C++ struct name, unique within a set."""
    taken = {camel(f["name"]) for f in fields}
    out: dict[tuple[str, str | None], str] = {}
    for f in fields:
        if not model.per_device(f):
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
    ns = reserved_namespace(protocol) if is_reserved else set_namespace(set_)
    names = layout_names(protocol["reserved_fields"] if is_reserved else set_["fields"])
    types = [f"{pkg}::{ns}::{names[(field['name'], model.layout_device(field, v))]}" for v in field["variants"]]
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
    if not is_reserved and field.get("role") == "command" and set_["kind"] == "command":
        # The typed command API (commands.hpp.j2): api::<set>::<command>::<function>(connection, ...).
        call = f"{pkg}::api::{set_namespace(set_)}::{ident(field['name'])}"
        functions = list(dict.fromkeys(fn for v in field["variants"] for fn in v["functions"] or []))
        if len(functions) > 1:
            out["session"] = f"{call}::{{{','.join(ident(fn) for fn in functions)}}}(connection, ...)"
        else:
            out["session"] = f"{call}::{_cpp_fn(functions[0] if functions else None)}(connection, ...)"
    return out


class _Protocol:
    def __init__(self, proto: dict):
        self.p = proto
        self.ns = ident(proto["package"])
        self.types = {t["name"]: t for t in proto["types"]}
        self.reserved_ns = reserved_namespace(proto)

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
        names = layout_names(fields)
        out = []
        for f, v, dev in model.layouts_of(fields):
            params = self.params(v["params"], v["functions"])
            out.append(
                {
                    "cpp": names[(f["name"], dev)],
                    "name": f["name"],
                    "title": " ".join(f["title"].split()),
                    "set": set_["id"] if set_ else None,
                    "descriptor": f["id"],
                    "device": dev,
                    "device_cpp": ident(dev) if dev else None,
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
            ns = set_namespace(s)
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
        names = layout_names(fields)
        cases = []
        for f in fields:
            multi = model.per_device(f)
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
        sets = [{"id": s["id"], "cases": self.lookup_cases(s["fields"], set_namespace(s))} for s in self.p["sets"]]
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
                shared = {"kind": ident("data"), "cases": self.lookup_cases(sset["fields"], set_namespace(sset))}
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
            "nmea": f["nmea"],
            "rtcm3": f["rtcm3"],
            "nmea_max": f["nmea_max"],
            "parser_capacity": f["parser_capacity"],
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


def packet_models(P: _Protocol) -> list[dict]:
    """The straight-line packet decoders (issue 38; templates packets.hpp.j2, packet_set.hpp.j2): the
    members and fast loads of generator/packet_plan.py in C++ names, one model per data set.
    A member is named after its field (a clash, or the name `index`, gets the owning set's suffix);
    a fast load is one Plain<V>::load per parameter, or a byte per bool (checked <= 1)."""
    proto = P.p
    sets = {s["id"]: s for s in proto["sets"]}
    out = []
    for set_id, plan in packet_plan.packet_plans(proto).items():
        if plan is None:
            continue
        s = sets[set_id]
        names = [ident(m.field["name"]) for m in plan.members]
        members = []
        headers = set()
        for m, name in zip(plan.members, names):
            owner = sets[m.field_set] if m.field_set is not None else None
            ns = set_namespace(owner) if owner else P.reserved_ns
            if names.count(name) > 1 or name in ("index", "Packet"):
                name = f"{name}_{ns}"
            fields = owner["fields"] if owner else proto["reserved_fields"]
            loads = []
            if m.fast:
                views = {q.name: P.param(q) for q in model.layout(proto, m.variant)}
                first: dict[str, int] = {}
                for x in m.fast.loads:
                    v = views[x.param]
                    if x.primitive == "bool":
                        index = f"[{x.index}]" if x.index is not None else ""
                        loads.append({"bool": True, "member": v["member"] + index, "off": x.off})
                    elif x.param not in first:
                        first[x.param] = x.off
                        vt = f"std::array<{v['elem']}, {v['count']}>" if v["kind"] == "fixed" else v["elem"]
                        loads.append({"bool": False, "member": v["member"], "type": vt, "off": x.off})
            headers.add(f"{proto['package']}/fields/{ns}.hpp")
            members.append(
                {
                    "descriptor": m.descriptor,
                    "member": name,
                    "type": f"::{P.ns}::{ns}::{layout_names(fields)[(m.field['name'], None)]}",
                    "source": m.source,
                    "size": m.fast.size if m.fast else None,
                    "bools": list(m.fast.bools) if m.fast else [],
                    "loads": loads,
                }
            )
        ns = set_namespace(s)
        out.append(
            {"ns": ns, "file": ns, "id": set_id, "name": s["name"], "members": members, "includes": sorted(headers)}
        )
    return out


def render(ir: dict, vectors: list[dict], release: Release | None = None, sessions: list[dict] = ()) -> dict[str, str]:
    release = release or load_release()
    env = environment()
    env.filters["cpp_string"] = cpp_string
    env.filters["cpp_int"] = int_literal
    env.filters["pow2"] = lambda v: 1 << v
    files: dict[str, str] = {}
    sessions = list(sessions)
    for proto in ir["protocols"]:
        P = _Protocol(proto)
        pkg = proto["package"]
        root = f"cpp/{pkg}"
        inc = f"{root}/include/{pkg}"
        sets = P.set_models()
        caps = {c["device"]: c for c in proto.get("capabilities", {}).get("devices", [])}
        link = link_facts(proto)
        ctx = {
            "ns": P.ns,
            "pkg": pkg,
            "PKG": pkg.upper(),
            "protocol": proto["name"],
            "title": proto["title"],
            "framing": P.framing(),
            "limits": P.limits(),
            "devices": [
                {
                    "id": d["id"],
                    "cpp": ident(d["id"]),
                    "title": d["title"],
                    "manual": d["manual"],
                    "commands": [f"0x{s:02X}{x:02X}" for s, x in caps.get(d["id"], {}).get("commands", [])],
                    "data": [f"0x{s:02X}{x:02X}" for s, x in caps.get(d["id"], {}).get("data", [])],
                    "baud_rates": [f"{r}u" for r in lf["rates"]],
                    "default_baud": lf["default"] or 0,
                }
                for d, lf in zip(proto["devices"], link["devices"])
            ],
            "link_facts": link,
            "clock_model": clock_model(proto),
            "types": [P.type_model(t) for t in model.type_order(P.p)],
            "sets": sets,
            "lookup": P.lookup(),
            "vectors": P.vector_cases(vectors),
            "bitfield_test": P.bitfield_test(),
            "canonical": canonical_literals(cpp_string, "ULL", "u"),
            "sample_rule": proto["samples"],
            "example": examples.example_context(proto, api_names),
            **release.stamp(proto),
        }
        files[f"{root}/LICENSE"] = release.license
        # The hand-written runtime, with the package's names put in for the placeholder.
        for rel, text in copy_runtime(
            "cpp", runtime_files(pkg), runtime_names(pkg, P.ns), first_line=GENERATED_LINE
        ).items():
            files[f"{root}/{rel}"] = text
        spec = {
            "framing.hpp": "framing.hpp.j2",
            "devices.hpp": "devices.hpp.j2",
            "types.hpp": "types.hpp.j2",
            "types_json.hpp": "types_json.hpp.j2",
            "lookup_tables.hpp": "lookup_tables.hpp.j2",
            "layouts_json.hpp": "layouts_json.hpp.j2",
            f"{pkg}.hpp": "package.hpp.j2",
            "version.hpp": "version.hpp.j2",
        }
        for out, tpl in spec.items():
            files[f"{inc}/{out}"] = env.get_template(f"cpp/include/{tpl}").render(ctx)
        session = session_context(P)
        files[f"{inc}/session_facts.hpp"] = env.get_template("cpp/include/session_facts.hpp.j2").render(ctx, **session)
        files[f"{inc}/commands.hpp"] = env.get_template("cpp/include/commands.hpp.j2").render(ctx, **session)
        for s in sets:
            files[f"{inc}/fields/{s['file']}.hpp"] = env.get_template("cpp/include/fields.hpp.j2").render(ctx, set=s)
            files[f"{inc}/fields/{s['file']}_json.hpp"] = env.get_template("cpp/include/fields_json.hpp.j2").render(
                ctx, set=s
            )
        packets = packet_models(P)
        for k in packets:
            files[f"{inc}/packets/{k['file']}.hpp"] = env.get_template("cpp/include/packet_set.hpp.j2").render(ctx, k=k)
        files[f"{inc}/packet_index.hpp"] = env.get_template("cpp/include/packet_index.hpp.j2").render(ctx)
        files[f"{inc}/packets.hpp"] = env.get_template("cpp/include/packets.hpp.j2").render(ctx, packets=packets)
        # The library's sources (src/): the definitions the headers declare, compiled once.
        sources = library_sources(sets, session)
        for rel, (tpl, extra) in sources.items():
            files[f"{root}/{rel}"] = env.get_template(f"cpp/src/{tpl}").render(ctx, **extra)
        ctx["library_sources"] = sorted([*sources, *(f"src/{c}" for c in RUNTIME_SOURCES)])
        files[f"{root}/examples/getting_started.cpp"] = env.get_template("cpp/examples/getting_started.cpp.j2").render(
            ctx
        )
        files[f"{root}/tests/test_vectors.cpp"] = env.get_template("cpp/tests/test_vectors.cpp.j2").render(ctx)
        example = configure_example(P, session)
        if example is not None:
            files[f"{root}/examples/configure_and_stream.cpp"] = env.get_template(
                "cpp/examples/configure_and_stream.cpp.j2"
            ).render(ctx, ex=example)
        files[f"{root}/tests/test_sessions.cpp"] = env.get_template("cpp/tests/test_sessions.cpp.j2").render(
            ctx, session_cases=session_cases(proto, sessions)
        )
        files[f"{root}/tests/test_types.cpp"] = env.get_template("cpp/tests/test_types.cpp.j2").render(ctx)
        files[f"{root}/tests/canonical_cases.hpp"] = env.get_template("cpp/tests/canonical_cases.hpp.j2").render(ctx)
        files[f"{root}/CMakeLists.txt"] = env.get_template("cpp/CMakeLists.txt.j2").render(ctx)
        files[f"{root}/README.md"] = env.get_template("cpp/README.md.j2").render(ctx)
        files.update(cmake_package_files(f"{root}/", ctx, pkg_config(pkg, proto["title"], "cpp")))
    return files


def library_sources(sets: list[dict], session: dict) -> dict[str, tuple[str, dict]]:
    """The generated sources of the library (package-relative path -> template under
    templates/cpp/src/ and its extra context): the out-of-line definitions of the named types'
    and the layouts' wire and JSON codecs, one file per descriptor set, the session facts and the
    typed command API (session: session_context's)."""
    out: dict[str, tuple[str, dict]] = {
        "src/types.cpp": ("types.cpp.j2", {}),
        "src/types_json.cpp": ("types_json.cpp.j2", {}),
        "src/session_facts.cpp": ("session_facts.cpp.j2", session),
        "src/commands.cpp": ("commands.cpp.j2", session),
    }
    for s in sets:
        out[f"src/fields/{s['file']}.cpp"] = ("fields.cpp.j2", {"set": s})
        out[f"src/fields/{s['file']}_json.cpp"] = ("fields_json.cpp.j2", {"set": s})
    return out


# ----------------------------------------------------------------------------- session layer
def session_context(P: _Protocol) -> dict:
    """What session_facts.hpp.j2 (the ack rule, the function names and their device limits, one
    CommandRow per command layout and a CommandTraits<T> per layout struct) and commands.hpp.j2
    (the typed command API) print: the command model of generator/commands.py with C++'s names;
    session_macros.j2 spells the rows and the calls."""
    proto = P.p
    devices = [d["id"] for d in proto["devices"]]
    if len(devices) > 32:
        raise ValueError("the C++ session's device masks hold at most 32 devices")
    cm = commands.commands(proto)
    for f in cm.functions:
        if not 0 <= f.value < 64:
            raise ValueError(f"function selector value {f.value} does not fit the C++ session's masks")
    rule = proto.get("session")
    ack = None
    if rule:
        rf = next(f for f in proto["reserved_fields"] if f["id"] == rule["ack"] and f.get("role") == "ack")
        ack = {
            "descriptor": rule["ack"],
            "ok": rule["ok"],
            "type": f"::{P.ns}::{P.reserved_ns}::{layout_names(proto['reserved_fields'])[(rf['name'], None)]}",
            "echo": ident(rule["echo"]),
            "code": ident(rule["code"]),
        }
    sets = {s["id"]: s for s in proto["sets"]}
    fields = {(s["id"], f["name"]): f for s in proto["sets"] for f in s["fields"]}
    rows = []
    for lay in cm.layouts:
        if len(lay.reads) > 8:
            raise ValueError("the C++ session's CommandFacts hold at most 8 parameter slots (kMaxParamSlots)")
        v = fields[(lay.set, lay.field)]["variants"][lay.variant]
        params = {q["name"]: q for q in v["params"]}
        rows.append(
            {
                "index": len(rows),
                "layout": lay,
                "type": _layout_type(P, sets[lay.set], fields[(lay.set, lay.field)], lay.device),
                "device": devices.index(lay.device) if lay.device else -1,
                "devices": sum(1 << devices.index(d) for d in lay.devices),
                "slot": {q: i for i, q in enumerate(lay.reads)},
                "reads": [{"field": ident(q), "optional": params[q]["optional"]} for q in lay.reads],
            }
        )
    api_sets: list[dict] = []
    calls: dict[commands.Call, dict] = {}
    for g in cm.api_sets():
        s = sets[g.set]
        api_sets.append({"id": g.set, "ns": set_namespace(s), "title": s["title"], "commands": []})
        for cmd in g.commands:
            f = fields[(g.set, cmd.field)]
            ns, cs = ident(f["name"]), [_call(P, cm, s, f, c) for c in cmd.calls]
            api_sets[-1]["commands"].append(
                {"id": cmd.descriptor, "ns": ns, "title": " ".join(f["title"].split()), "calls": cs}
            )
            calls.update({c: {"set": api_sets[-1]["ns"], "command": ns, "call": x} for c, x in zip(cmd.calls, cs)})
    shared = (proto.get("shared_data") or {}).get("set")
    reference_times = []
    for e in (proto.get("time") or {}).get("reference_time", []):
        gps = e["kind"] == "gps"
        reference_times.append(
            {
                "device": ident(e["device"]),
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
        "session_ack": ack,
        "session_functions": [
            {"value": f.value, "name": f.name, "devices": sum(1 << devices.index(d) for d in f.devices)}
            for f in cm.functions
        ],
        "session_rows": rows,
        "api_sets": api_sets,
        "calls": calls,
    }


def _cpp_fn(fn: str | None) -> str:
    return "call" if fn is None else ident(fn)


def call_name(c: commands.Call) -> str:
    """The function of a typed command call: its function (`call` without one), `_<device>` for a
    call per device, escaped as a whole (`default_`, but `default_gx5_45`, never `default__gx5_45`,
    which C++ reserves: issue 37)."""
    return ident(("call" if c.function is None else c.function) + (f"_{c.device}" if c.device is not None else ""))


def _layout_type(P: _Protocol, s: dict, f: dict, device: str | None) -> str:
    """The struct of field f's layout for device (None: its only layout)."""
    multi = model.per_device(f)
    return f"::{P.ns}::{set_namespace(s)}::{layout_names(s['fields'])[(f['name'], device if multi else None)]}"


def _call(P: _Protocol, cm: commands.Commands, s: dict, f: dict, c: commands.Call) -> dict:
    """One function of the typed API: its name, arguments (typed after the first layout's members),
    the members each layout sets (the other devices' layouts first, each when its device is
    selected; the first layout last, for any other device or none) and the reply struct."""
    name = call_name(c)
    first = _layout_type(P, s, f, model.layout_device(f, f["variants"][c.variants[0]]))
    args = [{"name": ident(a.name), "required": a.required, "optional": a.optional} for a in c.arguments]
    sent = {a.name for a in c.arguments}
    layouts = []
    for i in c.variants:
        v = f["variants"][i]
        params = {q["name"]: q for q in v["params"]}
        layouts.append(
            {
                "type": _layout_type(P, s, f, model.layout_device(f, v)),
                "device": ident(v["device"]) if v["device"] else None,
                "members": [ident(q["name"]) for q in v["params"] if q["name"] in sent],
                "counts": [
                    {"field": ident(k.param), "array": ident(k.array), "optional": params[k.array]["optional"]}
                    for k in c.counts
                ],
            }
        )
    reply = None
    if c.reply_kind == commands.FIELD and not c.reply.per_device:
        reply = _layout_type(P, s, next(x for x in s["fields"] if x["id"] == c.reply.descriptor), None)
    return {
        "name": name,
        "function": ident(c.function) if c.function is not None else None,
        "function_enum": cm.function_enum,
        "first": first,
        "args": args,
        "reply": reply,
        "layouts": layouts[1:] + [{**layouts[0], "device": None}],
    }


def session_cases(proto: dict, sessions: list[dict]) -> list[dict]:
    """The corpus cases of one protocol as C++ literals (test_sessions.cpp.j2)."""
    out = []
    for c in sessions:
        if c["protocol"] != proto["name"]:
            continue
        out.append(
            {
                "name": re.sub(r"[^A-Za-z0-9]", "_", c["name"]),
                "source": c["name"],
                "file": c["file"],
                "device": cpp_string(c["device"]) if c["device"] else "nullptr",
                "timeout_ms": c["timeout_ms"],
                "inter_packet_timeout_ms": c["inter_packet_timeout_ms"],
                "steps": session_steps(c, cpp_string),
                "expect": [cpp_string(line) for line in c["expect"]],
            }
        )
    return out


def configure_example(P: _Protocol, session: dict) -> dict | None:
    """The configure-and-stream example (generator/examples.py session_example): per step the call
    of the typed command API (commands.hpp) with its arguments as values session_macros.j2 spells
    (and the bounded vectors they fill), the data-field structs it prints as canonical JSON; None
    for a protocol without the example."""
    ex = examples.session_example(P.p)
    if ex is None:
        return None
    types = {t["name"]: t for t in P.p["types"]}

    def literal(tref: dict, value) -> dict:
        return examples.example_literal(
            types, tref, value, "C++", lambda k, n: camel(n) if k == "type" else ident(n), "f"
        )

    def call(step: str, fn: str | None) -> dict:
        """The call, its arguments and the vectors it fills first."""
        st = ex[step]
        at = session["calls"][st["calls"][fn]]
        args, fills = [], []
        for a, q, value in examples.example_arguments(P.p, ex, step, fn, "C++"):
            if value is None:
                continue  # optional arguments come last: left at their default
            tref = q.ir["type"]
            if q.kind == "fixed":
                args.append({"kind": "array", "elems": [literal(tref, v) for v in value]})
            elif q.kind in ("counted", "remaining"):
                fills.append(
                    {
                        "name": ident(a.name),
                        "required": a.required,
                        "optional": a.optional,
                        "elems": [literal(tref, v) for v in value],
                    }
                )
                args.append({"kind": "local", "name": ident(a.name)})
            else:
                args.append(literal(tref, value))
        what = f"{st['set']['name']}.{st['field']['name']}" + (f" {fn}" if fn else "")
        return {**at, "args": args, "fills": fills, "what": what}

    data_set = ex["data"]["set"]
    fields = []
    for f in ex["data"]["fields"]:
        if model.per_device(f):
            raise ExampleError(f"C++ back end: the example's data field {f['name']} has per-device layouts")
        fields.append({"name": f["name"], "type": _layout_type(P, data_set, f, None)})
    return {
        **examples.session_example_context(ex, call),
        "device": ident(ex["device"]),
        "data_fields": fields,
    }


def public_name(protocol: dict, kind: str, *path) -> str:
    """The C++ name of a set (`kind` "set") or enum value (kind "value": enum type, value), for
    `mipgen diff` (generator/wirediff.py public_names, which names fields and members itself)."""
    if kind == "set":
        return f"{protocol['package']}::{set_namespace(path[0])}"
    return f"{protocol['package']}::{path[0]['name']}::{ident(path[1]['name'])}"
