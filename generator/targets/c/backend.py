"""C back end: one C99 library per protocol at generated/c/<package>/ (see docs/design.md).

All naming and type mapping happens here; the templates in templates/c/ only loop and print.
The runtime (parser, checksum, JSON) is plain C in generator/targets/c/runtime/, copied into each
package with its symbol prefix; its only protocol input is the generated include/<pkg>/protocol.h.
"""

from __future__ import annotations

import re

from generator import commands, diagnostics, model, packet_plan
from generator.clock_model import clock_model
from generator.cmake import cmake_package_files, pkg_config
from generator.device_tables import device_tables
from generator.examples import (
    ExampleError,
    device_variant,
    example_context,
    example_literal,
    session_example,
    session_example_context,
)
from generator.linkfacts import link_facts
from generator.naming import snake
from generator.primitives import PRIMITIVES
from generator.release import Release, load_release
from generator.render import GENERATED_BANNER, copy_runtime, environment
from generator.targets.cfamily import c_string, session_steps
from generator.testcases import VectorCase, bitfield_cases, canonical_literals, vector_cases

from .facts import KEYWORDS as _KEYWORDS
from .facts import PRIMITIVE_TYPES as _PRIM
from .facts import RESERVED as _RESERVED

OUTPUT_DIRS = ["c"]

# The runtime: plain C in generator/targets/c/runtime/, written with the neutral prefix codec_/CODEC_,
# package name codec and include directory codec/ (so that it compiles and is tested in place)
# -> generated file, where "codec/" becomes the package's include directory.
# The copies carry the generated banner (render.add_banner), but for the vendored grisu3.h.
_RUNTIME_VENDORED = frozenset({"src/grisu3.h"})
_RUNTIME_FILES = {
    "include/codec/status.h": "include/codec/status.h",
    "src/status.c": "src/status.c",
    "include/codec/framing.h": "include/codec/framing.h",
    "src/framing.c": "src/framing.c",
    "src/checksum_impl.h": "src/checksum_impl.h",
    "include/codec/parser.h": "include/codec/parser.h",
    "src/parser.c": "src/parser.c",
    "include/codec/field_iter.h": "include/codec/field_iter.h",
    "src/field_iter.c": "src/field_iter.c",
    "include/codec/samples.h": "include/codec/samples.h",
    "src/samples.c": "src/samples.c",
    "include/codec/clock.h": "include/codec/clock.h",
    "src/clock.c": "src/clock.c",
    "src/wire.h": "src/wire.h",
    "src/wire.c": "src/wire.c",
    "src/grisu3.h": "src/grisu3.h",
    "src/json_writer.h": "src/json_writer.h",
    "src/json_writer.c": "src/json_writer.c",
    "src/json_reader.h": "src/json_reader.h",
    "src/json_reader.c": "src/json_reader.c",
    "src/hex.h": "src/hex.h",
    "include/codec/json.h": "include/codec/json.h",
    "src/json_codec.c": "src/json_codec.c",
    "include/codec/session.h": "include/codec/session.h",
    "src/session.c": "src/session.c",
    "include/codec/link.h": "include/codec/link.h",
    "src/link.c": "src/link.c",
    "include/codec/posix_transport.h": "include/codec/posix_transport.h",
    "src/address.h": "src/address.h",
    "src/posix_transport.c": "src/posix_transport.c",
    "include/codec/win32_transport.h": "include/codec/win32_transport.h",
    "src/win32_transport.c": "src/win32_transport.c",
    "include/codec/native_transport.h": "include/codec/native_transport.h",
    "tools/session.c": "tools/session.c",
    "tools/decode.c": "tools/decode.c",
    "tools/encode.c": "tools/encode.c",
    "tools/tool_io.h": "tools/tool_io.h",
    "tools/device/device.h": "tools/device/device.h",
    "tools/device/text.c": "tools/device/text.c",
    "tools/device/values.c": "tools/device/values.c",
    "tools/device/yaml.c": "tools/device/yaml.c",
    "tools/device/connect.c": "tools/device/connect.c",
    "tools/device/settings.c": "tools/device/settings.c",
    "tools/device/budget.c": "tools/device/budget.c",
    "tools/device/requests.c": "tools/device/requests.c",
    "tools/device/plan.c": "tools/device/plan.c",
    "tools/device/stream.c": "tools/device/stream.c",
    "tools/device/record.c": "tools/device/record.c",
    "tools/device/timesync.c": "tools/device/timesync.c",
    "tools/device/main.c": "tools/device/main.c",
    "tests/package/test_support.hpp": "tests/test_support.hpp",
    "tests/package/runtime_test.cpp": "tests/runtime_test.cpp",
    "tests/package/canonical_test.cpp": "tests/canonical_test.cpp",
    "tests/package/session_test.cpp": "tests/session_test.cpp",
}

# Template -> generated file (relative to the package directory): what varies with the spec.
_TEMPLATES = {
    "protocol.h.j2": "include/{pkg}/protocol.h",
    "types.h.j2": "include/{pkg}/types.h",
    "types_internal.h.j2": "src/types_internal.h",
    "dispatch.h.j2": "include/{pkg}/dispatch.h",
    "dispatch.c.j2": "src/dispatch.c",
    "dispatch_json.c.j2": "src/dispatch_json.c",
    "layouts_internal.h.j2": "src/layouts_internal.h",
    "umbrella.h.j2": "include/{pkg}/{pkg}.h",
    "version.h.j2": "include/{pkg}/version.h",
    "CMakeLists.txt.j2": "CMakeLists.txt",
    "README.md.j2": "README.md",
    "examples/getting_started.c.j2": "examples/getting_started.c",
    "tests/vectors_test.cpp.j2": "tests/vectors_test.cpp",
    "tests/canonical_cases.hpp.j2": "tests/canonical_cases.hpp",
    "tests/bitfields_test.cpp.j2": "tests/bitfields_test.cpp",
    "session_facts.c.j2": "src/session_facts.c",
    "commands.h.j2": "include/{pkg}/commands.h",
    "commands.c.j2": "src/commands.c",
    "tests/session_cases.hpp.j2": "tests/session_cases.hpp",
}


