"""The simulated device's live status (docs/simulator.md, issue 51): what a device status reply
reports while the device runs, filled in by role from the spec's `simulation.status`
(`_sim.STATUS`, generated): the system timer (milliseconds since power-on, in simulated time),
the stream-enabled flags (stream control's state), the bytes written to and read from the host's
link, the 1PPS pulses of the internal receiver (one per whole simulated second while it has a
fix) and the messages the internal sensors delivered (one per tick of their data set's base
rate; the receiver's while it has a fix). The decisions behind these rules are the spec's notes.
"""

from __future__ import annotations

from typing import Any, Callable, Dict, Optional, Set

from .. import _sim

U32 = 1 << 32


class Ticks:
    """Ticks of a clock of `rate` Hz counted up to a simulated time, each only when `when(t)`
    holds (None: always); incremental, so that a long run costs what it adds."""

    def __init__(self, rate: float, when: Optional[Callable[[float], bool]] = None) -> None:
        self.rate = rate
        self.when = when
        self.upto = 0  # ticks 1..upto are counted
        self.count = 0
        self.last = 0  # the last counted tick

    def advance(self, t: float) -> None:
        now = int(t * self.rate)
        if self.when is None:
            self.count, self.last = max(self.count, now), max(self.last, now)
        else:
            for tick in range(self.upto + 1, now + 1):
                if self.when(tick / self.rate):
                    self.count += 1
                    self.last = tick
        self.upto = max(self.upto, now)

    def last_ms(self) -> int:
        return int(self.last * 1000 / self.rate) if self.count else 0


class Counters:
    """What the device counts as it runs: bytes written to and read from the host's link, the
    1PPS pulses and the internal sensors' messages (Ticks, made on first use)."""

    def __init__(self) -> None:
        self.written = 0
        self.read = 0
        self.now = 0.0  # real time of the latest bytes from the host
        self.ticks: Dict[Any, Ticks] = {}

    def of(self, key: Any, rate: float, when: Optional[Callable[[float], bool]]) -> Ticks:
        if key not in self.ticks:
            self.ticks[key] = Ticks(rate, when)
        return self.ticks[key]


def set_of(source: Any, command: Any) -> Optional[int]:
    """The data set a streaming command refers to (_sim.py: a number, a parameter, alternatives)."""
    if isinstance(source, int):
        return source
    if isinstance(source, str):
        value = getattr(command, source, None)
        return None if value is None else int(value)
    for alt in source:
        name, mapping = (alt, None) if isinstance(alt, str) else alt
        if hasattr(command, name):
            value = getattr(command, name)
            if value is None:
                return None
            return mapping.get(int(value)) if mapping else int(value)
    return None


def counters(sim: Any) -> Counters:
    """The Simulator's counters (made on first use)."""
    found: Optional[Counters] = sim.__dict__.get("status_counters")
    if found is None:
        found = sim.__dict__["status_counters"] = Counters()
    return found


def received(sim: Any, data: bytes, now: float) -> None:
    """The host sent `data` at real time `now` (the time the replies to it are built at)."""
    counters(sim).read += len(data)
    counters(sim).now = now


def write(link: Any, chunk: bytes, sim: Any) -> None:
    """Writes `chunk` to the host's link, counting it."""
    link.write(chunk)
    if sim is not None:
        counters(sim).written += len(chunk)


def streams_enabled(sim: Any) -> Set[int]:
    """The data sets whose stream stream control has enabled (its factory value, then the
    writes in their order) and those it cannot address (always on)."""
    on: Set[int] = set()
    for cls, (_, flag) in _sim.ENABLES.items():
        if getattr(cls, "DEVICE", None) in (None, sim.device) and _sim.FACTORY.get(sim.device, {}).get(cls, {}).get(
            flag
        ):
            on |= set(sim.base_rates)
    for value in sim.current.values():
        en = _sim.ENABLES.get(type(value))
        if en is None:
            continue
        set_id = set_of(en[0], value)
        if set_id is not None:
            (on.add if getattr(value, en[1], None) else on.discard)(set_id)
    return on | set(_sim.UNADDRESSED.get(sim.device, ()))


def _set(obj: Any, values: Dict[str, int]) -> None:
    """Sets the named attributes of `obj` and of the structures it holds."""
    for name in getattr(obj, "_ATTRS", ()):
        current = getattr(obj, name, None)
        if name in values:
            setattr(obj, name, values[name] % U32)
        elif hasattr(current, "_ATTRS"):
            _set(current, values)


def fill(sim: Any, value: Any) -> None:
    """Writes the live status into a reply `value` of a class in _sim.STATUS, as the Simulator
    `sim` is when the host's latest command came."""
    roles = _sim.STATUS.get(type(value))
    if roles is None:
        return
    c = counters(sim)
    t = sim.sim_time(c.now)  # simulated seconds since power-on
    has_fix = sim.world.gnss_fix
    values: Dict[str, int] = {}
    for name in roles.get("timer", ()):
        values[name] = int(t * 1000)
    for name in roles.get("power", ()):
        values[name] = 1
    enabled = streams_enabled(sim)
    for name, set_id in roles.get("streams", {}).items():
        values[name] = 1 if set_id in enabled else 0
    if roles.get("bytes"):
        values[roles["bytes"]["written"]] = c.written
        values[roles["bytes"]["read"]] = c.read
    if roles.get("pps"):  # one pulse at each whole second while a PPS is present
        clocks = getattr(sim, "clocks", None)  # a PPS present (clocks.py), else the receiver's fix
        pps = c.of("pps", 1.0, (lambda s: bool(clocks.pps_kind_at(s))) if clocks is not None else has_fix)
        pps.advance(t)
        values[roles["pps"]["count"]] = pps.count
        values[roles["pps"]["last"]] = pps.last_ms()
    for set_id, count, last, while_fix in roles.get("messages", ()):
        rate = float(sim.base_rates.get(set_id, 0) or 0)
        if rate:
            ticks = c.of(set_id, rate, has_fix if while_fix else None)
            ticks.advance(t)
            values[count] = ticks.count
            values[last] = ticks.last_ms()
    _set(value, values)
