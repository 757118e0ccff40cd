"""The simulated device's clocks (issue 52; docs/timesync.md, docs/simulator.md): what the spec's
`time.sync` facts (`_sim.TIME_SYNC`, with their manual lines) and `time.reference_time`
(`_columns.REFERENCE_TIMES`) say, in simulated time.

- **Reference clock**: from power-on, running fast by `drift_ppm` against true (simulated) time
  (--clock-drift): `reference(t) = t (1 + drift_ppm 1e-6)`.
- **Link delay** (--link-jitter MS): each data packet waits a random 0..MS ms (seeded) before it is
  sent, never before the packet ahead of it (the stream's bytes keep their order).
- **PPS**: `input` (a PPS on the device's pin: --pps-input) and `receiver` (the GNSS receiver's,
  while it has a fix) pulse at each whole second of GPS time; `generated` at each whole second of
  the reference clock. The CV7 takes the kind its PPS Source setting chooses; the GX5-45 any of
  input and receiver (PPS Beacon Good).
- **External time**: a GPS Time Update (week or time of week) received while a PPS is present and
  at most `window_ms` after its last rising edge labels that edge (the time of week: the edge's
  whole seconds); later edges count on from it, and between edges the time runs on the reference
  clock (so its fraction is the time since the last PPS, as the GX5-45 manual says, line 2165).
  Without a PPS it runs on from the last edge on the reference clock (it drifts). An update outside
  the window, or without a PPS, is acknowledged and not used (the spec's decision; `late` counts
  them). With a receiver's PPS the time is the receiver's GPS time, valid while it has a fix.
- **Flags**: CV7 GPS Timestamp (0xFF,0xD3) tow and week_number once each was set; External
  Timestamp (0xFF,0xD7) valid while synced and set; Time Sync Status (0xA0,0x02) synced while a PPS
  is present, seconds since the last one (at most 255). GX5-45 GPS Correlation Timestamp
  (0x80,0x12): PPS Beacon Good while a PPS is present, GPS Time Initialized from the first refresh,
  GPS Time Refresh toggling with each refresh (an applied update, the receiver's time returning).
"""

from __future__ import annotations

import math
import random
from typing import Any, Dict, List, Optional, Tuple

from .. import _columns, _sim

WEEK_S = 604800
LOOKBACK_S = 256  # how far back the last PPS is looked for (Time Sync Status saturates at 255)