def _fast_loads(fast: packet_plan.FastLayout | None) -> dict | None:
    """The C names of a layout's constant-offset decode (generator/packet_plan.py decides it):
    its size and one load per value (member, array index, the runtime's load suffix, offset)."""
    if fast is None:
        return None
    return {
        "size": fast.size,
        "loads": [
            {"c": member(x.param), "index": x.index, "ld": _PRIM[x.primitive][1], "off": x.off} for x in fast.loads
        ],
    }


# A spec the C back end cannot express: a spec error located at the element it names (pipeline.py).
BackendError = diagnostics.BackendError


# ---------------------------------------------------------------------------- naming helpers
def member(name: str) -> str:
    """A spec identifier as a C struct member (keywords and the library's and compilers' macros,
    facts.py, get a trailing underscore)."""
    return name + "_" if name in _KEYWORDS or name in _RESERVED else name


def c_prefix(package: str) -> str:
    """The C symbol prefix of a package (without the trailing underscore; its upper case is the
    macro prefix): the package name without a trailing "codec", plus "c" (mipcodec -> mipc_/MIPC_,
    mscipcodec -> mscipc_/MSCIPC_). The vendor SDKs name their C API after the protocol (mip_,
    MIP_), so a prefix that is not the protocol's name lets both be linked into one program; the
    runtime is written with the neutral codec_/CODEC_ that this replaces (runtime_replacements)."""
    base = package[: -len("codec")] if package.endswith("codec") and package != "codec" else package
    return re.sub(r"[^a-z0-9_]", "_", base.lower()) + "c"


def prefix_of(protocol: dict) -> str:
    return c_prefix(protocol["package"])


def _int_literal(value: int, ctype: str, base: str) -> str:
    bits = PRIMITIVES[base][0] * 8
    signed = PRIMITIVES[base][2]
    if bits == 64:
        if signed and value == -(1 << 63):
            lit = "(-INT64_C(9223372036854775807) - 1)"
        elif signed:
            lit = f"INT64_C({value})"
        else:
            lit = f"UINT64_C({value})"
    elif value < 0:
        lit = f"({value})"
    else:
        lit = f"{value}" + ("u" if not signed else "")
    return f"(({ctype}){lit})"


def _mask_literal(mask: int, ctype: str, base: str) -> str:
    if PRIMITIVES[base][0] == 8:
        return f"(({ctype})UINT64_C(0x{mask:X}))"
    return f"(({ctype})0x{mask:X}u)"


def _comment(text: str | None) -> str:
    """Text safe to put inside a /* */ comment, on one line."""
    return " ".join((text or "").replace("*/", "* /").split())


