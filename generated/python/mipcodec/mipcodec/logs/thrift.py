"""Thrift's compact protocol (https://github.com/apache/thrift/blob/master/doc/specs/thrift-compact-protocol.md),
as much as Parquet's footers and page headers use (logs/parquet_part.py): a decoder into
{field id: (type, value)} dicts that keeps every field, and an encoder that writes them back
byte for byte; `fields` encodes some fields of a struct, so that a caller can splice encoded
parts (`Reader.spans` says where each field is)."""

import struct
from typing import Any, Dict, Tuple

# The compact protocol's types (a bool field's type is its value).
STOP, TRUE, FALSE, BYTE, I16, I32, I64, DOUBLE, BINARY, LIST, SET, MAP, STRUCT = range(13)

Struct = Dict[int, Tuple[int, Any]]


class Reader:
    """Decodes Thrift compact protocol into {field id: (type, value)} dicts (lists as (element
    type, values)): every field kept, so that encoding it again gives the same bytes."""

    __slots__ = ("b", "i")

    def __init__(self, b: Any, i: int = 0) -> None:
        self.b, self.i = b, i

    def varint(self) -> int:
        b, i, shift, out = self.b, self.i, 0, 0
        while True:
            c: int = b[i]
            i += 1
            out |= (c & 0x7F) << shift
            if c < 0x80:
                self.i = i
                return out
            shift += 7

    def zigzag(self) -> int:
        n = self.varint()
        return (n >> 1) ^ -(n & 1)

    def value(self, t: int) -> Any:
        if t == TRUE or t == FALSE:
            return t == TRUE
        if t in (I16, I32, I64):
            return self.zigzag()
        if t == BINARY:
            n = self.varint()
            v = bytes(self.b[self.i : self.i + n])
            self.i += n
            return v
        if t == STRUCT:
            return self.struct()
        if t in (LIST, SET):
            n, et = self.list_header()
            if et in (TRUE, FALSE):  # a bool element is one byte
                values = [self.b[k] == TRUE for k in range(self.i, self.i + n)]
                self.i += n
                return (et, values)
            return (et, [self.value(et) for _ in range(n)])
        if t == BYTE:
            v = self.b[self.i]
            self.i += 1
            return v - 256 if v > 127 else v
        if t == DOUBLE:
            v = struct.unpack_from("<d", self.b, self.i)[0]
            self.i += 8
            return v
        if t == MAP:
            n = self.varint()
            if not n:
                return (0, 0, [])
            head = self.b[self.i]
            self.i += 1
            kt, vt = head >> 4, head & 15
            return (kt, vt, [(self.value(kt), self.value(vt)) for _ in range(n)])
        raise ValueError(f"Thrift compact type {t} at byte {self.i}")

    def spans(self, keep: Any) -> Tuple[Struct, Dict[int, Tuple[int, int]]]:
        """A struct's fields whose ids are in `keep` (the others skipped, not decoded), and where
        each field is (from its header to its value's end)."""
        out: Struct = {}
        where: Dict[int, Tuple[int, int]] = {}
        fid = 0
        while True:
            at = self.i
            head = self.b[self.i]
            self.i += 1
            if head == STOP:
                return out, where
            t, delta = head & 15, head >> 4
            fid = fid + delta if delta else self.zigzag()
            if fid in keep:
                out[fid] = (t, self.value(t))
            else:
                self.skip(t)
            where[fid] = (at, self.i)

    def list_header(self) -> Tuple[int, int]:
        """A list's or set's (element count, element type)."""
        head = self.b[self.i]
        self.i += 1
        n, et = head >> 4, head & 15
        if n == 15:
            n = self.varint()
        return n, et

    def find(self, fid: int) -> int:
        """Past the fields of the struct being read up to field `fid` (the others skipped); its
        type. A ValueError when the struct ends first."""
        at = 0
        while True:
            head: int = self.b[self.i]
            self.i += 1
            if head == STOP:
                raise ValueError(f"no field {fid}")
            t, delta = head & 15, head >> 4
            at = at + delta if delta else self.zigzag()
            if at == fid:
                return t
            self.skip(t)

    def skip(self, t: int) -> None:
        """Past a value of type `t`, decoding nothing."""
        b = self.b
        if t in (I16, I32, I64):
            while b[self.i] & 0x80:
                self.i += 1
            self.i += 1
        elif t == BINARY:
            n = self.varint()
            self.i += n
        elif t == STRUCT:
            while True:
                head = b[self.i]
                self.i += 1
                if head == STOP:
                    return
                if not head >> 4:
                    self.zigzag()
                self.skip(head & 15)
        elif t in (LIST, SET):
            n, et = self.list_header()
            if et in (TRUE, FALSE, BYTE):
                self.i += n
            elif et == DOUBLE:
                self.i += 8 * n
            else:
                for _ in range(n):
                    self.skip(et)
        elif t == BYTE:
            self.i += 1
        elif t == DOUBLE:
            self.i += 8
        elif t not in (TRUE, FALSE):
            self.value(t)  # a map (not in Parquet's footer): decoded

    def struct(self) -> Struct:
        out: Struct = {}
        fid = 0
        while True:
            head = self.b[self.i]
            self.i += 1
            if head == STOP:
                return out
            t, delta = head & 15, head >> 4
            fid = fid + delta if delta else self.zigzag()
            out[fid] = (t, self.value(t))


def varint(out: bytearray, n: int) -> None:
    while n >= 0x80:
        out.append((n & 0x7F) | 0x80)
        n >>= 7
    out.append(n)


def _value(out: bytearray, t: int, v: Any) -> None:
    if t in (I16, I32, I64):
        varint(out, (v << 1) ^ (v >> 63))
    elif t == BINARY:
        varint(out, len(v))
        out += v
    elif t == STRUCT:
        if isinstance(v, (bytes, bytearray)):  # encoded already
            out += v
        else:
            _struct(out, v)
    elif t in (LIST, SET):
        et, values = v
        n = len(values)
        if n < 15:
            out.append(n << 4 | et)
        else:
            out.append(0xF0 | et)
            varint(out, n)
        if et in (TRUE, FALSE):
            out += bytes(TRUE if x else FALSE for x in values)
        else:
            for x in values:
                _value(out, et, x)
    elif t == BYTE:
        out.append(v & 0xFF)
    elif t == DOUBLE:
        out += struct.pack("<d", v)
    elif t == MAP:
        kt, vt, items = v
        varint(out, len(items))
        if items:
            out.append(kt << 4 | vt)
            for k, x in items:
                _value(out, kt, k)
                _value(out, vt, x)
    elif t not in (TRUE, FALSE):
        raise ValueError(f"Thrift compact type {t}")


def _struct(out: bytearray, s: Struct) -> None:
    fields(out, s, 0)
    out.append(STOP)


def fields(out: bytearray, s: Struct, last: int) -> int:
    """Struct `s`'s fields (no stop byte), ids counted from `last`; the last id written."""
    for fid in sorted(s):
        t, v = s[fid]
        if t in (TRUE, FALSE):
            t = TRUE if v else FALSE
        delta = fid - last
        if 0 < delta <= 15:
            out.append(delta << 4 | t)
        else:
            out.append(t)
            varint(out, (fid << 1) ^ (fid >> 63))
        last = fid
        _value(out, t, v)
    return last


def encode(s: Struct) -> bytes:
    out = bytearray()
    _struct(out, s)
    return bytes(out)
