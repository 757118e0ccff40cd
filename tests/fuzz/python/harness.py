"""Fuzz harnesses over the generated pure-Python packages (mipcodec, mscipcodec).

The targets take the input format of the C harnesses (tests/fuzz/c/), so an input saved by any
language replays in all of them, and check the same properties:

- ``parser(pkg, data)``: byte 0 is a control byte (chunk plan in its low 6 bits, device in its top
  2 bits), the rest a byte stream. The events cover the stream exactly (contiguous offsets, skip and
  packet lengths summing to its length, no two skip runs in a row, packets with a valid checksum
  equal to the stream's bytes); the stream fed in chunks gives the same events and the same lines
  (``decode_stream``); ``decode_bytes`` gives the lines of the events; every field is walked and
  decoded through ``decode_field`` (no device and each device) and a field that decodes re-encodes
  to exactly its bytes; every canonical line is printable ASCII and encodes back to the event's
  bytes. The stream is also wrapped as (set, payload) into a packet with a valid checksum.
- ``decode(pkg, data)``: the lean companion of ``parser`` (for execution count; the input format
  of ``parser``): one whole parse with the event checks, every field walked and decoded with the
  control byte's device only and re-encoded, and the stream wrapped into a packet; no chunked
  re-parse, no canonical lines.
- ``json(pkg, data)``: each line of the input (UTF-8; other input is not a line the encode tool
  reads) goes through ``encode_line``; when accepted, the bytes are parsed and every event's line
  must encode back to that event's bytes. A rejected line raises only ``EncodeError``.

A failed check raises ``FuzzCheckFailed`` (a finding for atheris, a failure for pytest). The
Python library prints into strings, so the C harnesses' small-buffer checks have no counterpart.
"""

from __future__ import annotations

from types import ModuleType

from tests.helpers.generated import python_package


class FuzzCheckFailed(AssertionError):
    """A harness property does not hold."""


def check(cond: object, message: str) -> None:
    if not cond:
        raise FuzzCheckFailed(message)


def load(package: str) -> ModuleType:
    """The generated package (generated/python/<package>), imported from the source tree."""
    return python_package(package)


def chunk_sizes(control: int):
    """Chunk sizes of the chunked parse (the same plan as tests/fuzz/c/fuzz_common.h)."""
    state = control
    top = (control & 0x3F) + 1
    while True:
        state = (state * 73 + 41) & 0xFF
        yield 1 + state % top


def _events(m: ModuleType, stream: bytes, chunks=None) -> list:
    parser = m.Parser()
    out = []
    if chunks is None:
        out += parser.feed(stream)
    else:
        pos = 0
        while pos < len(stream):
            n = min(next(chunks), len(stream) - pos)
            out += parser.feed(stream[pos : pos + n])
            pos += n
    out += parser.flush()
    end = 0
    last = None
    for ev in out:
        check(ev.offset == end, f"event at {ev.offset}, expected {end}")
        check(len(ev.data) > 0, "empty event")
        check(bytes(ev.data) == stream[ev.offset : ev.offset + len(ev.data)], f"event bytes differ at {ev.offset}")
        if isinstance(ev, m.Skip):
            check(not isinstance(last, m.Skip), "two skip runs in a row")
        else:
            check(isinstance(ev, (m.RawPacket, m.Nmea, m.Rtcm)), f"event {ev!r}")
        end += len(ev.data)
        last = ev
    check(end == len(stream), f"the events cover {end} of {len(stream)} bytes")
    return out


def _check_field(m: ModuleType, set_id: int, descriptor: int, data: bytes, device) -> None:
    entry = m.decode_field(set_id, descriptor, data, device)
    if isinstance(entry, m.DecodedField):
        check(entry.descriptor == descriptor, "decoded descriptor")
        again = entry.value.encode()
        check(
            again == data,
            f"{entry.name} (set {set_id} descriptor {descriptor}) re-encodes to {again.hex()}, data {data.hex()}",
        )
    else:
        check(isinstance(entry, m.RawField) and entry.error, f"raw field without an error: {entry!r}")


def _check_line(m: ModuleType, line: str, data: bytes) -> None:
    check(all(0x20 <= ord(c) < 0x7F for c in line), f"not printable ASCII: {line}")
    try:
        out = m.encode_line(line)
    except m.EncodeError as e:
        raise FuzzCheckFailed(f"the decoded line does not encode ({e}): {line}") from None
    check(out == data, f"the line encodes to {out.hex()}, not {data.hex()}: {line}")


def _check_packet(m: ModuleType, packet: bytes, offset: int, device, tracker) -> str:
    framing = m.codec.framing
    check(len(packet) >= framing.HEADER_SIZE + framing.CHECKSUM_SIZE, "short packet")
    set_id = packet[framing.SET_OFFSET]
    payload = packet[framing.HEADER_SIZE : -framing.CHECKSUM_SIZE]
    check(packet[framing.LENGTH_OFFSET] == len(payload), "payload length byte")
    check(framing.checksum_bytes(packet[: -framing.CHECKSUM_SIZE]) == packet[-framing.CHECKSUM_SIZE :], "checksum")
    pos = 0
    ended = False
    for f in m.iter_fields(set_id, payload):
        check(not ended, "an entry after the trailing entry")
        check(f.offset == pos, f"entry at {f.offset}, expected {pos}")
        if isinstance(f, framing.TrailingBytes):
            check(f.data == payload[pos:] and f.data and f.error, "trailing entry is not the rest")
            pos = len(payload)
            ended = True
            continue
        head = payload[pos : pos + framing.FIELD_HEADER_SIZE]
        check(f.descriptor == head[framing.FIELD_DESCRIPTOR_OFFSET], "field descriptor")
        adjust = framing.field_length_adjust(set_id, f.descriptor)
        check(len(f.data) == head[framing.FIELD_LENGTH_OFFSET] - adjust, "field length")
        pos += framing.FIELD_HEADER_SIZE + len(f.data)
        _check_field(m, set_id, f.descriptor, f.data, None)
        for d in m.DEVICES:
            _check_field(m, set_id, f.descriptor, f.data, d)
    check(pos == len(payload), f"the entries cover {pos} of {len(payload)} payload bytes")
    line = m.decode_packet(packet, offset, device).line()
    _check_line(m, line, packet)
    tracker.feed(packet)
    return line


