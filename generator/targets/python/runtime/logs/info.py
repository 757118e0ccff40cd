"""`<package> info`: a bounded summary of a log (per set and field: counts, rates, intervals)."""

from __future__ import annotations

import argparse
import math
from typing import Any, Dict, List, Optional, Tuple

from .. import registry
from .._protocol import SYNC
from ..codec.packets import DecodedField, Packet
from .pipeline import ClockLines, LogDevice, PacketClock
from .writers import COLUMN_SETS, Events, SkipPart, Source, packet_time


# --------------------------------------------------------------------------------------- info
class Intervals:
    """The intervals between one field's timestamps, as a histogram of at most MAX_BINS bins:
    exact (one bin per distinct interval) while there are that few, then geometric bins of
    relative width `scale` (doubled whenever the bins would exceed MAX_BINS), each counted at its
    centre. So `info` holds the same small state per (set, field) whatever the log's length."""

    MAX_BINS = 2048

    def __init__(self) -> None:
        self.bins: Dict[float, int] = {}
        self.scale = 0.0  # 0: exact

    def _key(self, dt: float) -> float:
        if self.scale == 0.0:
            return dt
        return math.exp((math.floor(math.log(dt) / self.scale) + 0.5) * self.scale)

    def add(self, dt: float, n: int = 1) -> None:
        key = self._key(dt)
        self.bins[key] = self.bins.get(key, 0) + n
        while len(self.bins) > self.MAX_BINS:
            old, self.bins = self.bins, {}
            self.scale = 1e-4 if self.scale == 0.0 else 2 * self.scale
            for k, m in old.items():
                k2 = self._key(k)
                self.bins[k2] = self.bins.get(k2, 0) + m

    def rate(self) -> Tuple[Optional[float], int, int]:
        """(rate in Hz from the median interval, gaps over 1.5 times it, samples they dropped)."""
        total = sum(self.bins.values())
        if not total:
            return None, 0, 0
        ordered = sorted(self.bins.items())
        seen, step = 0, ordered[-1][0]
        for dt, n in ordered:  # the interval at index total // 2 of the sorted intervals
            seen += n
            if seen > total // 2:
                step = dt
                break
        gaps = dropped = 0
        for dt, n in ordered:
            if dt > 1.5 * step:
                gaps += n
                dropped += n * (round(dt / step) - 1)
        return 1.0 / step, gaps, dropped


class FieldSummary:
    """What `info` keeps of one (set, descriptor, name): counts, the last time, its intervals."""

    __slots__ = ("count", "untimed", "last", "intervals")

    def __init__(self) -> None:
        self.count = 0
        self.untimed = 0
        self.last: Optional[float] = None
        self.intervals = Intervals()

    def add(self, t: Optional[float]) -> None:
        self.count += 1
        if t is None:
            self.untimed += 1
            return
        if self.last is not None and t > self.last:
            self.intervals.add(t - self.last)
        self.last = t


class Summary:
    """What `info` prints, computed from a stream of events in bounded memory (a `FieldSummary`
    per (set, field), not a list per entry)."""

    def __init__(self) -> None:
        self.packets: Dict[int, int] = {}
        self.fields: Dict[Tuple[int, int, str], FieldSummary] = {}
        self.skipped = 0
        self.skip_runs = 0
        self.bad_checksums = 0
        self.first: Optional[float] = None
        self.last: Optional[float] = None
        self.bytes = 0

    def add(self, e: Any) -> None:
        if isinstance(e, Packet):
            self.packets[e.set] = self.packets.get(e.set, 0) + 1
            t = packet_time(e)
            if t is not None:
                self.first = t if self.first is None else min(self.first, t)
                self.last = t if self.last is None else max(self.last, t)
            for f in e.fields:
                d = getattr(f, "descriptor", None)
                if d is None:
                    continue
                name = f.name if isinstance(f, DecodedField) else "(undecoded)"
                key = (e.set, d, name)
                summary = self.fields.get(key)
                if summary is None:
                    summary = self.fields[key] = FieldSummary()
                summary.add(t)
        elif isinstance(e, SkipPart):  # the start of a run still going on
            self.skipped += len(e.data)
            self.bad_checksums += bad_checksums(bytes(e.data) + bytes(e.after), len(e.data))
        else:
            self.skipped += len(e.data)
            self.skip_runs += 1
            self.bad_checksums += bad_checksums(bytes(e.data))

    def lines(self) -> List[str]:
        out = []
        total = sum(self.packets.values())
        out.append(
            f"bytes: {self.bytes}  packets: {total}  skipped bytes: {self.skipped} in {self.skip_runs} runs  bad checksums: {self.bad_checksums}"
        )
        for s in sorted(self.packets):
            out.append(f"set 0x{s:02X} {registry.SET_NAMES.get(s, '?')}: {self.packets[s]} packets")
            for (fs, d, name), summary in sorted(self.fields.items()):
                if fs != s:
                    continue
                hz, gaps, dropped = summary.intervals.rate()
                rate = f"{hz:10.3f} Hz" if hz is not None else "         - Hz"
                # Rates, gaps and drops come from the entries whose packet carries a timestamp.
                note = f"  ({summary.untimed} without timestamp)" if summary.untimed else ""
                out.append(f"  0x{d:02X} {name:32} {summary.count:8} {rate}  gaps {gaps}  dropped {dropped}{note}")
        return out


def bad_checksums(data: bytes, starts: Optional[int] = None) -> int:
    """Complete packets with a wrong checksum inside a skipped run (same header, wrong sum),
    among those that start before `starts` (default: anywhere)."""
    from .._protocol import CHECKSUM_SIZE, HEADER_SIZE, LENGTH_OFFSET
    from ..codec.framing import checksum_bytes

    limit = len(data) if starts is None else starts
    n = 0
    i = data.find(SYNC, 0, limit + len(SYNC) - 1)
    while 0 <= i < limit:
        if i + HEADER_SIZE <= len(data):
            end = i + HEADER_SIZE + data[i + LENGTH_OFFSET] + CHECKSUM_SIZE
            if end <= len(data):
                if checksum_bytes(data[i : end - CHECKSUM_SIZE]) != data[end - CHECKSUM_SIZE : end]:
                    n += 1
        i = data.find(SYNC, i + 1, limit + len(SYNC) - 1)
    return n


def info(args: argparse.Namespace) -> int:
    """The log's counts, its device, a line per clock (device clock, GPS time, UTC: pipeline's
    ClockLines and timebase's TimeReport, the time model of export), its fields' rates and its
    synchronization health (sync.SyncReport)."""
    from . import timebase
    from .sync import SyncReport

    dev = LogDevice.of(args.log, args.device)
    clock = PacketClock(args.log)
    report = timebase.TimeReport(COLUMN_SETS)
    clocks = ClockLines(COLUMN_SETS)
    sync = SyncReport(COLUMN_SETS)
    source = Source(args.log)
    summary = Summary()
    stream = Events(dev.device)

    def add(e: Any) -> None:
        summary.add(e)
        if isinstance(e, Packet):
            dev.packet(e, stream.decoder, strict=False)  # info reports an unknown device, decodes on
            pt = timebase.packet_time(e)
            clocks.add(e, pt)
            times = clock.step(pt)
            report.add(e, pt, times)
            sync.add(e, pt, times)

    for chunk in source.chunks():
        summary.bytes += len(chunk)
        for e in stream.feed(chunk):
            add(e)
    for e in stream.flush():
        add(e)
    lines = summary.lines()
    print("\n".join(lines[:1] + [dev.line()] + clocks.lines() + lines[1:] + report.lines() + sync.lines()))
    return 0
