"""Packets: payload -> typed fields (docs/conformance.md section 2), canonical JSON lines, and back.

`decode_packet` splits a packet into fields and decodes each by (set, descriptor) through the
registry; `packet_line` / `decode_stream` print the canonical JSON lines; `encode_line` turns one
such line back into bytes (the encode CLI).
"""

from __future__ import annotations

from array import array
from typing import Any, Dict, Iterable, List, Optional, Tuple, Union

from . import registry
from .canonical import JsonError, error_text, hex_bytes, is_int, loads, skip_line
from .codec import DecodeError, EncodeError, Field, fast_items
from .framing import (
    CHECKSUM_SIZE,
    HEADER_SIZE,
    SET_OFFSET,
    FramingError,
    PacketBuilder,
    Parser,
    RawPacket,
    Skip,
    TrailingBytes,
    _speedups,
    iter_fields,
    parse,
)

if _speedups is not None:
    _PacketBase: Any = _speedups.PacketBase
    _DecodedBase: Any = _speedups.DecodedFieldBase
    _PACKET_SLOTS: Tuple[str, ...] = ()  # the attributes live in the C bases
    _DECODED_SLOTS: Tuple[str, ...] = ()
else:
    _PacketBase = _DecodedBase = object
    _PACKET_SLOTS = ("offset", "set", "fields")
    _DECODED_SLOTS = ("descriptor", "value")


class DecodedField(_DecodedBase):
    """A field decoded into its typed value (value.NAME, value.DEVICE, ...)."""

    __slots__ = _DECODED_SLOTS

    def __init__(self, descriptor: int, value: Field) -> None:
        self.descriptor = descriptor
        self.value = value

    @property
    def name(self) -> str:
        return self.value.NAME

    def line(self) -> str:
        v = self.value
        device = f',"device":"{v.DEVICE}"' if v.DEVICE is not None else ""
        return (
            '{"descriptor":'
            + str(self.descriptor)
            + ',"name":"'
            + v.NAME
            + '"'
            + device
            + ',"values":'
            + v.to_json()
            + "}"
        )

    def __reduce__(self) -> Any:
        return (type(self), (self.descriptor, self.value))

    def __repr__(self) -> str:
        return f"DecodedField({self.value!r})"


class RawField:
    """A field that could not be decoded: its descriptor, data and the reason."""

    __slots__ = ("descriptor", "data", "error")

    def __init__(self, descriptor: int, data: bytes, error: str) -> None:
        self.descriptor = descriptor
        self.data = data
        self.error = error

    def line(self) -> str:
        return (
            '{"descriptor":'
            + str(self.descriptor)
            + ',"data":"'
            + self.data.hex()
            + '","error":'
            + error_text(self.error)
            + "}"
        )

    def __repr__(self) -> str:
        return f"RawField(descriptor=0x{self.descriptor:02X}, data={self.data.hex()}, error={self.error!r})"


class Trailing:
    """Payload bytes after the last complete field, with the framing problem."""

    __slots__ = ("data", "error")

    def __init__(self, data: bytes, error: str) -> None:
        self.data = data
        self.error = error

    def line(self) -> str:
        return '{"trailing":"' + self.data.hex() + '","error":' + error_text(self.error) + "}"

    def __repr__(self) -> str:
        return f"Trailing(data={self.data.hex()}, error={self.error!r})"


Entry = Union[DecodedField, RawField, Trailing]


class Packet(_PacketBase):
    """A decoded packet: stream offset, descriptor set and its field entries in payload order."""

    __slots__ = _PACKET_SLOTS

    def __init__(self, offset: int, set_id: int, fields: List[Entry]) -> None:
        self.offset = offset
        self.set = set_id
        self.fields = fields

    def line(self) -> str:
        """The canonical JSON line of the packet."""
        inner = ",".join(f.line() for f in self.fields)
        return '{"offset":' + str(self.offset) + ',"set":' + str(self.set) + ',"fields":[' + inner + "]}"

    def __reduce__(self) -> Any:
        return (type(self), (self.offset, self.set, self.fields))

    def values(self) -> List[Field]:
        """The typed values of the decoded fields."""
        return [f.value for f in self.fields if isinstance(f, DecodedField)]

    def __repr__(self) -> str:
        return f"Packet(offset={self.offset}, set=0x{self.set:02X}, fields={self.fields!r})"


