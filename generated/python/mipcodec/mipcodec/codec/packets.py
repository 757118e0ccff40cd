"""Packets: payload -> typed fields (docs/conformance.md section 2), canonical JSON lines, and back.

`decode_packet` splits a packet into fields and decodes each by (set, descriptor) through the
registry; `packet_line` / `decode_stream` print the canonical JSON lines; `encode_line` turns one
such line back into bytes (the encode CLI).
"""

from __future__ import annotations

from array import array
from typing import TYPE_CHECKING, Any, Dict, Iterable, List, Optional, Tuple, Type, Union, cast

from .. import _extras, registry
from .canonical import JsonError, error_text, foreign_line, hex_bytes, is_int, loads, skip_line
from .framing import (
    CHECKSUM_SIZE,
    HEADER_SIZE,
    LENGTH_OFFSET,
    SET_OFFSET,
    SYNC,
    Event,
    FramingError,
    Nmea,
    PacketBuilder,
    Parser,
    RawPacket,
    Rtcm,
    Skip,
    TrailingBytes,
    checksum_bytes,
    iter_fields,
    parse,
)
from .framing import (
    speedups as _speedups,
)
from .layout import BytesLike, DecodeError, EncodeError, Field, fast_items

# Type checkers see the pure-Python classes (the C bases hold the same attributes).
_PACKET_SLOTS: Tuple[str, ...] = ("offset", "set", "fields")
_DECODED_SLOTS: Tuple[str, ...] = ("descriptor", "value")
if _speedups is not None and not TYPE_CHECKING:
    _PacketBase = _speedups.PacketBase
    _DecodedBase = _speedups.DecodedFieldBase
    _PACKET_SLOTS = ()  # the attributes live in the C bases
    _DECODED_SLOTS = ()
else:
    _PacketBase = object
    _DecodedBase = object


class DecodedField(_DecodedBase):
    """A field decoded into its typed value (value.NAME, value.DEVICE, ...).

    With the C accelerator, the value of a field of a fixed layout is built when `value` is first
    read (and kept): until then the field holds its data bytes, already checked to decode.
    """

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
    if device is not None and device not in registry.DEVICES:
        check_device(device)
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


def _decode_unchecked(packet: bytes, offset: int = 0, device: Optional[str] = None) -> Packet:
    """decode_packet of a packet known to be whole (from the Parser): no checks."""
    set_id = packet[SET_OFFSET]
    fields: List[Entry] = []
    for f in iter_fields(set_id, packet[HEADER_SIZE:-CHECKSUM_SIZE]):
        if isinstance(f, TrailingBytes):
            fields.append(Trailing(f.data, f.error))
        else:
            fields.append(decode_field(set_id, f.descriptor, f.data, device))
    return Packet(offset, set_id, fields)


def check_device(device: Optional[str]) -> None:
    """FramingError unless device is None or one of registry.DEVICES."""
    if device is not None and device not in registry.DEVICES:
        raise FramingError(f"unknown device {device!r} (expected None or one of {', '.join(registry.DEVICES)})")


def packet_bytes(packet: Any) -> bytes:
    """The bytes of a bytes-like packet (bytes, bytearray, memoryview, array); TypeError for others."""
    try:
        with memoryview(packet) as view:
            return view.tobytes()
    except TypeError:
        raise TypeError(
            f"packet must be bytes-like (bytes, bytearray, memoryview), not {type(packet).__name__}"
        ) from None


def decode_packet(packet: Any, offset: int = 0, device: Optional[str] = None, *, check: bool = True) -> Packet:
    """Decode one complete packet (sync, header, payload, checksum) into typed fields.

    `packet` is bytes-like. FramingError (a ValueError) names what is wrong with bad input: fewer
    bytes than a header and checksum, an unknown `device`, and unless check=False, a packet that
    does not start with the sync bytes, whose length byte disagrees with its size, or whose
    checksum is wrong. With check=False the payload is the bytes between header and checksum."""
    data = packet_bytes(packet)
    check_device(device)
    n = len(data)
    if n < HEADER_SIZE + CHECKSUM_SIZE:
        raise FramingError(
            f"a packet of {n} bytes is shorter than a header and checksum ({HEADER_SIZE + CHECKSUM_SIZE} bytes)"
        )
    if check:
        if data[: len(SYNC)] != SYNC:
            raise FramingError(f"the packet does not start with the sync bytes {SYNC.hex(' ')}")
        stated = data[LENGTH_OFFSET]
        if HEADER_SIZE + stated + CHECKSUM_SIZE != n:
            raise FramingError(
                f"the length byte says {stated} payload bytes, the packet holds {n - HEADER_SIZE - CHECKSUM_SIZE}"
                " (pass check=False to decode it anyway)"
            )
        expected = checksum_bytes(data[:-CHECKSUM_SIZE])
        if data[-CHECKSUM_SIZE:] != expected:
            raise FramingError(
                f"checksum {data[-CHECKSUM_SIZE:].hex(' ')} is wrong, expected {expected.hex(' ')}"
                " (pass check=False to decode it anyway)"
            )
    return _decode_event(data, offset, device)


