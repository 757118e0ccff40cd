"""`info`'s synchronization section: how healthy a log's time synchronization was (docs/time.md,
"Logs: synchronization health").

Fed every packet in log order with its `timebase.PacketTime` and `timebase.Times`, in memory that
does not grow with the log (the first `SHOW` stretches or jumps of each kind are kept, the rest
counted):

- **stretches without PPS**, per field saying whether a PPS is present (the spec's
  `time.sync_health`, `_columns.SYNC_PPS`: the CV7's Time Sync Status 0xA0,0x02 `time_sync`, the
  GPS Correlation Timestamp 0x80,0x12's PPS flag): a run of packets of that field saying "no PPS";
- **invalid-time stretches**, per clock the packets carry (their GPS time, their external time):
  a run of packets whose field of that clock is present with its valid flags not saying valid;
- **time jumps**: a packet's own time (GPS or external, `PacketTime.gps_ns`) stepping against
  the device clock, from the previous packet of the same data set with both, by more than
  `JUMP_NS` plus `JUMP_PPM` of the device clock's step (the clocks are compared per data set: a
  set's time fields and its device clock describe the same sample; sets may differ by their
  latency). A device clock reset (a new epoch, `timebase.RESET_NS`) forgets the previous packets.

A run is broken only by a packet of the same field saying the opposite; packets without that
field do not break it. Its span: from its first packet to the packet that ends it (the first
saying PPS / valid again), or to its last packet when the log ends first; given on the device
clock when both ends have one (the latest device clock seen at or before each), else in UTC (only
its end, `until UTC ...`, when the log had no time yet at its start), else only as log offsets.
"""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Tuple

from .. import _columns, registry
from ..codec.packets import DecodedField, Packet
from .timebase import NS, RESET_NS, iso

# A time jump: the own time's step minus the device clock's step, in absolute value, over
# JUMP_NS + JUMP_PPM * 1e-6 * (device clock step). A crystal's error is tens of ppm (the simulator's
# --clock-drift example is 100 ppm) and a PPS-disciplined external time corrects it each second by
# at most that (100 us a second); a GPS Time Update sets whole seconds (its time of week, week
# number). 1 ms + 1000 ppm is above the first and below the second.
JUMP_NS = 1_000_000
JUMP_PPM = 1000


# (set, descriptor) -> (attribute, mask) of the PPS fields.
_PPS_FIELDS = {(s, d): (attr, mask) for s, d, attr, mask in _columns.SYNC_PPS}


def _pps(value: Any, attr: str, mask: int) -> bool:
    v = getattr(value, attr)
    return bool(v) if mask == 0 else (int(v) & mask) == mask


class _Runs:
    """Runs of "bad" packets of one field: each run's first and last offset, its packets, the
    clocks at its first packet and at the packet that ended it."""

    SHOW = 10

    def __init__(self, title: str) -> None:
        self.title = title
        self.packets = 0
        self.bad = 0
        self.count = 0
        self.shown: List[str] = []
        self.run: Optional[List[Any]] = None  # [first offset, last offset, packets, start clocks, end clocks]

    def add(self, offset: int, bad: bool, clocks: Tuple[Optional[int], Optional[int]]) -> None:
        self.packets += 1
        if bad:
            self.bad += 1
            if self.run is None:
                self.run = [offset, offset, 0, clocks, clocks]
            self.run[1] = offset
            self.run[2] += 1
            self.run[4] = clocks
        elif self.run is not None:
            self._close(clocks, False)

    def _close(self, end: Tuple[Optional[int], Optional[int]], at_end: bool) -> None:
        assert self.run is not None
        first, last, n, start, _last_clocks = self.run
        self.run = None
        self.count += 1
        if len(self.shown) >= self.SHOW:
            return
        where = f"offset {first}" if first == last else f"offsets {first}-{last}"
        text = f"{where}: {n} packet{'' if n == 1 else 's'}"
        span = _span(start, end)
        if span:
            text += f", {span}"
        if at_end:
            text += " (to the end of the log)"
        self.shown.append(text)

    def lines(self, what: str) -> List[str]:
        if self.run is not None:
            self._close(self.run[4], True)
        # "word N", the same words whatever the counts (a docs example's counts depend on timing)
        out = [f"  {self.title}: packets {self.packets}, {what} {self.bad}, stretches {self.count}"]
        out += ["    " + t for t in self.shown]
        if self.count > len(self.shown):
            out.append(f"    ... and {self.count - len(self.shown)} more")
        return out


