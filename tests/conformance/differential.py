"""Differential testing from the IR: hostile, randomised values and corrupted packets.

The hostile counterpart of `samples.py`. Driven only by `generated/ir.json` (through
`generator.spec.load_spec()`), a seeded generator builds, for every field layout (every set and
descriptor, every per-device variant, every function selector, the reserved fields such as
ack/nack in every command set, the shared data descriptors in every data set, and both in a set
the spec does not define):

- values: every enum value and values the enum does not name (in its base range), bitfields with
  reserved and undefined bits set, counted and remaining arrays of length 0, 1, maximum and
  random, every union member, optional parameters present and absent (any prefix, a count whose
  array is cut off included), function selector values the layout does not list, floats and
  doubles by bit pattern (canonical NaN, NaN with payloads of both signs, signalling NaN, +-inf,
  -0.0, denormals, min/max normals, random bits), integers at 0, -1, min, max and random, strings
  made of every byte value 0..255, bools;
- for each value: the canonical JSON text of docs/conformance.md §4 (written here by its rules,
  with `generator/canonical.py` for floats and strings) and the wire bytes (written here from the
  IR: byte order, sizes, field header, irregular size bytes, Fletcher-16), together with the
  offsets of the bytes worth corrupting (bools, counts, union selectors, function selectors);
- mutants: the packets corrupted field by field (truncated, extended, bytes replaced, field length
  byte changed, descriptor or set changed to unknown or to other defined ones, counts past the
  maximum or past the data, invalid bool bytes, selectors without a member, payload cut or
  extended, junk and false packets between packets), payload length and checksum recomputed so
  that they reach the field decoders.

`check_group` runs the four languages' `encode` / `decode` CLIs over one device group (one stream
per language and direction; C, C++ and Rust decode both streams again with `--decoder straight`
and `--decoder cached`, the packet decoders of issue 38) and returns every disagreement as text. `test_differential.py` runs
one round in `make test`; `python -m tests.conformance.differential --rounds N [--seed S]`
(`make differential`) runs many. Nothing here calls generated code.
"""

from __future__ import annotations

import argparse
import os
import random
import re
import shutil
import struct
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from generator.canonical import string_text
from generator.primitives import PRIMITIVES, int_range
from tests.conformance.reference import Reference, float_bits_text
from tests.conformance.respell import invalidate, respell
from tests.helpers.langs import langs
from tests.helpers.packets import packet

ROOT = Path(__file__).resolve().parents[2]

LANGS = langs()  # the target registry (generator/targets/__init__.py)
INTS = ("u8", "u16", "u32", "u64", "s8", "s16", "s32", "s64")
WORK = ROOT / "build" / "differential"
MAX_SAMPLES_PER_LAYOUT = 160
# How strings are made (see string_bytes): mostly every byte value in turn, so that a round
# covers 0..255 even in a protocol with few strings.
STRING_MODES = [1, 1, 1, 1, 0, 2, 3, 4, 5]
# The languages whose decode tool also runs the straight-line decoder and the layout cache
# (`--decoder straight|cached`, docs/conformance.md §5).
TYPED_DECODER_LANGS = ("c", "cpp", "rust")
ELEMENT = re.compile(r"\[[1-9]")  # a path inside an array element past the first


def session_seed() -> int:
    """DIFF_SEED from the environment (decimal or 0x...), else a fresh random seed."""
    env = os.environ.get("DIFF_SEED", "").strip()
    return int(env, 0) if env else random.SystemRandom().randrange(1 << 32)


SEED = session_seed()


def replay_command(seed: int) -> str:
    return f"DIFF_SEED={seed} .venv/bin/python -m pytest -q tests/conformance/test_differential.py"


# ----------------------------------------------------------------------------------------- floats
F32_SPECIAL = [
    0x7FC00000,  # canonical quiet NaN
    0xFFC00000,  # negative quiet NaN
    0x7FC00001,  # quiet NaN with payload
    0x7F800001,  # signalling NaN
    0xFF800001,
    0x7FBFFFFF,  # largest signalling payload
    0x7FFFFFFF,
    0xFFFFFFFF,
    0x7F800000,  # +inf
    0xFF800000,  # -inf
    0x00000000,
    0x80000000,  # -0.0
    0x00000001,  # smallest denormal
    0x80000001,
    0x007FFFFF,  # largest denormal
    0x807FFFFF,
    0x00800000,  # smallest normal
    0x80800000,
    0x7F7FFFFF,  # largest normal
    0xFF7FFFFF,
    0x3F800000,  # 1.0
    0xBF800000,
    0x3DCCCCCD,  # 0.1 (shortest text needs 9 digits as a double)
    0x4B800000,  # 2**24
    0x4B7FFFFF,
    0x5A000000,  # 9.007199254740992e15: positional/exponent boundary region
    0x38D1B717,  # ~1e-4: the -4 exponent boundary
]
F64_SPECIAL = [
    0x7FF8000000000000,
    0xFFF8000000000000,
    0x7FF8000000000001,
    0x7FF0000000000001,
    0xFFF0000000000001,
    0x7FF7FFFFFFFFFFFF,
    0x7FFFFFFFFFFFFFFF,
    0xFFFFFFFFFFFFFFFF,
    0x7FF0000000000000,
    0xFFF0000000000000,
    0x0000000000000000,
    0x8000000000000000,
    0x0000000000000001,  # 5e-324
    0x8000000000000001,
    0x000FFFFFFFFFFFFF,
    0x800FFFFFFFFFFFFF,
    0x0010000000000000,
    0x8010000000000000,
    0x7FEFFFFFFFFFFFFF,
    0xFFEFFFFFFFFFFFFF,
    0x3FF0000000000000,
    0xBFF0000000000000,
    0x3FB999999999999A,  # 0.1
    0x4340000000000000,  # 2**53 = 9007199254740992.0
    0x4341C37937E08000,  # 1e16: first exponent form
    0x4341C37937E07FFF,  # just below 1e16
    0x3F1A36E2EB1C432D,  # 1e-4: last positional form
    0x3F1A36E2EB1C432C,  # just below 1e-4: exponent form
    0x3FD5555555555555,  # 1/3, 17 significant digits
]