def _decode_event(packet: bytes, offset: int, device: Optional[str]) -> Packet:
    """decode_packet of a packet the Parser found (whole, checksum verified): in C when it can."""
    if _fast_decode_packet is not None and device is None:
        fast: Packet = _fast_decode_packet(packet, offset)
        return fast
    return _decode_unchecked(packet, offset, device)


_decode_packet_pure = _decode_unchecked
_fast_decode_packet: Any = None


def _program(set_id: int, descriptor: int) -> Any:
    """For the C accelerator: (class, fast_items, head, keys) of the first layout of a field, or
    None. head and keys are the canonical JSON around the values (DecodedField.line): the entry up
    to the values object's brace, and '"name":' per item."""
    classes = registry.lookup(set_id, descriptor)
    if classes is None:
        return None
    cls = classes[0]
    items = fast_items(cls)
    if items is None:
        return None
    device = f',"device":"{cls.DEVICE}"' if cls.DEVICE is not None else ""
    head = '{"descriptor":' + str(descriptor) + ',"name":"' + cls.NAME + '"' + device + ',"values":{'
    keys = tuple(p.key.encode("ascii") for op in cls._OPS for p in op.params)
    return (cls, items, head.encode("ascii"), keys)


def _field_line(set_id: int, descriptor: int, data: bytes) -> str:
    """For the C accelerator: the canonical entry of a field it does not print itself."""
    return decode_field(set_id, descriptor, data).line()


def _packet_line(packet: bytes, offset: int) -> str:
    """For the C accelerator: the canonical line of a packet whose payload does not split into fields."""
    return _decode_unchecked(packet, offset).line()


if _speedups is not None:
    _speedups.setup(
        RawPacket, Skip, Packet, DecodedField, _decode_packet_pure, decode_field, _program, _field_line, _packet_line
    )
    _fast_decode_packet = _speedups.decode_packet  # the unchecked decode, in C


DecodedEvent = Union["Packet", Skip, Nmea, Rtcm]


class Decoder(Parser):
    """A stream parser whose packets come out decoded: feed(bytes) -> [Packet | Skip], flush() at end.

    The events are those of `Parser` with each `RawPacket` e replaced by
    `decode_packet(e.data, e.offset, device)`; in C, without the intermediate RawPacket objects,
    when the accelerator is built.
    """

    def __init__(self, device: Optional[str] = None) -> None:
        check_device(device)
        super().__init__()
        self.device = device

    # Returns decoded events where Parser returns raw ones (the override narrows the element type).
    def feed(self, data: BytesLike) -> List[DecodedEvent]:  # type: ignore[override]
        """Consume more input; returns the (decoded) events it completes."""
        return cast(List[DecodedEvent], super().feed(data))

    def flush(self) -> List[DecodedEvent]:  # type: ignore[override]
        """End of input: returns the last (decoded) events."""
        return cast(List[DecodedEvent], super().flush())

    def _scan(self, final: bool) -> List[Any]:
        if _speedups is None or self.device is not None:
            device = self.device
            return [
                _decode_event(e.data, e.offset, device) if isinstance(e, RawPacket) else e for e in super()._scan(final)
            ]
        events: List[Any]
        events, pos, self._skip_at = _speedups.scan(self._buf, self._base, self._skip, self._skip_at, final, True)
        del self._buf[:pos]
        self._base += pos
        return events


class LineDecoder(Parser):
    """A stream parser whose output is the canonical JSON lines (the decode CLI's loop):
    feed(bytes) -> bytes of complete lines (ASCII, each ending in a newline), flush() at end.

    The lines are those of `event_line` for the events `Parser` gives, whatever the chunking;
    with the C accelerator they are printed in C (fields it cannot print come from the same
    Python line writers), without a Python object per packet.
    """

    # Returns text where Parser returns events.
    def feed(self, data: BytesLike) -> bytes:  # type: ignore[override]
        """Consume more input; returns the lines of the events it completes."""
        self._buf += data
        return self._lines(False)

    def flush(self) -> bytes:  # type: ignore[override]
        """End of input: returns the last lines (the trailing skip run among them)."""
        text = self._lines(True)
        if self._skip:
            text += (skip_line(self._skip_at, self._skip) + "\n").encode("ascii")
            self._skip = bytearray()
        return text

    def _lines(self, final: bool) -> bytes:
        if _speedups is None:
            return "".join(event_line(e) + "\n" for e in self._scan(final)).encode("ascii")
        text: bytes
        text, pos, self._skip_at = _speedups.scan_text(self._buf, self._base, self._skip, self._skip_at, final)
        del self._buf[:pos]
        self._base += pos
        return text


