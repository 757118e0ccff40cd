"""Framing of the <protocol title>: constants, Fletcher-16, packet builder, stream parser, field splitter.

The constants are rendered from the IR (protocols[].framing) into _protocol.py; the code below is
the same for every protocol and follows docs/conformance.md sections 1 and 2.
"""

from __future__ import annotations

import importlib
import os
import re
from operator import mul
from typing import TYPE_CHECKING, Any, Iterator, List, Tuple, Union

# The protocol's constants (generated). framing.MAX_PACKET and the others the code below does not
# use are part of the package's API: re-exported (listed in __all__ at the end, so type checkers see them exported).
from .._protocol import (  # noqa: F401
    CHECKSUM_SIZE,
    CHECKSUM_SUM1_FIRST,
    FIELD_DESCRIPTOR_OFFSET,
    FIELD_HEADER_SIZE,
    FIELD_LENGTH_ADJUST,
    FIELD_LENGTH_COUNTS_HEADER,
    FIELD_LENGTH_OFFSET,
    FOREIGN_NMEA,
    FOREIGN_RTCM3,
    HEADER_SIZE,
    IRREGULAR_LENGTHS,
    LENGTH_OFFSET,
    MAX_FIELD_DATA,
    MAX_PACKET,
    MAX_PAYLOAD,
    NMEA_MAX,
    PACKAGE,
    SET_OFFSET,
    SYNC,
)

if TYPE_CHECKING:
    from .layout import BytesLike, Field

# The optional C accelerator (_speedups.c, built by setup.py when a compiler is there): the parser
# loop and packet decoding run in C with the same results. <PACKAGE>_PURE=1 in the
# environment forces the pure-Python code (tests run both ways).
_speedups: Any = None
if os.environ.get(PACKAGE.upper() + "_PURE", "") in ("", "0"):
    try:
        _speedups = importlib.import_module("._speedups", __package__)
    except ImportError:
        _speedups = None
ACCELERATED = _speedups is not None
speedups = _speedups  # the accelerator module or None, for the modules that call it (packets, session)
# Type checkers see the pure-Python classes (the C base holds the same attributes).
_EVENT_SLOTS: Tuple[str, ...] = ("offset", "data")
if _speedups is not None and not TYPE_CHECKING:
    _EventBase = _speedups.EventBase
    _EVENT_SLOTS = ()  # offset and data live in the C base
else:
    _EventBase = object


def field_length_adjust(set_id: int, descriptor: int) -> int:
    """Length byte - data length of field `descriptor` in a packet of descriptor set `set_id`."""
    return FIELD_LENGTH_ADJUST + IRREGULAR_LENGTHS.get((set_id, descriptor), 0)


class FramingError(ValueError):
    """A packet or field that does not fit the framing (too long)."""


# ----------------------------------------------------------------------------------- checksum
def fletcher16(data: BytesLike) -> int:
    """Fletcher-16 (mod 256) of `data` as (sum1 << 8) | sum2."""
    n = len(data)
    sum1 = sum(data) & 0xFF
    sum2 = sum(map(mul, data, range(n, 0, -1))) & 0xFF
    return int((sum1 << 8) | sum2)


def checksum_bytes(data: BytesLike) -> bytes:
    """The two checksum bytes of `data` in wire order."""
    c = fletcher16(data)
    sum1, sum2 = c >> 8, c & 0xFF
    return bytes((sum1, sum2) if CHECKSUM_SUM1_FIRST else (sum2, sum1))