# ----------------------------------------------------------------------------------------- framing
class Framing:
    """Field headers and packets written from `protocols[].framing` (docs/conformance.md §1, §2)."""

    def __init__(self, protocol: dict):
        fr = protocol["framing"]
        self.fr = fr
        self.sync = bytes(fr["sync"])
        self.irregular = {(e["set"], e["descriptor"]): e["adjust"] for e in fr["irregular_lengths"]}
        self.max_payload = fr["max_payload"]
        self.max_field_data = fr["max_field_data"]

    def adjust(self, set_id: int, descriptor: int) -> int:
        return self.fr["field_length_adjust"] + self.irregular.get((set_id, descriptor), 0)

    def field(self, set_id: int, descriptor: int, data: bytes, length: int | None = None) -> bytes | None:
        """Field header + data; `length` overrides the length byte. None if it does not fit a byte."""
        if length is None:
            length = len(data) + self.adjust(set_id, descriptor)
        if not 0 <= length <= 255:
            return None
        hdr = bytearray(self.fr["field_header_size"])
        hdr[self.fr["field_length_offset"]] = length
        hdr[self.fr["field_descriptor_offset"]] = descriptor
        return bytes(hdr) + data

    def packet(self, set_id: int, payload: bytes, bad_checksum: bool = False) -> bytes:
        return packet(self.fr, set_id, payload, bad_checksum)


# ----------------------------------------------------------------------------------------- values
@dataclass
class Spot:
    """Bytes of a field's data worth corrupting: a bool, a count, a union selector, ..."""

    offset: int
    size: int
    kind: str  # bool, count, selector, function, enum, float, double
    path: str
    info: dict = field(default_factory=dict)


@dataclass
class FieldSample:
    """One field of a packet: the canonical JSON of its entry and its data bytes."""

    set_id: int
    descriptor: int
    name: str
    device: str | None  # the variant's device when the field has several layouts
    values: str  # canonical JSON text of "values"
    data: bytes
    spots: list
    what: str  # where it comes from, for failure messages

    def line(self) -> str:
        dev = f',"device":"{self.device}"' if self.device else ""
        return f'{{"descriptor":{self.descriptor},"name":"{self.name}"{dev},"values":{self.values}}}'


@dataclass
class Placement:
    """A layout placed in a packet set: a set's own field, a reserved field, a shared field."""

    set_id: int
    set_name: str
    field: dict
    variant: dict
    device: str | None  # decode for this device (None: any)


