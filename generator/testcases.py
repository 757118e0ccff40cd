"""Test cases the generated packages carry, computed once for all four languages.

Every back end renders tests that check its runtime against facts the generator knows: the
golden vectors, the canonical text of floats and strings (generator/canonical.py), each bitfield
member's mask, the decode error of each fixed layout fed too little or too much data, and typed
sample values that must round-trip. This module decides which cases exist and what their values
and expected canonical text are; a back end only spells the values as its own literals and
names. Keeping the cases here means the four languages test the same facts, and a new case (a
float with an odd NaN payload, a bitfield member) reaches all of them at once.
"""

from __future__ import annotations

import hashlib
import random
import struct
from dataclasses import dataclass
from typing import Callable, Iterator, Union

from generator.canonical import float_text, string_text
from generator.primitives import PRIMITIVES, int_range


# ------------------------------------------------------------------------------ golden vectors
@dataclass(frozen=True)
class VectorCase:
    """One golden vector or stream case (generator/vectors.py) of a protocol."""

    name: str
    corpus: str  # "vectors" or "streams": the directory the case came from
    hex: str
    device: str | None
    rejected: bool
    expect: tuple[str, ...]  # the canonical JSON lines the decoder must print
    source: str  # "file:line" of the case, for messages


def vector_cases(vectors: list[dict], protocol: dict) -> list[VectorCase]:
    """The golden cases of one protocol, in corpus order, for the packages' own suites (decode
    whole and in chunks of every size, then encode the lines back). Cases with NMEA or RTCM3
    lines (docs/conformance.md section 1) are left out here: those lines are not encoder input
    (section 5); tests/conformance decodes them in all four languages (test_cross_language,
    test_decode_paths) and checks encode's refusal of their lines."""
    return [
        VectorCase(
            name=c["name"],
            corpus=c["corpus"],
            hex=c["hex"],
            device=c.get("device"),
            rejected=bool(c.get("rejected")),
            expect=tuple(c["expect"]),
            source=f"{c.get('file', '')}:{c.get('line', '')}",
        )
        for c in vectors
        if c.get("protocol") == protocol["name"]
        and not any('"nmea":' in line or '"rtcm":' in line for line in c["expect"])
    ]


# ------------------------------------------------------------------------------ canonical floats
@dataclass(frozen=True)
class FloatCase:
    bits: int  # the raw IEEE 754 bits (NaN payloads matter)
    text: str  # the canonical JSON text (docs/conformance.md section 4)


@dataclass(frozen=True)
class CanonicalCases:
    doubles: tuple[FloatCase, ...]
    floats: tuple[FloatCase, ...]
    all_bytes: str  # canonical JSON string of the 256 byte values 0..255 in order


# Values whose shortest round-trip text is easy to get wrong: signed zero, exponent thresholds
# (1e16 vs 9999999999999998), subnormals, the extremes, NaN payloads (quiet, signalling, negative)
# and infinities. Random bit patterns from a fixed seed follow them.
_DOUBLES = (
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.1,
    0.5,
    123.456,
    1e16,
    1e15,
    9999999999999998.0,
    1.5e16,
    1e-4,
    1e-5,
    0.00012345,
    2.5e-310,
    5e-324,
    1.7976931348623157e308,
    2.2250738585072014e-308,
    1e22,
    1e21,
    123456789012345680.0,
    0.30000000000000004,
    100.0,
    1e100,
    -1e-100,
    3.14159,
)
_DOUBLE_BITS = (
    0x7FF8000000000000,
    0xFFF8000000000000,
    0x7FF0000000000001,
    0x7FF4000000000000,
    0x7FF0000000000000,
    0xFFF0000000000000,
)
_FLOATS = (0.0, -0.0, 1.0, 0.1, 16777216.0, 3.4028234663852886e38, 1e-45, 1.1754943508222875e-38, 0.24452066)
_FLOAT_BITS = (0x7FC00000, 0xFFC00000, 0x7FE5BF7F, 0x7F800001, 0x7FA00000, 0x7F800000, 0xFF800000)
_RANDOM_SEED = 20240611
_RANDOM_COUNT = 300


