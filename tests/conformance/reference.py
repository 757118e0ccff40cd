"""A reference decoder written from docs/conformance.md §1-§4 and the IR alone.

It is the oracle of the differential test's mutation pass: the four generated decoders must print
exactly its text for corrupted packets, so that a misreading of the contract shared by all four
languages (they come from one generator) does not go unnoticed. It is slow, simple and separate
from the generator's templates; `test_differential.py` first checks it against every golden vector
(whose expected text was derived by hand or read off the manuals).
"""

from __future__ import annotations

import json

from generator.canonical import float_text, string_text
from generator.primitives import PRIMITIVES
from generator.vectors import foreign_fields, foreign_length, foreign_line
from tests.helpers.packets import checksum

INTS = ("u8", "u16", "u32", "u64", "s8", "s16", "s32", "s64")


class DecodeError(Exception):
    """A layout does not match the field data; str() is the message of §3."""


class Reference:
    """Decoder of one protocol's streams into canonical JSON lines."""

    def __init__(self, protocol: dict):
        self.p = protocol
        fr = protocol["framing"]
        self.fr = fr
        self.sync = bytes(fr["sync"])
        self.types = {t["name"]: t for t in protocol["types"]}
        self.order = "big" if protocol["byte_order"] == "big" else "little"
        self.sets = {s["id"]: s for s in protocol["sets"]}
        self.fields = {(s["id"], f["id"]): f for s in protocol["sets"] for f in s["fields"]}
        self.reserved = {(r["applies_to"], r["id"]): r for r in protocol["reserved_fields"]}
        self.shared = protocol["shared_data"]["set"] if protocol["shared_data"] else None
        self.irregular = {(e["set"], e["descriptor"]): e["adjust"] for e in fr["irregular_lengths"]}
        self.kinds = protocol["set_kinds"]
        self.samples = protocol["samples"]

    # -- §1 stream parser over the whole input (flush at the end) ------------------------------
    def decode_stream(self, buf: bytes, device: str | None = None, samples: bool = False) -> list[str]:
        """The canonical lines of a stream; with `samples`, every packet of a data set carries its
        sample number (§6) after its set."""
        fr = self.fr
        tracker = SampleNumbers(self) if samples else None
        hs = fr["header_size"]
        n = len(buf)
        lines: list[str] = []
        skip_start = None
        skipped = bytearray()

        def skip(i: int, count: int) -> None:
            nonlocal skip_start
            if count <= 0:
                return
            if skip_start is None:
                skip_start = i
            skipped.extend(buf[i : i + count])

        def flush_skip() -> None:
            nonlocal skip_start
            if skip_start is not None:
                lines.append('{"offset":%d,"skipped":"%s"}' % (skip_start, skipped.hex()))
                skip_start = None
                skipped.clear()

        pos = 0
        while pos < n:
            i = buf.find(self.sync, pos)
            # Bytes before the next sync are skipped, but for the NMEA sentences and RTCM3 frames
            # among them (§1, foreign frames; generator/vectors.py checks the corpus the same way).
            end = i if i >= 0 else n
            while pos < end:
                size = foreign_length(buf, pos, fr) if fr.get("foreign_frames") else 0
                if size:
                    flush_skip()
                    lines.append(foreign_line(foreign_fields(buf[pos : pos + size]) | {"offset": pos}))
                    pos += size
                else:
                    skip(pos, 1)
                    pos += 1
            if i < 0 or pos > i:
                continue
            if n - i < hs:
                skip(i, 1)
                pos = i + 1
                continue
            length = buf[i + fr["length_offset"]]
            total = hs + length + fr["checksum_size"]
            if length > fr["max_payload"] or n - i < total:
                skip(i, 1)
                pos = i + 1
                continue
            want = checksum(fr, buf[i : i + hs + length])
            if buf[i + hs + length : i + total] != want:
                skip(i, 1)
                pos = i + 1
                continue
            flush_skip()
            line = self.packet_line(i, buf[i : i + total], device)
            if tracker is not None:
                number = tracker.feed(buf[i : i + total])
                if number is not None:
                    at = line.index(',"fields":')
                    line = line[:at] + f',"sample":{number}' + line[at:]
            lines.append(line)
            pos = i + total
        flush_skip()
        return lines

    # -- §2 payload -> fields -----------------------------------------------------------------
    def split(self, set_id: int, payload: bytes) -> list:
        """The complete fields of a payload as (descriptor, header + data), up to a trailing entry."""
        fr = self.fr
        hsz = fr["field_header_size"]
        out = []
        o = 0
        while len(payload) - o >= hsz:
            desc = payload[o + fr["field_descriptor_offset"]]
            dlen = (
                payload[o + fr["field_length_offset"]]
                - fr["field_length_adjust"]
                - self.irregular.get((set_id, desc), 0)
            )
            if dlen < 0 or hsz + dlen > len(payload) - o:
                break
            out.append((desc, payload[o : o + hsz + dlen]))
            o += hsz + dlen
        return out

    def packet_line(self, offset: int, pkt: bytes, device: str | None) -> str:
        fr = self.fr
        set_id = pkt[fr["set_offset"]]
        payload = pkt[fr["header_size"] : len(pkt) - fr["checksum_size"]]
        entries = []
        o = 0
        hsz = fr["field_header_size"]
        while o < len(payload):
            r = len(payload) - o
            if r < hsz:
                entries.append(
                    self.trailing(payload[o:], f"field header at payload offset {o} needs {hsz} bytes, {r} left")
                )
                break
            length = payload[o + fr["field_length_offset"]]
            desc = payload[o + fr["field_descriptor_offset"]]
            dlen = length - fr["field_length_adjust"] - self.irregular.get((set_id, desc), 0)
            if dlen < 0:
                entries.append(
                    self.trailing(
                        payload[o:], f"field length {length} at payload offset {o} is shorter than the field header"
                    )
                )
                break
            if hsz + dlen > r:
                entries.append(
                    self.trailing(
                        payload[o:],
                        f"field length {length} at payload offset {o} overruns the payload ({r} bytes left)",
                    )
                )
                break
            entries.append(self.field_entry(set_id, desc, payload[o + hsz : o + hsz + dlen], device))
            o += hsz + dlen
        return '{"offset":%d,"set":%d,"fields":[%s]}' % (offset, set_id, ",".join(entries))

    @staticmethod
    def trailing(data: bytes, error: str) -> str:
        return '{"trailing":"%s","error":%s}' % (data.hex(), json.dumps(error))

    def kind(self, set_id: int) -> str | None:
        return next((k for k, r in self.kinds.items() if r["first"] <= set_id <= r["last"]), None)

    def lookup(self, set_id: int, desc: int) -> dict | None:
        f = self.fields.get((set_id, desc))
        if f is not None:
            return f
        kind = self.kind(set_id)
        f = self.reserved.get((kind, desc))
        if f is not None:
            return f
        if kind == "data" and self.shared is not None:
            return self.fields.get((self.shared, desc))
        return None

    def field_entry(self, set_id: int, desc: int, data: bytes, device: str | None) -> str:
        f = self.lookup(set_id, desc)
        if f is None:
            error = "unknown descriptor" if set_id in self.sets else "unknown descriptor set"
            return '{"descriptor":%d,"data":"%s","error":%s}' % (desc, data.hex(), json.dumps(error))
        variants = f["variants"]
        if device is not None and len(variants) > 1:
            variants = [v for v in variants if v["device"] == device] or variants
        first_error = None
        for v in variants:
            try:
                values = self.layout(v, data)
            except DecodeError as e:
                first_error = first_error or str(e)
                continue
            dev = f',"device":"{v["device"]}"' if len(f["variants"]) > 1 else ""
            return '{"descriptor":%d,"name":"%s"%s,"values":%s}' % (desc, f["name"], dev, values)
        return '{"descriptor":%d,"data":"%s","error":%s}' % (desc, data.hex(), json.dumps(first_error))

    # -- §3 field data -> values ---------------------------------------------------------------
    def layout(self, variant: dict, data: bytes) -> str:
        parts = []
        o = 0
        if variant["functions"] is not None:
            v, o = self.read_int(data, o, "u8", "function")
            parts.append(f'"function":{v}')
        text, o = self.params(variant["params"], data, o, "", top=True)
        if o != len(data):
            raise DecodeError(f"{len(data) - o} unexpected bytes at offset {o}")
        inner = text[1:-1]
        return "{" + ",".join(x for x in (",".join(parts), inner) if x) + "}"

    def read_int(self, data: bytes, o: int, base: str, path: str) -> tuple[int, int]:
        size, _, signed = PRIMITIVES[base]
        if len(data) - o < size:
            raise DecodeError(f"{path}: needs {size} bytes at offset {o}, {len(data) - o} left")
        return int.from_bytes(data[o : o + size], self.order, signed=signed), o + size

    def params(self, params: list[dict], data: bytes, o: int, prefix: str, top: bool = False) -> tuple[str, int]:
        ints: dict = {}
        items: list = []  # (param, text, start, end)
        for p in params:
            if p["optional"] and o >= len(data):
                continue
            start = o
            text, o = self.param(p, data, o, prefix + p["name"], ints)
            items.append((p, text, start, o))
        # §4: an optional parameter that took no bytes and has nothing after it prints as absent.
        while items and items[-1][0]["optional"] and items[-1][2] == items[-1][3]:
            items.pop()
        return "{" + ",".join(f'"{p["name"]}":{t}' for p, t, _, _ in items) + "}", o

    def param(self, p: dict, data: bytes, o: int, path: str, ints: dict) -> tuple[str, int]:
        t = p["type"]
        c = p["count"]
        if t["kind"] == "union":
            union = self.types[t["name"]]
            sel = ints[t["selector"]]
            member = next((m for m in union["members"] if m["value"] == sel), None)
            if member is None:
                raise DecodeError(f"{path}: no member for selector value {sel}")
            if member["type"] is None:
                return "null", o
            return self.params(self.types[member["type"]]["params"], data, o, path + ".")
        if c is None:
            text, o, raw = self.value(t, data, o, path)
            if raw is not None:
                ints[p["name"]] = raw
            return text, o
        if c["kind"] == "fixed":
            n = c["value"]
        elif c["kind"] == "param":
            n = ints[c["param"]]
            if n > p["max_count"]:
                raise DecodeError(f"{path}: count {n} exceeds maximum {p['max_count']}")
        else:
            size = t["size"]
            h = len(data) - o
            if size["fixed"]:
                if h % size["max"]:
                    raise DecodeError(f"{path}: {h} bytes left at offset {o}, not a multiple of {size['max']}")
                n = h // size["max"]
                if n > p["max_count"]:
                    raise DecodeError(f"{path}: count {n} exceeds maximum {p['max_count']}")
            else:
                out = []
                while o < len(data):
                    if len(out) == p["max_count"]:
                        raise DecodeError(f"{path}: count {len(out) + 1} exceeds maximum {p['max_count']}")
                    text, o, _ = self.value(t, data, o, f"{path}[{len(out)}]")
                    out.append(text)
                return "[" + ",".join(out) + "]", o
        out = []
        for i in range(n):
            text, o, _ = self.value(t, data, o, f"{path}[{i}]")
            out.append(text)
        return "[" + ",".join(out) + "]", o

    def value(self, t: dict, data: bytes, o: int, path: str) -> tuple[str, int, int | None]:
        kind = t["kind"]
        if kind == "primitive":
            name = t["name"]
            if name in INTS:
                v, o = self.read_int(data, o, name, path)
                return str(v), o, v
            if name == "bool":
                v, o2 = self.read_int(data, o, "u8", path)
                if v > 1:
                    raise DecodeError(f"{path}: invalid bool value {v} at offset {o}")
                return ("true" if v else "false"), o2, None
            if name in ("float", "double"):
                single = name == "float"
                bits, o = self.read_int(data, o, "u32" if single else "u64", path)
                return float_bits_text(bits, single), o, None
            if name == "char":
                n = 1
            else:
                raise NotImplementedError(name)
        if kind == "string" or kind == "primitive":
            n = t.get("length", 1)
            if len(data) - o < n:
                raise DecodeError(f"{path}: needs {n} bytes at offset {o}, {len(data) - o} left")
            return string_text(data[o : o + n]), o + n, None
        if kind in ("enum", "bitfield"):
            v, o = self.read_int(data, o, t["base"], path)
            return str(v), o, v
        if kind == "struct":
            text, o = self.params(self.types[t["name"]]["params"], data, o, path + ".")
            return text, o, None
        raise NotImplementedError(kind)