class ValueGen:
    """Hostile values of one protocol's layouts, from the IR alone."""

    def __init__(self, protocol: dict, rng: random.Random):
        self.p = protocol
        self.rng = rng
        self.types = {t["name"]: t for t in protocol["types"]}
        self.order = "big" if protocol["byte_order"] == "big" else "little"
        self.fmt = ">" if self.order == "big" else "<"
        self.framing = Framing(protocol)
        fs = protocol["function_selector"]
        self.fn_enum = self.types[fs["enum"]] if fs else None
        self.salts: dict = {}
        self.counts: dict = {}
        self.need: dict = {}  # key -> number of options, for the choices of the current layout
        self.string_cursor = rng.randrange(256)
        self.covered: dict = {"enum": set(), "union": set(), "length": set(), "bytes": set()}
        self._choices: dict = {}

    # -- cycling choices ---------------------------------------------------------------------
    def pick(self, key: tuple, options: list):
        """The i-th time a choice (layout, path, what) is made it takes option (i + salt): made
        len(options) times, it has taken every option once. Keys of array elements past the
        first do not have to cycle (`samples` stops when the others have)."""
        i = self.counts.get(key, 0)
        self.counts[key] = i + 1
        salt = self.salts.get(key)
        if salt is None:
            salt = self.salts[key] = self.rng.randrange(1 << 16)
        if not ELEMENT.search(str(key[1])):
            self.need[key] = len(options)
        return options[(i + salt) % len(options)]

    def enum_choices(self, name: str) -> list[int]:
        """Every named value, and values the enum does not name: the base's min and max, the
        first unnamed above the largest name, and random unnamed ones (a fresh pair per round)."""
        if name in self._choices:
            return self._choices[name]
        t = self.types[name]
        named = sorted({v["value"] for v in t["values"]})
        lo, hi = int_range(t["base"])
        unknown = {lo, hi, max(named) + 1 if named and max(named) < hi else lo}
        for _ in range(2):
            for _try in range(50):
                v = self.rng.randint(lo, hi)
                if v not in named:
                    unknown.add(v)
                    break
        out = named + sorted(v for v in unknown if v not in named)
        self.rng.shuffle(out)
        self._choices[name] = out
        return out

    def bitfield_choices(self, name: str) -> list[int]:
        t = self.types[name]
        lo, hi = int_range(t["base"])
        defined = 0
        reserved = 0
        for m in t["members"]:
            if m.get("reserved"):
                reserved |= m["mask"]
            else:
                defined |= m["mask"]
        undefined = hi & ~(defined | reserved)
        out = [0, hi, defined, reserved | undefined, defined | reserved, self.rng.randint(lo, hi)]
        out += [m["mask"] for m in t["members"]]
        return out

    # -- scalars -------------------------------------------------------------------------------
    def int_value(self, name: str) -> int:
        lo, hi = int_range(name)
        r = self.rng.random()
        if r < 0.45:
            return self.rng.choice([0, lo, hi, 1, -1 if lo < 0 else hi - 1, lo + 1])
        if r < 0.6:
            return max(lo, min(hi, self.rng.randint(-3, 300)))
        return self.rng.randint(lo, hi)

    def float_bits(self, single: bool) -> int:
        width = 32 if single else 64
        exp_bits = 8 if single else 11
        mant_bits = width - 1 - exp_bits
        r = self.rng.random()
        if r < 0.4:
            return self.rng.choice(F32_SPECIAL if single else F64_SPECIAL)
        if r < 0.55:  # NaN with a random payload and sign
            sign = self.rng.getrandbits(1) << (width - 1)
            mant = self.rng.randrange(1, 1 << mant_bits)
            return sign | (((1 << exp_bits) - 1) << mant_bits) | mant
        if r < 0.65:  # denormal
            return (self.rng.getrandbits(1) << (width - 1)) | self.rng.randrange(1, 1 << mant_bits)
        if r < 0.75:  # a short decimal
            v = self.rng.choice([1, -1]) * self.rng.randint(0, 10**6) / 10 ** self.rng.randint(0, 8)
            return struct.unpack(">I" if single else ">Q", struct.pack(">f" if single else ">d", v))[0]
        return self.rng.getrandbits(width)

    def string_bytes(self, n: int, mode: int) -> bytes:
        if mode == 0:
            return bytes(self.rng.randrange(256) for _ in range(n))
        if mode == 1:  # every byte value in turn across the round
            out = bytes((self.string_cursor + i) & 0xFF for i in range(n))
            self.string_cursor = (self.string_cursor + n) & 0xFF
            return out
        if mode == 2:  # text padded with NUL or spaces, left or right
            text = bytes(self.rng.choice(b"ABCxyz019 -_") for _ in range(self.rng.randint(0, n)))
            pad = self.rng.choice([b"\x00", b" "]) * (n - len(text))
            return text + pad if self.rng.random() < 0.5 else pad + text
        if mode == 3:
            return bytes(
                self.rng.choice(b'"\\\x00\x01\x1f\x20\x7e\x7f\x80\x9f\xa0\xff/\x08\x0c\n\r\t') for _ in range(n)
            )
        if mode == 4:
            return bytes([0]) * n
        return bytes(self.rng.randrange(0x20, 0x7F) for _ in range(n))

    # -- a parameter list ------------------------------------------------------------------------
    def params(self, params: list[dict], ctx: dict, buf: bytearray, spots: list, path: str, cut: int) -> str:
        """Write params[:cut] into buf; return the JSON object text (trailing zero-size optional
        parameters left out, as a decoder cannot see them)."""
        selectors = {}
        counts = {}
        for p in params:
            t = p["type"]
            if t["kind"] == "union":
                selectors[t["selector"]] = p
            if p["count"] and p["count"]["kind"] == "param":
                counts[p["count"]["param"]] = p
        chosen_member: dict = {}
        lengths: dict = {}
        present = {q["name"] for q in params[:cut]}
        items = []
        for p in params[:cut]:
            start = len(buf)
            pp = f"{path}{p['name']}"
            t = p["type"]
            if p["name"] in selectors and selectors[p["name"]]["name"] not in present:
                # The union is cut off: the selector may hold any value, one without a member too
                # (the decoder never reads the union, so the value decodes).
                v = self.pick((ctx["layout"], pp, "enum", t["name"]), self.enum_choices(t["name"]))
                text = self.write_int(buf, t["base"], v)
                spots.append(Spot(start, t["size"]["max"], "enum", pp, {"base": t["base"]}))
            elif p["name"] in selectors:
                union = self.types[selectors[p["name"]]["type"]["name"]]
                m = self.pick((ctx["layout"], pp, "member"), union["members"])
                chosen_member[selectors[p["name"]]["name"]] = m
                self.covered["union"].add((union["name"], m["value"]))
                text = self.write_int(buf, t["base"], m["value"])
                spots.append(
                    Spot(
                        start,
                        t["size"]["max"],
                        "selector",
                        pp,
                        {"base": t["base"], "enum": t["name"], "members": [x["value"] for x in union["members"]]},
                    )
                )
            elif p["name"] in counts:
                arr = counts[p["name"]]
                base = t["name"]
                lo, hi = int_range(base)
                if arr["name"] in present:
                    n = self.array_length(arr, ctx, f"{path}{arr['name']}")
                    n = min(n, hi)
                    lengths[arr["name"]] = n
                else:  # the array is cut off: its count can be anything (hostile)
                    n = self.int_value(base)
                    n = max(0, n)
                text = self.write_int(buf, base, n)
                spots.append(
                    Spot(start, t["size"]["max"], "count", pp, {"base": base, "max": arr["max_count"], "n": n})
                )
            else:
                text = self.param(p, ctx, buf, spots, pp, lengths, chosen_member)
            items.append((p, text, start, len(buf)))
        while items and items[-1][0]["optional"] and items[-1][2] == items[-1][3]:
            items.pop()
        return "{" + ",".join(f'"{p["name"]}":{text}' for p, text, _, _ in items) + "}"

    def array_length(self, p: dict, ctx: dict, pp: str) -> int:
        mx = p["max_count"]
        mx = max(0, min(mx, int(mx * ctx["scale"])))
        choice = self.pick((ctx["layout"], pp, "len", str(p["type"])), ["zero", "one", "max", "rand"])
        n = {"zero": 0, "one": min(1, mx), "max": mx, "rand": self.rng.randint(0, mx)}[choice]
        self.covered["length"].add((ctx["layout"], pp, choice))
        return n

    def param(self, p, ctx, buf, spots, pp, lengths, chosen_member) -> str:
        c = p["count"]
        t = p["type"]
        if t["kind"] == "union":
            m = chosen_member[p["name"]]
            if m["type"] is None:
                return "null"
            st = self.types[m["type"]]
            return self.params(st["params"], ctx, buf, spots, pp + ".", len(st["params"]))
        if c is None:
            return self.value(t, ctx, buf, spots, pp)
        if c["kind"] == "fixed":
            n = c["value"]
        elif c["kind"] == "param":
            n = lengths[p["name"]]
        else:  # remaining: up to the end of the field, within its maximum
            n = self.array_length(p, ctx, pp)
            elem = t["size"]["max"]
            room = (self.framing.max_field_data - len(buf)) // max(1, elem)
            n = max(0, min(n, room))
        out = [self.value(t, ctx, buf, spots, f"{pp}[{i}]") for i in range(n)]
        return "[" + ",".join(out) + "]"

    def write_int(self, buf: bytearray, base: str, v: int) -> str:
        size = PRIMITIVES[base][0]
        buf += v.to_bytes(size, self.order, signed=PRIMITIVES[base][2])
        return str(v)

    def value(self, t: dict, ctx: dict, buf: bytearray, spots: list, pp: str) -> str:
        kind = t["kind"]
        start = len(buf)
        if kind == "primitive":
            name = t["name"]
            if name in INTS:
                return self.write_int(buf, name, self.int_value(name))
            if name == "bool":
                v = self.rng.random() < 0.5
                buf.append(1 if v else 0)
                spots.append(Spot(start, 1, "bool", pp))
                return "true" if v else "false"
            if name in ("float", "double"):
                single = name == "float"
                bits = self.float_bits(single)
                buf += bits.to_bytes(4 if single else 8, self.order)
                spots.append(Spot(start, 4 if single else 8, name, pp))
                return float_bits_text(bits, single)
            raise NotImplementedError(f"differential.py does not build primitive {name}")
        if kind == "string":
            raw = self.string_bytes(t["length"], self.pick((ctx["layout"], pp, "string"), STRING_MODES))
            self.covered["bytes"].update(raw)
            buf += raw
            return string_text(raw)
        if kind == "enum":
            v = self.pick((ctx["layout"], pp, "enum", t["name"]), self.enum_choices(t["name"]))
            self.covered["enum"].add((t["name"], v))
            spots.append(Spot(start, t["size"]["max"], "enum", pp, {"base": t["base"]}))
            return self.write_int(buf, t["base"], v)
        if kind == "bitfield":
            v = self.pick((ctx["layout"], pp, "bits", t["name"]), self.bitfield_choices(t["name"]))
            return self.write_int(buf, t["base"], v)
        if kind == "struct":
            st = self.types[t["name"]]
            return self.params(st["params"], ctx, buf, spots, pp + ".", len(st["params"]))
        raise NotImplementedError(f"differential.py does not build {kind}")

    def function_choices(self, variant: dict) -> list[int]:
        """The variant's functions, the selector's other named values, values it does not name."""
        named = {v["name"]: v["value"] for v in self.fn_enum["values"]}
        listed = [named[f] for f in variant["functions"]]
        other = sorted(set(named.values()) - set(listed))
        unknown = sorted(
            {0, 255, self.rng.choice([v for v in range(256) if v not in named.values()])} - set(named.values())
        )
        return listed + listed + other + unknown

    def samples(self, pl: Placement) -> list[FieldSample]:
        """Samples of one placed layout until every choice (function, cut, enum value, union
        member, array length class, ...) has taken each of its options once."""
        v = pl.variant
        params = v["params"]
        layout = (pl.set_id, pl.field["id"], v["device"])
        ctx = {"layout": layout, "scale": 1.0}
        fns = self.function_choices(v) if v["functions"] else None
        first_opt = next((i for i, p in enumerate(params) if p["optional"]), len(params))
        # Every cut of the optional parameters; all of them present half the time.
        cuts = list(range(first_opt, len(params) + 1))
        cuts += [len(params)] * (len(cuts) - 1)
        multi = len(pl.field["variants"]) > 1
        self.need = {}
        out = []
        k = 0
        while k < MAX_SAMPLES_PER_LAYOUT and (k < 3 or any(self.counts[key] < n for key, n in self.need.items())):
            for scale in (1.0, 0.5, 0.25, 0.1, 0.0):
                ctx["scale"] = scale
                buf = bytearray()
                spots: list = []
                prefix = ""
                if fns is not None:
                    fn = self.pick((layout, "function"), fns)
                    buf.append(fn)
                    spots.append(Spot(0, 1, "function", "function"))
                    prefix = f'"function":{fn},'
                cut = self.pick((layout, "cut"), cuts)
                text = self.params(params, ctx, buf, spots, "", cut)
                if (
                    len(buf) <= self.framing.max_field_data
                    and len(buf) + self.framing.adjust(pl.set_id, pl.field["id"]) >= 0
                ):
                    break
            else:
                raise AssertionError(f"cannot fit {pl.set_name}.{pl.field['name']} in a field")
            if prefix:
                text = "{" + prefix + text[1:] if text != "{}" else "{" + prefix[:-1] + "}"
            out.append(
                FieldSample(
                    set_id=pl.set_id,
                    descriptor=pl.field["id"],
                    name=pl.field["name"],
                    device=v["device"] if multi else None,
                    values=text,
                    data=bytes(buf),
                    spots=spots,
                    what=f"{pl.set_name}(0x{pl.set_id:02x}).{pl.field['name']}(0x{pl.field['id']:02x})"
                    + (f" [{v['device']}]" if multi else "")
                    + f" #{k}",
                )
            )
            k += 1
        return out


