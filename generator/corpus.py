"""The corpus cases' common part: how a packet written as a person reads it (set, fields by
descriptor and name, values as enum names, bit names, decimal floats) is checked against the IR
and re-spelled as the exact canonical JSON line (docs/conformance.md) every language prints.

The golden vectors and the stream corpus (generator/vectors.py) and the session corpus
(generator/sessions.py) write their packets this way and both read them through this module.
"""

from __future__ import annotations

import math
import re
import struct

from .canonical import float_text, string_text
from .diagnostics import SpecError
from .model import per_device
from .passes.context import SpecFile
from .passes.lookup_order import entries as lookup_entries
from .passes.lookup_order import set_kind
from .primitives import PRIMITIVES, int_range


class CorpusFile:
    """One corpus file being read: its loaded YAML (for locating errors), the protocol of the IR
    its cases are checked against, and the errors found so far."""

    def __init__(self, sf: SpecFile, proto: dict):
        self.sf = sf
        self.proto = proto
        self.types = {t["name"]: t for t in proto["types"]}
        self.errors: list[SpecError] = []

    def err(self, path: tuple, msg: str, expected: str | None = None) -> None:
        self.errors.append(SpecError(self.sf.locate(path), msg, expected))


def fletcher16(data: bytes) -> bytes:
    """Fletcher-16 as docs/conformance.md §1 defines it: sum1 then sum2."""
    s1 = s2 = 0
    for b in data:
        s1 = (s1 + b) & 0xFF
        s2 = (s2 + s1) & 0xFF
    return bytes([s1, s2])


def packet_line(ctx: CorpusFile, path: tuple, p: dict, device: str | None) -> str:
    set_id = p.get("set")
    fields = []
    for k, f in enumerate(p.get("fields", [])):
        fp = path + ("fields", k)
        if "trailing" in f:
            fields.append('{"trailing":"%s","error":%s}' % (f["trailing"].lower(), json_str(f["error"])))
            continue
        if "data" in f:
            fields.append(
                '{"descriptor":%d,"data":"%s","error":%s}'
                % (f["descriptor"], f["data"].replace(" ", "").lower(), json_str(f["error"]))
            )
            continue
        fdef = _find_field(ctx, set_id, f.get("descriptor"))
        if fdef is None:
            ctx.err(
                fp + ("descriptor",),
                f"no field 0x{f.get('descriptor', 0):02X} in set 0x{set_id:02X}",
                "a descriptor defined in spec/",
            )
            continue
        if f.get("name") != fdef["name"]:
            ctx.err(
                fp + ("name",),
                f"descriptor 0x{fdef['id']:02X} is '{fdef['name']}', the vector says '{f.get('name')}'",
                fdef["name"],
            )
        dev = f.get("device", device)
        variants = fdef["variants"]
        if per_device(fdef):
            match = [v for v in variants if v["device"] == dev]
            if not match:
                ctx.err(
                    fp,
                    f"field {fdef['name']} has per-device variants; name one with device:",
                    ", ".join(v["device"] for v in variants),
                )
                continue
            layout = match[0]
            head = '{"descriptor":%d,"name":"%s","device":"%s","values":' % (fdef["id"], fdef["name"], layout["device"])
        else:
            layout = variants[0]
            head = '{"descriptor":%d,"name":"%s","values":' % (fdef["id"], fdef["name"])
        fields.append(head + _layout_values(ctx, fp + ("values",), layout, f.get("values") or {}) + "}")
    return '{"offset":%d,"set":%d,"fields":[%s]}' % (p.get("offset", 0), set_id, ",".join(fields))


def _find_field(ctx: CorpusFile, set_id: int, desc: int) -> dict | None:
    hit = resolve_field(ctx.proto, set_id, desc)
    return hit[1] if hit else None