# ----------------------------------------------------------------------------------- builder
class PacketBuilder:
    """Builds one packet: fields (header + data) appended to a bounded payload, then length and checksum."""

    def __init__(self, set_id: int) -> None:
        if not 0 <= set_id <= 0xFF:
            raise FramingError(f"descriptor set {set_id} is not a byte")
        self.set = set_id
        self.payload = bytearray()

    def add(self, value: Field) -> PacketBuilder:
        """Append a typed field value (a generated layout: DESCRIPTOR and encode()). A layout that
        is not a field of this packet's descriptor set (its own, a reserved or a shared data field;
        docs/conformance.md section 2) raises FramingError: its descriptor means another field here."""
        from .. import registry  # the dispatch tables (imported here: they import this module)

        classes = registry.lookup(self.set, value.DESCRIPTOR)
        if classes is None or type(value) not in classes:
            name = getattr(type(value), "NAME", type(value).__name__)
            raise FramingError(
                f"{name} (descriptor 0x{value.DESCRIPTOR:02x}) is not a field of descriptor set 0x{self.set:02x}"
            )
        return self.add_field(value.DESCRIPTOR, value.encode())

    def add_field(self, descriptor: int, data: BytesLike) -> PacketBuilder:
        """Append a field from its descriptor and data bytes."""
        if not 0 <= descriptor <= 0xFF:
            raise FramingError(f"descriptor {descriptor} is not a byte")
        adjust = field_length_adjust(self.set, descriptor)
        length = len(data) + adjust
        if length > 0xFF:
            raise FramingError(f"field data of {len(data)} bytes is longer than the maximum {0xFF - adjust}")
        if length < 0:
            raise FramingError(
                f"field data of {len(data)} bytes is shorter than the minimum {-adjust} for descriptor 0x{descriptor:02x} of set 0x{self.set:02x}"
            )
        header = bytearray(FIELD_HEADER_SIZE)
        header[FIELD_LENGTH_OFFSET] = length
        header[FIELD_DESCRIPTOR_OFFSET] = descriptor
        return self.add_bytes(bytes(header) + bytes(data))

    def add_bytes(self, raw: BytesLike) -> PacketBuilder:
        """Append raw payload bytes (e.g. a trailing entry)."""
        if len(self.payload) + len(raw) > MAX_PAYLOAD:
            raise FramingError(
                f"payload of {len(self.payload) + len(raw)} bytes is longer than the maximum {MAX_PAYLOAD}"
            )
        self.payload += raw
        return self

    def build(self) -> bytes:
        """The complete packet: sync, header, payload, checksum."""
        header = bytearray(HEADER_SIZE)
        header[: len(SYNC)] = SYNC
        header[SET_OFFSET] = self.set
        header[LENGTH_OFFSET] = len(self.payload)
        body = bytes(header) + bytes(self.payload)
        return body + checksum_bytes(body)


def build_packet(set_id: int, *values: Field) -> bytes:
    """A packet holding the given typed field values."""
    b = PacketBuilder(set_id)
    for v in values:
        b.add(v)
    return b.build()


# ----------------------------------------------------------------------------------- parser
class RawPacket(_EventBase):
    """A complete packet with a valid checksum found at `offset` in the stream."""

    __slots__ = _EVENT_SLOTS

    def __init__(self, offset: int, data: bytes) -> None:
        self.offset = offset
        self.data = data

    @property
    def set(self) -> int:
        return self.data[SET_OFFSET]

    @property
    def payload(self) -> bytes:
        return self.data[HEADER_SIZE:-CHECKSUM_SIZE]

    def __eq__(self, other: object) -> bool:
        return isinstance(other, RawPacket) and (other.offset, other.data) == (self.offset, self.data)

    def __reduce__(self) -> Any:
        return (type(self), (self.offset, self.data))

    def __repr__(self) -> str:
        return f"RawPacket(offset={self.offset}, data={self.data.hex()})"


class Skip(_EventBase):
    """A maximal run of skipped bytes (no packet there) starting at `offset` in the stream."""

    __slots__ = _EVENT_SLOTS

    def __init__(self, offset: int, data: bytes) -> None:
        self.offset = offset
        self.data = data

    @property
    def count(self) -> int:
        return len(self.data)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Skip) and (other.offset, other.data) == (self.offset, self.data)

    def __reduce__(self) -> Any:
        return (type(self), (self.offset, self.data))

    def __repr__(self) -> str:
        return f"Skip(offset={self.offset}, data={self.data.hex()})"


class Nmea(_EventBase):
    """A whole NMEA-0183 sentence with a valid checksum at `offset` (between packets; section 1)."""

    __slots__ = _EVENT_SLOTS

    def __init__(self, offset: int, data: bytes) -> None:
        self.offset = offset
        self.data = data

    @property
    def sentence(self) -> str:
        """The sentence without its CR LF ("$GPGGA,...*hh")."""
        return self.data[:-2].decode("ascii")

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Nmea) and (other.offset, other.data) == (self.offset, self.data)

    def __reduce__(self) -> Any:
        return (type(self), (self.offset, self.data))

    def __repr__(self) -> str:
        return f"Nmea(offset={self.offset}, data={self.data!r})"