# ----------------------------------------------------------------------------------------- layouts
def placements(protocol: dict, rng: random.Random) -> list[Placement]:
    """Every layout in every set it can travel in: each set's own fields; reserved fields in every
    set of their kind and in one the spec does not define; shared data fields in every data set,
    in the shared set itself and in an undefined data set."""
    sets = protocol["sets"]
    defined = {s["id"] for s in sets}
    kinds = protocol["set_kinds"]

    def undefined(kind: str) -> int | None:
        r = kinds.get(kind)
        if not r:
            return None
        free = [i for i in range(r["first"], r["last"] + 1) if i not in defined]
        return rng.choice(free) if free else None

    out = []

    def add(set_id, set_name, f):
        multi = len(f["variants"]) > 1
        for v in f["variants"]:
            out.append(Placement(set_id, set_name, f, v, v["device"] if multi else None))

    for s in sets:
        for f in s["fields"]:
            add(s["id"], s["name"], f)
    for r in protocol["reserved_fields"]:
        targets = [(s["id"], s["name"]) for s in sets if s["kind"] == r["applies_to"]]
        u = undefined(r["applies_to"])
        if u is not None:
            targets.append((u, "undefined"))
        for sid, sname in targets:
            add(sid, sname, r)
    shared = [s for s in sets if s.get("shared")]
    if shared:
        targets = [(s["id"], s["name"]) for s in sets if s["kind"] == "data" and not s.get("shared")]
        u = undefined("data")
        if u is not None:
            targets.append((u, "undefined"))
        for s in shared:
            for f in s["fields"]:
                for sid, sname in targets:
                    add(sid, sname, f)
    return out


# ----------------------------------------------------------------------------------------- a round
@dataclass
class Packet:
    set_id: int
    fields: list  # FieldSample

    def payload(self, framing: Framing) -> bytes:
        return b"".join(framing.field(self.set_id, f.descriptor, f.data) for f in self.fields)

    def line(self, offset: int) -> str:
        return f'{{"offset":{offset},"set":{self.set_id},"fields":[{",".join(f.line() for f in self.fields)}]}}'


@dataclass
class Group:
    """One protocol and device (None: any): the values stream and the mutants stream."""

    protocol: str
    device: str | None
    ref: Reference
    gen: ValueGen
    packets: list = field(default_factory=list)
    lines: list = field(default_factory=list)  # expected decode lines of the values stream
    what: list = field(default_factory=list)  # per line: the samples in it
    stream: bytes = b""
    mutants: bytes = b""
    mutant_what: dict = field(default_factory=dict)  # offset -> description

    @property
    def gid(self) -> str:
        return f"{self.protocol}-{self.device or 'any'}"

    def text(self) -> str:
        return "".join(x + "\n" for x in self.lines)


def build_round(protocols: list[dict], seed: int) -> list[Group]:
    """The groups of one round: values and mutants of every layout of every protocol."""
    rng = random.Random(seed)
    groups: dict = {}
    for proto in sorted(protocols, key=lambda p: p["name"]):
        gen = ValueGen(proto, rng)
        framing = gen.framing
        ref = Reference(proto)
        per_group: dict = {}
        for pl in placements(proto, rng):
            per_group.setdefault(pl.device, []).extend(gen.samples(pl))
        for device in sorted(per_group, key=lambda d: d or ""):
            g = Group(proto["name"], device, ref, gen)
            # Pack samples of the same set into packets of one to several fields.
            pk = None
            for s in per_group[device]:
                size = len(framing.field(s.set_id, s.descriptor, s.data))
                if (
                    pk is None
                    or pk.set_id != s.set_id
                    or rng.random() < 0.6
                    or len(pk.payload(framing)) + size > framing.max_payload
                ):
                    pk = Packet(s.set_id, [])
                    g.packets.append(pk)
                pk.fields.append(s)
            out = bytearray()
            for p in g.packets:
                g.lines.append(p.line(len(out)))
                g.what.append([f.what for f in p.fields])
                out += framing.packet(p.set_id, p.payload(framing))
            g.stream = bytes(out)
            groups[(proto["name"], device)] = g
        mutate(proto, gen, framing, groups, rng)
    return [groups[k] for k in sorted(groups, key=lambda k: (k[0], k[1] or ""))]