def canonical_cases() -> CanonicalCases:
    """The float and string canonical-text table every language's tests check."""
    rnd = random.Random(_RANDOM_SEED)
    dbits = [struct.unpack(">Q", struct.pack(">d", x))[0] for x in _DOUBLES] + list(_DOUBLE_BITS)
    dbits += [rnd.getrandbits(64) for _ in range(_RANDOM_COUNT)]
    fbits = [struct.unpack(">I", struct.pack(">f", x))[0] for x in _FLOATS] + list(_FLOAT_BITS)
    fbits += [rnd.getrandbits(32) for _ in range(_RANDOM_COUNT)]
    doubles = tuple(
        FloatCase(b, float_text(struct.unpack(">d", struct.pack(">Q", b))[0], b, single=False)) for b in dbits
    )
    floats = tuple(
        FloatCase(b, float_text(struct.unpack(">f", struct.pack(">I", b))[0], b, single=True)) for b in fbits
    )
    return CanonicalCases(doubles, floats, string_text(bytes(range(256))))


def canonical_literals(string: Callable[[str], str], u64: str = "", u32: str = "") -> dict:
    """The canonical table as one language's literals, for its tests/canonical_cases template:
    `string` spells a string literal, `u64` and `u32` end the hex bit patterns (a suffix)."""
    cases = canonical_cases()
    return {
        "doubles": [{"bits": f"0x{c.bits:016X}{u64}", "text": string(c.text)} for c in cases.doubles],
        "floats": [{"bits": f"0x{c.bits:08X}{u32}", "text": string(c.text)} for c in cases.floats],
        "all_bytes": string(cases.all_bytes),
    }


# ------------------------------------------------------------------------------ bitfields
@dataclass(frozen=True)
class BitfieldMemberCase:
    name: str
    first_bit: int
    width: int
    mask: int  # the member's mask as the spec states it
    max: int  # every bit of the member set, as the accessor returns it
    value: int  # a value to write through the accessor: `max`, or 1 for a 64-bit member
    raw: int  # the bitfield's raw value after writing `value` into a zero bitfield

    @property
    def flag(self) -> bool:
        """A one-bit member: its accessor reads and writes a bool."""
        return self.width == 1


@dataclass(frozen=True)
class BitfieldCase:
    name: str  # the bitfield type
    base: str  # its wire primitive
    members: tuple[BitfieldMemberCase, ...]

    def wide_member(self) -> BitfieldMemberCase:
        """The first member wider than one bit (the first member when all are flags)."""
        return next((m for m in self.members if not m.flag), self.members[0])

    def first_flag(self) -> BitfieldMemberCase | None:
        return next((m for m in self.members if m.flag), None)


def bitfield_cases(protocol: dict) -> list[BitfieldCase]:
    """Every member of every bitfield type, in IR order: the accessor cases of all languages."""
    out = []
    for t in protocol["types"]:
        if t["kind"] != "bitfield":
            continue
        members = []
        for m in t["members"]:
            width, first = m["width"], m["first_bit"]
            full = (1 << width) - 1
            value = full if width < 64 else 1
            members.append(BitfieldMemberCase(m["name"], first, width, m["mask"], full, value, value << first))
        out.append(BitfieldCase(t["name"], t["base"], tuple(members)))
    return out


# ------------------------------------------------------------------------------ fixed-layout errors
def layouts(protocol: dict) -> Iterator[tuple[dict | None, dict, dict]]:
    """(set or None for a reserved field, field, layout) for every layout, in IR order."""
    for s in protocol["sets"]:
        for f in s["fields"]:
            for v in f["variants"]:
                yield s, f, v
    for r in protocol["reserved_fields"]:
        yield None, r, r["variants"][0]


@dataclass(frozen=True)
class LayoutErrorCase:
    set: dict | None  # None for a reserved field
    field: dict
    layout: dict
    # Decoding empty data: None when the outcome is not checked, "" when it succeeds, else the
    # error text of docs/conformance.md section 3.
    empty: str | None
    extra_len: int | None  # a length one byte past the layout's maximum, when that case is checked
    extra: str | None  # the error text of decoding `extra_len` zero bytes
    zero_safe: bool  # every parameter is fixed-size and the zero value round-trips