class Clocks:
    """The clocks of one simulated device `sim` (a Simulator: its device, world, settings)."""

    def __init__(
        self, sim: Any, seed: int = 0, drift_ppm: float = 0.0, jitter_ms: float = 0.0, pps_input: bool = False
    ) -> None:
        self.sim = sim
        self.facts: Dict[str, Any] = _sim.TIME_SYNC.get(sim.device, {})
        self.drift_ppm = drift_ppm
        self.jitter_ms = jitter_ms
        self.pps_input = pps_input
        self.rng = random.Random(f"link-jitter:{seed}")  # its own stream: the values' stay as they were
        self.sent_at = -math.inf  # real time the latest delayed packet is sent at
        self.anchor: Optional[Tuple[int, int]] = None  # (PPS edge index, its whole seconds of week)
        self.week: Optional[int] = None
        self.refreshes: List[float] = []  # simulated times of the applied updates
        self.late = 0  # updates not used: outside the window, or no PPS
        self._last: Tuple[Any, Optional[Tuple[int, float]]] = (None, None)  # last_edge's latest answer
        self._kind: Tuple[int, str] = (-1, "")  # (the simulator's command count, the PPS kind then)
        # the GPS-time reference fields' parameter names (the GX5-45's correlation timestamp)
        self.gps_names = {
            (s, d): (tow, week) for dev, s, d, kind, _p, _n, tow, week, _m in _columns.REFERENCE_TIMES if kind == "gps"
        }
        self.reference = next(
            (
                (s, d, param, per)
                for dev, s, d, kind, param, per, *_ in _columns.REFERENCE_TIMES
                if dev == sim.device and kind == "count"
            ),
            None,
        )

    # ------------------------------------------------------------------ clocks
    def ref(self, t: float) -> float:
        """The reference clock (seconds since power-on) at true simulated time t."""
        return t * (1.0 + self.drift_ppm * 1e-6)

    def kind(self) -> str:
        """The PPS the device uses: the PPS source setting's kind (CV7), else "any" (input or receiver)."""
        setting = self.facts.get("pps_source")
        if setting is None:
            return "any"
        if self._kind[0] == self.sim.commands:  # the settings change only with a command
            return self._kind[1]
        self._kind = (self.sim.commands, self._kind_of(setting))
        return self._kind[1]

    def _kind_of(self, setting: Dict[str, Any]) -> str:
        value = None
        for v in self.sim.current.values():
            if getattr(v, "NAME", "") == setting["command"] and getattr(v, setting["param"], None) is not None:
                value = int(getattr(v, setting["param"]))
        if value is None:
            for cls in self.sim._named(setting["command"]):
                got = self.sim._factory(cls).get(setting["param"])
                if got is not None:
                    value = int(got)
        return str(setting["kinds"].get(value, "none")) if value is not None else "none"

    def _gps_phase(self) -> float:
        return float(self.sim.world.gps_start[1]) % 1.0

    def edge(self, t: float, kind: Optional[str] = None) -> Tuple[int, float]:
        """(index, true time) of the last rising edge at or before t of the PPS of `kind`."""
        kind = kind or self.kind()
        if kind == "generated":
            n = math.floor(self.ref(t) + 1e-12)
            return n, n / (1.0 + self.drift_ppm * 1e-6)
        n = math.floor(t + self._gps_phase() + 1e-12)
        return n, n - self._gps_phase()

    def present(self, t: float, kind: Optional[str] = None) -> bool:
        """Whether a PPS pulses at t."""
        kind = kind or self.kind()
        fix = bool(self.sim.world.gnss_fix(t))
        if kind == "any":
            return self.pps_input or fix
        return {"input": self.pps_input, "receiver": fix, "generated": True}.get(kind, False)

    def pps_kind_at(self, t: float) -> str:
        """The kind of the PPS present at t ("" none): the GX5-45's receiver wins over pin 7."""
        kind = self.kind()
        if kind == "any":
            return "receiver" if self.sim.world.gnss_fix(t) else ("input" if self.pps_input else "")
        return kind if self.present(t, kind) else ""

    def last_edge(self, t: float) -> Optional[Tuple[int, float]]:
        """The last edge at or before t while a PPS was present (within LOOKBACK_S), or None."""
        kind = self.kind()
        n, at = self.edge(t, "generated" if kind == "generated" else "input")
        key = (kind, self.pps_input, n)
        if self._last[0] != key:
            self._last = (key, self._last_edge(kind, n, at))
        return self._last[1]

    def _last_edge(self, kind: str, n: int, at: float) -> Optional[Tuple[int, float]]:
        for _ in range(LOOKBACK_S):
            if at < 0:
                return None
            if self.pps_kind_at(at):
                return n, at
            n, at = n - 1, at - (1.0 if kind != "generated" else 1.0 / (1.0 + self.drift_ppm * 1e-6))
        return None

    def gps_time(self, t: float) -> Tuple[int, float]:
        """(week, time of week) of true GPS time at t (the world's)."""
        week, tow = self.sim.world.gps_start[0], self.sim.world.gps_start[1] + t
        return week + int(tow // WEEK_S), tow % WEEK_S

    def external(self, t: float) -> Tuple[int, float, bool, bool]:
        """(week, time of week, tow set, week set) of the device's external time at t."""
        kind = self.kind()
        if kind == "receiver" and self.sim.world.gnss_fix(t):  # the receiver's GPS time
            week, tow = self.gps_time(t)
            return week, tow, True, True
        last = self.last_edge(t)
        week = self.week or 0
        if last is None:  # no PPS yet: the reference clock
            whole, at = 0, 0.0
        else:
            n, at = last
            if self.anchor is not None:
                whole = self.anchor[1] + n - self.anchor[0]
            elif self.pps_kind_at(at) == "receiver":  # the receiver's GPS time at that edge
                week, g = self.gps_time(at)
                whole = round(g)
            else:
                whole = n
        tow = whole + (self.ref(t) - self.ref(at))
        if kind == "receiver":  # valid only while the receiver has a fix (CV7 line 1604)
            return week, tow, False, False
        return week, tow, self.anchor is not None, self.week is not None

    # ------------------------------------------------------------------ commands
    def command(self, command: Any, t: float) -> None:
        """A command the device received at simulated time t: a GPS Time Update (write) sets the
        external time's week or time of week when it counts (a PPS present, within the window)."""
        update = self.facts.get("update")
        if update is None or getattr(command, "NAME", "") != update["command"]:
            return
        fn = getattr(command, "function", None)
        if fn is not None and int(fn) not in (1, 6):  # write, write without ack (the manuals' values)
            return
        last = self.last_edge(t)
        kind = self.pps_kind_at(t)
        if not kind or last is None or (t - last[1]) * 1000.0 > self.facts["window_ms"] or kind == "receiver":
            self.late += 1
            return
        selector = int(getattr(command, update["selector"], 0) or 0)
        value = int(getattr(command, update["value"], 0) or 0)
        if selector == update["week"]:
            self.week = value
        elif selector == update["tow"]:
            self.anchor = (last[0], value)
        else:
            return
        self.refreshes.append(t)

    # ------------------------------------------------------------------ data
    def fill(self, value: Any, t: float) -> None:
        """Sets the time fields of a data value sampled at simulated time t."""
        key = (getattr(type(value), "SET", None), getattr(type(value), "DESCRIPTOR", None))
        if self.reference is not None and key == self.reference[:2]:
            setattr(value, self.reference[2], int(round(self.ref(t) * self.reference[3])))
            return
        status = self.facts.get("status")
        if status is not None and key == (status["set"], status["descriptor"]):
            last = self.last_edge(t)
            setattr(value, status["synced"], bool(self.pps_kind_at(t)))
            since = status["last_pps_max"] if last is None else min(status["last_pps_max"], int(t - last[1]))
            setattr(value, status["last_pps"], since)
            return
        for x in self.facts.get("external", ()):
            if key == (x["set"], x["descriptor"]):
                week, tow, tow_set, week_set = self.external(t)
                flags = 0
                if "tow" in x:
                    setattr(value, x["tow"], float(tow))
                    setattr(value, x["week"], int(week))
                    flags = (x["tow_mask"] if tow_set else 0) | (x["week_mask"] if week_set else 0)
                else:
                    # the external time as a count (the spec's time.external entry of the field)
                    setattr(value, x["ns"], max(0, int(round((week * WEEK_S + tow) * x["per_second"]))))
                    flags = x["ns_mask"] if (tow_set and week_set and self.pps_kind_at(t)) else 0
                _flags(value, x["flags"], flags)
                return
        c = self.facts.get("correlation")
        if c is not None and key == (c["set"], c["descriptor"]):
            fix = self.sim.world.gnss_fix(t)
            if fix:
                week, tow = self.gps_time(t)
            else:
                week, tow, _, _ = self.external(t)
            refreshes = len([r for r in self.refreshes if r <= t]) + self._fix_refreshes(t)
            flags = (c["pps"] if self.pps_kind_at(t) else 0) | (c["refresh"] if refreshes % 2 else 0)
            flags |= c["initialized"] if refreshes else 0
            names = self.gps_names.get(key, ("tow", "week_number"))
            setattr(value, names[0], float(tow))
            setattr(value, names[1], int(week))
            _flags(value, c["flags"], flags)

    def _fix_refreshes(self, t: float) -> int:
        """How many times the receiver's GPS time became valid by t (its first fix, each outage's end)."""
        world = self.sim.world
        from .world import GNSS_FIX_AFTER

        starts = [GNSS_FIX_AFTER] + [b for _, b in world.gnss_outages if b > GNSS_FIX_AFTER]
        return sum(1 for s in starts if s <= t and world.gnss_fix(s))

    # ------------------------------------------------------------------ link
    def delay(self, chunks: List[Tuple[float, bytes]], speed: float) -> List[Tuple[float, bytes]]:
        """The data packets `chunks` (real send time, bytes), each delayed by 0..jitter_ms of
        simulated time, none before the one ahead of it."""
        if not self.jitter_ms:
            return chunks
        out = []
        for when, data in sorted(chunks, key=lambda c: c[0]):
            at = max(when + self.rng.uniform(0.0, self.jitter_ms) / 1000.0 / speed, self.sent_at)
            self.sent_at = at
            out.append((at, data))
        return out


def _flags(value: Any, attr: str, bits: int) -> None:
    current = getattr(value, attr, None)
    setattr(value, attr, type(current)(bits) if current is not None else bits)