# ----------------------------------------------------------------------------------------- mutants
def mutate(proto: dict, gen: ValueGen, framing: Framing, groups: dict, rng: random.Random) -> None:
    """Corrupted copies of every packet of the protocol. A device group gets its own packets'
    mutants (decoded for that device); the any-device group gets every packet's mutants."""
    defined = {s["id"]: s for s in proto["sets"]}
    descriptors = {s["id"]: sorted(f["id"] for f in s["fields"]) for s in proto["sets"]}
    reserved = {}
    for r in proto["reserved_fields"]:
        reserved.setdefault(r["applies_to"], set()).add(r["id"])
    kinds = proto["set_kinds"]

    def kind_of(set_id: int) -> str | None:
        return next((k for k, r in kinds.items() if r["first"] <= set_id <= r["last"]), None)

    def unknown_descriptor(set_id: int) -> int:
        used = set(descriptors.get(set_id, [])) | reserved.get(kind_of(set_id), set())
        if kind_of(set_id) == "data" and proto["shared_data"]:
            used |= set(descriptors.get(proto["shared_data"]["set"], []))
        free = [d for d in range(256) if d not in used]
        return rng.choice(free)

    protos = [g for (p, _), g in groups.items() if p == proto["name"]]
    any_group = next(g for g in protos if g.device is None)
    rule = proto["samples"]
    for g in protos:
        targets = [g] if g.device is None else [g, any_group]
        streams = {id(t): bytearray(t.mutants) for t in targets}
        by_set: dict = {}
        for p in g.packets:
            by_set.setdefault(p.set_id, []).append(p)
        for p in g.packets:
            for pkt, what in continuation(p, by_set, rule, framing, rng):
                for t in targets:
                    t.mutant_what[len(streams[id(t)])] = what
                    streams[id(t)] += pkt
            for _ in range(2):
                fields = [
                    [f.descriptor, bytearray(f.data), None, f] for f in p.fields
                ]  # descriptor, data, length, sample
                set_id = p.set_id
                desc = []
                for _m in range(rng.choice([1, 1, 1, 2, 3])):
                    set_id, what = mutate_one(
                        rng, fields, set_id, gen, framing, defined, descriptors, unknown_descriptor
                    )
                    desc.append(what)
                payload = bytearray()
                for d, data, length, _ in fields:
                    fb = framing.field(set_id, d, bytes(data), length)
                    if fb is None:
                        fb = framing.field(set_id, d, bytes(data))
                    if fb is None:
                        fb = bytes(data)
                    payload += fb
                extra = rng.random()
                if extra < 0.05:  # cut the payload anywhere
                    cut = rng.randrange(len(payload) + 1)
                    payload = payload[:cut]
                    desc.append(f"payload cut at {cut}")
                elif extra < 0.1:
                    junk = bytes(rng.randrange(256) for _ in range(rng.randint(1, 3)))
                    payload += junk
                    desc.append(f"payload + {junk.hex()}")
                if len(payload) > framing.max_payload:
                    payload = payload[: framing.max_payload]
                    desc.append(f"payload cut at {framing.max_payload}")
                origin = ", ".join(f[3].what for f in fields)
                bad = rng.random() < 0.02
                pkt = framing.packet(set_id, bytes(payload), bad_checksum=bad)
                junk = b""
                r = rng.random()
                if r < 0.03:
                    junk = bytes(rng.randrange(256) for _ in range(rng.randint(1, 4)))
                elif r < 0.05:  # a false sync with a length running into the next packet
                    junk = framing.sync + bytes([rng.randrange(256), rng.randrange(256)])
                for t in targets:
                    s = streams[id(t)]
                    if junk:
                        t.mutant_what[len(s)] = f"junk {junk.hex()} before the mutant of {origin}"
                        s += junk
                    t.mutant_what[len(s)] = f"{origin}: {'; '.join(desc)}" + (" (bad checksum)" if bad else "")
                    s += pkt
        for t in targets:
            t.mutants = bytes(streams[id(t)])
    # The end of each stream: framing the flush rule of §1 has to sort out.
    for g in protos:
        s = bytearray(g.mutants)
        good = framing.packet(0x01, framing.field(0x01, 0x01, b""))
        tails = [
            (framing.sync + bytes([0x01, 0x40]) + good, "false sync whose length runs past the end, then a packet"),
            (good[:-1], "a packet missing its last checksum byte"),
            (framing.sync[:1], "half a sync sequence"),
            (framing.sync + bytes([0x01]), "a sync and a set byte"),
        ]
        rng.shuffle(tails)
        for tail, what in tails[: rng.randint(1, len(tails))]:
            g.mutant_what[len(s)] = what
            s += tail
        g.mutants = bytes(s)


def continuation(p: Packet, by_set: dict, rule: dict, framing: Framing, rng: random.Random) -> list:
    """For a data packet that starts with shared fields (§6): the packet itself, then a packet
    of the same set repeating its leading shared run before other fields (a continuation), at
    times with a packet of another set or a keyless one in between, or a byte of the run changed."""
    if p.set_id not in rule["data_sets"] or rng.random() < 0.5:
        return []
    lead = []
    for f in p.fields:
        if f.descriptor < rule["first_shared"]:
            break
        lead.append(f)
    if not lead:
        return []
    lead_bytes = bytearray(b"".join(framing.field(p.set_id, f.descriptor, f.data) for f in lead))
    other = rng.choice(by_set[p.set_id])
    rest = b"".join(framing.field(p.set_id, f.descriptor, f.data) for f in other.fields)
    what = f"continuation of {p.fields[0].what}"
    out = [(framing.packet(p.set_id, p.payload(framing)), f"{p.fields[0].what}: the first packet of a sample")]
    r = rng.random()
    if r < 0.2:
        at = rng.randrange(len(lead_bytes))
        lead_bytes[at] ^= 1 << rng.randrange(8)
        what += f" with byte {at} of the shared run changed"
    elif r < 0.4:
        q = rng.choice([q for qs in by_set.values() for q in qs])
        out.append(
            (framing.packet(q.set_id, q.payload(framing)), f"{q.fields[0].what}: between two packets of a sample")
        )
    elif r < 0.5:
        plain = [f for f in other.fields if f.descriptor < rule["first_shared"]]
        payload = b"".join(framing.field(p.set_id, f.descriptor, f.data) for f in plain)
        out.append((framing.packet(p.set_id, payload), "a packet of the same set without a shared run"))
    payload = (bytes(lead_bytes) + rest)[: framing.max_payload]
    out.append((framing.packet(p.set_id, payload), what))
    if rng.random() < 0.3:
        out.append(
            (framing.packet(p.set_id, (bytes(lead_bytes) + rest[::-1])[: framing.max_payload]), what + " (again)")
        )
    return out