def layout_error_cases(protocol: dict) -> list[LayoutErrorCase]:
    """Per layout: the decode result of empty data and of one byte too many."""
    types = {t["name"]: t for t in protocol["types"]}
    max_data = protocol["framing"]["max_field_data"]
    out = []
    for s, f, v in layouts(protocol):
        first = _first_read(types, v)
        if first == "ok":
            empty = ""
        elif first is not None:
            path, n = first
            empty = f"{path}: needs {n} bytes at offset 0, 0 left"
        else:
            empty = None
        zero_safe = _zero_safe(types, v["params"])
        extra_len = extra = None
        size = v["size"]
        if all(q["size"]["fixed"] for q in v["params"]) and zero_safe and size["max"] + 1 <= max_data:
            extra_len = size["max"] + 1
            extra = f"1 unexpected bytes at offset {size['max']}"
        out.append(LayoutErrorCase(s, f, v, empty, extra_len, extra, zero_safe))
    return out


def _first_read(types: dict, layout: dict):
    """What decoding empty data meets first: "ok" (nothing required), (path, bytes needed), or
    None when that depends on more than the layout (a counted array, a union)."""
    if layout["functions"] is not None:
        return ("function", 1)
    params = layout["params"]
    if not params or params[0]["optional"]:
        return "ok"
    return _first_of_param(types, params[0], params[0]["name"])


def _first_of_param(types: dict, q: dict, path: str):
    c = q["count"]
    t = q["type"]
    if c is not None:
        if c["kind"] != "fixed":
            return None
        path += "[0]"
    kind = t["kind"]
    if kind in ("primitive", "enum", "bitfield", "string"):
        return (path, t["size"]["min"])
    if kind == "struct":
        ps = types[t["name"]]["params"]
        if not ps:
            return None
        return _first_of_param(types, ps[0], path + "." + ps[0]["name"])
    return None


def _zero_safe(types: dict, params: list[dict]) -> bool:
    for q in params:
        t = q["type"]
        if t["kind"] == "union" or (q["count"] is not None and q["count"]["kind"] != "fixed"):
            return False
        if t["kind"] == "struct" and not _zero_safe(types, types[t["name"]]["params"]):
            return False
    return True


# ------------------------------------------------------------------------------ typed samples
@dataclass(frozen=True)
class EnumValue:
    type: str
    name: str


@dataclass(frozen=True)
class Flags:
    type: str  # a bitfield type
    mask: int


@dataclass(frozen=True)
class StructValue:
    type: str
    args: tuple[tuple[str, Sample], ...]  # (parameter name, value) in layout order


# A sample value: int, float, bool, bytes (a char or a string with its padding), EnumValue,
# Flags, StructValue, a list of samples (an array), or None (a union member without data).
Sample = Union[int, float, bool, bytes, EnumValue, Flags, StructValue, list, None]

_SAMPLE_FLOATS = (1.5, -2.25, 0.375, 1024.0, -0.0)  # exact in binary32
_SAMPLE_DOUBLES = (0.1, -2.5e-310, 1e16, 123.456, -0.0)


def layout_sample(protocol: dict, set_: dict | None, field: dict, layout: dict) -> list[tuple[str, Sample]]:
    """Sample values of one layout of a field (set_ None for a reserved field), seeded by the
    field alone: adding or changing another field leaves these values as they are."""
    if set_ is None:
        key = (protocol["name"], "reserved", field["applies_to"], field["id"], field["name"], layout["device"])
    else:
        key = (protocol["name"], set_["id"], field["id"], field["name"], layout["device"])
    return Sampler(protocol, stable_seed(*key)).layout(layout["params"], layout["functions"])


def struct_sample(protocol: dict, t: dict) -> StructValue:
    """A sample value of a struct type, seeded by the type alone."""
    return Sampler(protocol, stable_seed(protocol["name"], "type", t["name"])).struct(t)