class Rtcm(_EventBase):
    """A whole RTCM3 frame with a valid CRC-24Q at `offset` (between packets; section 1)."""

    __slots__ = _EVENT_SLOTS

    def __init__(self, offset: int, data: bytes) -> None:
        self.offset = offset
        self.data = data

    @property
    def message_type(self) -> int:
        """The message number: the first 12 bits of the payload."""
        return (self.data[3] << 4) | (self.data[4] >> 4)

    @property
    def length(self) -> int:
        """The payload length (the frame less its 3 header and 3 CRC bytes)."""
        return len(self.data) - 6

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Rtcm) and (other.offset, other.data) == (self.offset, self.data)

    def __reduce__(self) -> Any:
        return (type(self), (self.offset, self.data))

    def __repr__(self) -> str:
        return f"Rtcm(offset={self.offset}, data={self.data.hex()})"


Event = Union[RawPacket, Skip, Nmea, Rtcm]


# ------------------------------------------------------------------- foreign frames (section 1)
# Where the parser would skip bytes, a whole NMEA-0183 sentence or RTCM3 frame is reported as an
# Nmea or Rtcm event instead; a candidate that fails stays skipped bytes, one byte at a time.
_FOREIGN_START = re.compile(
    b"[" + (b"$!" if FOREIGN_NMEA else b"") + (b"\\xd3" if FOREIGN_RTCM3 else b"") + b"]"
    if FOREIGN_NMEA or FOREIGN_RTCM3
    else b"(?!)"
)
_NMEA_BODY = bytes(b in range(0x20, 0x7F) and b not in b"$!*" for b in range(256))
_HEX_DIGIT = b"0123456789ABCDEFabcdef"
FOREIGN_WAIT = -1


def crc24q(data: BytesLike) -> int:
    """CRC-24Q of RTCM3 (polynomial 0x1864CFB, initial value 0, not reflected)."""
    crc = 0
    for b in data:
        crc = _CRC24Q[((crc >> 16) ^ b) & 0xFF] ^ ((crc << 8) & 0xFFFFFF)
    return crc


def _crc24q_table() -> List[int]:
    table = []
    for i in range(256):
        c = i << 16
        for _ in range(8):
            c = ((c << 1) ^ 0x1864CFB) if c & 0x800000 else c << 1
        table.append(c & 0xFFFFFF)
    return table


_CRC24Q = _crc24q_table()


def foreign_frame(buf: BytesLike, i: int, n: int) -> int:
    """The foreign frame starting at buf[i] (a start byte) with buf[i:n] available: its length
    when it is whole and valid, 0 when it is not one, FOREIGN_WAIT when more bytes decide."""
    if buf[i] == 0xD3:
        if n - i < 3:
            return FOREIGN_WAIT
        if buf[i + 1] & 0xFC:
            return 0
        length = ((buf[i + 1] & 3) << 8) | buf[i + 2]
        total = 3 + length + 3
        if length < 2:
            return 0
        if n - i < total:
            return FOREIGN_WAIT
        crc = (buf[i + total - 3] << 16) | (buf[i + total - 2] << 8) | buf[i + total - 1]
        return total if crc24q(memoryview(buf)[i : i + total - 3]) == crc else 0
    lim = i + NMEA_MAX - 4  # the '*' stands before lim: '*', two digits, CR, LF end the sentence
    j = i + 1
    stop = min(n, lim)
    while j < stop and _NMEA_BODY[buf[j]]:
        j += 1
    if j == lim:
        return 0  # overlong
    if j == n:
        return FOREIGN_WAIT
    if buf[j] != 0x2A:
        return 0
    total = j + 5 - i
    if n - i < total:
        return FOREIGN_WAIT
    h, lo = buf[j + 1], buf[j + 2]
    if h not in _HEX_DIGIT or lo not in _HEX_DIGIT or buf[j + 3] != 0x0D or buf[j + 4] != 0x0A:
        return 0
    x = 0
    for b in memoryview(buf)[i + 1 : j]:
        x ^= b
    return total if x == int(bytes((h, lo)), 16) else 0


