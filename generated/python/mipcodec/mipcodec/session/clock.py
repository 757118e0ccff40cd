"""The host clock model (docs/time.md): from each data packet's device reference time and its host
arrival time, an online estimate of the device clock against the host's monotonic clock.

A packet never arrives before it was sent, so the model estimates the lower envelope of the
arrival times: per bucket of device time (BUCKET_NS) it keeps the packet with the smallest
arrival - device time, keeps the last BUCKETS buckets, and when a bucket closes fits the line under
every kept point that is highest at their mean device time (the lower convex hull's edge spanning
the mean). The hull is exact integer arithmetic; only the slope and what uses it are doubles. C,
C++ and Rust carry the same algorithm step for step (tests/clock/cases.txt, run by all four).
"""

from __future__ import annotations

import math
from typing import Any, Optional

from .. import _columns
from ..codec.packets import DecodedField

# The model's parameters: the spec's time.clock_model (the project's own choice), generated.
BUCKET_NS = _columns.CLOCK_BUCKET_NS  # device time per bucket
BUCKETS = _columns.CLOCK_BUCKETS  # closed buckets kept
MIN_BUCKETS = _columns.CLOCK_MIN_BUCKETS  # closed buckets before there is an estimate
RESTART_NS = _columns.CLOCK_RESTART_NS  # consecutive packets whose arrival and device time steps differ by more restart


class ClockModel:
    """Offset and drift of a device's reference clock against the host's.

    `add(device_ns, host_ns)` per data packet carrying the reference time returns the packet's host
    time (None until estimated); `estimated`, `drift_ppm`, `offset_ns`, `bound_ns` and
    `host_time(device_ns)` read the current estimate; `restarts` counts discontinuities.
    """

    def __init__(self) -> None:
        self.restarts = 0
        self._restart()

    def _restart(self) -> None:
        self._count = 0
        self._d0 = self._a0 = 0
        self._last_d = self._last_a = 0
        self._bucket = 0
        self._cur = (0, 0)
        self._xs: list[int] = []
        self._ys: list[int] = []
        self.estimated = False
        self._fx = self._fy = 0
        self._slope = 0.0
        self.bound_ns = 0

    def add(self, device_ns: int, host_ns: int) -> int | None:
        d, a = device_ns, host_ns
        if self._count:
            if d < self._last_d or abs((a - self._last_a) - (d - self._last_d)) > RESTART_NS:
                self._restart()
                self.restarts += 1
        if not self._count:
            self._d0, self._a0 = d, a
        x = d - self._d0
        y = (a - self._a0) - x
        b = x // BUCKET_NS
        if not self._count:
            self._bucket, self._cur = b, (x, y)
        elif b != self._bucket:
            self._close()
            self._bucket, self._cur = b, (x, y)
        elif y < self._cur[1]:
            self._cur = (x, y)
        self._count += 1
        self._last_d, self._last_a = d, a
        return self.host_time(d)

    def _close(self) -> None:
        self._xs.append(self._cur[0])
        self._ys.append(self._cur[1])
        if len(self._xs) > BUCKETS:
            del self._xs[0], self._ys[0]
        if len(self._xs) < MIN_BUCKETS:
            return
        xs, ys = self._xs, self._ys
        hull: list[int] = []  # indices of the lower convex hull, by increasing x
        for k in range(len(xs)):
            while len(hull) >= 2:
                o, p = hull[-2], hull[-1]
                # p is dropped when it is on or above the line from o to k
                if (xs[p] - xs[o]) * (ys[k] - ys[o]) - (ys[p] - ys[o]) * (xs[k] - xs[o]) > 0:
                    break
                hull.pop()
            hull.append(k)
        n, sum_x = len(xs), sum(xs)
        i = 0
        while xs[hull[i + 1]] * n < sum_x:
            i += 1
        p, q = hull[i], hull[i + 1]
        self._fx, self._fy = xs[p], ys[p]
        self._slope = (ys[q] - ys[p]) / (xs[q] - xs[p])
        worst = 0.0
        for k in range(n):
            r = float(ys[k] - self._fy) - self._slope * float(xs[k] - self._fx)
            worst = max(worst, r)
        self.bound_ns = math.ceil(worst)
        self.estimated = True

    def host_time(self, device_ns: int) -> int | None:
        """The host time (ns, the host clock of `add`) of device time `device_ns`; None until estimated."""
        if not self.estimated:
            return None
        x = device_ns - self._d0
        return self._a0 + x + self._fy + math.floor(self._slope * float(x - self._fx) + 0.5)

    @property
    def drift_ppm(self) -> float | None:
        """How fast the device's reference clock runs against the host's, in ppm (positive: faster)."""
        if not self.estimated:
            return None
        return -1e6 * self._slope / (1.0 + self._slope)

    @property
    def offset_ns(self) -> int | None:
        """Host time minus device time at the latest packet's device time."""
        h = self.host_time(self._last_d)
        return None if h is None else h - self._last_d


WEEK_NS = 604_800 * 1_000_000_000


def reference_ns(packet: Any, device: Optional[str] = None) -> Optional[int]:
    """The device's reference time (ns) of a decoded packet: the field the spec names for `device`
    (`_columns.REFERENCE_TIMES`, the protocol's `time.reference_time`; every device's when None),
    or None when the packet carries none."""
    for dev, s, d, kind, param, per_second, tow, week, _monotonic in _columns.REFERENCE_TIMES:
        if device is not None and dev != device:
            continue
        for f in packet.fields:
            if not isinstance(f, DecodedField) or (type(f.value).SET, type(f.value).DESCRIPTOR) != (s, d):
                continue
            if kind == "count":
                return int(getattr(f.value, param)) * (1_000_000_000 // per_second)
            t = float(getattr(f.value, tow))
            if not 0.0 <= t < 1e7:
                continue  # not a time of week (NaN, negative, absurd)
            return int(getattr(f.value, week)) * WEEK_NS + math.floor(t * 1e9 + 0.5)
    return None