def decode_field(set_id: int, descriptor: int, data: bytes, device: Optional[str] = None) -> Entry:
    """Decode one field by (set, descriptor) with the dispatch rules of section 2."""
    classes = registry.lookup(set_id, descriptor)
    if classes is None:
        error = "unknown descriptor" if set_id in registry.SET_NAMES else "unknown descriptor set"
        return RawField(descriptor, data, error)
    if device is not None and len(classes) > 1:
        chosen = tuple(c for c in classes if c.DEVICE == device)
        classes = chosen or classes
    first_error = None
    for cls in classes:
        try:
            return DecodedField(descriptor, cls.decode(data))
        except DecodeError as e:
            if first_error is None:
                first_error = str(e)
    return RawField(descriptor, data, first_error or "")


def decode_packet(packet: Any, offset: int = 0, device: Optional[str] = None) -> Packet:
    """Decode a complete packet (as found by the Parser) into typed fields."""
    packet = bytes(packet)
    set_id = packet[SET_OFFSET]
    fields: List[Entry] = []
    for f in iter_fields(set_id, packet[HEADER_SIZE:-CHECKSUM_SIZE]):
        if isinstance(f, TrailingBytes):
            fields.append(Trailing(f.data, f.error))
        else:
            fields.append(decode_field(set_id, f.descriptor, f.data, device))
    return Packet(offset, set_id, fields)


_decode_packet_pure = decode_packet


def _program(set_id: int, descriptor: int) -> Any:
    """For the C accelerator: (class, fast_items) of the first layout of a field, or None."""
    classes = registry.lookup(set_id, descriptor)
    if classes is None:
        return None
    items = fast_items(classes[0])
    return None if items is None else (classes[0], items)


if _speedups is not None:
    _speedups.setup(RawPacket, Skip, Packet, DecodedField, _decode_packet_pure, decode_field, _program)
    decode_packet = _speedups.decode_packet  # noqa: F811 - same contract, in C


class Decoder(Parser):
    """A stream parser whose packets come out decoded: feed(bytes) -> [Packet | Skip], flush() at end.

    The events are those of `Parser` with each `RawPacket` e replaced by
    `decode_packet(e.data, e.offset, device)`; in C, without the intermediate RawPacket objects,
    when the accelerator is built.
    """

    def __init__(self, device: Optional[str] = None) -> None:
        super().__init__()
        self.device = device

    def feed(self, data: Any) -> List[Any]:
        """Consume more input; returns the (decoded) events it completes."""
        return super().feed(data)

    def flush(self) -> List[Any]:
        """End of input: returns the last (decoded) events."""
        return super().flush()

    def _scan(self, final: bool) -> List[Any]:
        if _speedups is None or self.device is not None:
            device = self.device
            return [
                decode_packet(e.data, e.offset, device) if isinstance(e, RawPacket) else e for e in super()._scan(final)
            ]
        events, pos, self._skip_at = _speedups.scan(self._buf, self._base, self._skip, self._skip_at, final, True)
        del self._buf[:pos]
        self._base += pos
        return events


def decode_all(data: Any, device: Optional[str] = None) -> List[Union[Packet, Skip]]:
    """Every event of a complete stream with its packets decoded: `Packet` and `Skip` in stream order.

    The same as `decode_packet(e.data, e.offset, device)` for each `RawPacket` of `parse(data)`, in
    one pass (in C, without the intermediate RawPacket objects, when the accelerator is built).
    """
    if _speedups is not None and device is None:
        return _speedups.decode_all(data)
    return [decode_packet(e.data, e.offset, device) if isinstance(e, RawPacket) else e for e in parse(data)]


# Column type codes of the C accelerator's tables, by item kind (see fast_items).
_COLUMN_CODES = {"f": "d", "d": "d", "i": "q", "u": "Q", "e": "Q", "F": "Q", "?": "B"}


