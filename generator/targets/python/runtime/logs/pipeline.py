"""The one pipeline of the log tools: bytes, frames, the log's device, columns, time, a writer.

Every log tool (`export` CSV/JSONL/Parquet and `--join`, `plot`, `info`, `export --dataset` and
the Spark job) goes through the functions here for the two facts a log's tables depend on beyond
its bytes (docs/log-to-csv.md, "The device" and "Time"):

- **The device.** Some fields have a layout per device (the filter status of the 3DM-GX5-45 and of
  the 3DM-CV7-GNSS/INS). The log's device is the one its own Device Information reply names
  (0x01,0x03 -> 0x81, the model name compared as the session compares it), else `--device` (for
  the dataset: `--model` as a device id); `--device` naming another device than the reply is an
  error; a log whose device is unknown and that holds a field with per-device layouts is an error
  (`unknown_device`), never decoded with a guessed layout. `LogDevice` carries it; the packet path
  decodes with it (`packets.Decoder(device)`), the columnar path re-decodes the per-device entries
  `decode_columns` read with the first device's layout (`columns`).
- **Time.** Every row's `t_ns` (UTC ns since the Unix epoch, None/null where unknown) comes from
  the time model of `timebase` (GPS time, else external time, else the device clock through the
  log's clock map), the
  same as the dataset's: `PacketClock` packet by packet, `SplitClock.block` block by block; `time`
  is the same instant as ISO 8601 text (`iso`, CSV and JSONL) or a UTC timestamp in microseconds
  (Parquet). `ClockLines` gives `info` a line per clock (device clock, GPS time, external time).

Errors are `writers.ToolError` (one line, exit status 2) for the single-log tools and
`DeviceUnknown` (a `dataset.ReadError`: the log's `_files` row, status `unreadable`) for the
dataset.
"""

from __future__ import annotations

import importlib
import os
from typing import Any, Dict, List, Optional, Tuple

from .. import _columns, registry
from ..codec.packets import DecodedField, Packet
from . import identity as ids
from .arrow import to_arrow
from .identity import ReadError
from .writers import ToolError

# (set, descriptor) of the data fields that have a layout per device.
PER_DEVICE = frozenset((s, d) for s, d, dev in _columns.COLUMNS if dev)


def _tool_error(message: str) -> Exception:
    return ToolError(message)


class DeviceUnknown(ReadError):
    """A log whose device is unknown holds a field with per-device layouts (see `unknown_device`)."""


def _field_text(cls: Any) -> str:
    return f"{registry.SET_NAMES.get(cls.SET, f'set_{cls.SET:02x}')}.{cls.NAME}"


def unknown_device(log: str, cls: Any, option: str = "--device") -> str:
    """The error line of a log of unknown device holding the per-device field `cls`."""
    devices = sorted({dev for s, d, dev in _columns.COLUMNS if dev and (s, d) == (cls.SET, cls.DESCRIPTOR)})
    return (
        f"{log}: the log's device is unknown (it has no Device Information reply) and {_field_text(cls)} "
        f"has a layout per device ({', '.join(devices)}): give {option} {'|'.join(registry.DEVICES)}"
    )


def reported_device(identity: Any) -> Optional[str]:
    """The registry device id of a log identity's model (`identity.device_of`), None when unknown."""
    if identity is None or identity.model == ids.UNKNOWN:
        return None
    device: Optional[str] = ids.device_of(identity.model)
    return device