if _speedups is not None:
    _speedups.setup_foreign(Nmea, Rtcm)


def _foreign_event(offset: int, data: bytes) -> Event:
    return Rtcm(offset, data) if data[0] == 0xD3 else Nmea(offset, data)


def checksum_ok(buf: bytearray, i: int, body: int) -> bool:
    return checksum_bytes(memoryview(buf)[i : i + body]) == buf[i + body : i + body + CHECKSUM_SIZE]


class Parser:
    """Streaming parser (docs/conformance.md section 1): feed(bytes) -> events, flush() at end of input.

    The events do not depend on how the input is split into chunks. Skip runs are merged and
    reported just before the next packet or at flush.
    """

    def __init__(self) -> None:
        self._buf = bytearray()
        self._base = 0  # stream offset of _buf[0]
        self._skip = bytearray()
        self._skip_at = 0

    def feed(self, data: BytesLike) -> List[Event]:
        """Consume more input; returns the events it completes."""
        self._buf += data
        return self._scan(final=False)

    def flush(self) -> List[Event]:
        """End of input: every byte that cannot be part of a complete packet is skipped."""
        events = self._scan(final=True)
        if self._skip:
            events.append(Skip(self._skip_at, bytes(self._skip)))
            self._skip = bytearray()
        return events

    def _skipped(self, a: int, b: int) -> None:
        if not self._skip:
            self._skip_at = self._base + a
        self._skip += self._buf[a:b]

    def _gap(self, a: int, b: int, final: bool, events: List[Event]) -> int:
        """Bytes a..b-1 hold no sync: skipped, but for the foreign frames among them (section 1).
        Returns where scanning goes on (b, or before b after a frame or where a candidate waits)."""
        buf = self._buf
        while a < b:
            m = _FOREIGN_START.search(buf, a, b)
            if m is None:
                break
            s = m.start()
            if s > a:
                self._skipped(a, s)
            r = foreign_frame(buf, s, len(buf))
            if r == FOREIGN_WAIT and not final:
                return -1 - s  # wait at s
            if r > 0:
                if self._skip:
                    events.append(Skip(self._skip_at, bytes(self._skip)))
                    self._skip = bytearray()
                events.append(_foreign_event(self._base + s, bytes(buf[s : s + r])))
                a = s + r
                if a > b:
                    return a  # the frame ran past the sync: scanning resumes after it
                continue
            self._skipped(s, s + 1)
            a = s + 1
        if a < b:
            self._skipped(a, b)
        return b

    def _scan(self, final: bool) -> List[Event]:
        if _speedups is None:
            return self._scan_pure(final)
        events: List[Event]
        events, pos, self._skip_at = _speedups.scan(self._buf, self._base, self._skip, self._skip_at, final)
        del self._buf[:pos]
        self._base += pos
        return events

    def _scan_pure(self, final: bool) -> List[Event]:
        buf = self._buf
        n = len(buf)
        pos = 0
        events: List[Event] = []
        sync_len = len(SYNC)
        while pos < n:
            i = buf.find(SYNC, pos)
            if i < 0:
                # Keep a partial sync sequence at the very end (unless this is the end of input).
                keep = n
                if not final:
                    for j in range(max(pos, n - sync_len + 1), n):
                        if buf[j:] == SYNC[: n - j]:
                            keep = j
                            break
                at = self._gap(pos, keep, final, events)
                if at < 0:
                    pos = -1 - at
                    break
                if at > keep:
                    pos = at
                    continue
                pos = keep
                break
            at = self._gap(pos, i, final, events) if i > pos else i
            if at < 0:
                pos = -1 - at
                break
            if at != i:
                pos = at
                continue
            length = buf[i + LENGTH_OFFSET] if n - i >= HEADER_SIZE else -1
            if 0 <= length <= MAX_PAYLOAD:
                body = HEADER_SIZE + length
                total = body + CHECKSUM_SIZE
                if n - i >= total:
                    if checksum_ok(buf, i, body):
                        if self._skip:
                            events.append(Skip(self._skip_at, bytes(self._skip)))
                            self._skip = bytearray()
                        events.append(RawPacket(self._base + i, bytes(buf[i : i + total])))
                        pos = i + total
                        continue
                elif not final:
                    pos = i  # wait for the rest of the packet
                    break
            elif length < 0 and not final:
                pos = i  # wait for the rest of the header
                break
            # A false sync (bad length or checksum, or incomplete at end of input): skip one byte.
            self._skipped(i, i + 1)
            pos = i + 1
        del buf[:pos]
        self._base += pos
        return events