def decode_all(data: BytesLike, device: Optional[str] = None) -> List[DecodedEvent]:
    """Every event of a complete stream with its packets decoded: `Packet` and `Skip` in stream order.

    The same as `decode_packet(e.data, e.offset, device)` for each `RawPacket` of `parse(data)`, in
    one pass (in C, without the intermediate RawPacket objects, when the accelerator is built).
    """
    check_device(device)
    if _speedups is not None and device is None:
        events: List[DecodedEvent] = _speedups.decode_all(data)
        return events
    return [_decode_event(e.data, e.offset, device) if isinstance(e, RawPacket) else e for e in parse(data)]


# Column type codes of the C accelerator's tables, by item kind (see fast_items).
_COLUMN_CODES = {"f": "d", "d": "d", "i": "q", "u": "Q", "e": "Q", "F": "Q", "?": "B"}
_NUMPY_TYPES = {"f": "float64", "d": "float64", "i": "int64", "u": "uint64", "e": "uint64", "F": "uint64", "?": "uint8"}


class Table:
    """The rows of one field (set, descriptor) from `decode_columns`: one array per parameter.

    `columns[attr]` is an `array` of numbers: floats as 'd', signed integers as 'q', unsigned
    integers, enums and bitfields as 'Q' (their wire values), bools as 'B' (0 or 1); a fixed array
    parameter of n values has n numbers per row. `offsets[i]` is the stream offset of row i's
    packet and `index[i]` the position of the field in it. `row(i)` is the typed value (an instance
    of `cls`) equal to the one `decode_packet` gives.

    The C accelerator writes the rows straight into one buffer per column; `arrays()` gives numpy
    views of those buffers (no copy), and `columns`, `offsets` and `index` are `array` copies of
    them, made on first use.
    """

    def __init__(
        self,
        set_id: int,
        descriptor: int,
        cls: Type[Field],
        rows: int,
        offsets: BytesLike,
        index: BytesLike,
        cols: List[BytesLike],
    ) -> None:
        self.set = set_id
        self.descriptor = descriptor
        self.cls = cls
        self.rows = rows
        self._items = fast_items(cls) or ()
        self._raw_offsets = offsets
        self._raw_index = index
        self._raw: Dict[str, BytesLike] = {item[0]: data for item, data in zip(self._items, cols)}
        self._offsets: Optional[array[int]] = None
        self._index: Optional[array[int]] = None
        self._columns: Optional[Dict[str, array[Any]]] = None

    @property
    def offsets(self) -> array[int]:
        """The stream offset of each row's packet ('q')."""
        if self._offsets is None:
            self._offsets = array("q", self._raw_offsets)
        return self._offsets

    @property
    def index(self) -> array[int]:
        """The position of each row's field in its packet ('q')."""
        if self._index is None:
            self._index = array("q", self._raw_index)
        return self._index

    @property
    def columns(self) -> Dict[str, array[Any]]:
        """attribute -> `array` of its numbers (see the class)."""
        if self._columns is None:
            self._columns = {attr: array(_COLUMN_CODES[kind], self._raw[attr]) for attr, kind, *_ in self._items}
        return self._columns

    def __len__(self) -> int:
        return self.rows

    def row(self, i: int) -> Field:
        """The typed value of row i."""
        vals: List[Any] = []
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

    def arrays(self) -> Dict[str, Any]:
        """The columns as numpy arrays shaped by the spec (needs numpy): one row per entry.

        A scalar parameter is an array of n values, a vector n x 3, a quaternion n x 4, a 3x3
        matrix n x 3 x 3, any other fixed array n x count; floats float64 (float32 values widen
        exactly), signed integers int64, unsigned integers, enums and bitfields uint64, bools bool.
        Row i belongs to the packet at `offsets[i]` (`np.asarray(table.offsets)`).

            import numpy as np
            cols = decode_columns(data)
            accel = cols.tables[(0x80, 0x04)].arrays()["scaled_accel"]   # shape (n, 3)
            norm = np.linalg.norm(accel, axis=1)
        """
        np = _extras.need("numpy", "export")
        from .. import _columns

        key = _columns_key(self.cls)
        shapes = _columns.SHAPES.get(key, {}) if key is not None else {}
        out: Dict[str, Any] = {}
        for attr, kind, _size, count, _aux in self._items:
            a = np.frombuffer(self._raw[attr], dtype=_NUMPY_TYPES[kind])
            if kind == "?":
                a = a.astype(bool)
            if count >= 0:
                a = a.reshape((self.rows,) + tuple(shapes.get(attr, (count,))))
            out[attr] = a
        return out

    def dataframe(self) -> Any:
        """The columns as a pandas DataFrame (needs pandas): one row per entry, one column per
        value, named as in `export` (`scaled_accel.x`, ...), and "offset"."""
        np = _extras.need("numpy", "pandas")
        pd = _extras.need("pandas", "pandas")
        from .. import _columns

        key = _columns_key(self.cls)
        specs = _columns.COLUMNS.get(key, ()) if key is not None else ()
        arrays = self.arrays()
        data: Dict[str, Any] = {"offset": np.frombuffer(self._raw_offsets, dtype=np.int64)}
        for name, path, _units, _kind, _enum in specs:
            a = arrays[str(path[0])]  # the attribute; indices follow
            if len(path) > 1:
                a = a.reshape(self.rows, -1)[:, path[1]]
            data[name] = a
        return pd.DataFrame(data)

    def __repr__(self) -> str:
        return f"Table(set=0x{self.set:02X}, descriptor=0x{self.descriptor:02X}, {self.cls.__name__}, rows={self.rows})"