class LogDevice:
    """The device of one log: `device` (a registry device id or None), `identity` (model, serial,
    firmware from the log's Device Information reply; `dataset.Identity`) and where the device
    came from (`source`: "reply", "--device" or "unknown")."""

    def __init__(self, log: str, identity: Any, given: Optional[str]) -> None:
        if given is not None and given not in registry.DEVICES:
            raise _tool_error(f"--device: unknown device {given!r} (one of {', '.join(registry.DEVICES)})")
        self.log = log
        self.identity = identity
        self.given = given
        reported = reported_device(identity)
        if reported is not None and given is not None and given != reported:
            raise _tool_error(self._contradiction(reported))
        self.device = reported or given
        self.source = "reply" if reported else ("--device" if given else "unknown")
        self._identity_sets = frozenset(getattr(c, "SET", None) for c in ids.identity_reports())

    def _contradiction(self, reported: str) -> str:
        return (
            f"{self.log}: --device {self.given} contradicts the log's Device Information reply "
            f"(model {self.identity.model}, serial {self.identity.serial}: {reported})"
        )

    @classmethod
    def of(cls, path: str, given: Optional[str], follow: bool = False) -> LogDevice:
        """The device of the log at `path`: a regular file is searched for its Device Information
        reply first; stdin (`-`) or a followed file have only `given` until a reply streams by."""
        if path == "-" or follow or not os.path.isfile(path):
            return cls(path, ids.Identity(), given)
        try:
            read_at, size = ids.file_reader(path)
            identity = ids.log_identity(read_at, size)
        except ReadError as e:
            raise _tool_error(str(e)) from None
        return cls(path, identity, given)

    def line(self) -> str:
        """`info`'s device line."""
        ident = self.identity
        if self.source == "reply":
            firmware = f" firmware {ident.firmware}" if ident.firmware is not None else ""
            return f"device: {self.device} (model {ident.model}, serial {ident.serial}{firmware}; its Device Information reply)"
        if self.source == "--device":
            return f"device: {self.device} (--device; the log has no Device Information reply)"
        model = f" (model {ident.model})" if ident.model != ids.UNKNOWN else ""
        return f"device: unknown{model} (no Device Information reply naming a known device, no --device)"

    def packet(self, p: Packet, decoder: Any = None, strict: bool = True) -> None:
        """Check a decoded packet in log order: a Device Information reply streaming by names the
        device (the decoder follows it); a per-device field while the device is unknown is an
        error (`strict`; `info` only reports it)."""
        if p.set in self._identity_sets and self.source != "reply":
            ident = ids.identity_from_packet(p)
            reported = reported_device(ident)
            if reported is not None:
                if self.given is not None and self.given != reported:
                    self.identity = ident
                    raise _tool_error(self._contradiction(reported))
                self.identity, self.device, self.source = ident, reported, "reply"
                if decoder is not None:
                    decoder.device = reported
        if self.device is None and strict:
            for f in p.fields:
                if isinstance(f, DecodedField) and _per_device(f.value):
                    raise _tool_error(unknown_device(self.log, type(f.value)))

    def columns(self, cols: Any, data: Any) -> None:
        """A `decode_columns` block decoded for the log's device (`identity.for_device`), or the
        unknown-device error when it holds a per-device field and the device is unknown."""
        if self.device is None:
            cls = per_device_class(cols)
            if cls is not None:
                raise _tool_error(unknown_device(self.log, cls))
            return
        ids.for_device(cols, data, self.device)


def per_device_class(cols: Any) -> Any:
    """The layout class of the first per-device entry of a `decode_columns` block, else None."""
    for t in cols.tables.values():
        if t.rows and _per_device(t.cls):
            return t.cls
    for _off, _k, entry in cols.others:
        if isinstance(entry, DecodedField) and _per_device(entry.value):
            return type(entry.value)
    return None


def _per_device(cls_or_value: Any) -> bool:
    """A data field layout (class or value) of a field with a layout per device (PER_DEVICE: the
    tables' fields; replies to commands are not exported)."""
    return getattr(cls_or_value, "DEVICE", None) is not None and (
        (cls_or_value.SET, cls_or_value.DESCRIPTOR) in PER_DEVICE
    )


def split_device(cols: Any, data: Any, identity: Any, log: str) -> None:
    """The dataset's device rule for one decoded split: its per-device entries decoded with the
    device of `identity` (its reply, else `--model` as a device id); DeviceUnknown (a ReadError:
    the log's `_files` row says why) when it is unknown and the split holds a per-device field."""
    device = reported_device(identity)
    if device is None:
        cls = per_device_class(cols)
        if cls is not None:
            raise DeviceUnknown(unknown_device(log or "log", cls, "--model"))
        return
    ids.for_device(cols, data, device)