def float_bits_text(bits: int, single: bool) -> str:
    import math
    import struct

    nan = (
        (bits & 0x7F800000) == 0x7F800000 and (bits & 0x007FFFFF) != 0
        if single
        else (bits & 0x7FF0000000000000) == 0x7FF0000000000000 and (bits & 0x000FFFFFFFFFFFFF) != 0
    )
    if nan:
        return float_text(math.nan, bits=bits, single=single)
    value = struct.unpack(">f" if single else ">d", bits.to_bytes(4 if single else 8, "big"))[0]
    return float_text(value, single=single)


class SampleNumbers:
    """§6: the sample number of each packet of a data set, from the keys of its leading shared run."""

    def __init__(self, ref: Reference):
        rule = ref.samples
        self.ref = ref
        self.data_sets = set(rule["data_sets"])
        self.first_shared = rule["first_shared"]
        self.sizes = {t["descriptor"]: t["size"] for t in rule["timestamps"]}
        self.next = 0
        self.last: dict = {}  # set -> (number, key)

    def key(self, set_id: int, payload: bytes) -> bytes | None:
        key = b""
        seen = set()
        hsz = self.ref.fr["field_header_size"]
        for desc, raw in self.ref.split(set_id, payload):
            if desc < self.first_shared:
                break
            if self.sizes.get(desc) == len(raw) - hsz and desc not in seen:
                seen.add(desc)
                key += raw
        return key or None

    def feed(self, pkt: bytes) -> int | None:
        fr = self.ref.fr
        set_id = pkt[fr["set_offset"]]
        if set_id not in self.data_sets:
            return None
        key = self.key(set_id, pkt[fr["header_size"] : len(pkt) - fr["checksum_size"]])
        last = self.last.get(set_id)
        if key is not None and last is not None and last[1] == key:
            return last[0]
        number = self.next
        self.next += 1
        self.last[set_id] = (number, key)
        return number