def _columns_key(cls: Type[Field]) -> Optional[Tuple[int, int, Optional[str]]]:
    """The (set, descriptor, device) key of a field layout in the generated `_columns` tables
    (None for a layout of no set, which has no entry)."""
    return None if cls.SET is None else (cls.SET, cls.DESCRIPTOR, cls.DEVICE)


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


def decode_columns(data: BytesLike, want: Optional[bytes] = None) -> Columns:
    """A complete stream decoded into per-field tables of numbers (see `Columns`): the fast bulk API.

    In C when the accelerator is built; it builds no Python object per packet for the fields it
    reads. The same fields and values as `decode_all(data)` (see `Columns.entries`).
    `want` (`field_mask`): the fields the caller reads; the accelerator leaves the others out
    (the pure-Python decoder gives every field: a caller must not rely on their absence).
    """
    if _speedups is not None:
        return Columns(*_speedups.decode_columns(data, want))
    skips: List[Skip] = []
    others: List[Tuple[int, int, Any]] = []
    packets = 0
    for e in decode_all(data):
        if isinstance(e, Skip):
            skips.append(e)
            continue
        if isinstance(e, (Nmea, Rtcm)):
            continue  # other protocols' frames hold no fields
        packets += 1
        if any(isinstance(f, Trailing) for f in e.fields):
            others.append((e.offset, -1, e))
        else:
            others.extend((e.offset, k, f) for k, f in enumerate(e.fields))
    return Columns(packets, skips, [], others)


def field_mask(fields: Iterable[Tuple[int, int]]) -> bytes:
    """`decode_columns`' `want` for fields given as (set, descriptor) of their layout class: a
    field of the shared set (`registry.SHARED_SET`) in packets of any set."""
    mask = bytearray(65536)
    shared = getattr(registry, "SHARED_SET", None)
    for s, d in fields:
        for set_id in range(256) if s == shared else (s,):
            mask[(set_id << 8) | d] = 1
    return bytes(mask)


def event_line(event: Event, device: Optional[str] = None) -> str:
    """The canonical JSON line of a parser event."""
    if isinstance(event, Skip):
        return skip_line(event.offset, event.data)
    if isinstance(event, (Nmea, Rtcm)):
        return foreign_line(event.offset, event.data)
    check_device(device)
    return _decode_event(event.data, event.offset, device).line()


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
def _keys(obj: Dict[str, Any], required: Iterable[str], optional: Iterable[str], what: str) -> None:
    allowed = set(required) | set(optional)
    for k in required:
        if k not in obj:
            raise EncodeError(f"{what}: missing {k!r}")
    for k in obj:
        if k not in allowed:
            raise EncodeError(f"{what}: unknown key {k!r}")


def _byte(obj: Dict[str, Any], key: str, what: str) -> int:
    v = obj[key]
    if not is_int(v) or not 0 <= v <= 0xFF:
        raise EncodeError(f"{what}: {key} must be an integer 0..255")
    return int(v)


def _offset(obj: Dict[str, Any], what: str) -> None:
    v = obj["offset"]
    if not is_int(v) or not 0 <= v <= 0xFFFFFFFFFFFFFFFF:
        raise EncodeError(f"{what}: offset must be an integer 0..18446744073709551615")


def _error_text(entry: Dict[str, Any], what: str) -> None:
    if not isinstance(entry["error"], str):
        raise EncodeError(f"{what}: error must be a string")


def _field_bytes(set_id: int, entry: Any, what: str) -> Tuple[Optional[int], bytes]:
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
            devices = ", ".join(str(c.DEVICE) for c in classes)
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
    "field_mask",
    "Columns",
    "Table",
    "Decoder",
    "LineDecoder",
    "decode_stream",
    "decode_bytes",
    "event_line",
    "encode_line",
    "encode_lines",
    "encode_value",
]
