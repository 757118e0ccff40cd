"""Samples: continuation packets grouped by their shared timestamp (docs/conformance.md section 6).

`SampleTracker` numbers the samples of raw packets (what `decode --samples` prints);
`SampleGrouper` collects decoded packets into `Sample`s with the fields of all their packets.

    grouper = SampleGrouper()
    for event in Parser().feed(data):
        if isinstance(event, RawPacket):
            for sample in grouper.feed(event):
                use(sample.set, sample.fields)
    for sample in grouper.flush():
        use(sample.set, sample.fields)
"""

from __future__ import annotations

from typing import Dict, List, Optional, Tuple, Union

from .._protocol import DATA_SETS, FIRST_SHARED, MAX_KEY, TIMESTAMPS  # noqa: F401 (samples.MAX_KEY: API)
from .framing import CHECKSUM_SIZE, FIELD_HEADER_SIZE, HEADER_SIZE, SET_OFFSET, FieldBytes, RawPacket, iter_fields
from .layout import BytesLike
from .packets import Entry, Packet, decode_packet


def shared_prefix(set_id: int, payload: BytesLike) -> Tuple[int, int]:
    """(number of fields, bytes) of the leading shared run of the payload of a packet of set `set_id`."""
    count = size = 0
    for f in iter_fields(set_id, payload):
        if not isinstance(f, FieldBytes) or f.descriptor < FIRST_SHARED:
            break
        count += 1
        size = f.offset + FIELD_HEADER_SIZE + len(f.data)
    return count, size


def sample_key(packet: BytesLike) -> Optional[bytes]:
    """The key of a complete packet (section 6), or None when it has none."""
    packet = bytes(packet)
    if packet[SET_OFFSET] not in DATA_SETS:
        return None
    payload = packet[HEADER_SIZE:-CHECKSUM_SIZE]
    key = bytearray()
    seen = set()
    for f in iter_fields(packet[SET_OFFSET], payload):
        if not isinstance(f, FieldBytes) or f.descriptor < FIRST_SHARED:
            break
        size = TIMESTAMPS.get(f.descriptor)
        if size is None or size != len(f.data) or f.descriptor in seen:
            continue
        seen.add(f.descriptor)
        key += payload[f.offset : f.offset + FIELD_HEADER_SIZE + size]
    return bytes(key) if key else None


class SampleTracker:
    """Assigns each data packet its sample number; fixed state (one slot per data set)."""

    def __init__(self) -> None:
        self._next = 0
        self._last: Dict[int, Tuple[int, Optional[bytes]]] = {}

    def feed(self, packet: BytesLike) -> Optional[Tuple[int, bool]]:
        """(sample number, continues an earlier packet) for a packet of a data set, else None."""
        packet = bytes(packet)
        set_id = packet[SET_OFFSET]
        if set_id not in DATA_SETS:
            return None
        key = sample_key(packet)
        last = self._last.get(set_id)
        if key is not None and last is not None and last[1] == key:
            return last[0], True
        number = self._next
        self._next += 1
        self._last[set_id] = (number, key)
        return number, False


class Sample:
    """One sample: its set, number, packets (decoded) and fields (shared copies removed)."""

    __slots__ = ("number", "set", "packets", "fields")

    def __init__(self, number: int, packet: Packet) -> None:
        self.number = number
        self.set = packet.set
        self.packets: List[Packet] = [packet]
        self.fields: List[Entry] = list(packet.fields)

    def _continue(self, packet: Packet, skip: int) -> None:
        self.packets.append(packet)
        self.fields.extend(packet.fields[skip:])

    @property
    def offsets(self) -> List[int]:
        return [p.offset for p in self.packets]

    def __repr__(self) -> str:
        return f"Sample(number={self.number}, set=0x{self.set:02X}, offsets={self.offsets}, fields={self.fields!r})"


class SampleGrouper:
    """Groups decoded data packets into samples; a sample is returned once it is complete."""

    def __init__(self, device: Optional[str] = None) -> None:
        self.device = device
        self._tracker = SampleTracker()
        self._open: Dict[int, Sample] = {}

    def feed(self, packet: Union[RawPacket, BytesLike], offset: Optional[int] = None) -> List[Sample]:
        """Feed one complete packet (a RawPacket or its bytes); returns the samples it completes.

        Packets of command sets are ignored."""
        if isinstance(packet, RawPacket):
            offset, data = packet.offset, packet.data
        else:
            data = bytes(packet)
        placed = self._tracker.feed(data)
        if placed is None:
            return []
        number, continues = placed
        decoded = decode_packet(data, offset or 0, self.device)
        set_id = decoded.set
        open_sample = self._open.get(set_id)
        if continues and open_sample is not None:
            skip, _ = shared_prefix(data[SET_OFFSET], data[HEADER_SIZE:-CHECKSUM_SIZE])
            open_sample._continue(decoded, skip)
            return []
        # (A continuation whose first packets were already flushed starts a new Sample object
        # with the same number.)
        done = self._open.pop(set_id, None)
        self._open[set_id] = Sample(number, decoded)
        return [done] if done is not None else []

    def flush(self) -> List[Sample]:
        """The samples still open (end of the stream), in order of their numbers."""
        done = sorted(self._open.values(), key=lambda s: s.number)
        self._open.clear()
        return done


__all__ = ["SampleTracker", "SampleGrouper", "Sample", "sample_key", "shared_prefix", "DATA_SETS", "TIMESTAMPS"]