class Table:
    """The rows of one field (set, descriptor) from `decode_columns`: one array per parameter.

    `columns[attr]` is an `array` of numbers: floats as 'd', signed integers as 'q', unsigned
    integers, enums and bitfields as 'Q' (their wire values), bools as 'B' (0 or 1); a fixed array
    parameter of n values has n numbers per row. `offsets[i]` is the stream offset of row i's
    packet and `index[i]` the position of the field in it. `row(i)` is the typed value (an instance
    of `cls`) equal to the one `decode_packet` gives.
    """

    def __init__(
        self, set_id: int, descriptor: int, cls: Any, rows: int, offsets: bytes, index: bytes, cols: List[bytes]
    ) -> None:
        self.set = set_id
        self.descriptor = descriptor
        self.cls = cls
        self.rows = rows
        self.offsets = array("q", offsets)
        self.index = array("q", index)
        self._items = fast_items(cls) or ()
        self.columns: Dict[str, Any] = {}
        for (attr, kind, _size, _count, _aux), data in zip(self._items, cols):
            self.columns[attr] = array(_COLUMN_CODES[kind], data)

    def __len__(self) -> int:
        return self.rows

    def row(self, i: int) -> Any:
        """The typed value of row i."""
        vals = []
        for attr, kind, _size, count, aux in self._items:
            col = self.columns[attr]
            raw = [col[i]] if count < 0 else list(col[i * count : (i + 1) * count])
            if kind == "e":
                raw = [aux.get(v, v) for v in raw]
            elif kind == "F":
                raw = [aux(v) for v in raw]
            elif kind == "?":
                raw = [v == 1 for v in raw]
            vals.append(raw[0] if count < 0 else raw)
        return self.cls(*vals)

    def __repr__(self) -> str:
        return f"Table(set=0x{self.set:02X}, descriptor=0x{self.descriptor:02X}, {self.cls.__name__}, rows={self.rows})"


class Columns:
    """A complete stream decoded by `decode_columns`.

    `packets` counts the packets; `skips` are the Skip events; `tables[(set, descriptor)]` holds
    the fields the C accelerator reads (fixed layouts of numbers, enums, bitfields and bools, no
    NaN, no decoding error) as arrays; `others` holds every other field entry as objects:
    (packet offset, field index, entry), or (offset, -1, Packet) for a packet whose payload does
    not split into fields. Without the accelerator every entry is in `others`.
    """

    def __init__(self, packets: int, skips: List[Skip], tables: List[Any], others: List[Tuple[int, int, Any]]) -> None:
        self.packets = packets
        self.skips = skips
        self.tables: Dict[Tuple[int, int], Table] = {(t[0], t[1]): Table(*t) for t in tables}
        self.others = others

    def entries(self) -> List[Tuple[int, int, Any]]:
        """Every field entry in stream order, as (packet offset, field index, DecodedField or other entry)."""
        out = list(self.others)
        for t in self.tables.values():
            for i in range(t.rows):
                out.append((t.offsets[i], t.index[i], DecodedField(t.descriptor, t.row(i))))
        out.sort(key=lambda x: (x[0], x[1]))
        return out


def decode_columns(data: Any) -> Columns:
    """A complete stream decoded into per-field tables of numbers (see `Columns`): the fast bulk API.

    In C when the accelerator is built; it builds no Python object per packet for the fields it
    reads. The same fields and values as `decode_all(data)` (see `Columns.entries`).
    """
    if _speedups is not None:
        return Columns(*_speedups.decode_columns(data))
    skips: List[Skip] = []
    others: List[Tuple[int, int, Any]] = []
    packets = 0
    for e in decode_all(data):
        if isinstance(e, Skip):
            skips.append(e)
            continue
        packets += 1
        if any(isinstance(f, Trailing) for f in e.fields):
            others.append((e.offset, -1, e))
        else:
            others.extend((e.offset, k, f) for k, f in enumerate(e.fields))
    return Columns(packets, skips, [], others)


def event_line(event: Union[RawPacket, Skip], device: Optional[str] = None) -> str:
    """The canonical JSON line of a parser event."""
    if isinstance(event, Skip):
        return skip_line(event.offset, event.data)
    return decode_packet(event.data, event.offset, device).line()


def decode_stream(chunks: Iterable[Any], device: Optional[str] = None) -> Iterable[str]:
    """Canonical JSON lines of a byte stream given as chunks of any size."""
    parser = Parser()
    for chunk in chunks:
        for event in parser.feed(chunk):
            yield event_line(event, device)
    for event in parser.flush():
        yield event_line(event, device)


def decode_bytes(data: Any, device: Optional[str] = None) -> List[str]:
    """Canonical JSON lines of a complete byte stream."""
    return list(decode_stream([data], device))


# ----------------------------------------------------------------------------------- encode
def _keys(obj: dict, required: Iterable[str], optional: Iterable[str], what: str) -> None:
    allowed = set(required) | set(optional)
    for k in required:
        if k not in obj:
            raise EncodeError(f"{what}: missing {k!r}")
    for k in obj:
        if k not in allowed:
            raise EncodeError(f"{what}: unknown key {k!r}")