def resolve_field(proto: dict, set_id: int, desc: int) -> tuple[dict | None, dict] | None:
    """(set, field) that decodes descriptor desc in a packet of set set_id, by the dispatch rule of
    docs/conformance.md §2 as the IR's `lookup` resolves it: the set's own field, else a reserved
    field (set None), else in a data set a field of the shared set. None when nothing matches."""
    e = next((e for e in lookup_entries(proto, set_id) if e["descriptor"] == desc), None)
    if e is None:
        return None
    if e["source"] == "reserved":
        kind = set_kind(proto, set_id)
        return None, next(r for r in proto["reserved_fields"] if r["applies_to"] == kind and r["id"] == desc)
    s = next(s for s in proto["sets"] if s["id"] == e["set"])
    return s, next(f for f in s["fields"] if f["id"] == desc)


def json_str(s: str) -> str:
    return string_text(s.encode("latin-1"))


def _layout_values(ctx: CorpusFile, path: tuple, layout: dict, values: dict) -> str:
    parts = []
    known = {q["name"] for q in layout["params"]} | ({"function"} if layout["functions"] else set())
    for k in values:
        if k not in known:
            ctx.err(path + (k,), f"unknown parameter '{k}'", "one of " + ", ".join(sorted(known)))
    if layout["functions"]:
        if "function" not in values:
            ctx.err(path, "missing 'function'")
        else:
            fs = ctx.types[ctx.proto["function_selector"]["enum"]]
            parts.append('"function":' + _enum_value(ctx, path + ("function",), fs, values["function"]))
    parts.extend(_params(ctx, path, layout["params"], values))
    return "{" + ",".join(parts) + "}"


def _params(ctx: CorpusFile, path: tuple, params: list[dict], values: dict) -> list[str]:
    parts = []
    seen: dict = {}
    for q in params:
        if q["name"] not in values:
            if not q["optional"]:
                ctx.err(path, f"missing parameter '{q['name']}'")
            continue
        v = values[q["name"]]
        seen[q["name"]] = v
        parts.append('"%s":%s' % (q["name"], _param_value(ctx, path + (q["name"],), q, v, seen)))
    last = next((q for q in reversed(params) if q["name"] in values), None)
    if last is not None and last["optional"] and last["count"] is not None and values[last["name"]] == []:
        # It takes no bytes and nothing follows, so no decoder can tell it from absent (conformance.md §3).
        ctx.err(
            path + (last["name"],),
            f"optional parameter '{last['name']}' is empty and last: decoders print it absent",
            f"leave '{last['name']}' out",
        )
    return parts


def _param_value(ctx: CorpusFile, path: tuple, q: dict, v, seen: dict) -> str:
    c = q["count"]
    if c is None:
        return _value(ctx, path, q["type"], v, seen)
    if not isinstance(v, list):
        ctx.err(path, f"{q['name']} is an array", "a list")
        return "[]"
    if c["kind"] == "fixed" and len(v) != c["value"]:
        ctx.err(path, f"{q['name']} has {len(v)} elements", f"{c['value']}")
    if c["kind"] == "param" and seen.get(c["param"]) != len(v):
        ctx.err(path, f"{q['name']} has {len(v)} elements but {c['param']} = {seen.get(c['param'])}", "matching count")
    return "[" + ",".join(_value(ctx, path + (i,), q["type"], x, seen) for i, x in enumerate(v)) + "]"


