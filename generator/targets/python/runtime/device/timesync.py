"""`<package>-device ADDRESS timesync [--duration S] [--json] [--pps-source NAME]` (docs/timesync.md):
sets up the device's time synchronization as its manual says, then monitors it with the host clock
model (session/clock.py, docs/time.md), one line a second.

The facts come from the spec (`_sim.TIME_SYNC`, the protocol's `time.sync`): the GPS Time Update
command and its window after the PPS edge, the PPS source setting, the status field and flags.

- Setup. A model with a PPS source setting (CV7) gets the source asked for (default: the first
  member of kind receiver: "In almost all cases, the DISABLED and GENERATED options ... should not
  be used", 3dm-cv7-ins-docs.txt:966); with a receiver's PPS the device takes GPS time itself (line
  1604). Otherwise (a GPIO or generated PPS, the GX5-45) the host sends GPS Time Updates from its
  own clock each second (GX5-45 line 867: "recommended ... once per second"), UPDATE_AFTER_S after
  the device's PPS edge, inside the window: the edge is found from the device's timestamps, whose
  fraction is the time since the last PPS (GX5-45 line 2165). The data set carrying the status and
  time fields streams at RATE_HZ (its previous format is restored at the end).
- Each second: `synced` (a PPS present and the time valid), `pps`, `time_valid`, `drift_ppm` (the
  device's reference clock against the host's, positive when the device's is faster), `offset_ms`
  (host minus device time at the latest packet), `jitter_ms` (the model's error bound), `updates`
  (sent so far), and `reason` when not synced: "no data", "no PPS", "no GPS time", "updates outside
  the window" (updates were sent and acknowledged, a PPS is present, and the time is still not set).

Exit status: 0 synced at the end; 1 not synced (the reason on stderr) or the device refused a
command; 2 a usage error (device/cli.py).
"""

from __future__ import annotations

import json
import math
import time
from typing import Any, Callable, Dict, List, Optional

from .. import _sim
from .._columns import GPS_EPOCH_UNIX_S, LEAP_TABLE, REFERENCE_TIMES
from ..session import SessionError

RATE_HZ = 50.0  # the status and time fields' rate (enough packets per second for the clock model)
UPDATE_AFTER_S = 0.15  # an update is sent this long after the device's PPS edge (window: the spec's)
WEEK_S = 604800


def gps_minus_utc(unix_s: float) -> int:
    """GPS - UTC (s) at a UTC instant (Unix seconds), from the GPS time scale (`_columns.LEAP_TABLE`,
    spec/common/gps_time.yaml)."""
    return next((leap for at, leap in reversed(LEAP_TABLE) if unix_s >= at), 0)


def host_gps_seconds() -> float:
    """The host's wall clock (UTC) as GPS seconds since the GPS epoch."""
    now = time.time()
    return now - GPS_EPOCH_UNIX_S + gps_minus_utc(now)


def check_duration(duration: float) -> float:
    """--duration: finite, above 0 (ValueError names it: a usage error, exit 2)."""
    if not (math.isfinite(duration) and 0 < duration <= 7 * 86400):
        raise ValueError(f"--duration {duration:g}: expected seconds above 0 (at most a week)")
    return duration


class Monitor:
    """What the device reports about its time, from the data packets (facts: _sim.TIME_SYNC[model])."""

    def __init__(self, facts: Dict[str, Any]) -> None:
        self.facts = facts
        self.packets = 0
        self.pps: Optional[bool] = None
        self.time_valid: Optional[bool] = None
        self.refresh: Optional[int] = None
        self.refreshes = 0
        self.edge: Optional[float] = None  # host time (s) of the device's latest PPS edge

    def packet(self, packet: Any, at: float) -> None:
        """A data packet, received (or, by the clock model, sent with the least delay) at host time `at`."""
        f = self.facts
        for e in packet.fields:
            v = getattr(e, "value", None)
            key = (getattr(type(v), "SET", None), getattr(type(v), "DESCRIPTOR", None))
            st = f.get("status")
            if st is not None and key == (st["set"], st["descriptor"]):
                self.packets += 1
                self.pps = bool(getattr(v, st["synced"]))
            for x in f.get("external", ()):
                if key == (x["set"], x["descriptor"]) and "tow" in x:
                    flags = int(getattr(v, x["flags"]))
                    want = x["tow_mask"] | x["week_mask"]
                    self.time_valid = flags & want == want
                    self._edge(float(getattr(v, x["tow"])), at)
            c = f.get("correlation")
            if c is not None and key == (c["set"], c["descriptor"]):
                self.packets += 1
                flags = int(getattr(v, c["flags"]))
                self.pps = bool(flags & c["pps"])
                self.time_valid = bool(flags & c["initialized"])
                bit = flags & c["refresh"]
                if self.refresh is not None and bit != self.refresh:
                    self.refreshes += 1
                self.refresh = bit
                self._edge(float(getattr(v, "tow", 0.0)), at)

    def _edge(self, tow: float, at: float) -> None:
        if math.isfinite(tow) and tow >= 0:
            self.edge = at - (tow % 1.0)