def parse(data: BytesLike) -> List[Event]:
    """All events of a complete stream."""
    p = Parser()
    return p.feed(data) + p.flush()


# ----------------------------------------------------------------------------------- fields
class FieldBytes:
    """One complete field of a payload: descriptor and data (after the field header)."""

    __slots__ = ("offset", "descriptor", "data")

    def __init__(self, offset: int, descriptor: int, data: bytes) -> None:
        self.offset = offset
        self.descriptor = descriptor
        self.data = data

    def __repr__(self) -> str:
        return f"FieldBytes(offset={self.offset}, descriptor=0x{self.descriptor:02X}, data={self.data.hex()})"


class TrailingBytes:
    """The rest of a payload that does not form a field, with the reason (section 2)."""

    __slots__ = ("offset", "data", "error")

    def __init__(self, offset: int, data: bytes, error: str) -> None:
        self.offset = offset
        self.data = data
        self.error = error

    def __repr__(self) -> str:
        return f"TrailingBytes(offset={self.offset}, data={self.data.hex()}, error={self.error!r})"


def iter_fields(set_id: int, payload: BytesLike) -> Iterator[Union[FieldBytes, TrailingBytes]]:
    """Split the payload of a packet of set `set_id` into fields; framing problems end it with a TrailingBytes entry."""
    payload = bytes(payload)
    n = len(payload)
    o = 0
    while o < n:
        r = n - o
        if r < FIELD_HEADER_SIZE:
            yield TrailingBytes(
                o, payload[o:], f"field header at payload offset {o} needs {FIELD_HEADER_SIZE} bytes, {r} left"
            )
            return
        length = payload[o + FIELD_LENGTH_OFFSET]
        descriptor = payload[o + FIELD_DESCRIPTOR_OFFSET]
        data_length = length - field_length_adjust(set_id, descriptor)
        if data_length < 0:
            yield TrailingBytes(
                o, payload[o:], f"field length {length} at payload offset {o} is shorter than the field header"
            )
            return
        size = FIELD_HEADER_SIZE + data_length
        if size > r:
            yield TrailingBytes(
                o, payload[o:], f"field length {length} at payload offset {o} overruns the payload ({r} bytes left)"
            )
            return
        yield FieldBytes(o, descriptor, payload[o + FIELD_HEADER_SIZE : o + size])
        o += size


__all__ = [
    "FramingError",
    "fletcher16",
    "checksum_bytes",
    "field_length_adjust",
    "PacketBuilder",
    "build_packet",
    "RawPacket",
    "Skip",
    "Nmea",
    "Rtcm",
    "Event",
    "crc24q",
    "foreign_frame",
    "FOREIGN_WAIT",
    "Parser",
    "parse",
    "FieldBytes",
    "TrailingBytes",
    "iter_fields",
    "ACCELERATED",
    "CHECKSUM_SIZE",
    "CHECKSUM_SUM1_FIRST",
    "FIELD_DESCRIPTOR_OFFSET",
    "FIELD_HEADER_SIZE",
    "FIELD_LENGTH_ADJUST",
    "FIELD_LENGTH_COUNTS_HEADER",
    "FIELD_LENGTH_OFFSET",
    "FOREIGN_NMEA",
    "FOREIGN_RTCM3",
    "HEADER_SIZE",
    "IRREGULAR_LENGTHS",
    "LENGTH_OFFSET",
    "MAX_FIELD_DATA",
    "MAX_PACKET",
    "MAX_PAYLOAD",
    "NMEA_MAX",
    "PACKAGE",
    "SET_OFFSET",
    "SYNC",
]