def _set_int(data: bytearray, spot: Spot, value: int, order: str) -> None:
    size = spot.size
    lo, hi = int_range(spot.info["base"]) if "base" in spot.info else (0, (1 << (8 * size)) - 1)
    value = max(lo, min(hi, value))
    data[spot.offset : spot.offset + size] = value.to_bytes(size, order, signed=lo < 0)


def mutate_one(rng, fields, set_id, gen: ValueGen, framing: Framing, defined, descriptors, unknown_descriptor):
    """Apply one corruption to the packet (fields: [descriptor, data, length byte or None, sample])."""
    i = rng.randrange(len(fields))
    f = fields[i]
    data = f[1]
    spots = [s for s in f[3].spots if s.offset + s.size <= len(data)]
    r = rng.random()
    order = gen.order
    if r < 0.35 and spots:
        s = rng.choice(spots)
        if s.kind == "bool":
            v = rng.choice([2, 0xFF, rng.randrange(2, 256)])
            data[s.offset] = v
            return set_id, f"{s.path} bool byte {v}"
        if s.kind == "count":
            lo, hi = int_range(s.info["base"])
            v = rng.choice(
                [
                    s.info["max"] + 1,
                    min(hi, s.info["max"] + rng.randint(1, 300)),
                    hi,
                    s.info["n"] + 1,
                    max(0, s.info["n"] - 1),
                ]
            )
            _set_int(data, s, v, order)
            return set_id, f"{s.path} count {v} (max {s.info['max']}, was {s.info['n']})"
        if s.kind == "selector":
            lo, hi = int_range(s.info["base"])
            free = [v for v in (gen.enum_choices(s.info["enum"]) + [lo, hi]) if v not in s.info["members"]]
            v = rng.choice(free) if free else rng.choice(s.info["members"])
            _set_int(data, s, v, order)
            return set_id, f"{s.path} selector {v}"
        if s.kind == "function":
            v = rng.randrange(256)
            data[s.offset] = v
            return set_id, f"function {v}"
        if s.kind == "enum":
            lo, hi = int_range(s.info["base"])
            v = rng.randint(lo, hi)
            _set_int(data, s, v, order)
            return set_id, f"{s.path} enum {v}"
        bits = gen.float_bits(s.kind == "float")
        data[s.offset : s.offset + s.size] = bits.to_bytes(s.size, order)
        return set_id, f"{s.path} bits {bits:x}"
    if r < 0.47 and data:
        n = rng.choice([1, 1, 2, rng.randint(1, len(data))])
        n = min(n, len(data))
        del data[len(data) - n :]
        return set_id, f"field {i} data cut by {n}"
    if r < 0.57:
        n = rng.choice([1, 1, 2, 4, rng.randint(1, 12)])
        data += bytes(rng.choice([0, 1, 0xFF, rng.randrange(256)]) for _ in range(n))
        return set_id, f"field {i} data + {n} bytes"
    if r < 0.69 and data:
        at = rng.randrange(len(data))
        v = rng.choice([data[at] ^ (1 << rng.randrange(8)), rng.randrange(256), 0, 0xFF, 2])
        data[at] = v
        return set_id, f"field {i} byte {at} = {v:02x}"
    if r < 0.77:
        real = len(data) + framing.adjust(set_id, f[0])
        v = rng.choice([0, 1, 2, 3, 255, real + 1, real - 1, real + 2, rng.randrange(256)])
        f[2] = v if 0 <= v <= 255 else None
        return set_id, f"field {i} length byte {v}"
    if r < 0.85:
        old = f[0]
        if rng.random() < 0.5 and descriptors.get(set_id):
            f[0] = rng.choice(descriptors[set_id])
        else:
            f[0] = unknown_descriptor(set_id)
        return set_id, f"field {i} descriptor {old:02x} -> {f[0]:02x}"
    choices = list(defined) + [rng.randrange(256), 0]
    new = rng.choice(choices)
    return new, f"set {set_id:02x} -> {new:02x}"


# ----------------------------------------------------------------------------------------- running
def run_cli(tool: str, lang: str, protocol: str, data: bytes = b"", args: tuple = ()) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(ROOT / "tests/conformance" / tool), lang, *args, "--protocol", protocol],
        input=data,
        capture_output=True,
    )


def _first_diff(a: list, b: list) -> int:
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            return i
    return min(len(a), len(b))


def _short(text: str, n: int = 600) -> str:
    return text if len(text) <= n else text[:n] + "..."


def write_files(g: Group, seed: int) -> Path:
    d = WORK / str(seed)
    d.mkdir(parents=True, exist_ok=True)
    (d / f"values-{g.gid}.jsonl").write_text(g.text())
    (d / f"values-{g.gid}.bin").write_bytes(g.stream)
    (d / f"mutants-{g.gid}.bin").write_bytes(g.mutants)
    return d