def _byte(obj: dict, key: str, what: str) -> int:
    v = obj[key]
    if not is_int(v) or not 0 <= v <= 0xFF:
        raise EncodeError(f"{what}: {key} must be an integer 0..255")
    return int(v)


def _offset(obj: dict, what: str) -> None:
    v = obj["offset"]
    if not is_int(v) or not 0 <= v <= 0xFFFFFFFFFFFFFFFF:
        raise EncodeError(f"{what}: offset must be an integer 0..18446744073709551615")


def _error_text(entry: dict, what: str) -> None:
    if not isinstance(entry["error"], str):
        raise EncodeError(f"{what}: error must be a string")


def _field_bytes(set_id: int, entry: Any, what: str) -> tuple:
    """(descriptor, data) or (None, raw payload bytes) of one field entry of a packet line."""
    if not isinstance(entry, dict):
        raise EncodeError(f"{what}: expected an object")
    if "trailing" in entry:
        _keys(entry, ("trailing", "error"), (), what)
        _error_text(entry, what)
        return None, hex_bytes(entry["trailing"], f"{what}: trailing")
    if "data" in entry:
        _keys(entry, ("descriptor", "data", "error"), (), what)
        _error_text(entry, what)
        return _byte(entry, "descriptor", what), hex_bytes(entry["data"], f"{what}: data")
    _keys(entry, ("descriptor", "name", "values"), ("device",), what)
    descriptor = _byte(entry, "descriptor", what)
    classes = registry.lookup(set_id, descriptor)
    if classes is None:
        raise EncodeError(f"{what}: no field with descriptor {descriptor} in set {set_id}")
    name = entry["name"]
    if name != classes[0].NAME:
        raise EncodeError(f"{what}: descriptor {descriptor} in set {set_id} is {classes[0].NAME!r}, not {name!r}")
    device = entry.get("device")
    if len(classes) > 1:
        match = [c for c in classes if c.DEVICE == device]
        if not match:
            devices = ", ".join(c.DEVICE for c in classes)
            raise EncodeError(f"{what}: {name} has per-device layouts; 'device' must be one of {devices}")
        cls = match[0]
    else:
        if "device" in entry:
            raise EncodeError(f"{what}: {name} has a single layout; 'device' does not apply")
        cls = classes[0]
    value = cls.from_json(entry["values"], f"{what}: values.")
    try:
        return descriptor, value.encode()
    except EncodeError as e:
        raise EncodeError(f"{what}: values.{e}") from None


def encode_value(obj: Any) -> bytes:
    """Bytes of one parsed canonical JSON line (a packet or a skip run)."""
    if not isinstance(obj, dict):
        raise EncodeError("expected a JSON object")
    if "skipped" in obj:
        _keys(obj, ("offset", "skipped"), (), "skip run")
        _offset(obj, "skip run")
        return hex_bytes(obj["skipped"], "skip run: skipped")
    _keys(obj, ("offset", "set", "fields"), (), "packet")
    _offset(obj, "packet")
    set_id = _byte(obj, "set", "packet")
    if not isinstance(obj["fields"], list):
        raise EncodeError("packet: fields must be an array")
    builder = PacketBuilder(set_id)
    for k, entry in enumerate(obj["fields"]):
        what = f"fields[{k}]"
        descriptor, data = _field_bytes(set_id, entry, what)
        try:
            if descriptor is None:
                builder.add_bytes(data)
            else:
                builder.add_field(descriptor, data)
        except FramingError as e:
            raise EncodeError(f"{what}: {e}") from None
    return builder.build()


def encode_line(text: str) -> bytes:
    """Bytes of one canonical JSON line; raises EncodeError (or JsonError) naming what is wrong."""
    if not text.strip(" \t\r\n"):  # RFC 8259 whitespace only
        raise EncodeError("empty line (expected a JSON object)")
    try:
        obj = loads(text)
    except JsonError as e:
        raise EncodeError(str(e)) from None
    try:
        return encode_value(obj)
    except JsonError as e:
        raise EncodeError(str(e)) from None


def encode_lines(lines: Iterable[str]) -> bytes:
    """Bytes of several canonical JSON lines (raises on the first bad line)."""
    return b"".join(encode_line(line) for line in lines)


__all__ = [
    "DecodedField",
    "RawField",
    "Trailing",
    "Packet",
    "decode_field",
    "decode_packet",
    "decode_all",
    "decode_columns",
    "Columns",
    "Table",
    "Decoder",
    "decode_stream",
    "decode_bytes",
    "event_line",
    "encode_line",
    "encode_lines",
    "encode_value",
]
