"""The time model of recorded logs: GPS time, the device clock and UTC (shared by `export`,
`export --dataset`, `info` and the session).

A packet's time comes from, in this order:

1. its own GPS time (week number + time of week) when its valid flags say it is valid: which
   fields carry GPS time, in which parameters, and which flag bits must be set is a spec fact
   (the protocol's `time` section; the generated table `_columns.GPS_TIMES`);
2. else its external time when its valid flag says it is valid (the CV7's External Timestamp
   0xFF,0xD7, "Equivalent to the GPS Timestamp but in nanoseconds": a count of ns on the GPS time
   scale, since the GPS epoch; the spec's `time.external`, `_columns.EXTERNAL_TIMES`);
3. else its device clock (the reference timestamp, ns since power-on; `_columns.DEVICE_CLOCKS`)
   through the log's clock map (below);
4. else no time (`t_ns` None / null).

A packet's own time (1 or 2) is its `PacketTime.gps_ns`; the rest of the model (anchors, the
block path) does not distinguish the two.

GPS time to UTC: UTC = GPS - leap seconds, the leap seconds being the log's own report
(`_columns.LEAP_SECONDS`, e.g. the CV7's GPS leap seconds 0x91/0x92,0x11, when its valid flag is
set) -- the latest at or before the row, else the log's first -- and otherwise this module's
table `LEAP_TABLE` (the GPS time scale of spec/common/gps_time.yaml; IERS Bulletin C).

**Clock map.** Anchors are (device_ns, gps_ns) pairs from packets that carry both a device clock
and a valid GPS time. A row with only a device clock gets gps = anchor.gps + (device_ns -
anchor.device_ns) from the latest anchor at or before it in the log; rows before the first anchor
use the first anchor. The device clock going backwards by more than `RESET_NS` from the previous
device clock value in the log (a device reset) starts a new *epoch*: rows of an epoch use only
that epoch's anchors (the latest at or before them, else the epoch's first), and an epoch without
anchors gives no time. Small backward steps (up to `RESET_NS`, packets of different data sets
emitted out of sample order) are not resets. The rule compares each device clock value only with
the previous one, so it is computable per split of a log: `split_anchors` summarises one split
(cheap), `ClockMap.from_splits` combines the summaries in log order and `ClockMap.split(k)` gives
split k its starting state; decoding split k with it gives exactly the times the whole log gives.

**Arithmetic.** Everything is integer nanoseconds. The time of week (a double) becomes whole
seconds plus the nearest nanosecond of its fraction (`tow_ns`), exact to the double's own
resolution (about 0.1 ns at the end of a week), so `t_ns` differs from the exact value of the
double by at most 0.5 ns; the device clock is already integer ns. `t_ns` is ns since the Unix
epoch (UTC, POSIX: leap seconds not counted). A time inside an inserted leap second (23:59:60.x
UTC) is given as 00:00:00.x of the next day, as POSIX `timegm` normalises it, so that UTC second
repeats.

Heavy libraries (numpy) are imported only by the block path (`SplitClock.block`).
"""

from __future__ import annotations

import importlib
import math
import os
from typing import Any, Dict, Iterable, List, NamedTuple, Optional, Sequence, Tuple

from .. import _columns
from ..codec.packets import DecodedField, Packet

NS = 1_000_000_000
SECONDS_PER_WEEK = 604_800
WEEK_NS = SECONDS_PER_WEEK * NS
# The GPS time scale (spec/common/gps_time.yaml, generated into _columns): the GPS epoch
# 1980-01-06T00:00:00Z in Unix seconds, and `LEAP_TABLE`, GPS - UTC in seconds from each UTC
# instant on (the Unix time of the first UTC second with the new offset; IERS Bulletin C), 0 before
# the first.
GPS_EPOCH_UNIX_S = _columns.GPS_EPOCH_UNIX_S
GPS_EPOCH_UNIX_NS = GPS_EPOCH_UNIX_S * NS
# A device clock going back by more than this from its previous value is a reset (new epoch).
RESET_NS = 1 * NS
LEAP_TABLE: Tuple[Tuple[int, int], ...] = _columns.LEAP_TABLE
# The same instants on the GPS time scale (ns since the GPS epoch): the UTC instant T with the new
# offset L is GPS T - epoch + L. GPS instants before it use the previous offset, so the inserted
# second 23:59:60 (GPS T - epoch + L - 1 .. + L) maps to T .. T + 1 (see the module docstring).
_LEAP_GPS_NS: Tuple[int, ...] = tuple((t - GPS_EPOCH_UNIX_S + leap) * NS for t, leap in LEAP_TABLE)


def table_leap_seconds(gps_ns: int) -> int:
    """GPS - UTC (s) at a GPS instant (ns since the GPS epoch), from `LEAP_TABLE`."""
    leap = 0
    for at, (_t, value) in zip(_LEAP_GPS_NS, LEAP_TABLE):
        if gps_ns < at:
            break
        leap = value
    return leap


def tow_ns(tow_s: float) -> int:
    """A time of week in seconds (a double) as integer ns: the whole seconds plus the nearest ns
    of the fraction (ties to even, as numpy's rint in the block path)."""
    whole = math.floor(tow_s)
    return int(whole) * NS + int(round((tow_s - whole) * NS))


def valid_tow(tow_s: float) -> bool:
    """A time of week that can be a GPS time: finite, 0 <= tow <= one week."""
    return math.isfinite(tow_s) and 0.0 <= tow_s <= SECONDS_PER_WEEK


def gps_ns(week: int, tow_s: float) -> int:
    """GPS week + time of week -> ns since the GPS epoch (exact integer arithmetic)."""
    return int(week) * WEEK_NS + tow_ns(tow_s)


def gps_ns_to_utc_ns(gps: int, leap: Optional[int] = None) -> int:
    """ns since the GPS epoch -> UTC ns since the Unix epoch; `leap` = GPS - UTC in seconds (the
    device's report), else from `LEAP_TABLE`."""
    if leap is None:
        leap = table_leap_seconds(gps)
    return gps + GPS_EPOCH_UNIX_NS - leap * NS