# ------------------------------------------------------------------------------------------ time
class PacketClock:
    """UTC time of the packets of one log, packet by packet or block by block, in log order: the
    dataset's model (timebase). A regular file is read once more first for its clock map
    (`timebase.file_clock`), so rows before the first GPS anchor of an epoch are timed as the
    dataset times them; stdin or a followed file is timed as it streams (such rows have none)."""

    def __init__(self, path: str, follow: bool = False) -> None:
        from . import timebase

        self.timebase = timebase
        if path != "-" and not follow and os.path.isfile(path):
            try:
                self.clock = timebase.file_clock(path).split(0)
            except OSError as e:
                raise _tool_error(f"cannot read {path}: {e.strerror or e}") from None
        else:
            self.clock = timebase.SplitClock()

    def t_ns(self, p: Packet) -> Optional[int]:
        """The next packet's UTC ns (None when unknown), advancing the clock."""
        t: Optional[int] = self.clock.times(p).t_ns
        return t

    def step(self, pt: Any) -> Any:
        """The next packet's times from its `timebase.PacketTime` (`SplitClock.step`), advancing
        the clock."""
        return self.clock.step(pt)

    def block(self, cols: Any, base: int) -> Any:
        """The `timebase.BlockTimes` of the next `decode_columns` block (decoded from log offset
        `base`), advancing the clock."""
        return self.clock.block(cols, base)


class UtcText(str):
    """A row's `time` cell on the packet path: ISO 8601 UTC text (CSV, JSONL), carrying its
    `t_ns` for Parquet (a timestamp in microseconds)."""

    t_ns: int

    def __new__(cls, t_ns: int) -> UtcText:
        from .timebase import iso

        self = super().__new__(cls, iso(t_ns))
        self.t_ns = t_ns
        return self


TIME_COLUMNS = ("t_ns", "time")


def time_cells(t_ns: Optional[int]) -> List[Any]:
    """The `t_ns` and `time` cells of a row on the packet path."""
    return [None, None] if t_ns is None else [t_ns, UtcText(t_ns)]


def t_ns_array(np: Any, pa: Any, block: Any, offsets: Any) -> Any:
    """The arrow int64 `t_ns` of packets at log `offsets` from a block's `BlockTimes` (null where
    unknown)."""
    got = block.lookup(offsets)
    return to_arrow(np, pa, np.asarray(got["t_ns"], dtype=np.int64), got["t_valid"])


def time_array(pa: Any, t_ns: Any, text: bool) -> Any:
    """The `time` column of an arrow int64 `t_ns` column: UTC timestamps in microseconds, or
    (`text`) their ISO 8601 text as `timebase.iso` writes it."""
    pc = importlib.import_module("pyarrow.compute")
    if isinstance(t_ns, pa.ChunkedArray):
        t_ns = t_ns.combine_chunks()
    us = pc.divide(t_ns, pa.scalar(1000, pa.int64())).cast(pa.timestamp("us", tz="UTC"))
    return pc.strftime(us, format="%Y-%m-%dT%H:%M:%SZ") if text else us