def check_group(g: Group, seed: int, langs=LANGS) -> tuple[list[str], dict]:
    """Every check of one group; returns (failures, counts). Each failure is self-contained text."""
    d = write_files(g, seed)
    rel = os.path.relpath(d, ROOT)
    dev = ("--device", g.device) if g.device else ()
    devtxt = f" --device {g.device}" if g.device else ""
    head = f"[seed {seed}, group {g.gid}; replay: {replay_command(seed)}]"
    fails: list[str] = []
    counts = {"samples": sum(len(w) for w in g.what), "packets": len(g.packets), "mutants": len(g.mutant_what)}

    # 0. the generator and the reference decoder agree on the values stream.
    want_values = g.ref.decode_stream(g.stream, g.device)
    if want_values != g.lines:
        bad = [i for i, (w, x) in enumerate(zip(g.lines, want_values)) if w != x]
        fails.append(
            f"{head} generator and reference decoder disagree (a bug of the test): {len(bad)} packets\n"
            + "\n".join(
                f"  {'; '.join(g.what[i])}:\n    gen {_short(g.lines[i])}\n    ref {_short(want_values[i])}"
                for i in bad[:5]
            )
        )

    # 1. every encoder writes the reference bytes.
    text = g.text().encode()
    for lang in langs:
        enc = run_cli("encode", lang, g.protocol, text)
        if enc.returncode != 0 or enc.stdout != g.stream:
            msg = enc.stderr.decode(errors="replace").strip().splitlines()
            detail = ""
            if enc.stdout != g.stream:
                # Find the packet where the bytes first differ.
                offs = [int(x.split(",", 1)[0][10:]) for x in g.lines]
                at = _first_diff(list(enc.stdout), list(g.stream))
                idx = max((i for i, o in enumerate(offs) if o <= at), default=0)
                end = offs[idx + 1] if idx + 1 < len(offs) else len(g.stream)
                detail = (
                    f"\n  first difference at byte {at}, in packet {idx} ({'; '.join(g.what[idx])})"
                    f"\n  line: {_short(g.lines[idx])}\n  want: {g.stream[offs[idx] : end].hex()}"
                    f"\n  got:  {enc.stdout[offs[idx] : end].hex()}"
                )
            fails.append(
                f"{head} {lang} encode (exit {enc.returncode}) does not give the reference bytes"
                f" ({len(enc.stdout)} vs {len(g.stream)} bytes); stderr: {_short(' | '.join(msg[:5]))}{detail}"
                f"\n  cmd: tests/conformance/encode {lang} --protocol {g.protocol} < {rel}/values-{g.gid}.jsonl"
            )

    # 2. every decoder gives back the lines, and decode | encode the bytes.
    vfile = d / f"values-{g.gid}.bin"
    for lang in langs:
        dec = run_cli("decode", lang, g.protocol, args=(str(vfile),) + dev)
        got = dec.stdout.decode(errors="replace").splitlines()
        cmd = f"tests/conformance/decode {lang} {rel}/values-{g.gid}.bin{devtxt} --protocol {g.protocol}"
        if dec.returncode != 0 or got != g.lines:
            bad = [i for i, (w, x) in enumerate(zip(g.lines, got)) if w != x]
            lines = [
                f"  {'; '.join(g.what[i])}:\n    want {_short(g.lines[i])}\n    got  {_short(got[i])}" for i in bad[:8]
            ]
            fails.append(
                f"{head} {lang} decode (exit {dec.returncode}): {len(bad)} of {len(g.lines)} packets differ,"
                f" {len(got)} lines for {len(g.lines)}\n  cmd: {cmd}\n" + "\n".join(lines)
            )
            continue
        back = run_cli("encode", lang, g.protocol, dec.stdout)
        if back.returncode != 0 or back.stdout != g.stream:
            fails.append(
                f"{head} {lang}: decode | encode does not give back the values stream\n  cmd: {cmd} | tests/conformance/encode {lang} --protocol {g.protocol}"
            )

    # 3. mutants: the four decoders print the same text; decode | encode gives back the bytes.
    mfile = d / f"mutants-{g.gid}.bin"
    outs = {}
    for lang in langs:
        dec = run_cli("decode", lang, g.protocol, args=(str(mfile),) + dev)
        outs[lang] = dec.stdout.decode(errors="replace").splitlines()
        cmd = f"tests/conformance/decode {lang} {rel}/mutants-{g.gid}.bin{devtxt} --protocol {g.protocol}"
        if dec.returncode != 0:
            fails.append(
                f"{head} {lang} decode of the mutants exits {dec.returncode}: {_short(dec.stderr.decode(errors='replace'))}\n  cmd: {cmd}"
            )
            continue
        back = run_cli("encode", lang, g.protocol, dec.stdout)
        if back.returncode != 0 or back.stdout != g.mutants:
            at = _first_diff(list(back.stdout), list(g.mutants))
            where = max((o for o in g.mutant_what if o <= at), default=0)
            fails.append(
                f"{head} {lang}: decode | encode of the mutants differs from byte {at}"
                f" (mutant at {where}: {g.mutant_what.get(where)}); stderr: {_short(back.stderr.decode(errors='replace'))}"
                f"\n  cmd: {cmd} | tests/conformance/encode {lang} --protocol {g.protocol} | cmp - {rel}/mutants-{g.gid}.bin"
            )
    # With --samples (§6), where the protocol has data sets.
    if g.ref.samples["data_sets"]:
        want = g.ref.decode_stream(g.mutants, g.device, samples=True)
        for lang in langs:
            dec = run_cli("decode", lang, g.protocol, args=(str(mfile), "--samples") + dev)
            got = dec.stdout.decode(errors="replace").splitlines()
            if got != want:
                i = _first_diff(got, want)
                fails.append(
                    f"{head} {lang} decode --samples of the mutants differs from the reference at line {i}:"
                    f"\n    reference {_short(want[i]) if i < len(want) else '(none)'}"
                    f"\n    {lang:9} {_short(got[i]) if i < len(got) else '(none)'}"
                    f"\n  cmd: tests/conformance/decode {lang} {rel}/mutants-{g.gid}.bin --samples{devtxt} --protocol {g.protocol}"
                )

    # The reference decoder (docs/conformance.md read independently) prints the same text.
    outs["reference"] = g.ref.decode_stream(g.mutants, g.device)
    counts["mutant_lines"] = len(outs["reference"])
    ref_lang = "reference"
    for lang, got in outs.items():
        ref = outs[ref_lang]
        if got == ref:
            continue
        bad = [i for i in range(max(len(got), len(ref))) if i >= len(got) or i >= len(ref) or got[i] != ref[i]]
        lines = []
        for i in bad[:6]:
            r = ref[i] if i < len(ref) else "(none)"
            x = got[i] if i < len(got) else "(none)"
            try:
                off = int(r.split(",", 1)[0][10:])
            except ValueError:
                off = -1
            lines.append(
                f"  mutant at {off}: {g.mutant_what.get(off, '?')}\n    {ref_lang:9} {_short(r)}\n    {lang:9} {_short(x)}"
            )
        fails.append(
            f"{head} {lang} and {ref_lang} decode the mutants differently ({len(bad)} lines)"
            f"\n  cmd: tests/conformance/decode {lang} {rel}/mutants-{g.gid}.bin{devtxt} --protocol {g.protocol}\n"
            + "\n".join(lines)
        )

    # 3b. the packet decoders of issue 38 (C, C++, Rust `decode --decoder straight|cached`: the set's
    # straight-line decoder and the layout cache, their typed members written by the same JSON
    # writer) print the same lines on both streams: the same two files, 12 more decode runs.
    for lang in [x for x in TYPED_DECODER_LANGS if x in langs]:
        for decoder in ("straight", "cached"):
            for name, path, want in (("values", vfile, g.lines), ("mutants", mfile, outs["reference"])):
                dec = run_cli("decode", lang, g.protocol, args=(str(path), "--decoder", decoder) + dev)
                got = dec.stdout.decode(errors="replace").splitlines()
                if dec.returncode != 0 or got != want:
                    i = _first_diff(got, want)
                    fails.append(
                        f"{head} {lang} decode --decoder {decoder} of the {name} (exit {dec.returncode},"
                        f" {_short(dec.stderr.decode(errors='replace'))}) differs at line {i}:"
                        f"\n    want {_short(want[i]) if i < len(want) else '(none)'}"
                        f"\n    got  {_short(got[i]) if i < len(got) else '(none)'}"
                        f"\n  cmd: tests/conformance/decode {lang} {rel}/{path.name} --decoder {decoder}{devtxt}"
                        f" --protocol {g.protocol}"
                    )

    # 4. encoder input (§5): other spellings of the same lines give the same bytes; lines made
    # invalid are refused by every encoder, and the others still encoded.
    rng = random.Random(seed ^ 0x5EED ^ len(g.lines))
    fails += check_spellings(g, g.lines, g.stream, "values", rng, langs, head, rel)
    fails += check_spellings(g, outs["reference"], g.mutants, "mutants", rng, langs, head, rel)
    counts["respelled"] = len(g.lines) + len(outs["reference"])
    return fails, counts