def gps_to_utc_ns(week: int, tow_s: float, leap: Optional[int] = None) -> int:
    """GPS week number + time of week (s) -> UTC ns since the Unix epoch.

    Integer ns: the tow's fraction is rounded to the nearest ns (see `tow_ns`). `leap` is GPS -
    UTC in seconds when the device reported it, else `LEAP_TABLE` gives it."""
    return gps_ns_to_utc_ns(gps_ns(week, tow_s), leap)


class Anchor(NamedTuple):
    """A point of the clock map: the device clock and the GPS time (ns since the GPS epoch) of
    one packet that carries both."""

    device_ns: int
    gps_ns: int


class PacketTime(NamedTuple):
    """The time facts one packet carries (None where it carries none).

    `device_ns`: its device clock; `gps_week`/`gps_tow`: its own GPS time as sent (raw, whatever
    the flags); `gps_ns`: the packet's own time in ns since the GPS epoch: that GPS time when
    valid (flags set, tow in range), else its external time when valid, else None; `leap`: a valid
    GPS - UTC leap second report; `ext_ns`: its external time as sent (ns on the GPS scale, raw,
    whatever the flag), `ext_valid` its valid flag; `external`: `gps_ns` is the external time."""

    offset: int
    device_ns: Optional[int] = None
    gps_week: Optional[int] = None
    gps_tow: Optional[float] = None
    gps_ns: Optional[int] = None
    leap: Optional[int] = None
    ext_ns: Optional[int] = None
    ext_valid: bool = False
    external: bool = False

    def has_time(self) -> bool:
        return (
            self.device_ns is not None or self.gps_week is not None or self.leap is not None or self.ext_ns is not None
        )


class Times(NamedTuple):
    """A packet's times: `t_ns` UTC ns since the Unix epoch (None when unknown) and the device's
    own time kept raw (`device_ns`, `gps_week`, `gps_tow`; None where the packet has none)."""

    t_ns: Optional[int]
    device_ns: Optional[int]
    gps_week: Optional[int]
    gps_tow: Optional[float]


def _flags_ok(flags: Any, mask: int, inverted: int) -> bool:
    value = int(flags)
    return (value & mask) == mask and (value & inverted) == 0


def _field_key(value: Any) -> Tuple[Any, Any]:
    return (type(value).SET, type(value).DESCRIPTOR)