class TimeSync:
    """Sets up and monitors one connection's time synchronization (`run` gives the exit status)."""

    def __init__(
        self,
        conn: Any,
        pps_source: Optional[str] = None,
        as_json: bool = False,
        out: Callable[[str], Any] = print,
        gps_now: Callable[[], float] = host_gps_seconds,
        tools: Any = None,
    ) -> None:
        # the device command line's helpers (device/cli.py passes them: it imports this module)
        self.cli = cli = tools
        self.conn = conn
        self.model = conn.model
        facts = _sim.TIME_SYNC.get(self.model)
        if facts is None:
            raise cli.usage(f"timesync: the spec gives no time synchronization facts for {self.model}")
        self.facts = facts
        self.as_json = as_json
        self.out = out
        self.gps_now = gps_now
        self.monitor = Monitor(facts)
        self.updates = 0
        self.send_updates = True
        self.source = self._source(pps_source)
        self.restore: List[Any] = []

    def _source(self, name: Optional[str]) -> Optional[int]:
        """The PPS source value to write (None: the model has no such setting)."""
        setting = self.facts.get("pps_source")
        if setting is None:
            if name is not None:
                raise self.cli.usage(f"--pps-source: {self.model} has no PPS source setting")
            return None
        cls = self._command(setting["command"])
        enum = next(iter(_enum_types(cls, setting["param"])), None)
        members = {m.name.lower(): int(m) for m in enum} if enum is not None else {}
        if name is None:
            name = next((n for n, v in members.items() if setting["kinds"].get(v) == "receiver"), None)
        if name not in members:
            raise self.cli.usage(f"--pps-source {name}: expected one of {', '.join(members)}")
        value = members[name]
        kind = setting["kinds"].get(value, "none")
        if kind == "none":
            raise self.cli.usage(f"--pps-source {name}: no PPS (expected one of {', '.join(members)} but {name})")
        self.send_updates = kind != "receiver"  # a receiver's PPS: the device takes GPS time itself
        return value

    def _command(self, name: str) -> Any:
        classes = self.cli.command_classes(name, self.model)
        if not classes:
            raise self.cli.trouble(f"timesync: {self.model} has no {name} command")
        return classes[0]

    # ------------------------------------------------------------------ setup
    def setup(self) -> None:
        device = self.conn.device
        write = self.cli.function_value("write")
        if self.source is not None:
            setting = self.facts["pps_source"]
            cls = self._command(setting["command"])
            device.call(cls.from_json({"function": write, setting["param"]: self.source}))
        st = self.facts.get("status")
        c = self.facts.get("correlation")
        if st is not None:
            set_id = st["set"]
            descriptors = [st["descriptor"]] + [x["descriptor"] for x in self.facts["external"]]
        elif c is not None:
            set_id, descriptors = c["set"], [c["descriptor"]]
        else:
            raise self.cli.trouble(f"timesync: the spec names no status field for {self.model}")
        ref = next((r for r in REFERENCE_TIMES if r[0] == self.model), None)  # the clock model's field
        if ref is not None and ref[2] not in descriptors and ref[1] in (set_id, 0xFF):
            descriptors.append(ref[2])
        self._stream(set_id, descriptors)

    def _stream(self, set_id: int, descriptors: List[int]) -> None:
        cli, st = self.cli, self.cli.st
        found = cli.format_setting(self.model, set_id)
        if found is None:
            raise cli.trouble(f"timesync: {self.model} has no message format for data set 0x{set_id:02X}")
        s, key = found
        base = cli.read_base_rates(self.conn).get(set_id)
        if not base:
            raise cli.trouble(f"timesync: no base rate known for data set 0x{set_id:02X}")
        decimation = max(1, round(base / RATE_HZ))
        spec = _sim.FORMATS[s.cls]
        item_cls = cli.list_item_class(s)
        items = [item_cls(**{spec[2]: d, spec[3]: decimation}) for d in descriptors]
        previous = st.read_entry(self.conn.device, s, key)
        entry = {**key, spec[1]: [json.loads(i.to_json()) if hasattr(i, "to_json") else i for i in items]}
        self.conn.device.call(st.command_of(s, {**previous, **entry}))
        self.restore.append(st.command_of(s, {**key, **previous}))
        cli.enable(self.conn, set_id)

    def _update(self, edge: float, now: float) -> None:
        """GPS Time Updates (time of week, then week) labelling the PPS edge at host time `edge`."""
        u = self.facts["update"]
        cls = self._command(u["command"])
        label = round(self.gps_now() - (now - edge))  # the host's GPS time at the edge, whole seconds
        write = self.cli.function_value("write")
        for selector, value in ((u["tow"], label % WEEK_S), (u["week"], label // WEEK_S)):
            self.conn.device.call(cls.from_json({"function": write, u["selector"]: selector, u["value"]: value}))
        self.updates += 1

    # ------------------------------------------------------------------ run
    def state(self, t: float) -> Dict[str, Any]:
        m = self.monitor
        model = self.conn.device.host_clock
        drift = model.drift_ppm
        offset = model.offset_ns
        synced = bool(m.pps and m.time_valid)
        line: Dict[str, Any] = {
            "t": round(t, 3),
            "synced": synced,
            "pps": bool(m.pps),
            "time_valid": bool(m.time_valid),
            "drift_ppm": None if drift is None else round(drift, 3),
            "offset_ms": None if offset is None else round(offset / 1e6, 3),
            "jitter_ms": round(model.bound_ns / 1e6, 3) if model.estimated else None,
            "updates": self.updates,
        }
        if not synced:
            if not m.packets:
                line["reason"] = "no data"
            elif not m.pps:
                line["reason"] = "no PPS"
            elif self.send_updates and self.updates >= 2:
                line["reason"] = "updates outside the window"
            else:
                line["reason"] = "no GPS time"
        return line

    def show(self, line: Dict[str, Any]) -> None:
        if self.as_json:
            self.out(json.dumps(line, separators=(",", ":")))
            return
        words = [f"t={line['t']:.1f}s", "synced" if line["synced"] else f"not synced ({line['reason']})"]
        words.append(f"pps={'yes' if line['pps'] else 'no'}")
        words.append(f"time_valid={'yes' if line['time_valid'] else 'no'}")
        for key, unit, spec in (("drift_ppm", "ppm", "+.1f"), ("offset_ms", "ms", "+.3f"), ("jitter_ms", "ms", ".3f")):
            words.append(f"{key.rsplit('_', 1)[0]}={'-' if line[key] is None else format(line[key], spec) + unit}")
        words.append(f"updates={line['updates']}")
        self.out(" ".join(words))

    def run(self, duration: float) -> int:
        device = self.conn.device
        device.host_clock  # noqa: B018 (its first use starts the host clock model)

        def now() -> float:
            return float(device.now_ms()) / 1000.0

        def on_packet(packet: Any) -> None:
            h = device.host_ns(packet)
            self.monitor.packet(packet, now() if h is None else h / 1e9)

        device.on_packet(on_packet)
        start = now()
        end = start + duration
        next_line = start + 1.0
        next_update: Optional[float] = None
        last: Dict[str, Any] = {}
        try:
            self.setup()
            while True:
                t = now()
                if t >= next_line or t >= end:
                    last = self.state(t - start)
                    self.show(last)
                    next_line += 1.0
                    if t >= end:
                        break
                edge = self.monitor.edge
                if self.send_updates and edge is not None:
                    if next_update is None:
                        k = math.floor(t - edge - UPDATE_AFTER_S) + 1
                        next_update = edge + k + UPDATE_AFTER_S
                    if t >= next_update:
                        self._update(next_update - UPDATE_AFTER_S, t)
                        next_update = None
                wake = min(next_line, end, next_update if next_update is not None else math.inf)
                device.pump(max(1, int((wake - now()) * 1000)))
        finally:
            for command in self.restore:
                try:
                    device.call(command)
                except (SessionError, ValueError, OSError):
                    self.cli.note("could not restore the previous message format")
        if not last.get("synced"):
            self.cli.note(f"not synchronized: {last.get('reason', 'no data')}")
            return 1
        return 0


def _enum_types(cls: Any, attr: str) -> List[Any]:
    """The enum classes of a command class's parameter `attr` (from its annotations)."""
    import typing

    from ..codec.layout import Enum

    hint = typing.get_type_hints(cls).get(attr)
    found = []
    for h in [hint] + list(getattr(hint, "__args__", ())):
        if isinstance(h, type) and issubclass(h, Enum):
            found.append(h)
    return found