def _span(start: Tuple[Optional[int], Optional[int]], end: Tuple[Optional[int], Optional[int]]) -> str:
    (d0, t0), (d1, t1) = start, end
    if d0 is not None and d1 is not None and d1 >= d0:
        return f"device clock {d0 / NS:.6f} s to {d1 / NS:.6f} s ({(d1 - d0) / NS:.3f} s)"
    if t0 is not None and t1 is not None:
        return f"UTC {iso(t0)} to {iso(t1)} ({(t1 - t0) / NS:.3f} s)"
    if t1 is not None:
        return f"until UTC {iso(t1)}"
    return ""


class SyncReport:
    """The synchronization section of `info` (see the module docstring): `add` every packet in log
    order, then `lines()`."""

    def __init__(self, data_sets: Any) -> None:
        self.data_sets = frozenset(data_sets)
        self.pps: Dict[Tuple[Any, Any], _Runs] = {}
        self.gps = _Runs("GPS time fields")
        self.external = _Runs("external time fields")
        self.device: Optional[int] = None
        self.utc: Optional[int] = None
        self.previous: Dict[int, Tuple[int, int]] = {}  # set -> (device ns, own time ns)
        self.has_device_and_time = False
        self.jumps = 0
        self.shown: List[str] = []

    def add(self, packet: Packet, pt: Any, times: Any) -> None:
        """One packet (any set; only data sets count), its `PacketTime` and its `Times`."""
        d = pt.device_ns
        if d is not None:
            if self.device is not None and d < self.device - RESET_NS:
                self.previous.clear()
            self.device = d
        if times.t_ns is not None:
            self.utc = times.t_ns
        if packet.set not in self.data_sets:
            return
        clocks = (self.device, self.utc)
        for f in packet.fields if _PPS_FIELDS else ():
            if not isinstance(f, DecodedField):
                continue
            key: Tuple[Any, Any] = (type(f.value).SET, type(f.value).DESCRIPTOR)
            hit = _PPS_FIELDS.get(key)
            if hit is not None:
                runs = self.pps.get(key)
                if runs is None:
                    name = f"{registry.SET_NAMES.get(key[0], '?')} 0x{key[0]:02X},0x{key[1]:02X} {f.name}"
                    runs = self.pps[key] = _Runs(f"PPS ({name})")
                runs.add(packet.offset, not _pps(f.value, hit[0], hit[1]), clocks)
        if pt.gps_week is not None:
            self.gps.add(packet.offset, pt.gps_ns is None or pt.external, clocks)
        if pt.ext_ns is not None:
            self.external.add(packet.offset, not pt.ext_valid, clocks)
        if d is not None and pt.gps_ns is not None:
            self.has_device_and_time = True
            prev = self.previous.get(packet.set)
            self.previous[packet.set] = (d, pt.gps_ns)
            if prev is not None:
                dd = d - prev[0]
                step = (pt.gps_ns - prev[1]) - dd
                if abs(step) > JUMP_NS + abs(dd) * JUMP_PPM // 1_000_000:
                    self.jumps += 1
                    if len(self.shown) < _Runs.SHOW:
                        self.shown.append(
                            f"set 0x{packet.set:02X} offset {packet.offset}: {step / NS:+.6f} s"
                            f" at device clock {d / NS:.6f} s"
                            + (f" (UTC {iso(times.t_ns)})" if times.t_ns is not None else "")
                        )

    def lines(self) -> List[str]:
        """The section's text (docs/time.md, "Logs: synchronization health")."""
        parts: List[str] = []
        for key in sorted(self.pps):
            parts += self.pps[key].lines("without PPS")
        if self.gps.packets:
            parts += self.gps.lines("not valid")
        if self.external.packets:
            parts += self.external.lines("not valid")
        if not parts:
            return ["synchronization: no synchronization fields"]
        out = ["synchronization:"] + parts
        limit = f"{JUMP_NS / 1e6:g} ms + {JUMP_PPM} ppm"
        if self.has_device_and_time:
            out.append(f"  time jumps against the device clock (over {limit}): {self.jumps}")
            out += ["    " + t for t in self.shown]
            if self.jumps > len(self.shown):
                out.append(f"    ... and {self.jumps - len(self.shown)} more")
        else:
            out.append("  time jumps: no packet with both a device clock and a valid time to compare")
        return out