def parser(package: str, data: bytes) -> None:
    """The `parser` target."""
    if not data:
        return
    m = load(package)
    control, stream = data[0], bytes(data[1:])
    dev = control >> 6
    device = m.DEVICES[dev - 1] if 1 <= dev <= len(m.DEVICES) else None
    tracker = m.SampleTracker()
    lines = []
    whole = _events(m, stream)
    for ev in whole:
        if isinstance(ev, m.RawPacket):
            lines.append(_check_packet(m, bytes(ev.data), ev.offset, device, tracker))
        elif isinstance(ev, (m.Nmea, m.Rtcm)):  # section 1 foreign frames: not encoder input
            line = m.codec.packets.event_line(ev, device)
            check(all(0x20 <= ord(c) < 0x7F for c in line), f"not printable ASCII: {line}")
            lines.append(line)
        else:
            line = m.codec.packets.event_line(ev, device)
            _check_line(m, line, bytes(ev.data))
            lines.append(line)
    chunked = _events(m, stream, chunk_sizes(control))
    check(
        [(type(e), e.offset, bytes(e.data)) for e in whole] == [(type(e), e.offset, bytes(e.data)) for e in chunked],
        "events differ when fed in chunks",
    )
    check(m.decode_bytes(stream, device) == lines, "decode_bytes differs from the event lines")
    sizes = chunk_sizes(control)
    pieces = []
    pos = 0
    while pos < len(stream):
        n = next(sizes)
        pieces.append(stream[pos : pos + n])
        pos += n
    check(list(m.decode_stream(pieces, device)) == lines, "decode_stream in chunks differs")
    if stream:
        built = m.PacketBuilder(stream[0]).add_bytes(stream[1 : 1 + m.codec.framing.MAX_PAYLOAD]).build()
        one = _events(m, built)
        check(len(one) == 1 and isinstance(one[0], m.RawPacket), "a built packet does not parse as one packet")
        _check_packet(m, built, 0, device, m.SampleTracker())


def _decode_fields(m: ModuleType, packet: bytes, device) -> None:
    framing = m.codec.framing
    set_id = packet[framing.SET_OFFSET]
    payload = packet[framing.HEADER_SIZE : -framing.CHECKSUM_SIZE]
    check(packet[framing.LENGTH_OFFSET] == len(payload), "payload length byte")
    pos = 0
    for f in m.iter_fields(set_id, payload):
        check(f.offset == pos, f"entry at {f.offset}, expected {pos}")
        if isinstance(f, framing.TrailingBytes):
            check(f.data == payload[pos:] and f.data and f.error, "trailing entry is not the rest")
            pos = len(payload)
            continue
        pos += framing.FIELD_HEADER_SIZE + len(f.data)
        _check_field(m, set_id, f.descriptor, f.data, device)
    check(pos == len(payload), f"the entries cover {pos} of {len(payload)} payload bytes")


def decode(package: str, data: bytes) -> None:
    """The `decode` target."""
    if not data:
        return
    m = load(package)
    dev = data[0] >> 6
    device = m.DEVICES[dev - 1] if 1 <= dev <= len(m.DEVICES) else None
    stream = bytes(data[1:])
    for ev in _events(m, stream):
        if isinstance(ev, m.RawPacket):
            _decode_fields(m, bytes(ev.data), device)
    if stream:
        built = m.PacketBuilder(stream[0]).add_bytes(stream[1 : 1 + m.codec.framing.MAX_PAYLOAD]).build()
        one = _events(m, built)
        check(len(one) == 1 and isinstance(one[0], m.RawPacket), "a built packet does not parse as one packet")
        _decode_fields(m, built, device)


def json(package: str, data: bytes) -> None:
    """The `json` target."""
    m = load(package)
    try:
        text = bytes(data).decode("utf-8")
    except UnicodeDecodeError:
        return
    for line in text.split("\n"):
        try:
            out = m.encode_line(line)
        except m.EncodeError:
            continue
        for ev in _events(m, out):
            again = m.codec.packets.event_line(ev, None)
            if isinstance(ev, (m.Nmea, m.Rtcm)):
                # a foreign frame's line is not encoder input (docs/conformance.md section 5)
                try:
                    m.encode_line(again)
                except m.EncodeError as e:
                    check(str(e) != "", f"{again} refused without a message")
                    continue
                raise FuzzCheckFailed(f"the foreign frame's line encodes: {again}")
            try:
                back = m.encode_line(again)
            except m.EncodeError as e:
                raise FuzzCheckFailed(f"the decoded line does not encode ({e}): {again}") from None
            check(back == bytes(ev.data), f"{again} encodes to {back.hex()}, not {bytes(ev.data).hex()}")


TARGETS = {"parser": parser, "decode": decode, "json": json}