def packet_time(packet: Packet) -> PacketTime:
    """The time facts of a decoded packet (its first device clock field, its most preferred GPS
    time field -- the spec table's order, first occurrence --, its most preferred external time
    field and its first valid leap report)."""
    device: Optional[int] = None
    gps: Optional[Tuple[int, Any, Any, Any]] = None
    ext: Optional[Tuple[int, int, bool]] = None
    leap: Optional[int] = None
    for f in packet.fields:
        if not isinstance(f, DecodedField):
            continue
        key = _field_key(f.value)
        for s, d, attr, per_second in _columns.DEVICE_CLOCKS:
            if device is None and key == (s, d):
                device = int(getattr(f.value, attr)) * (NS // per_second)
        for rank, (s, d, tow, week, flags, mask, inverted) in enumerate(_columns.GPS_TIMES):
            if key == (s, d) and (gps is None or rank < gps[0]):
                v = f.value
                gps = (rank, getattr(v, week), getattr(v, tow), _flags_ok(getattr(v, flags), mask, inverted))
        for rank, (s, d, attr, per_second, flags, mask) in enumerate(_columns.EXTERNAL_TIMES):
            if key == (s, d) and (ext is None or rank < ext[0]):
                v = f.value
                ext = (rank, int(getattr(v, attr)) * (NS // per_second), _flags_ok(getattr(v, flags), mask, 0))
        for s, d, attr, flags, mask in _columns.LEAP_SECONDS:
            if leap is None and key == (s, d) and _flags_ok(getattr(f.value, flags), mask, 0):
                leap = int(getattr(f.value, attr))
    ext_ns, ext_ok = (ext[1], ext[2]) if ext is not None else (None, False)
    own: Optional[int] = None
    wk: Optional[int] = None
    sec: Optional[float] = None
    if gps is not None:
        wk, sec = int(gps[1]), float(gps[2])
        if gps[3] and valid_tow(sec):
            own = gps_ns(wk, sec)
    external = own is None and ext_ok
    if external:
        own = ext_ns
    return PacketTime(packet.offset, device, wk, sec, own, leap, ext_ns, ext_ok, external)


class Segment(NamedTuple):
    """A stretch of a split without a reset: its first and last anchors (None: no anchor)."""

    first: Optional[Anchor]
    last: Optional[Anchor]


class SplitAnchors(NamedTuple):
    """What the clock map needs of one split: its first and last device clock values, its
    segments (the first from the split start, one more after each reset inside the split) and
    its first and last valid leap second reports."""

    first_device_ns: Optional[int]
    last_device_ns: Optional[int]
    segments: Tuple[Segment, ...]
    first_leap: Optional[int]
    last_leap: Optional[int]


def summarize(times: Iterable[PacketTime]) -> SplitAnchors:
    """The `SplitAnchors` of a split's packets, given in log order."""
    first_dev: Optional[int] = None
    prev: Optional[int] = None
    segments: List[Segment] = []
    seg_first: Optional[Anchor] = None
    seg_last: Optional[Anchor] = None
    first_leap: Optional[int] = None
    last_leap: Optional[int] = None
    for pt in times:
        if pt.leap is not None:
            if first_leap is None:
                first_leap = pt.leap
            last_leap = pt.leap
        d = pt.device_ns
        if d is None:
            continue
        if first_dev is None:
            first_dev = d
        elif prev is not None and d < prev - RESET_NS:
            segments.append(Segment(seg_first, seg_last))
            seg_first = seg_last = None
        prev = d
        if pt.gps_ns is not None:
            a = Anchor(d, pt.gps_ns)
            if seg_first is None:
                seg_first = a
            seg_last = a
    segments.append(Segment(seg_first, seg_last))
    return SplitAnchors(first_dev, prev, tuple(segments), first_leap, last_leap)


def split_anchors(data: Any, base: int, start: int, end: int, arrays: Optional[List[Any]] = None) -> SplitAnchors:
    """The `SplitAnchors` of the packets whose first byte is in [start, end) (log offsets) of
    `data`, the log's bytes from offset `base` (decoded with `packets.decode_columns`; packets
    starting before `start` are read only to resynchronise). `arrays` (a list) gets the packets'
    time facts, which `SplitClock.block(..., arrays=)` takes instead of decoding them again."""
    from ..codec.packets import decode_columns

    np = importlib.import_module("numpy")
    p = _within(np, _columns_arrays(np, decode_columns(data, _time_fields()), base), start, end)
    if arrays is not None:
        arrays.append(p)
    return _summarize_arrays(np, p)


_TIME_FIELDS: List[bytes] = []


def _time_fields() -> bytes:
    """`decode_columns`' `want` of the fields with a time fact (all `_columns_arrays` reads)."""
    if not _TIME_FIELDS:
        from ..codec.packets import field_mask

        keys = {(r[0], r[1]) for table in (_columns.DEVICE_CLOCKS, _columns.GPS_TIMES) for r in table}
        keys |= {(r[0], r[1]) for table in (_columns.EXTERNAL_TIMES, _columns.LEAP_SECONDS) for r in table}
        _TIME_FIELDS.append(field_mask(keys))
    return _TIME_FIELDS[0]


def _within(np: Any, p: Dict[str, Any], start: int, end: int) -> Dict[str, Any]:
    """The arrays of `_columns_arrays` for the packets whose offset is in [start, end): a slice
    of each (the offsets are sorted)."""
    lo, hi = (int(i) for i in np.searchsorted(p["offset"], [start, end]))
    return {k: v[lo:hi] for k, v in p.items()}


def per_device_times() -> bool:
    """True when a field with a time fact has per-device layouts (its values then depend on the
    log's device, which `split_anchors` does not apply: its `arrays` are not the block's)."""
    keys = {(r[0], r[1]) for table in (_columns.DEVICE_CLOCKS, _columns.GPS_TIMES) for r in table}
    keys |= {(r[0], r[1]) for table in (_columns.EXTERNAL_TIMES, _columns.LEAP_SECONDS) for r in table}
    return any(k[2] is not None and (k[0], k[1]) in keys for k in _columns.COLUMNS)


def _summarize_arrays(np: Any, p: Dict[str, Any]) -> SplitAnchors:
    """`summarize` of the per-packet arrays of `_columns_arrays` (vectorised)."""
    leaps = p["leap"][p["leap_ok"]]
    first_leap = int(leaps[0]) if len(leaps) else None
    last_leap = int(leaps[-1]) if len(leaps) else None
    di = np.flatnonzero(p["has_device"])
    if not len(di):
        return SplitAnchors(None, None, (Segment(None, None),), first_leap, last_leap)
    dv = p["device_ns"][di]
    seg = np.zeros(len(dv), dtype=np.int64)
    seg[1:] = np.cumsum(dv[1:] < dv[:-1] - RESET_NS)
    anchors = np.flatnonzero(p["gps_ok"][di])
    gps = p["gps_ns"][di]
    firsts: Dict[int, Anchor] = {}
    lasts: Dict[int, Anchor] = {}
    if len(anchors):
        a_seg = seg[anchors]
        _u, first_i = np.unique(a_seg, return_index=True)
        for i in anchors[first_i]:
            firsts[int(seg[i])] = Anchor(int(dv[i]), int(gps[i]))
        rev = a_seg[::-1]
        _u, last_r = np.unique(rev, return_index=True)
        for i in anchors[::-1][last_r]:
            lasts[int(seg[i])] = Anchor(int(dv[i]), int(gps[i]))
    segments = tuple(Segment(firsts.get(k), lasts.get(k)) for k in range(int(seg[-1]) + 1))
    return SplitAnchors(int(dv[0]), int(dv[-1]), segments, first_leap, last_leap)


class SplitClock:
    """The clock map's state at one point of a log (the start of a split): feed it the packets
    from there on, in log order, and it gives their times.

    `times(packet)` for one decoded packet; `block(cols, base)` for a `decode_columns` block
    (vectorised). Both advance the state, so blocks and packets can follow each other."""

    def __init__(
        self,
        prev_device_ns: Optional[int] = None,
        latest: Optional[Anchor] = None,
        epoch: int = 0,
        firsts: Optional[Dict[int, Anchor]] = None,
        leap_latest: Optional[int] = None,
        leap_first: Optional[int] = None,
    ) -> None:
        self.prev_device_ns = prev_device_ns
        self.latest = latest
        self.epoch = epoch
        self.firsts: Dict[int, Anchor] = dict(firsts or {})
        self.leap_latest = leap_latest
        self.leap_first = leap_first

    def _leap(self, gps: int) -> int:
        leap = self.leap_latest if self.leap_latest is not None else self.leap_first
        return leap if leap is not None else table_leap_seconds(gps)

    def step(self, pt: PacketTime) -> Times:
        """The times of the next packet (its `PacketTime`), advancing the state."""
        if pt.leap is not None:
            self.leap_latest = pt.leap
        gps = pt.gps_ns
        d = pt.device_ns
        if d is not None:
            if self.prev_device_ns is not None and d < self.prev_device_ns - RESET_NS:
                self.epoch += 1
                self.latest = None
            self.prev_device_ns = d
            if gps is not None:
                self.latest = Anchor(d, gps)
            else:
                a = self.latest if self.latest is not None else self.firsts.get(self.epoch)
                if a is not None:
                    gps = a.gps_ns + (d - a.device_ns)
        t = None if gps is None else gps_ns_to_utc_ns(gps, self._leap(gps))
        return Times(t, d, pt.gps_week, pt.gps_tow)

    def times(self, packet: Packet) -> Times:
        """The times of the next decoded packet, advancing the state."""
        return self.step(packet_time(packet))

    def peek(self, packet: Packet) -> Times:
        """The times `times(packet)` would give now, without advancing the state."""
        other = SplitClock(self.prev_device_ns, self.latest, self.epoch, None, self.leap_latest, self.leap_first)
        other.firsts = self.firsts  # (read only by step)
        return other.step(packet_time(packet))

    def block(
        self, cols: Any, base: int, start: Optional[int] = None, end: Optional[int] = None, arrays: Any = None
    ) -> BlockTimes:
        """The times of every packet of a `decode_columns` block (`cols`, decoded from the bytes
        at log offset `base`) with a time fact, restricted to packets whose first byte is in
        [start, end) when given; advances the state past them. `arrays`: the block's time facts
        as `split_anchors` gave them for the same bytes and range (then `cols` is not read).
        Needs numpy."""
        np = importlib.import_module("numpy")
        if arrays is not None:
            return self._block(np, arrays)
        pts = _columns_arrays(np, cols, base)
        if start is not None or end is not None:
            pts = _within(np, pts, start if start is not None else -1, end if end is not None else 1 << 62)
        return self._block(np, pts)

    def _block(self, np: Any, p: Dict[str, Any]) -> BlockTimes:
        n = len(p["offset"])
        dev, has_dev = p["device_ns"], p["has_device"]
        gps, gps_ok = p["gps_ns"], p["gps_ok"]
        # Leap seconds: the latest valid report at or before each packet, else the state's.
        leap_i = np.where(p["leap_ok"], np.arange(n), -1)
        leap_at = np.maximum.accumulate(leap_i) if n else leap_i
        carried = self.leap_latest if self.leap_latest is not None else self.leap_first
        # Epochs: a break where the device clock drops by more than RESET_NS from the previous.
        di = np.flatnonzero(has_dev)
        dv = dev[di]
        prevs = np.empty(len(dv), dtype=np.int64)
        if len(dv):
            prevs[1:] = dv[:-1]
            prevs[0] = self.prev_device_ns if self.prev_device_ns is not None else dv[0]
        brk = dv < prevs - RESET_NS
        epoch_d = self.epoch + np.cumsum(brk)
        # The latest anchor at or before each device-clock packet, in its epoch.
        is_anchor = gps_ok[di]
        pos = np.where(is_anchor, np.arange(len(dv)), -1)
        last = np.maximum.accumulate(pos) if len(dv) else pos
        same = (last >= 0) & (epoch_d[np.maximum(last, 0)] == epoch_d)
        a_dev = np.zeros(len(dv), dtype=np.int64)
        a_gps = np.zeros(len(dv), dtype=np.int64)
        have = np.zeros(len(dv), dtype=bool)
        a_dev[same] = dv[last[same]]
        a_gps[same] = gps[di][last[same]]
        have |= same
        # Otherwise: the carried latest anchor (still the first epoch), else the epoch's first.
        for e in np.unique(epoch_d[~same]) if len(dv) else []:
            sel = (~same) & (epoch_d == e)
            a = self.latest if int(e) == self.epoch and self.latest is not None else self.firsts.get(int(e))
            if a is not None:
                a_dev[sel] = a.device_ns
                a_gps[sel] = a.gps_ns
                have[sel] = True
        mapped = a_gps + (dv - a_dev)
        g = gps.copy()
        ok = gps_ok.copy()
        use = have & ~gps_ok[di]
        g[di[use]] = mapped[use]
        ok[di[use]] = True
        # UTC.
        leaps = np.zeros(n, dtype=np.int64)
        own = leap_at >= 0
        leaps[own] = p["leap"][leap_at[own]]
        if carried is not None:
            leaps[~own] = carried
        else:
            leaps[~own] = _table_leaps(np, g[~own])
        t = g + GPS_EPOCH_UNIX_NS - leaps * NS
        # Advance the state.
        if len(dv):
            end_epoch = int(epoch_d[-1])
            self.prev_device_ns = int(dv[-1])
            if last[-1] >= 0 and epoch_d[last[-1]] == end_epoch:
                self.latest = Anchor(int(dv[last[-1]]), int(gps[di][last[-1]]))
            elif end_epoch != self.epoch:
                self.latest = None
            self.epoch = end_epoch
        if n and leap_at[-1] >= 0:
            self.leap_latest = int(p["leap"][leap_at[-1]])
        return BlockTimes(
            np,
            p["offset"],
            t,
            ok,
            dev,
            has_dev,
            p["gps_week"],
            p["gps_tow"],
            p["has_gps"],
        )


def _table_leaps(np: Any, gps: Any) -> Any:
    """`table_leap_seconds` of an int64 array of GPS ns."""
    at = np.array(_LEAP_GPS_NS, dtype=np.int64)
    values = np.array([0] + [v for _t, v in LEAP_TABLE], dtype=np.int64)
    if len(gps):
        lo, hi = np.searchsorted(at, [gps.min(), gps.max()], side="right")
        if lo == hi:  # every instant between the same two leap seconds (a log mostly is)
            return np.full(len(gps), values[lo], dtype=np.int64)
    return values[np.searchsorted(at, gps, side="right")]


class BlockTimes:
    """The times of a block's packets that have a time fact, sorted by log offset: numpy arrays
    `offset`, `t_ns` (int64, valid where `t_valid`), `device_ns` (int64, where `device_valid`),
    `gps_week` (int32) and `gps_tow` (float64) where `gps_valid` (the packet's own GPS time, raw).
    `lookup(offsets)` gives them for any packet offsets (a packet without a time fact: invalid)."""

    def __init__(
        self,
        np: Any,
        offset: Any,
        t_ns: Any,
        t_valid: Any,
        device_ns: Any,
        device_valid: Any,
        gps_week: Any,
        gps_tow: Any,
        gps_valid: Any,
    ) -> None:
        self._np = np
        self.offset = offset
        self.t_ns = t_ns
        self.t_valid = t_valid
        self.device_ns = device_ns
        self.device_valid = device_valid
        self.gps_week = gps_week
        self.gps_tow = gps_tow
        self.gps_valid = gps_valid

    def __len__(self) -> int:
        return len(self.offset)

    def lookup(self, offsets: Any) -> Dict[str, Any]:
        """Per given packet offset (log offsets, any order): `t_ns`, `t_valid`, `device_ns`,
        `device_valid`, `gps_week`, `gps_tow`, `gps_valid` arrays (invalid where the packet has
        no time fact)."""
        np = self._np
        offsets = np.asarray(offsets, dtype=np.int64)
        n = len(self.offset)
        if n == 0:
            z = np.zeros(len(offsets), dtype=bool)
            return {
                "t_ns": np.zeros(len(offsets), dtype=np.int64),
                "t_valid": z,
                "device_ns": np.zeros(len(offsets), dtype=np.int64),
                "device_valid": z,
                "gps_week": np.zeros(len(offsets), dtype=np.int32),
                "gps_tow": np.zeros(len(offsets), dtype=np.float64),
                "gps_valid": z,
            }
        if len(offsets) == n and np.array_equal(offsets, self.offset):  # every packet with a fact
            pos = np.arange(n)
            hit = np.ones(n, dtype=bool)
        else:
            pos = np.searchsorted(self.offset, offsets)
            pos[pos >= n] = 0
            hit = self.offset[pos] == offsets
        if bool(hit.all()):  # (each packet has a time fact: its entries as they are)
            return {
                "t_ns": self.t_ns[pos],
                "t_valid": self.t_valid[pos],
                "device_ns": self.device_ns[pos],
                "device_valid": self.device_valid[pos],
                "gps_week": self.gps_week[pos].astype(np.int32),
                "gps_tow": self.gps_tow[pos],
                "gps_valid": self.gps_valid[pos],
            }
        return {
            "t_ns": np.where(hit, self.t_ns[pos], 0),
            "t_valid": hit & self.t_valid[pos],
            "device_ns": np.where(hit, self.device_ns[pos], 0),
            "device_valid": hit & self.device_valid[pos],
            "gps_week": np.where(hit, self.gps_week[pos], 0).astype(np.int32),
            "gps_tow": np.where(hit, self.gps_tow[pos], 0.0),
            "gps_valid": hit & self.gps_valid[pos],
        }


def _columns_arrays(np: Any, cols: Any, base: int) -> Dict[str, Any]:
    """Per packet with a time fact, sorted by log offset: `offset`, `device_ns`/`has_device`,
    `gps_week`/`gps_tow`/`has_gps` (raw), `gps_ns`/`gps_ok` (valid GPS time), `leap`/`leap_ok`,
    from a `decode_columns` block; the same choices as `packet_time`."""
    # (offsets, rank, field index, values...) per kind, from the C tables and the other entries.
    dev_parts: List[Tuple[Any, Any, Any, Any]] = []
    gps_parts: List[Tuple[Any, Any, Any, Any, Any, Any]] = []
    ext_parts: List[Tuple[Any, Any, Any, Any, Any]] = []
    leap_parts: List[Tuple[Any, Any, Any, Any]] = []
    for t in cols.tables.values():
        if t.rows == 0:
            continue
        key = (t.cls.SET, t.cls.DESCRIPTOR)
        offs = np.frombuffer(t.offsets, dtype=np.int64)
        idx = np.frombuffer(t.index, dtype=np.int64)
        arrays: Optional[Dict[str, Any]] = None
        for rank, (s, d, attr, per_second) in enumerate(_columns.DEVICE_CLOCKS):
            if key == (s, d):
                arrays = arrays if arrays is not None else t.arrays()
                v = arrays[attr].astype(np.int64) * (NS // per_second)
                dev_parts.append((offs, np.full(len(offs), rank), idx, v))
        for rank, (s, d, tow, week, flags, mask, inverted) in enumerate(_columns.GPS_TIMES):
            if key == (s, d):
                arrays = arrays if arrays is not None else t.arrays()
                fl = arrays[flags].astype(np.int64)
                ok = ((fl & mask) == mask) & ((fl & inverted) == 0)
                gps_parts.append(
                    (
                        offs,
                        np.full(len(offs), rank),
                        idx,
                        arrays[week].astype(np.int64),
                        arrays[tow].astype(np.float64),
                        ok,
                    )
                )
        for rank, (s, d, attr, per_second, flags, mask) in enumerate(_columns.EXTERNAL_TIMES):
            if key == (s, d):
                arrays = arrays if arrays is not None else t.arrays()
                fl = arrays[flags].astype(np.int64)
                v = arrays[attr].astype(np.int64) * (NS // per_second)
                ext_parts.append((offs, np.full(len(offs), rank), idx, v, (fl & mask) == mask))
        for rank, (s, d, attr, flags, mask) in enumerate(_columns.LEAP_SECONDS):
            if key == (s, d):
                arrays = arrays if arrays is not None else t.arrays()
                fl = arrays[flags].astype(np.int64)
                ok = (fl & mask) == mask
                leap_parts.append((offs[ok], np.full(int(ok.sum()), rank), idx[ok], arrays[attr].astype(np.int64)[ok]))
    # Entries the C tables do not hold (and the pure-Python decoder's): one PacketTime each.
    extra: Dict[int, List[Tuple[int, Any]]] = {}
    for off, k, entry in cols.others:
        if k < 0:
            packet = entry
            for j, f in enumerate(packet.fields):
                extra.setdefault(off, []).append((j, f))
        else:
            extra.setdefault(off, []).append((k, entry))
    for off, entries in extra.items():
        for k, f in entries:
            if not isinstance(f, DecodedField):
                continue
            key = _field_key(f.value)
            for rank, (s, d, attr, per_second) in enumerate(_columns.DEVICE_CLOCKS):
                if key == (s, d):
                    dev_parts.append(_one(np, off, rank, k, int(getattr(f.value, attr)) * (NS // per_second)))
            for rank, (s, d, tow, week, flags, mask, inverted) in enumerate(_columns.GPS_TIMES):
                if key == (s, d):
                    v = f.value
                    ok = _flags_ok(getattr(v, flags), mask, inverted)
                    gps_parts.append(
                        (
                            np.array([off], dtype=np.int64),
                            np.array([rank]),
                            np.array([k]),
                            np.array([int(getattr(v, week))], dtype=np.int64),
                            np.array([float(getattr(v, tow))], dtype=np.float64),
                            np.array([ok]),
                        )
                    )
            for rank, (s, d, attr, per_second, flags, mask) in enumerate(_columns.EXTERNAL_TIMES):
                if key == (s, d):
                    v = f.value
                    e_ok = _flags_ok(getattr(v, flags), mask, 0)
                    ns = int(getattr(v, attr)) * (NS // per_second)
                    ext_parts.append(_one(np, off, rank, k, ns) + (np.array([e_ok]),))
            for rank, (s, d, attr, flags, mask) in enumerate(_columns.LEAP_SECONDS):
                if key == (s, d) and _flags_ok(getattr(f.value, flags), mask, 0):
                    leap_parts.append(_one(np, off, rank, k, int(getattr(f.value, attr))))
    dev_off, dev_val = _first(np, dev_parts, [3])
    gps_off, (g_week, g_tow, g_ok) = _first_many(np, gps_parts, [3, 4, 5])
    ext_off, (e_ns, e_ok) = _first_many(np, ext_parts, [3, 4])
    leap_off, leap_val = _first(np, leap_parts, [3])
    offsets = _union(np, [dev_off, gps_off, ext_off, leap_off])
    n = len(offsets)
    out: Dict[str, Any] = {"offset": offsets + base}

    def place(keys: Any, vals: Any, dtype: Any) -> Tuple[Any, Any]:
        a = np.zeros(n, dtype=dtype)
        m = np.zeros(n, dtype=bool)
        if len(keys) == n:  # distinct offsets among `offsets`, as many: all of them, in order
            a[:] = vals
            m[:] = True
        elif len(keys):
            i = np.searchsorted(offsets, keys)
            a[i] = vals
            m[i] = True
        return a, m

    out["device_ns"], out["has_device"] = place(dev_off, dev_val[0] if dev_val else [], np.int64)
    out["gps_week"], out["has_gps"] = place(gps_off, g_week, np.int64)
    out["gps_tow"], _ = place(gps_off, g_tow, np.float64)
    ok, _ = place(gps_off, g_ok, bool)
    tow = out["gps_tow"]
    with np.errstate(invalid="ignore"):
        ok &= np.isfinite(tow) & (tow >= 0) & (tow <= SECONDS_PER_WEEK)
    safe = np.where(ok, tow, 0.0)
    whole = np.floor(safe)
    out["gps_ns"] = np.where(
        ok, out["gps_week"] * WEEK_NS + whole.astype(np.int64) * NS + np.rint((safe - whole) * NS).astype(np.int64), 0
    )
    # The external time where the GPS time is not valid (the order of the module docstring).
    out["ext_ns"], out["has_ext"] = place(ext_off, e_ns, np.int64)
    out["ext_valid"], _ = place(ext_off, e_ok, bool)
    out["external"] = out["ext_valid"] & ~ok
    out["gps_ns"] = np.where(out["external"], out["ext_ns"], out["gps_ns"])
    out["gps_ok"] = ok | out["external"]
    out["leap"], out["leap_ok"] = place(leap_off, leap_val[0] if leap_val else [], np.int64)
    return out


def _union(np: Any, arrays: List[Any]) -> Any:
    """The sorted distinct int64 values of the arrays (np.union1d without np.unique's hashing
    path, which costs more than the block's decode on large blocks)."""
    a = np.sort(np.concatenate([np.asarray(x, dtype=np.int64) for x in arrays]))
    keep = np.ones(len(a), dtype=bool)
    keep[1:] = a[1:] != a[:-1]
    return a[keep]


def _one(np: Any, off: int, rank: int, k: int, value: int) -> Tuple[Any, Any, Any, Any]:
    return (np.array([off], dtype=np.int64), np.array([rank]), np.array([k]), np.array([value], dtype=np.int64))


def _first(np: Any, parts: List[Tuple[Any, ...]], value_cols: List[int]) -> Tuple[Any, List[Any]]:
    return _first_many(np, parts, value_cols)


def _first_many(np: Any, parts: List[Tuple[Any, ...]], value_cols: List[int]) -> Tuple[Any, List[Any]]:
    """Per packet offset, the values of its most preferred (lowest rank), first-occurring entry."""
    if not parts:
        return np.zeros(0, dtype=np.int64), [np.zeros(0) for _ in value_cols]
    if len(parts) == 1 and bool((parts[0][0][1:] > parts[0][0][:-1]).all()):
        return parts[0][0], [parts[0][c] for c in value_cols]  # one entry per packet, in order
    # by offset, then rank, then field index: the parts by rank, then a stable sort by offset
    # (a merge of the parts' runs), checked where offsets tie (else the three-key sort)
    parts = sorted(parts, key=lambda p: int(p[1][0]) if len(p[1]) else 0)
    offs = np.concatenate([p[0] for p in parts])
    ranks = np.concatenate([p[1] for p in parts])
    idx = np.concatenate([p[2] for p in parts])
    order = np.argsort(offs, kind="stable")
    so = offs[order]
    tie = so[1:] == so[:-1]
    if tie.any():
        r, i = ranks[order], idx[order]
        if bool((tie & ((r[1:] < r[:-1]) | ((r[1:] == r[:-1]) & (i[1:] < i[:-1])))).any()):
            order = np.lexsort((idx, ranks, offs))
    offs = offs[order]
    keep = np.ones(len(offs), dtype=bool)
    keep[1:] = offs[1:] != offs[:-1]
    vals = [np.concatenate([p[c] for p in parts])[order][keep] for c in value_cols]
    return offs[keep], vals


class ClockMap:
    """A log's clock map, from its splits' `SplitAnchors` in log order (`from_splits`); `split(k)`
    is the state split k starts from. A whole log is one split: `ClockMap.from_splits([a])`."""

    def __init__(self, starts: List[SplitClock], firsts: Dict[int, Anchor], leap_first: Optional[int]) -> None:
        self._starts = starts
        self.firsts = firsts
        self.leap_first = leap_first

    @classmethod
    def from_splits(cls, splits: Sequence[SplitAnchors]) -> ClockMap:
        prev: Optional[int] = None
        latest: Optional[Anchor] = None
        epoch = 0
        firsts: Dict[int, Anchor] = {}
        leap_latest: Optional[int] = None
        leap_first: Optional[int] = None
        starts: List[Tuple[Optional[int], Optional[Anchor], int, Optional[int]]] = []
        for s in splits:
            starts.append((prev, latest, epoch, leap_latest))
            for j, seg in enumerate(s.segments):
                if j > 0 or (
                    s.first_device_ns is not None and prev is not None and s.first_device_ns < prev - RESET_NS
                ):
                    epoch += 1
                    latest = None
                if seg.first is not None:
                    firsts.setdefault(epoch, seg.first)
                if seg.last is not None:
                    latest = seg.last
            if s.last_device_ns is not None:
                prev = s.last_device_ns
            if s.first_leap is not None and leap_first is None:
                leap_first = s.first_leap
            if s.last_leap is not None:
                leap_latest = s.last_leap
        clocks = [SplitClock(p, a, e, firsts, ll, leap_first) for p, a, e, ll in starts]
        return cls(clocks, firsts, leap_first)

    def __len__(self) -> int:
        return len(self._starts)

    def split(self, k: int) -> SplitClock:
        """A fresh state for split k (each call a new object: feed it split k's packets)."""
        s = self._starts[k]
        return SplitClock(s.prev_device_ns, s.latest, s.epoch, self.firsts, s.leap_latest, self.leap_first)


def columns_times(cols: Any, base: int) -> List[PacketTime]:
    """The `PacketTime` of every packet of a `decode_columns` block with a time fact, in log
    order (`base`: the block's log offset). Needs numpy."""
    np = importlib.import_module("numpy")
    p = _columns_arrays(np, cols, base)
    out: List[PacketTime] = []
    for i in range(len(p["offset"])):
        out.append(
            PacketTime(
                int(p["offset"][i]),
                int(p["device_ns"][i]) if p["has_device"][i] else None,
                int(p["gps_week"][i]) if p["has_gps"][i] else None,
                float(p["gps_tow"][i]) if p["has_gps"][i] else None,
                int(p["gps_ns"][i]) if p["gps_ok"][i] else None,
                int(p["leap"][i]) if p["leap_ok"][i] else None,
                int(p["ext_ns"][i]) if p["has_ext"][i] else None,
                bool(p["ext_valid"][i]),
                bool(p["external"][i]),
            )
        )
    return out


# A log file is read in splits of this many bytes by `file_clock` (small, so that the memory of
# `info` and of every single-log export, which time their rows with it, does not grow with the log:
# one split's columns at a time), each from FILE_LOOKBACK bytes before its start, to resynchronise
# as the dataset's splits do.
FILE_SPLIT = 1 << 20
FILE_LOOKBACK = 64 << 10


def file_clock(path: str, split_bytes: int = FILE_SPLIT) -> ClockMap:
    """The clock map of a log file in memory that does not grow with the log: `split_anchors` of
    each split of `split_bytes` (with numpy; decoded by `decode_columns`), or, without numpy, the
    file's packets decoded one by one (one split). `.split(0)` is then the state to time the whole
    file from its start, packet by packet."""
    from .._protocol import MAX_PACKET

    try:
        importlib.import_module("numpy")
    except ImportError:
        from ..codec.packets import Decoder

        dec = Decoder()
        found: List[PacketTime] = []
        anchors: List[SplitAnchors] = []
        with open(path, "rb") as fh:
            for chunk in iter(lambda: fh.read(1 << 16), b""):
                found.extend(packet_time(e) for e in dec.feed(chunk) if isinstance(e, Packet))
                if len(found) > 4096:  # summarise as it goes: one split per 4096 packets
                    anchors.append(summarize(found))
                    found = []
            found.extend(packet_time(e) for e in dec.flush() if isinstance(e, Packet))
        anchors.append(summarize(found))
        return ClockMap.from_splits([_merged(anchors)])
    size = os.path.getsize(path)
    out = []
    with open(path, "rb") as fh:
        for start in range(0, max(size, 1), split_bytes):
            end = min(size, start + split_bytes)
            base = max(0, start - FILE_LOOKBACK)
            fh.seek(base)
            data = fh.read(min(size, end + MAX_PACKET) - base)
            out.append(split_anchors(data, base, start, end))
    return ClockMap.from_splits(out)


def _merged(parts: List[SplitAnchors]) -> SplitAnchors:
    """One `SplitAnchors` of consecutive parts (what `summarize` of all their packets gives)."""
    first_dev: Optional[int] = None
    prev: Optional[int] = None
    segments: List[Segment] = []
    first_leap: Optional[int] = None
    last_leap: Optional[int] = None
    for p in parts:
        for j, seg in enumerate(p.segments):
            new = j > 0 or (p.first_device_ns is not None and prev is not None and p.first_device_ns < prev - RESET_NS)
            if segments and not new:
                a, b = segments[-1]
                segments[-1] = Segment(a if a is not None else seg.first, seg.last if seg.last is not None else b)
            else:
                segments.append(seg)
        if first_dev is None:
            first_dev = p.first_device_ns
        if p.last_device_ns is not None:
            prev = p.last_device_ns
        if first_leap is None:
            first_leap = p.first_leap
        if p.last_leap is not None:
            last_leap = p.last_leap
    return SplitAnchors(first_dev, prev, tuple(segments) or (Segment(None, None),), first_leap, last_leap)


def log_clock(packets: Iterable[Packet]) -> ClockMap:
    """The clock map of a whole log given as decoded packets (one split)."""
    return ClockMap.from_splits([summarize(packet_time(p) for p in packets)])


def iso(t_ns: int) -> str:
    """UTC ns since the Unix epoch as ISO 8601 text with microseconds (2017-01-01T00:00:00.000000Z)."""
    import datetime

    sec, ns = divmod(t_ns, NS)
    d = datetime.datetime.fromtimestamp(sec, tz=datetime.timezone.utc)
    return d.strftime("%Y-%m-%dT%H:%M:%S") + f".{ns // 1000:06d}Z"


class TimeReport:
    """`info`'s time report, fed every packet in log order (`add(packet, times)`), in memory that
    does not grow with the log (the first `SHOW` events of each kind are kept, the rest counted).
    `lines()` gives the text.

    - time span: first and last UTC time of the data packets, and how many had one (from their
      own GPS time, their external time or through the device clock);
    - time gaps: more than `GAP_NS` without a timed data packet (UTC, against the latest time so far);
    - backward jumps: a data set's UTC time going back from that set's previous timed packet;
    - device clock resets: the device clock going back by more than `RESET_NS` (a new epoch);
    - invalid-time stretches: runs of consecutive data packets without a UTC time, with why
      (GPS time not valid / device clock with no GPS anchor in its epoch / no time field)."""

    GAP_NS = NS
    SHOW = 10

    def __init__(self, data_sets: Iterable[int]) -> None:
        self.data_sets = frozenset(data_sets)
        self.packets = 0
        self.own = 0
        self.external = 0
        self.mapped = 0
        self.first: Optional[int] = None
        self.last: Optional[int] = None
        self.latest: Optional[int] = None
        self.per_set: Dict[int, int] = {}
        self.prev_device: Optional[int] = None
        self.events: Dict[str, List[str]] = {"gaps": [], "backward": [], "resets": [], "invalid": []}
        self.counts: Dict[str, int] = {k: 0 for k in self.events}
        self.run: Optional[List[Any]] = None  # [first offset, last offset, packets, reasons]

    def _event(self, kind: str, text: str) -> None:
        self.counts[kind] += 1
        if len(self.events[kind]) < self.SHOW:
            self.events[kind].append(text)

    def _end_run(self) -> None:
        if self.run is not None:
            first, last, n, reasons = self.run
            why = ", ".join(sorted(reasons))
            where = f"offset {first}" if first == last else f"offsets {first}-{last}"
            self._event("invalid", f"{where}: {n} packet{'' if n == 1 else 's'} ({why})")
            self.run = None

    def add(self, packet: Packet, pt: PacketTime, times: Times) -> None:
        """One packet (any set; only data sets count), its `PacketTime` and its `Times`."""
        d = times.device_ns
        if d is not None:
            if self.prev_device is not None and d < self.prev_device - RESET_NS:
                self._event(
                    "resets",
                    f"offset {packet.offset}: device clock {self.prev_device / NS:.6f} s -> {d / NS:.6f} s",
                )
            self.prev_device = d
        if packet.set not in self.data_sets:
            return
        self.packets += 1
        t = times.t_ns
        if t is None:
            if pt.gps_week is not None and d is None:
                reason = "GPS time not valid"
            elif pt.ext_ns is not None and d is None:
                reason = "external time not valid"
            elif d is not None:
                reason = "no GPS anchor for the device clock"
            else:
                reason = "no time field"
            if self.run is None:
                self.run = [packet.offset, packet.offset, 0, set()]
            self.run[1] = packet.offset
            self.run[2] += 1
            self.run[3].add(reason)
            return
        self._end_run()
        if pt.external:
            self.external += 1
        elif pt.gps_ns is not None:
            self.own += 1
        else:
            self.mapped += 1
        self.first = t if self.first is None else min(self.first, t)
        self.last = t if self.last is None else max(self.last, t)
        if self.latest is not None and t - self.latest > self.GAP_NS:
            self._event(
                "gaps", f"offset {packet.offset}: {iso(self.latest)} -> {iso(t)} (+{(t - self.latest) / NS:.3f} s)"
            )
        self.latest = t if self.latest is None else max(self.latest, t)
        prev = self.per_set.get(packet.set)
        if prev is not None and t < prev:
            self._event(
                "backward",
                f"set 0x{packet.set:02X} offset {packet.offset}: {iso(prev)} -> {iso(t)} ({(t - prev) / NS:.3f} s)",
            )
        self.per_set[packet.set] = t

    def lines(self) -> List[str]:
        """The report's text lines (docs/log-to-csv.md, "Time")."""
        self._end_run()
        timed = self.own + self.external + self.mapped
        ext = f", {self.external} by their external time" if self.external else ""
        if self.first is None or self.last is None:
            out = [f"UTC: none of {self.packets} data packets has a UTC time"]
        else:
            out = [
                f"UTC: first {iso(self.first)}  last {iso(self.last)}  span {(self.last - self.first) / NS:.6f} s"
                f"  ({timed} of {self.packets} data packets: {self.own} by their own GPS time{ext}, {self.mapped} by the device clock)"
            ]
        titles = {
            "gaps": f"time gaps over {self.GAP_NS / NS:g} s",
            "backward": "backward jumps",
            "resets": "device clock resets",
            "invalid": "invalid-time stretches",
        }
        for kind, title in titles.items():
            out.append(f"{title}: {self.counts[kind]}")
            out.extend("  " + e for e in self.events[kind])
            if self.counts[kind] > len(self.events[kind]):
                out.append(f"  ... and {self.counts[kind] - len(self.events[kind])} more")
        return out