def _value(ctx: CorpusFile, path: tuple, t: dict, v, seen: dict) -> str:
    kind = t["kind"]
    if kind == "primitive":
        name = t["name"]
        pk = PRIMITIVES[name][1]
        if pk == "int":
            lo, hi = int_range(name)
            if not isinstance(v, int) or isinstance(v, bool) or not lo <= v <= hi:
                ctx.err(path, f"{v!r} is not a valid {name}", f"an integer in {lo}..{hi}")
                return "0"
            return str(v)
        if pk == "bool":
            if not isinstance(v, bool):
                ctx.err(path, f"{v!r} is not a bool", "true or false")
            return "true" if v else "false"
        if pk == "char":
            if not isinstance(v, str) or len(v) != 1:
                ctx.err(path, f"{v!r} is not one character")
                return '"?"'
            return string_text(v.encode("latin-1"))
        return _float(ctx, path, name, v)
    if kind == "string":
        if not isinstance(v, str) or len(v.encode("latin-1", "replace")) != t["length"]:
            ctx.err(
                path,
                f"string {v!r} is not exactly {t['length']} characters (padding included)",
                f"{t['length']} characters",
            )
            return '""'
        return string_text(v.encode("latin-1"))
    if kind == "enum":
        return _enum_value(ctx, path, ctx.types[t["name"]], v)
    if kind == "bitfield":
        bt = ctx.types[t["name"]]
        if isinstance(v, list):
            members = {m["name"]: m for m in bt["members"]}
            total = 0
            for name in v:
                if name not in members:
                    ctx.err(path, f"'{name}' is not a member of bitfield {bt['name']}", ", ".join(members))
                else:
                    total |= members[name]["mask"]
            return str(total)
        lo, hi = int_range(bt["base"])
        if not isinstance(v, int) or not lo <= v <= hi:
            ctx.err(
                path,
                f"{v!r} is not a valid {bt['base']} for bitfield {bt['name']}",
                "an integer or a list of member names",
            )
            return "0"
        return str(v)
    if kind == "struct":
        st = ctx.types[t["name"]]
        if not isinstance(v, dict):
            ctx.err(path, f"{t['name']} is a struct", "a mapping")
            return "{}"
        for k in v:
            if k not in {q["name"] for q in st["params"]}:
                ctx.err(path + (k,), f"unknown member '{k}' of {t['name']}")
        return "{" + ",".join(_params(ctx, path, st["params"], v)) + "}"
    if kind == "union":
        ut = ctx.types[t["name"]]
        sel_value = seen.get(t["selector"])
        et = ctx.types[ut["selector_enum"]]
        sel_int = _enum_int(et, sel_value)
        member = next((m for m in ut["members"] if m["value"] == sel_int), None)
        if member is None:
            ctx.err(path, f"no member of union {ut['name']} for selector {sel_value!r}")
            return "null"
        if member["type"] is None:
            if v is not None:
                ctx.err(path, "this union member has no data", "null")
            return "null"
        return _value(ctx, path, {"kind": "struct", "name": member["type"]}, v, seen)
    ctx.err(path, f"cannot express type kind {kind}")
    return "null"


def _enum_int(et: dict, v):
    if isinstance(v, str):
        for x in et["values"]:
            if x["name"] == v:
                return x["value"]
        return None
    return v


def _enum_value(ctx: CorpusFile, path: tuple, et: dict, v) -> str:
    iv = _enum_int(et, v)
    lo, hi = int_range(et["base"])
    if iv is None or isinstance(iv, bool) or not isinstance(iv, int) or not lo <= iv <= hi:
        ctx.err(
            path,
            f"{v!r} is not a value of enum {et['name']}",
            "a value name (" + ", ".join(x["name"] for x in et["values"]) + ") or an integer",
        )
        return "0"
    return str(iv)


def _float(ctx: CorpusFile, path: tuple, name: str, v) -> str:
    single = name == "float"
    if isinstance(v, str):
        s = v.strip()
        if s == "nan":
            return '"nan"'
        if s in ("inf", "-inf"):
            return '"%s"' % s
        m = re.fullmatch(r"nan:0x([0-9a-f]+)", s)
        if m and len(m.group(1)) == (8 if single else 16):
            bits = int(m.group(1), 16)
            val = (
                struct.unpack(">f", struct.pack(">I", bits))[0]
                if single
                else struct.unpack(">d", struct.pack(">Q", bits))[0]
            )
            if not math.isnan(val):
                ctx.err(path, f"{s} is not a NaN bit pattern")
            return float_text(val, bits, single)
        m = re.fullmatch(r"bits:0x([0-9a-f]+)", s)
        if m:
            bits = int(m.group(1), 16)
            val = (
                struct.unpack(">f", struct.pack(">I", bits))[0]
                if single
                else struct.unpack(">d", struct.pack(">Q", bits))[0]
            )
            return float_text(val, bits, single)
        ctx.err(path, f"{v!r} is not a number", "a number, inf, -inf, nan, nan:0x<bits> or bits:0x<bits>")
        return "0.0"
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        ctx.err(path, f"{v!r} is not a number")
        return "0.0"
    if single:
        x = struct.unpack(">f", struct.pack(">f", float(v)))[0]
        # The decimal written in the vector must name this float exactly (shortest repr is fine).
        return float_text(x, single=True)
    return float_text(float(v))