def _line_bytes(lines: list[str], stream: bytes) -> list[bytes]:
    """The bytes of each decoded line of a stream (packets and skip runs tile it)."""
    offs = [int(x[10 : x.index(",")]) for x in lines] + [len(stream)]
    return [stream[a:b] for a, b in zip(offs, offs[1:])]


def check_spellings(g: Group, lines: list, stream: bytes, name: str, rng, langs, head: str, rel: str) -> list[str]:
    fails = []
    d = ROOT / rel
    spelled = [respell(x, rng) for x in lines]
    path = d / f"{name}-respelled-{g.gid}.jsonl"
    path.write_text("".join(x + "\n" for x in spelled), encoding="utf-8")
    per_line = _line_bytes(lines, stream)
    # Every fourth line or so made invalid: those must be refused, the others encoded.
    bad_lines = {}
    mixed = []
    for i, x in enumerate(spelled):
        if rng.random() < 0.25:
            text, what = invalidate(lines[i], rng)
            bad_lines[len(mixed) + 1] = (what, text)
            mixed.append(text)
        mixed.append(x)
    mpath = d / f"{name}-invalid-{g.gid}.jsonl"
    mpath.write_text("".join(x + "\n" for x in mixed), encoding="utf-8")
    for lang in langs:
        enc = run_cli("encode", lang, g.protocol, path.read_bytes())
        cmd = f"tests/conformance/encode {lang} --protocol {g.protocol} < {rel}/{path.name}"
        if enc.returncode != 0 or enc.stdout != stream:
            err = enc.stderr.decode(errors="replace").splitlines()
            at = _first_diff(list(enc.stdout), list(stream))
            idx = next((i for i, b in enumerate(_cumulative(per_line)) if b > at), len(lines) - 1)
            fails.append(
                f"{head} {lang} encode of respelled {name} lines (exit {enc.returncode}) does not give the bytes;"
                f" stderr: {_short(' | '.join(err[:3]))}\n  first difference in line {idx + 1}:"
                f"\n    canonical {_short(lines[idx])}\n    respelled {_short(spelled[idx])}\n  cmd: {cmd}"
            )
        enc = run_cli("encode", lang, g.protocol, mpath.read_bytes())
        err = enc.stderr.decode(errors="replace")
        named = {int(n) for n in re.findall(r"\bline (\d+):[ \t]*\S", err)}
        cmd = f"tests/conformance/encode {lang} --protocol {g.protocol} < {rel}/{mpath.name}"
        missed = [f"line {n}: {w}: {_short(t, 300)}" for n, (w, t) in sorted(bad_lines.items()) if n not in named]
        extra = sorted(named - set(bad_lines))
        if missed or extra or enc.stdout != stream or (enc.returncode != 1 if bad_lines else enc.returncode != 0):
            fails.append(
                f"{head} {lang} encode of {name} lines with invalid ones among them: {len(missed)} invalid lines"
                f" accepted, {len(extra)} valid lines refused (lines {extra[:5]}), exit {enc.returncode},"
                f" bytes {'equal' if enc.stdout == stream else 'differ'}\n  cmd: {cmd}\n"
                + "\n".join("  " + m for m in missed[:5])
                + (
                    "\n  refused: "
                    + _short(" | ".join(x for x in err.splitlines() if any(f"line {n}:" in x for n in extra[:3])))
                    if extra
                    else ""
                )
            )
    return fails


def _cumulative(parts: list[bytes]) -> list[int]:
    out, total = [], 0
    for p in parts:
        total += len(p)
        out.append(total)
    return out


def load_protocols() -> list[dict]:
    from generator.spec import load_spec

    return load_spec()["protocols"]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description="Differential test rounds over the four languages (docs/conformance.md).")
    ap.add_argument("--rounds", type=int, default=50)
    ap.add_argument(
        "--seed", type=lambda s: int(s, 0), default=None, help="first seed (then seed+1, ...); default: random seeds"
    )
    ap.add_argument("--langs", default=",".join(LANGS))
    args = ap.parse_args(argv)
    langs = args.langs.split(",")
    protocols = load_protocols()
    sysrng = random.SystemRandom()
    total = {"samples": 0, "packets": 0, "mutants": 0, "mutant_lines": 0, "respelled": 0}
    failed_seeds = []
    t0 = time.time()
    for r in range(args.rounds):
        seed = args.seed + r if args.seed is not None else sysrng.randrange(1 << 32)
        t = time.time()
        groups = build_round(protocols, seed)
        fails = []
        for g in groups:
            f, c = check_group(g, seed, langs)
            fails += f
            for k in total:
                total[k] += c[k]
        if not fails:  # keep the streams of failing seeds only (a round writes about 10 MB)
            shutil.rmtree(WORK / str(seed), ignore_errors=True)
        status = "ok" if not fails else f"{len(fails)} FAILURES"
        print(f"round {r + 1}/{args.rounds} seed {seed}: {status} ({time.time() - t:.1f} s)", flush=True)
        for f in fails:
            print(f, flush=True)
        if fails:
            failed_seeds.append(seed)
    print(
        f"differential: {args.rounds} rounds, {total['samples']} field samples in {total['packets']} packets,"
        f" {total['mutants']} mutants ({total['mutant_lines']} decoded lines), {total['respelled']} lines"
        f" respelled, {time.time() - t0:.0f} s; failing seeds: {failed_seeds or 'none'}"
    )
    return 1 if failed_seeds else 0


if __name__ == "__main__":
    sys.exit(main())