# ---------------------------------------------------------------------------- the package model
class _Protocol:
    """Everything the templates print for one protocol."""

    def __init__(self, proto: dict, vectors: list[dict]):
        self.proto = proto
        self.p = prefix_of(proto)
        self.P = self.p.upper()
        self.pkg = proto["package"]
        self.framing = proto["framing"]
        self.types = {t["name"]: t for t in proto["types"]}
        self.globals: dict[str, str] = {}  # C identifier -> what it names (collision check)
        self._check_framing()
        self.type_views = [self._type_view(t) for t in model.type_order(proto)]
        caps = {c["device"]: c for c in proto.get("capabilities", {}).get("devices", [])}
        self.devices = [
            {
                "id": d["id"],
                "c": f"{self.P}_DEVICE_{d['id'].upper()}",
                "title": d.get("title", d["id"]),
                "manual": d.get("manual", ""),
                # the capabilities table: (set << 8) | descriptor, ascending
                "commands": [f"0x{s:02X}{x:02X}" for s, x in caps.get(d["id"], {}).get("commands", [])],
                "data": [f"0x{s:02X}{x:02X}" for s, x in caps.get(d["id"], {}).get("data", [])],
            }
            for d in proto["devices"]
        ]
        self.link = link_facts(proto)
        for d, facts_of in zip(self.devices, self.link["devices"]):
            d["baud_rates"] = [f"{r}u" for r in facts_of["rates"]]
            d["default_baud"] = facts_of["default"] or 0
        self.layouts: list[dict] = []
        self.fields: list[dict] = []
        self.reserved = [self._field_view(None, r) for r in proto["reserved_fields"]]
        self.sets = [self._set_view(s) for s in proto["sets"]]
        self.commands = commands.commands(proto)
        self.set_kinds = [
            {"name": k, "c": f"{self.P}_SET_KIND_{k.upper()}", "first": r["first"], "last": r["last"]}
            for k, r in proto["set_kinds"].items()
        ]
        shared = proto.get("shared_data")
        self.shared_set = shared["set"] if shared and any(s["id"] == shared["set"] for s in proto["sets"]) else None
        self.data_kind = next((k for k in self.set_kinds if k["name"] == "data"), None)
        self._add_lookup_tables()
        self._add_packet_decoders()
        self._add_layout_cache()
        # Path elements are names; an index rides on its array's element (IR value_paths).
        self.path_depth = proto["value_paths"]["names"]
        longest = max([len(n) for n in self._all_param_names()] + [8])
        self.error_message_max = self.path_depth * (longest + 24) + 160
        self.vectors = [self._vector_view(c) for c in vector_cases(vectors, proto)]

    # -------------------------------------------------------------- checks
    def _claim(self, ident: str, what: str, where: tuple[str, ...] = ()) -> str:
        """ident for what, unless another spec element already has it; where locates what."""
        if ident in self.globals and self.globals[ident] != what:
            raise BackendError(
                f"C back end: the name {ident} would be used for both {self.globals[ident]} and {what}",
                self.proto["name"],
                where,
            )
        self.globals[ident] = what
        return ident

    def _check_framing(self) -> None:
        f = self.framing
        ck = f["checksum"]
        if ck.get("algorithm") != "fletcher16" or ck.get("covers") != "header_and_payload":
            raise BackendError(f"C back end: checksum {ck} is not supported (fletcher16 over header_and_payload)")
        if sorted(ck["order"]) != ["sum1", "sum2"]:
            raise BackendError(f"C back end: checksum order {ck['order']} is not a permutation of sum1, sum2")
        if f["header_size"] != len(f["sync"]) + 2 or f["field_header_size"] != 2:
            raise BackendError(
                "C back end: expected a two-byte packet header after the sync bytes and a two-byte field header"
            )

    # -------------------------------------------------------------- types
    def type_c(self, name: str) -> str:
        return f"{self.p}_{snake(name)}_t"

    def type_fn(self, name: str) -> str:
        return f"{self.p}_{snake(name)}"

    def type_macro(self, name: str) -> str:
        return f"{self.P}_{snake(name).upper()}"

    def _type_view(self, t: dict) -> dict:
        kind = t["kind"]
        view = {
            "kind": kind,
            "name": t["name"],
            "c": self._claim(self.type_c(t["name"]), f"type {t['name']}", (t["name"],)),
            "fn": self.type_fn(t["name"]),
            "doc": _comment(t.get("title")),
            "description": _comment(t.get("description")),
        }
        if kind in ("enum", "bitfield"):
            ctype = view["c"]
            view["base"] = _PRIM[t["base"]][0]
            macro = self.type_macro(t["name"])
            if kind == "enum":
                view["values"] = [
                    {
                        "macro": self._claim(
                            f"{macro}_{v['name'].upper()}", f"value {v['name']} of {t['name']}", (t["name"], v["name"])
                        ),
                        "literal": _int_literal(v["value"], ctype, t["base"]),
                        "doc": _comment(v.get("description"))
                        + (f" (devices: {', '.join(v['devices'])})" if v.get("devices") else ""),
                    }
                    for v in t["values"]
                ]
            else:
                view["members"] = [
                    {
                        "mask": self._claim(f"{macro}_{m['name'].upper()}_MASK", f"member {m['name']} of {t['name']}"),
                        "shift": self._claim(
                            f"{macro}_{m['name'].upper()}_SHIFT", f"member {m['name']} of {t['name']}"
                        ),
                        "mask_literal": _mask_literal(m["mask"], ctype, t["base"]),
                        "first_bit": m["first_bit"],
                        "width": m["width"],
                        "doc": (
                            f"bits {m['first_bit']}-{m['last_bit']}: " if m["width"] > 1 else f"bit {m['first_bit']}: "
                        )
                        + ("(reserved) " if m["reserved"] else "")
                        + _comment(m.get("description"))
                        + (f" (devices: {', '.join(m['devices'])})" if m.get("devices") else ""),
                    }
                    for m in t["members"]
                ]
        elif kind == "struct":
            view.update(self._params_view(t["params"], functions=None, owner=t["name"]))
        else:
            sel = self.types[t["selector_enum"]]
            view["sel_c"] = self.type_c(sel["name"])
            view["sel_signed"] = PRIMITIVES[sel["base"]][2]
            values = {v["name"]: v for v in sel["values"]}
            sel_macro = self.type_macro(sel["name"])
            view["members"] = []
            names = set()
            seen_values = set()
            for m in t["members"]:
                if m["value"] in seen_values:
                    continue  # per-device enum values sharing a number: one switch case (the first)
                seen_values.add(m["value"])
                c = member(m["when"])
                if c in names or c == "none_":
                    raise BackendError(f"C back end: union {t['name']} has two members named {c}")
                names.add(c)
                view["members"].append(
                    {
                        "when": m["when"],
                        "c": c,
                        "case": f"{sel_macro}_{m['when'].upper()}" if m["when"] in values else str(m["value"]),
                        "st": {"c": self.type_c(m["type"]), "fn": self.type_fn(m["type"])} if m["type"] else None,
                        "doc": _comment(m.get("description")),
                    }
                )
        return view

    # -------------------------------------------------------------- parameters
    def _elem(self, e: model.Elem) -> dict:
        """The C type of one value and the functions that read/write/print/parse it."""
        if e.kind in ("primitive", "enum", "bitfield"):
            suffix = _PRIM[e.primitive][1]
            ops = f"{self.p}_%s_{suffix}"
            return {
                "ctype": _PRIM[e.name][0] if e.kind == "primitive" else self.type_c(e.name),
                "rd": ops % "rd",
                "wr": ops % "wr",
                "jw": ops % "jw",
                "jr": ops % "jr",
                "size": e.size.min,
                "ld": suffix,
            }
        if e.kind in ("struct", "union"):
            fn = self.type_fn(e.name)
            return {
                "ctype": self.type_c(e.name),
                "rd": f"{fn}_read",
                "wr": f"{fn}_write",
                "jw": f"{fn}_to_json",
                "jr": f"{fn}_from_json",
                "size": e.size.min if e.size.fixed and e.size.min > 0 else None,
            }
        if e.kind == "string":
            return {"ctype": "char", "size": e.length}
        raise BackendError(f"C back end: unsupported type kind {e.kind}")

    def _param_view(self, q: model.Param) -> dict:
        """Names and C types of one parameter of the layout model; layout_code.j2 writes the C."""
        if q.function:
            doc = "function selector (" + ", ".join(q.functions) + ")"
        else:
            doc = _comment(q.description) + (f" [{q.units}]" if q.units else "")
        view = {
            "name": q.name,
            "c": member(q.name),
            "kind": q.kind,
            "optional": q.optional,
            "has": f"has_{q.name}" if q.optional else None,
            "e": self._elem(q.elem),
            "doc": doc,
            "n": q.elem.length if q.kind == model.STRING else q.count,
            "max": q.max_count,
            "count_check": q.count_check,
        }
        if q.kind == model.UNION:
            view["sel_c"] = member(q.selector)
        elif q.kind == model.COUNTED:
            view["count_c"] = member(q.count_param)
        elif q.kind == model.REMAINING:
            view["count_c"] = f"{q.name}_count"
        return view

    def _params_view(self, params: list[dict], functions: list[str] | None, owner: str) -> dict:
        plist = model.params(self.proto, params, functions)
        views = [self._param_view(q) for q in plist]
        # The struct members (layout_code.j2 `members`): a presence flag before each optional
        # parameter, an element count before each array that runs to the end of the data.
        names = []
        for v in views:
            names += [v["has"]] if v["optional"] else []
            names += [v["count_c"]] if v["kind"] == model.REMAINING else []
            names.append(v["c"])
        dup = {n for n in names if names.count(n) > 1}
        if dup:
            raise BackendError(f"C back end: {owner} would have two members named {', '.join(sorted(dup))}")
        return {
            "params": views,
            "needs_i": any(v["kind"] in ("fixed", "counted", "remaining") for v in views),
            "needs_n": any(v["kind"] == "remaining" and v["e"]["size"] for v in views),
            "has_optional": any(v["optional"] for v in views),
            "fast": _fast_loads(packet_plan.fast_layout(plist)),
        }

    # -------------------------------------------------------------- fields and layouts
    def _field_view(self, set_: dict | None, f: dict) -> dict:
        base = f"{self.p}_{set_['name']}_{f['name']}" if set_ else f"{self.p}_{f['name']}"
        multi = model.per_device(f)
        what = f"field {set_['name']}.{f['name']}" if set_ else f"reserved field {f['name']}"
        where = (set_["name"], f["name"]) if set_ else (f["name"],)
        fv = {
            "name": f["name"],
            "descriptor": f["id"],
            "macro": self._claim(f"{base.upper()}_DESCRIPTOR", what, where),
            "first": len(self.layouts),
            "count": len(f["variants"]),
            "has_variants": multi,
            "index": len(self.fields),
            "set": set_["id"] if set_ else None,
            "doc": _comment(f.get("title")),
            "role": f["role"],
            "applies_to": f.get("applies_to"),
        }
        layouts = []
        for v in f["variants"]:
            lbase = base + (f"_{v['device']}" if v["device"] else "")
            lv = {
                "c": self._claim(f"{lbase}_t", what, where),
                "fn": lbase,
                "id": self._claim(f"{self.P}_FIELD_{lbase[len(self.p) + 1 :].upper()}", what, where),
                "member": lbase[len(self.p) + 1 :],
                "name": f["name"],
                "device": v["device"] if multi else None,
                "device_c": f"{self.P}_DEVICE_{v['device'].upper()}" if v["device"] else f"{self.P}_DEVICE_ANY",
                "descriptor": f["id"],
                "field_index": fv["index"],
                "max_size": v["size"]["max"],
                "doc": _comment(f.get("title")) + (f" ({v['device']})" if v["device"] else ""),
                "description": _comment(f.get("description")),
                "role": f["role"],
            }
            for suffix in ("encode", "decode"):
                self._claim(f"{lbase}_{suffix}", what, where)
            lv.update(
                self._params_view(v["params"], v["functions"], f"{what} ({v['device']})" if v["device"] else what)
            )
            self.layouts.append(lv)
            layouts.append(lv)
        fv["layouts"] = layouts
        self.fields.append(fv)
        return fv

    def _set_view(self, s: dict) -> dict:
        name = s["name"]
        return {
            "name": name,
            "id": s["id"],
            "kind": s["kind"],
            "doc": _comment(s.get("title")),
            "macro": self._claim(f"{self.P}_{name.upper()}_SET", f"set {name}"),
            "header": f"{self.pkg}/sets/{name}.h",
            "guard": f"{self.P}_SETS_{name.upper()}_H",
            "fields": [self._field_view(s, f) for f in s["fields"]],
        }

    def _add_lookup_tables(self) -> None:
        """Each set view's `lookup`: its descriptor -> field table in the C dispatch, as the IR's
        `lookup` resolves it (the set's fields, reserved fields of its kind, shared data fields),
        so that a reserved or shared field (an ack/nack, a timestamp in every packet) is one table
        lookup like any other. `source` says which of the three an entry is."""
        views = {(s["id"], f["descriptor"]): f for s in self.sets for f in s["fields"]}
        views.update({(("reserved", r["applies_to"]), r["descriptor"]): r for r in self.reserved})
        tables = {t["set"]: t["fields"] for t in self.proto["lookup"]["sets"]}
        for s in self.sets:
            lookup = []
            for e in tables[s["id"]]:
                key = (("reserved", s["kind"]) if e["source"] == "reserved" else e["set"], e["descriptor"])
                lookup.append(dict(views[key], source=e["source"]))
            s["lookup"] = lookup

    def _add_packet_decoders(self) -> None:
        """Each data set view's `packet`: its straight-line packet decoder (set.h.j2, set.c.j2;
        issue 38), None for the other sets: the members and fast loads of generator/packet_plan.py
        in C names. `includes`: the headers of the members' types other than the set's own."""
        headers = {s["id"]: s["header"] for s in self.sets}
        fields = {(s["id"], f["descriptor"]): f for s in self.sets for f in s["fields"]}
        reserved = {(r["applies_to"], r["descriptor"]): r for r in self.reserved}
        plans = packet_plan.packet_plans(self.proto)
        # dispatch.h: the union of every set's packet struct and the decoder that picks by set
        self._claim(f"{self.p}_packet_t", "the packet of any data set")
        self._claim(f"{self.p}_decode_packet", "the straight-line decoder of any data set")
        for s in self.sets:
            plan = plans[s["id"]]
            if plan is None:
                s["packet"] = None
                continue
            what = f"set {s['name']}"
            members = []
            includes = set()
            for m in plan.members:
                if m.field_set is None:
                    f, header = reserved[(s["kind"], m.descriptor)], f"{self.pkg}/reserved.h"
                else:
                    f, header = fields[(m.field_set, m.descriptor)], headers[m.field_set]
                if header != s["header"]:
                    includes.add(header)
                layout = f["layouts"][0]
                fast = _fast_loads(m.fast)
                members.append(
                    {
                        "descriptor": m.descriptor,
                        "member": layout["member"],
                        "c": layout["c"],
                        "fn": layout["fn"],
                        "size": fast["size"] if fast else None,
                        "loads": fast["loads"] if fast else [],
                        "bools": list(m.fast.bools) if m.fast else [],
                        "source": m.source,
                    }
                )
            s["packet"] = {
                "c": self._claim(f"{self.p}_{s['name']}_packet_t", what, (s["name"],)),
                "fn": self._claim(f"{self.p}_{s['name']}_decode_packet", what, (s["name"],)),
                "members": members,
                "includes": sorted(includes),
            }

    def _add_layout_cache(self) -> None:
        """The layout cache (issue 38; the cache itself is the runtime's, field_iter.h): each data
        set's `packet.shape_members`, the table of its packet struct's members (descriptor, offset,
        loader: set.c.j2) that a cached shape decodes with, and the set-dispatching
        <p>_decode_packet_cached (dispatch.c.j2)."""
        self._claim(f"{self.p}_decode_packet_cached", "the layout-cached decoder of any data set")
        for s in self.sets:
            if s["packet"] is not None:
                s["packet"]["shape_members"] = self._claim(
                    f"{self.p}_{s['name']}_layout_members_", f"set {s['name']}", (s["name"],)
                )

    def _all_ir_layouts(self):
        for r in self.proto["reserved_fields"]:
            yield from r["variants"]
        for s in self.proto["sets"]:
            for f in s["fields"]:
                yield from f["variants"]

    def _all_param_names(self):
        yield "function"
        for v in self._all_ir_layouts():
            for q in v["params"]:
                yield q["name"]
        for t in self.types.values():
            for q in t.get("params", []):
                yield q["name"]

    # -------------------------------------------------------------- vectors (cases from generator/testcases.py)
    def _vector_view(self, case: VectorCase) -> dict:
        dev = case.device
        return {
            "name": re.sub(r"[^A-Za-z0-9_]", "_", case.name),
            "suite": case.corpus.capitalize(),
            "hex": case.hex,
            "device_c": f"{self.P}_DEVICE_{dev.upper()}" if dev else f"{self.P}_DEVICE_ANY",
            "expect": c_string("".join(line + "\n" for line in case.expect)),
            "rejected": case.rejected,
        }

    def bitfield_cases(self) -> list[dict]:
        """The bitfield members of generator/testcases.py with their C mask and shift macros."""
        views = {v["name"]: v for v in self.type_views}
        out = []
        for b in bitfield_cases(self.proto):
            view = views[b.name]
            members = [
                {
                    "mask": mv["mask"],
                    "shift": mv["shift"],
                    "first_bit": m.first_bit,
                    "mask_value": f"UINT64_C(0x{m.mask:X})",
                    "max": f"UINT64_C(0x{m.max:X})",
                }
                for m, mv in zip(b.members, view["members"])
            ]
            out.append({"name": b.name, "c": view["c"], "members": members})
        return out

    # -------------------------------------------------------------- render
    def example(self) -> dict:
        """The getting-started example (generator/examples.py) with the C name of its set."""
        example = example_context(self.proto, api_names)
        example["set_macro"] = next(s["macro"] for s in self.sets if s["id"] == example["set"]["id"])
        return example

    # -------------------------------------------------------------- session (docs/conformance.md section 8)
    def _layout_view(self, set_id: int, field: str, variant: int) -> dict:
        """The C layout view of a field's layout (by index in its variants)."""
        sv = next(x for x in self.sets if x["id"] == set_id)
        return next(x for x in sv["fields"] if x["name"] == field)["layouts"][variant]

    def session_context(self) -> dict:
        """The ack rule and the facts of every command layout (generator/commands.py) that
        session_facts.c.j2 prints with C's names: per layout its struct, id and member, the device
        masks, and how the facts code reads the parameters its conditions name."""
        cm = self.commands
        dev_bit = {d["id"]: i + 1 for i, d in enumerate(self.proto["devices"])}

        def mask(devices) -> str:
            return f"0x{sum(1 << dev_bit[d] for d in devices):X}u"

        rows = []
        for lay in cm.layouts:
            lv = self._layout_view(lay.set, lay.field, lay.variant)
            views = {q["name"]: q for q in lv["params"]}
            rows.append(
                {
                    "layout": lay,
                    "view": lv,
                    "field_devices": mask(lay.field_devices),
                    "layout_device": lv["device_c"] if lv["device"] else f"{self.P}_DEVICE_ANY",
                    "param": {q: {"c": views[q]["c"], "has": views[q]["has"]} for q in lay.reads},
                    "uses_c": lay.functions is not None or bool(lay.reads),
                }
            )
        rule = self.proto["session"]
        ack_layout = None
        if rule:
            r = next(r for r in self.reserved if r["descriptor"] == rule["ack"] and r["role"] == "ack")
            ack_layout = r["layouts"][0]
        return {
            "rule": rule,
            "ack_layout": ack_layout,
            "max_expect": max([len(x.replies) for x in cm.layouts] + [1]),
            "command_rows": rows,
            "functions": [
                {"value": f.value, "name": f.name, "mask": mask(f.devices) if f.devices else None} for f in cm.functions
            ],
            "all_devices": mask([d["id"] for d in self.proto["devices"]]),
            "reference_times": self._reference_times(),
        }

    def _reference_times(self) -> list[dict]:
        """The spec's time.reference_time as the rows of codec_reference_times (session_facts.c.j2)."""
        shared = (self.proto.get("shared_data") or {}).get("set")
        rows = []
        for e in (self.proto.get("time") or {}).get("reference_time", []):
            gps = e["kind"] == "gps"
            rows.append(
                {
                    "device": f"{self.P}_DEVICE_{e['device'].upper()}",
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
        return rows

    def command_api(self) -> list[dict]:
        """The typed command API (commands.h.j2, commands.c.j2): one C function per call of
        generator/commands.py (the plain command name without a function selector, suffix
        _<device> for a call split per device), its arguments in layout order, the layouts it
        fills (the link's device picks one) and the reply it decodes."""
        fs = self.proto.get("function_selector") or {}
        fmacro = self.type_macro(fs["enum"]) if fs.get("enum") else None
        out = []
        for c in self.commands.calls:
            name = f"{self.p}_{c.set_name}_{c.field}" + (f"_{c.function}" if c.function else "")
            if c.device is not None:
                name += f"_{c.device}"
            self._claim(name, f"command function {name}")
            layouts = [self._layout_view(c.set, c.field, i) for i in c.variants]
            out.append(
                {
                    "name": name,
                    "call": c,
                    "title": _comment(
                        next(
                            f
                            for s in self.proto["sets"]
                            if s["id"] == c.set
                            for f in s["fields"]
                            if f["name"] == c.field
                        ).get("title")
                    ),
                    "fn": c.function,
                    "fn_macro": f"{fmacro}_{c.function.upper()}" if c.function else None,
                    "args": self._api_args(layouts[0], c),
                    "layouts": [{**lv, "args": self._api_args(lv, c)} for lv in layouts],
                    "choose": len(layouts) > 1,
                    "reply": self._api_reply(c),
                }
            )
        return out

    def _api_args(self, lv: dict, c) -> list[dict]:
        """The arguments of one typed command function, in layout order: the parameters sent for
        the call's function (the function selector and the counts of counted arrays are set by
        the function); commands.h.j2 `decl` writes their C declarations."""
        views = {q["name"]: q for q in lv["params"]}
        sent = {a.name for a in c.arguments}
        args = []
        for q in lv["params"]:
            if q["name"] not in sent:
                continue
            a = {"name": q["name"], "c": q["c"], "arg": q["c"] + "_" if q["c"] in ("link", "reply") else q["c"]}
            a.update(has=q["has"], kind=q["kind"], ctype=q["e"]["ctype"], n=q["n"])
            if q["kind"] == model.UNION or q["kind"] == model.SCALAR and "ld" not in q["e"]:  # struct, union
                a["how"] = "struct"
            elif q["kind"] == model.SCALAR:
                a["how"] = "value"
            elif q["kind"] in (model.FIXED, model.STRING):
                a["how"] = "array"
            else:
                a["how"] = q["kind"]
                a.update(count_arg=f"{q['name']}_count", max=q["max"], count_c=q["count_c"])
                if q["kind"] == model.COUNTED:
                    k = next(k for k in c.counts if k.array == q["name"])
                    a["count_ctype"] = views[k.param]["e"]["ctype"]
                    a["count_has"] = views[k.param]["has"]  # an optional count is present when sent
            args.append(a)
        return args

    def _api_reply(self, c) -> dict | None:
        """The reply a typed command function returns: one layout of the command's set (its
        struct), any field (a field value), or None."""
        if c.reply_kind == "none":
            return None
        if c.reply_kind == "any" or c.reply.per_device:
            return {"value": True, "ctype": f"{self.p}_field_value_t"}
        lv = self._layout_view(c.set, c.reply.name, 0)
        return {"value": False, "ctype": lv["c"], "fn": lv["fn"], "descriptor": f"0x{c.reply.descriptor:02X}"}

    def stream_example(self) -> dict | None:
        """The configure-and-stream example (generator/examples.py session_example) as C: for
        each step the typed command function (commands.h) with its arguments as C literals (and
        the constant arrays or structs they point to), the printf format and arguments of the
        replies and data fields it prints, and the handlers of the data fields. None when the
        protocol has no such example."""
        ex = session_example(self.proto)
        if ex is None:
            return None
        P = self.P
        device = ex["device"]
        api = self.command_api()

        def function(step: str, fn: str | None) -> dict:
            c = ex[step]["calls"][fn]
            return next(r for r in api if r["call"] == c)

        def call(step: str, fn: str | None) -> dict:
            """The call of one step: function, arguments (after the link) as records that
            session_macros.j2 spells (`arg_list`, `consts`)."""
            st = ex[step]
            row = function(step, fn)
            types = {q["name"]: q["type"] for q in st["variant"]["params"]}
            args = []
            for a in row["args"]:
                if fn not in (None, "write") or a["name"] not in st["values"]:
                    raise ExampleError(
                        f"C back end: the configure-and-stream example gives no value for {a['name']} of"
                        f" {row['name']} (the protocol file's session_example)"
                    )
                value, tref = st["values"][a["name"]], types[a["name"]]
                arg = {"how": a["how"], "arg": a["arg"], "ctype": self._c_type(tref)}
                if a["how"] in ("value", "struct"):
                    arg["literal"] = self._literal(tref, value)
                elif tref["kind"] == "primitive" and tref["name"] == "char":
                    arg.update(how="string", text=c_string(value))
                else:
                    arg.update(items=[self._literal(tref, v) for v in value], count=len(value))
                args.append(arg)
            what = f"{st['set']['name']}.{st['field']['name']}" + (f" {fn}" if fn else "")
            return {"fn": row["name"], "arg_list": args, "what": what}

        def reply(step: str, fn: str | None, var: str) -> dict:
            r = function(step, fn)["reply"]
            if r is None or r["value"]:
                raise ExampleError(f"C back end: {ex[step]['field']['name']} has no typed reply to print")
            lv = next(lay for lay in self.layouts if lay["c"] == r["ctype"])
            return {"ctype": r["ctype"], **self._printf(self._layout_params(lv), var + ".")}

        data_set = ex["data"]["set"]
        fields = []
        for f in ex["data"]["fields"]:
            v = device_variant(self.proto, f, device)
            lv = self._layout_of(data_set, f, v)
            printed = self._printf(model.params(self.proto, v["params"], v["functions"]).params, "v->")
            fields.append(
                {
                    "name": f["name"],
                    "descriptor": f"0x{f['id']:02X}",
                    "handler": f"on_{f['name']}",
                    "ctype": lv["c"],
                    "member": lv["member"],
                    "id": lv["id"] if model.per_device(f) else None,
                    **printed,
                }
            )
        out = session_example_context(ex, call)
        out["info"].update(reply("info", None, "info"))
        out["setting_read"].update(reply("setting", list(ex["setting"]["calls"])[-1], "setting"))
        return {
            **out,
            "device": device,
            "device_c": f"{P}_DEVICE_{device.upper()}",
            "data_fields": fields,
        }

    def _layout_of(self, s: dict, f: dict, v: dict) -> dict:
        """The C layout view of variant v of field f of set s."""
        sv = next(x for x in self.sets if x["id"] == s["id"])
        fv = next(x for x in sv["fields"] if x["descriptor"] == f["id"])
        return fv["layouts"][f["variants"].index(v)]

    def _layout_params(self, lv: dict) -> tuple:
        """The parameters (layout model) of the IR layout behind a C layout view."""
        for s in self.proto["sets"]:
            for f in s["fields"]:
                for v in f["variants"]:
                    if self._layout_of(s, f, v) is lv:
                        return model.params(self.proto, v["params"], v["functions"]).params
        raise BackendError(f"C back end: no layout {lv['c']}")

    def _c_type(self, tref: dict) -> str:
        return _PRIM[tref["name"]][0] if tref["kind"] == "primitive" else self.type_c(tref["name"])

    def _literal(self, tref: dict, value) -> dict:
        """A value of the example as an examples.example_literal record with its C names (an
        enum's member macro, or its type for a number the spec does not name); session_macros.j2
        `literal` spells it."""
        return self._named(
            example_literal(self.types, tref, value, "C", lambda k, n: member(n) if k == "field" else n, "f")
        )

    def _named(self, r: dict) -> dict:
        if r["kind"] == "struct":
            return {**r, "fields": [{**x, "value": self._named(x["value"])} for x in r["fields"]]}
        if r["kind"] == "enum":
            view = next(t for t in self.type_views if t["name"] == r["type"])
            values = zip(self.types[r["type"]]["values"], view["values"])
            macro = next((vv["macro"] for tv, vv in values if tv["value"] == r["number"]), None)
            return {**r, "macro": macro, "ctype": view["c"]}
        return r

    def _printf(self, params, prefix: str) -> dict:
        """What session_macros.j2 `printf` prints of parameters as `name=value` pairs (arrays in
        brackets, strings in quotes), read from the C expression prefix + member: per parameter
        its label, kind (string, fixed, scalar) and C expression, per scalar its printf class
        (bool, float, signed, unsigned)."""
        items: list[dict] = []

        def scalar(e: model.Elem, expr: str) -> dict:
            if e.kind in ("struct", "union") or e.primitive is None:
                raise ExampleError(f"C back end: the configure-and-stream example cannot print {expr}")
            if e.primitive in ("bool", "float", "double"):
                cls = "bool" if e.primitive == "bool" else "float"
            else:
                cls = "signed" if PRIMITIVES[e.primitive][2] else "unsigned"
            return {"cls": cls, "expr": expr}

        def walk(qs, pre: str, label: str) -> None:
            for q in qs:
                if q.optional or q.kind not in (model.SCALAR, model.FIXED, model.STRING) or q.function:
                    raise ExampleError(f"C back end: the configure-and-stream example cannot print {q.name}")
                expr, name = pre + member(q.name), label + q.name
                if q.kind == model.STRING:
                    items.append({"kind": "string", "label": name, "expr": expr})
                elif q.kind == model.FIXED:
                    elems = [scalar(q.elem, f"{expr}[{i}]") for i in range(q.count)]
                    items.append({"kind": "fixed", "label": name, "elems": elems})
                elif q.elem.kind == "struct":
                    walk(
                        model.params(self.proto, self.types[q.elem.name]["params"], None).params, expr + ".", name + "."
                    )
                else:
                    items.append({"kind": "scalar", "label": name, "elems": [scalar(q.elem, expr)]})

        walk(params, prefix, "")
        return {"prints": items}

    def context(self) -> dict:
        return {
            "stream_example": self.stream_example(),
            "commands": self.command_api(),
            "session": self.session_context(),
            "p": self.p,
            "P": self.P,
            "pkg": self.pkg,
            "PKG": self.pkg.upper(),
            "byte_order": self.proto["byte_order"],
            "title": self.proto["title"],
            "protocol": self.proto["name"],
            "framing": self.framing,
            "path_depth": self.path_depth,
            "error_message_max": self.error_message_max,
            "types": self.type_views,
            "devices": self.devices,
            "link_facts": self.link,
            "clock_model": clock_model(self.proto),
            "layouts": self.layouts,
            "fields": self.fields,
            "reserved": self.reserved,
            "sets": self.sets,
            "set_kinds": self.set_kinds,
            "shared_set": self.shared_set,
            "sample_rule": self.proto["samples"],
            "data_kind": self.data_kind,
            "vectors": self.vectors,
            "canonical": canonical_literals(c_string, "ull", "u"),
            "bitfield_cases": self.bitfield_cases(),
            "example": self.example(),
            "name_max": max([len(f["name"]) for f in self.fields] + [len(d["id"]) for d in self.devices] + [1]) + 1,
        }


def runtime_replacements(prefix: str, package: str) -> list[tuple[str, str]]:
    """The replacements that turn the runtime's neutral names into a package's: symbols codec_ and
    CODEC_, program names codec-decode/codec-encode, include directory codec/. In this order no
    replacement matches the text an earlier one wrote (a prefix is [a-z0-9_]: its lower case has
    no '-' or '/', its upper case no lower-case letter; a package name has no '/').
    tests/generator/test_c_runtime.py checks that the runtime writes the tokens only at the start
    of a word, so that no other text changes."""
    return [
        ("codec_", f"{prefix}_"),
        ("CODEC_", f"{prefix.upper()}_"),
        ("codec-", f"{package}-"),
        ("codec/", f"{package}/"),
    ]


def _session_cases(ir: dict, sessions: list[dict]) -> dict[str, list[dict]]:
    """The session corpus (generator/sessions.py; the project's tests/sessions/, none for another
    spec) per protocol, as C literals."""
    out: dict[str, list[dict]] = {}
    prefixes = {p["name"]: prefix_of(p).upper() for p in ir["protocols"]}
    for c in sessions:
        P = prefixes[c["protocol"]]
        out.setdefault(c["protocol"], []).append(
            {
                "name": c["name"],
                "device_c": f"{P}_DEVICE_{c['device'].upper()}" if c["device"] else f"{P}_DEVICE_ANY",
                "timeout_ms": c["timeout_ms"],
                "inter_packet_timeout_ms": c["inter_packet_timeout_ms"],
                "steps": session_steps(c, c_string),
                "expect": c_string("".join(line + "\n" for line in c["expect"])),
            }
        )
    return out


def render(ir: dict, vectors: list[dict], release: Release | None = None, sessions: list[dict] = ()) -> dict[str, str]:
    release = release or load_release()
    env = environment()
    out: dict[str, str] = {}
    sessions = _session_cases(ir, list(sessions))
    for proto in ir["protocols"]:
        pkg = _Protocol(proto, vectors)
        ctx = {**pkg.context(), **release.stamp(proto), "session_cases": sessions.get(proto["name"], [])}
        root = f"c/{pkg.pkg}/"
        out[root + "LICENSE"] = release.license
        runtime = {src: root + dest.replace("codec/", f"{pkg.pkg}/") for src, dest in _RUNTIME_FILES.items()}
        out.update(
            copy_runtime(
                "c", runtime, runtime_replacements(pkg.p, pkg.pkg), banner=GENERATED_BANNER, vendored=_RUNTIME_VENDORED
            )
        )
        for tpl, path in _TEMPLATES.items():
            out[root + path.format(pkg=pkg.pkg)] = env.get_template(f"c/{tpl}").render(ctx)
        out[root + "tools/device_facts.h"] = env.get_template("c/tools/device_facts.h.j2").render(
            ctx,
            cs=lambda v: "NULL" if v is None else c_string(str(v)),
            gps_scale=proto["time"]["gps_scale"],
            **device_tables(proto),
        )
        if ctx["stream_example"]:
            out[root + "examples/configure_and_stream.c"] = env.get_template(
                "c/examples/configure_and_stream.c.j2"
            ).render(ctx, ex=ctx["stream_example"])
        out.update(cmake_package_files(root, ctx, pkg_config(pkg.pkg, proto["title"], "c"), toolchains=True))
        # The core library holds the binary encoders and decoders, the JSON library (<pkg>_json)
        # their canonical JSON: one source file of each per set, for the types and the reserved
        # fields, so that a firmware build compiles and links no JSON code.
        for part, suffix in (("wire", ""), ("json", "_json")):
            out[root + f"src/types{suffix}.c"] = env.get_template("c/types.c.j2").render(ctx, part=part)
        for s in pkg.sets:
            out[root + f"include/{s['header']}"] = env.get_template("c/set.h.j2").render(ctx, set=s)
            for part, suffix in (("wire", ""), ("json", "_json")):
                out[root + f"src/sets/{s['name']}{suffix}.c"] = env.get_template("c/set.c.j2").render(
                    ctx, set=s, part=part
                )
        reserved = {
            "name": "reserved",
            "header": f"{pkg.pkg}/reserved.h",
            "guard": f"{pkg.P}_RESERVED_H",
            "macro": None,
            "packet": None,
            "fields": pkg.reserved,
            "doc": "Reserved fields (valid in every set of their kind)",
        }
        out[root + f"include/{pkg.pkg}/reserved.h"] = env.get_template("c/set.h.j2").render(ctx, set=reserved)
        for part, suffix in (("wire", ""), ("json", "_json")):
            out[root + f"src/reserved{suffix}.c"] = env.get_template("c/set.c.j2").render(ctx, set=reserved, part=part)
    return out


_COMMAND_API: dict[int, tuple[dict, list[dict]]] = {}


def _command_api_of(protocol: dict) -> list[dict]:
    """The typed command API of a protocol (cached per protocol object for the docs back end)."""
    key = id(protocol)
    if key not in _COMMAND_API or _COMMAND_API[key][0] is not protocol:
        _COMMAND_API[key] = (protocol, _Protocol(protocol, []).command_api())
    return _COMMAND_API[key][1]


def api_names(protocol: dict, set_: dict | None, field: dict) -> dict[str, str]:
    """Names a C user types for a field: struct type(s), encode and decode functions, header."""
    p = prefix_of(protocol)
    base = f"{p}_{set_['name']}_{field['name']}" if set_ else f"{p}_{field['name']}"
    header = f"{protocol['package']}/sets/{set_['name']}.h" if set_ else f"{protocol['package']}/reserved.h"
    variants = field.get("variants") or [{"device": None}]
    bases = [base + (f"_{v['device']}" if v.get("device") else "") for v in variants]
    out = {
        "type": ", ".join(b + "_t" for b in bases),
        "encode": ", ".join(b + "_encode" for b in bases),
        "decode": ", ".join(b + "_decode" for b in bases),
        "descriptor": f"{base.upper()}_DESCRIPTOR",
        "header": header,
    }
    if set_ is not None and field.get("role") == "command" and set_["kind"] == "command":
        # The typed command API (commands.h.j2): one function per function the command supports,
        # per device when the layouts' parameters differ (_Protocol.command_api).
        names = [
            c["name"]
            for c in _command_api_of(protocol)
            if (c["call"].set, c["call"].field) == (set_["id"], field["name"])
        ]
        out["session"] = ", ".join(f"{n}(link, ...)" for n in names)
    return out


def public_name(protocol: dict, kind: str, *path) -> str:
    """The C name of a set (`kind` "set") or enum value (kind "value": enum type, value), for
    `mipgen diff` (generator/wirediff.py public_names, which names fields and members itself)."""
    p = prefix_of(protocol)
    if kind == "set":
        return f"{p}_{path[0]['name']}_*"
    return f"{p.upper()}_{snake(path[0]['name']).upper()}_{path[1]['name'].upper()}"