# ------------------------------------------------------------------------------------ info's clocks
class _Track:
    """One clock's values in log order: first, last, span, gaps (a forward step over GAP_NS) and
    backward jumps (a step back), with the first few of each."""

    SHOW = 3

    def __init__(self) -> None:
        self.count = 0
        self.first: Optional[int] = None
        self.last: Optional[int] = None
        self.low: Optional[int] = None
        self.high: Optional[int] = None
        self.gaps: List[str] = []
        self.jumps: List[str] = []
        self.n_gaps = 0
        self.n_jumps = 0

    def add(self, value: int, offset: int, gap_ns: int, show: Any) -> None:
        self.count += 1
        if self.last is not None:
            step = value - self.last
            if step > gap_ns:
                self.n_gaps += 1
                if len(self.gaps) < self.SHOW:
                    self.gaps.append(f"offset {offset}: {show(self.last)} -> {show(value)}")
            elif step < 0:
                self.n_jumps += 1
                if len(self.jumps) < self.SHOW:
                    self.jumps.append(f"offset {offset}: {show(self.last)} -> {show(value)}")
        if self.first is None:
            self.first = value
        self.last = value
        self.low = value if self.low is None else min(self.low, value)
        self.high = value if self.high is None else max(self.high, value)

    def text(self, what: str, show: Any, gap_ns: int, of: int) -> List[str]:
        if self.first is None or self.last is None or self.low is None or self.high is None:
            return [f"{what}: none of {of} data packets has it"]
        out = [
            f"{what}: first {show(self.first)}  last {show(self.last)}  span {(self.high - self.low) / 1e9:.6f} s"
            f"  ({self.count} of {of} data packets)  gaps over {gap_ns / 1e9:g} s: {self.n_gaps}"
            f"  backward jumps: {self.n_jumps}"
        ]
        out += [f"  gap {g}" for g in self.gaps] + [f"  backward {j}" for j in self.jumps]
        return out


class ClockLines:
    """`info`'s line per clock of the data packets, in memory that does not grow with the log:
    the device clock (reference time, ns since power-on) and the GPS time the packets carry as
    valid (week and time of week) and, when the log has an external time field, the external time
    the packets carry as valid (ns on the GPS scale); each with its first and last value, its span
    (from its lowest to its highest value), its gaps over GAP_NS and its backward jumps. The UTC line is
    `timebase.TimeReport`'s (the time model's result)."""

    GAP_NS = 1_000_000_000

    def __init__(self, data_sets: Any) -> None:
        self.data_sets = frozenset(data_sets)
        self.packets = 0
        self.device = _Track()
        self.gps = _Track()
        self.external = _Track()
        self.has_external = False

    def add(self, packet: Packet, pt: Any) -> None:
        """One packet in log order and its `timebase.PacketTime`."""
        if packet.set not in self.data_sets:
            return
        self.packets += 1
        if pt.device_ns is not None:
            self.device.add(pt.device_ns, packet.offset, self.GAP_NS, _seconds)
        if pt.gps_ns is not None and not pt.external:
            self.gps.add(pt.gps_ns, packet.offset, self.GAP_NS, _gps_text)
        if pt.ext_ns is not None:
            self.has_external = True
            if pt.ext_valid:
                self.external.add(pt.ext_ns, packet.offset, self.GAP_NS, _gps_text)

    def lines(self) -> List[str]:
        out = self.device.text("device clock", _seconds, self.GAP_NS, self.packets)
        out += self.gps.text("GPS time", _gps_text, self.GAP_NS, self.packets)
        if self.has_external:
            out += self.external.text("external time", _gps_text, self.GAP_NS, self.packets)
        return out


def _seconds(ns: int) -> str:
    return f"{ns / 1e9:.6f} s"


def _gps_text(gps_ns: int) -> str:
    week, rest = divmod(gps_ns, 604_800 * 1_000_000_000)
    return f"week {week} tow {rest / 1e9:.3f} s"


def plot_times(series: Dict[str, Tuple[List[Any], List[float], str]], timed: bool) -> Any:
    """x values of `plot`: UTC (numpy datetime64[ns]) of the rows with a time when the log has
    any, else the packet offsets; `series` maps a column to (x: (t_ns or None, offset), y, units)."""
    np = importlib.import_module("numpy")
    out = {}
    for name, (xs, ys, units) in series.items():
        if timed:
            pts = [(t, y) for (t, _o), y in zip(xs, ys) if t is not None]
            x = np.array([t for t, _y in pts], dtype="datetime64[ns]")
            out[name] = (x, [y for _t, y in pts], units)
        else:
            out[name] = ([float(o) for _t, o in xs], ys, units)
    return out


__all__ = [
    "PER_DEVICE",
    "DeviceUnknown",
    "LogDevice",
    "PacketClock",
    "ClockLines",
    "UtcText",
    "TIME_COLUMNS",
    "time_cells",
    "time_array",
    "t_ns_array",
    "split_device",
    "unknown_device",
    "per_device_class",
]
