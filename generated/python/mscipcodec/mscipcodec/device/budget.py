"""The link budget of the device command line (docs/configure-a-device.md "Link budget"): the
bits per second each configured data stream needs on a serial port, by the manuals' UART
bandwidth calculation, against the port's baud rate.

    bits/s = n (k f_mr + sum(S_f f_dr))

per data set (one packet per sample): n bits per UART word, k bytes of packet overhead, S_f each
field's size with its header, f_dr each field's rate (the set's base rate / its decimation) and
f_mr the highest of them. n, k and the header size come from the spec's `link: bandwidth` (the
generated `_link.UART_WORD_BITS`, `PACKET_OVERHEAD`, `FIELD_OVERHEAD`; the manual lines in
`_settings.BANDWIDTH_SOURCES`), the field sizes from the spec's layouts (`_settings.DATA_SIZES`:
the largest size of a variable-length field).
"""

from __future__ import annotations

from typing import List, Mapping, NamedTuple, Optional, Sequence, Tuple

from .. import _link, _settings, _sim, registry
from ..codec.layout import Field

Entries = Sequence[Tuple[int, int]]  # (descriptor, decimation)


class Stream(NamedTuple):
    """One data set's stream: its fields with their rates, and what it needs."""

    set: int
    base_hz: float
    fields: Tuple[Tuple[int, int, float], ...]  # (descriptor, field size with header, rate in Hz)
    packet_hz: float  # f_mr: the highest field rate (one packet per sample)
    bits_per_s: float

    @property
    def bytes_per_s(self) -> float:
        return self.bits_per_s / (_link.UART_WORD_BITS or 1)


class BudgetError(ValueError):
    """A stream that cannot be costed (an unknown field, a zero decimation, no base rate)."""


def available() -> bool:
    """Whether the spec gives the bandwidth calculation (the spec's link section)."""
    return None not in (_link.UART_WORD_BITS, _link.PACKET_OVERHEAD, _link.FIELD_OVERHEAD)


def source() -> str:
    """The manual lines of the calculation, for messages."""
    return _settings.BANDWIDTH_SOURCES or "no manual (the spec has no link bandwidth)"


def field_size(device: str, set_id: int, descriptor: int) -> Optional[int]:
    """The field's largest size on the wire with its header (S_f), None when the spec has no such field."""
    sizes = _settings.DATA_SIZES.get(device, {})
    size = sizes.get((set_id, descriptor))
    if size is None and registry.SHARED_SET is not None:  # a shared field, valid in every data set
        size = sizes.get((int(registry.SHARED_SET), descriptor))
    if size is None or _link.FIELD_OVERHEAD is None:
        return None
    return size + _link.FIELD_OVERHEAD


def stream(device: str, set_id: int, entries: Entries, base_hz: float) -> Stream:
    """What one data set's message format needs at the given base rate."""
    n, k = _link.UART_WORD_BITS, _link.PACKET_OVERHEAD
    if n is None or k is None:
        raise BudgetError("the spec gives no UART bandwidth calculation (link: bandwidth)")
    fields = []
    for descriptor, decimation in entries:
        size = field_size(device, set_id, descriptor)
        if size is None:
            raise BudgetError(f"data field 0x{set_id:02X},0x{descriptor:02X} is not a data field of {device}")
        if decimation <= 0:
            raise BudgetError(
                f"data field 0x{set_id:02X},0x{descriptor:02X}: decimation {decimation} (expected 1 or more)"
            )
        fields.append((descriptor, size, base_hz / decimation))
    packet_hz = max((f[2] for f in fields), default=0.0)
    bits = n * (k * packet_hz + sum(size * hz for _, size, hz in fields))
    return Stream(set_id, base_hz, tuple(fields), packet_hz, bits)


def format_entries(command: Field) -> Optional[Tuple[int, List[Tuple[int, int]]]]:
    """(data set, [(descriptor, decimation)]) of a message format command (the spec's simulation
    `formats`), None for another command."""
    spec = _sim.FORMATS.get(type(command))
    if spec is None:
        return None
    where, list_attr, desc_attr, dec_attr = spec
    set_id = where if isinstance(where, int) else getattr(command, where, None)
    items = getattr(command, list_attr, None) or []
    if set_id is None:
        return None
    # a list of bare descriptors (no member names): decimation 1 (a protocol-wide rate, MS-CIP)
    return int(set_id), [
        (int(getattr(x, desc_attr) if desc_attr else x), int(getattr(x, dec_attr)) if dec_attr else 1) for x in items
    ]


def check(streams: Sequence[Stream], baud: int) -> Tuple[float, bool]:
    """The total bits per second of the streams and whether it fits the baud rate."""
    total = sum(s.bits_per_s for s in streams)
    return total, total <= baud


def describe(streams: Sequence[Stream], baud: Optional[int], where: str = "") -> List[str]:
    """One line per stream and a total line, for `info`, `apply` and `stream`."""
    lines = []
    for s in streams:
        fields = ", ".join(f"0x{d:02X} ({size} B at {hz:g} Hz)" for d, size, hz in s.fields)
        lines.append(
            f"set 0x{s.set:02X}: {s.bits_per_s:.0f} bit/s ({s.bytes_per_s:.0f} bytes/s, "
            f"{s.packet_hz:g} packets/s): {fields or 'no fields'}"
        )
    total = sum(s.bits_per_s for s in streams)
    if baud:
        share = 100.0 * total / baud
        lines.append(f"total {total:.0f} bit/s of {baud} baud{where} ({share:.0f}%)")
    else:
        lines.append(f"total {total:.0f} bit/s (no baud rate known: --baud gives one)")
    return lines


def streams_for(device: str, formats: Mapping[int, Entries], base_rates: Mapping[int, float]) -> List[Stream]:
    """The streams of a set -> message format table (empty formats stream nothing)."""
    out = []
    for set_id in sorted(formats):
        entries = formats[set_id]
        if not entries:
            continue
        base = base_rates.get(set_id) or float(_sim.BASE_RATES.get(device, {}).get(set_id, 0))
        if not base:
            raise BudgetError(f"no base rate known for data set 0x{set_id:02X} of {device}")
        out.append(stream(device, set_id, entries, base))
    return out