def stable_seed(*parts: object) -> int:
    """A number that depends only on `parts` (hashlib, not Python's per-process string hash)."""
    text = "/".join(str(p) for p in parts)
    return int.from_bytes(hashlib.sha256(text.encode()).digest()[:4], "big")


class Sampler:
    """Typed sample values for round-trip tests: every parameter of a layout or struct gets a
    value that encodes, decodes and prints back unchanged. Array counts are two (at most the
    maximum) and a union takes its first member with data. Each value draws the next number of
    a counter that starts at `seed`, so the values vary from parameter to parameter."""

    def __init__(self, protocol: dict, seed: int = 0):
        self.types = {t["name"]: t for t in protocol["types"]}
        fs = protocol.get("function_selector") or {}
        self.function_enum = fs.get("enum")
        self.k = seed

    def layout(self, params: list[dict], function_names: list[str] | None) -> list[tuple[str, Sample]]:
        """(parameter name, value) for a layout (with its function selector) or a struct."""
        args: list[tuple[str, Sample]] = []
        if function_names is not None:
            args.append(("function", EnumValue(self.function_enum, function_names[-1])))
        counts: dict[str, int] = {}
        selectors: dict[str, str] = {}
        for q in params:
            c = q["count"]
            if c is not None and c["kind"] == "param":
                counts[c["param"]] = min(2, q["max_count"])
            if q["type"]["kind"] == "union":
                ut = self.types[q["type"]["name"]]
                with_data = [m for m in ut["members"] if m["type"]] or ut["members"]
                selectors[q["type"]["selector"]] = with_data[0]["when"]
        chosen: dict[str, str] = {}  # selector parameter -> member, once its value is written
        for q in params:
            name, tref, c = q["name"], q["type"], q["count"]
            if name in counts:
                args.append((name, counts[name]))
            elif name in selectors:
                chosen[name] = selectors[name]
                args.append((name, EnumValue(tref["name"], selectors[name])))
            elif tref["kind"] == "union":
                ut = self.types[tref["name"]]
                when = chosen.get(tref["selector"])
                member = next((m for m in ut["members"] if m["when"] == when), None)
                if member is None or not member["type"]:
                    args.append((name, None))
                else:
                    args.append((name, self.struct(self.types[member["type"]])))
            elif c is None:
                args.append((name, self.value(tref)))
            else:
                n = c["value"] if c["kind"] == "fixed" else counts.get(c.get("param", ""), min(2, q["max_count"]))
                args.append((name, [self.value(tref) for _ in range(n)]))
        return args

    def struct(self, t: dict) -> StructValue:
        return StructValue(t["name"], tuple(self.layout(t["params"], None)))

    def value(self, tref: dict) -> Sample:
        self.k += 1
        k = self.k
        kind = tref["kind"]
        if kind == "primitive":
            name = tref["name"]
            pk = PRIMITIVES[name][1]
            if pk == "int":
                lo, hi = int_range(name)
                return -(k % 100) - 1 if lo < 0 and k % 2 else (k * 37 + 1) % min(hi + 1, 251)
            if pk == "bool":
                return bool(k % 2)
            if pk == "char":
                return bytes([0x41 + k % 26])
            return (_SAMPLE_FLOATS if name == "float" else _SAMPLE_DOUBLES)[k % 5]
        if kind == "string":
            n = tref["length"]
            text = bytes([0x61 + (k + i) % 26 for i in range(min(n, 3))])
            pad = b" " if tref.get("padding") == "space" else b"\x00"
            return text + pad * (n - len(text))
        if kind == "enum":
            et = self.types[tref["name"]]
            return EnumValue(tref["name"], et["values"][k % len(et["values"])]["name"])
        if kind == "bitfield":
            bt = self.types[tref["name"]]
            ms = [m for m in bt["members"] if not m["alias"]] or bt["members"]
            return Flags(tref["name"], ms[k % len(ms)]["mask"])
        if kind == "struct":
            return self.struct(self.types[tref["name"]])
        raise ValueError(kind)
