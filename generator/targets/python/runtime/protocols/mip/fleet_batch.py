"""The fleet generator's batch path (fleet.py, docs/fleet.md): the data streams of one simulated
device written block by block with numpy, at the speed the log tools' tests and benchmarks need,
from the same facts as the simulator's own sample-by-sample path (`Simulator.poll`):

- the samples due: the simulator's plan after the configuration (data set, descriptors and
  decimation, `_sim.BASE_RATES`), every tick k * decimation / base rate up to the end;
- the world: `World.batch` (sim/world.py), the quantities of `World.quantities` on arrays, its
  filter's state that of every sample (NavFilter), one world per sample time as the simulator does;
- each field's values: the spec's `_sim.WORLD` (which quantity a parameter shows, converted to the
  parameter's units as `sim._show` does), `_sim.DATA` (the units of the values) and the clocks
  (`sim/clocks.py`: reference time, GPS time while the receiver has a fix, and sample by sample
  by `Clocks.fill` otherwise);
- the packet: one real sample built by the simulator (`sample_packets`, the generated codec's
  encoding) is the template; each parameter's bytes are at the offset the codec's layout (the
  field's `Run` of struct parameters) gives, written for every sample at once; the Fletcher
  checksum is computed on the rows and checked against framing's on the template.

What this path does not cover (a parameter it cannot compute, continuation packets, a world
`World.batchable` refuses) raises Unsupported: fleet.py then takes the sample-by-sample path. The
noise is drawn from a numpy generator seeded from the world's, so the same arguments give the same
bytes; they are not the bytes of the sample-by-sample path (other random draws)."""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from . import _sim, registry
from .codec import framing
from .codec.layout import Run
from .sim import all_bits
from .sim.world import GRAVITY, RADIANS

BLOCK_S = 120  # seconds of simulated time per block (bounded memory whatever the duration)
_DTYPES = {"f": ">f4", "d": ">f8", "B": "u1", "H": ">u2", "I": ">u4", "Q": ">u8"}
_DTYPES.update({"b": "i1", "h": ">i2", "i": ">i4", "q": ">i8", "?": "u1"})
_ELAPSED = {"ns": 1e9, "us": 1e6, "ms": 1e3}  # integer clocks `_plausible` sets from the elapsed time


class Unsupported(Exception):
    """Something the batch path does not compute (the sample-by-sample path does)."""


class _Param:
    def __init__(self, name: str, offset: int, code: str, count: Optional[int]) -> None:
        self.name, self.offset, self.count = name, offset, count
        if code not in _DTYPES:
            raise Unsupported(f"parameter {name}: struct code {code!r}")
        self.dtype = np.dtype(_DTYPES[code])
        self.size = self.dtype.itemsize * (count or 1)


class _Field:
    """One field of a stream's packet: its class, template value and parameters' offsets."""

    def __init__(self, sim: Any, set_id: int, descriptor: int, data_at: int, data: bytes) -> None:
        classes = registry.lookup(set_id, descriptor) or ()
        cls = next((c for c in classes if c.DEVICE in (None, sim.device)), None)
        ops: Any = getattr(cls, "_OPS", ())
        if cls is None or len(ops) != 1 or not isinstance(ops[0], Run) or ops[0].size != len(data):
            raise Unsupported(f"field 0x{set_id:02X},0x{descriptor:02X}: not one run of scalars")
        self.cls = cls
        self.key = (cls.SET, cls.DESCRIPTOR)
        self.template: Any = cls.decode(data)
        self.params = {p.name: _Param(p.name, data_at + p.offset, p.scalar.code, p.count) for p in ops[0].params}
        self.units = {a: u for a, u, _ in _sim.DATA.get(cls, ())}


class Stream:
    """One data set of the plan: its ticks, template packet and fields."""

    def __init__(self, sim: Any, set_id: int, entries: List[Tuple[int, int]], last_tick: int) -> None:
        decimations = {dec for _, dec in entries}
        if len(decimations) != 1:
            raise Unsupported(f"set 0x{set_id:02X}: descriptors at different rates")
        self.set = set_id
        self.dec = decimations.pop()
        self.rate = sim.base_rates[set_id]
        self.next = (last_tick // self.dec + 1) * self.dec
        packets = sim.sample_packets(set_id, [d for d, _ in entries], 0.0, 0.0)
        if len(packets) != 1:
            raise Unsupported(f"set 0x{set_id:02X}: continuation packets")
        self.template = np.frombuffer(packets[0], dtype=np.uint8)
        if _checksums(self.template[None, :])[0].tobytes() != packets[0][-2:]:
            raise Unsupported("checksum")
        self.fields: List[_Field] = []
        at = framing.HEADER_SIZE
        while at < len(packets[0]) - 2:
            length, descriptor = (
                packets[0][at + framing.FIELD_LENGTH_OFFSET],
                packets[0][at + framing.FIELD_DESCRIPTOR_OFFSET],
            )
            size = length - framing.field_length_adjust(set_id, descriptor)
            data_at = at + framing.FIELD_HEADER_SIZE
            self.fields.append(_Field(sim, set_id, descriptor, data_at, packets[0][data_at : data_at + size]))
            at = data_at + size

    def ticks(self, end_tick: int) -> Any:
        """The ticks from the next one to `end_tick` (included)."""
        out = np.arange(self.next, end_tick + 1, self.dec, dtype=np.int64)
        self.next = int(out[-1]) + self.dec if len(out) else self.next
        return out


def _checksums(rows: Any) -> Any:
    """The checksum bytes of each packet row (its last two bytes not read): framing.fletcher16."""
    body = rows[:, :-2]
    n = body.shape[1]
    sum1 = body.sum(axis=1, dtype=np.int64) & 0xFF
    sum2 = (body.astype(np.int64) @ np.arange(n, 0, -1, dtype=np.int64)) & 0xFF  # integers: no BLAS threads
    pair = (sum1, sum2) if framing.CHECKSUM_SUM1_FIRST else (sum2, sum1)
    return np.stack(pair, axis=1).astype(np.uint8)


def _convert(x: Any, units: Optional[str], quantity: str) -> Any:
    """sim._convert on arrays."""
    if units == "g":
        return x / GRAVITY
    if units == "deg" and quantity in RADIANS:
        return np.degrees(x)
    if units == "ms":
        return x * 1000.0
    return x


def _shown(field: _Field, attr: str, quantity: str, world: Dict[str, Any], nav: Dict[str, Any]) -> Any:
    """sim._show on arrays: the values of parameter `attr` (None: it keeps the template's)."""
    current: Any = getattr(field.template, attr, None)
    kind, _, name = quantity.partition(":")
    n = len(world["gnss_fix"])
    if kind == "valid":
        ok: Any = {"always": np.ones(n, dtype=bool), "gnss": world["gnss_fix"]}.get(name)
        valid = world[f"filter_valid_{name}"] if ok is None else ok
        return np.where(valid, all_bits(type(current)), 0)
    if kind == "enum":
        states = world.get(name)
        if states is None:
            fix = nav.get("fix", ["", ""])
            states = np.where(world["gnss_fix"], fix[0], fix[1])
        members = type(current).__members__
        names, where = np.unique(states, return_inverse=True)
        value = [members[str(s).upper()].value if str(s).upper() in members else int(current) for s in names.tolist()]
        return np.array(value, dtype=np.int64)[where]
    if kind == "flags":
        return world[name]
    index: Optional[int] = None
    if quantity.endswith("]"):
        quantity, _, rest = quantity.partition("[")
        index = int(rest[:-1])
    q = world[quantity]
    if index is not None:
        q = q[:, index]
    if isinstance(current, (list, float)):
        return _convert(q, field.units.get(attr), quantity)
    if isinstance(current, int) and not isinstance(current, bool):
        return np.rint(q)
    return None


def _gps_clock(sim: Any, field: _Field) -> Optional[Tuple[str, str, str]]:
    """(tow, week, flags) parameter names when `field` carries a GPS time the clocks set (the
    external time's time of week, the GX5-45's correlation timestamp), else None."""
    facts = sim.clocks.facts
    for x in facts.get("external", ()):
        if field.key == (x["set"], x["descriptor"]) and "tow" in x:
            return x["tow"], x["week"], x["flags"]
    c = facts.get("correlation")
    if c is not None and field.key == (c["set"], c["descriptor"]):
        tow, week = sim.clocks.gps_names.get(field.key, ("tow", "week_number"))
        return tow, week, c["flags"]
    return None


def _clock_values(sim: Any, field: _Field, ts: Any, world: Dict[str, Any]) -> Optional[Dict[str, Any]]:
    """The values `Clocks.fill` sets in `field` at the times `ts` (None: it sets none): the
    reference time on arrays; a GPS time through each run of samples with a receiver fix from the
    world's GPS time when the run's first sample, filled by the clocks, has it (its flags held);
    every other sample filled by the clocks one by one."""
    clocks = sim.clocks
    if clocks.reference is not None and field.key == clocks.reference[:2]:
        return {clocks.reference[2]: np.rint(clocks.ref(ts) * clocks.reference[3])}
    names: Optional[Tuple[str, ...]] = _gps_clock(sim, field)
    facts = clocks.facts
    status = facts.get("status")
    if names is None and status is not None and field.key == (status["set"], status["descriptor"]):
        names = (status["synced"], status["last_pps"])
    for x in facts.get("external", ()):
        if names is None and field.key == (x["set"], x["descriptor"]):
            names = (x["ns"], x["flags"])
    if names is None:
        return None
    out = {a: np.zeros(len(ts), dtype=float if a == names[0] else np.int64) for a in names}
    fix = world["gnss_fix"]
    bounds = np.flatnonzero(np.diff(fix.astype(np.int8))) + 1
    for lo, hi in zip([0, *bounds.tolist()], [*bounds.tolist(), len(ts)]):
        first = _filled(clocks, field, float(ts[lo]), names)
        held = (
            len(names) == 3
            and bool(fix[lo])
            and not clocks.refreshes
            and first[names[0]] == float(world["gps_tow"][lo])
            and first[names[1]] == int(world["gps_week"][lo])
        )
        if held:
            out[names[0]][lo:hi] = world["gps_tow"][lo:hi]
            out[names[1]][lo:hi] = world["gps_week"][lo:hi]
            out[names[2]][lo:hi] = first[names[2]]
            continue
        for a in range(lo, hi, PIECE):
            _piece(clocks, field, ts, names, out, a, min(a + PIECE, hi))
    return out


PIECE = 64  # samples a GPS time without the receiver's fix is checked to run on the reference clock over


def _piece(clocks: Any, field: _Field, ts: Any, names: Tuple[str, ...], out: Dict[str, Any], lo: int, hi: int) -> None:
    """Samples lo..hi-1 of a clock field, filled by the clocks at both ends: when the time of
    week runs on the reference clock between them (`Clocks.external` between PPS edges: the same
    week and flags, the time of week advanced by the reference clock's advance), the samples
    between follow it; else each sample is filled by the clocks."""
    first = _filled(clocks, field, float(ts[lo]), names)
    last = _filled(clocks, field, float(ts[hi - 1]), names)
    ref = clocks.ref(ts[lo:hi])
    if (
        len(names) == 3
        and first[names[1]] == last[names[1]]
        and first[names[2]] == last[names[2]]
        and abs((last[names[0]] - first[names[0]]) - (ref[-1] - ref[0])) < 1e-9
    ):
        out[names[0]][lo:hi] = first[names[0]] + (ref - ref[0])
        out[names[1]][lo:hi] = first[names[1]]
        out[names[2]][lo:hi] = first[names[2]]
        return
    for i in range(lo, hi):
        got = first if i == lo else last if i == hi - 1 else _filled(clocks, field, float(ts[i]), names)
        for a in names:
            out[a][i] = got[a]


def _filled(clocks: Any, field: _Field, t: float, names: Tuple[str, ...]) -> Dict[str, Any]:
    value = field.cls()
    clocks.fill(value, t)
    return {a: getattr(value, a) for a in names}


def rows(sim: Any, stream: Stream, elapsed: Any, world: Dict[str, Any]) -> Any:
    """The packets of `stream` at the simulated times `elapsed` (world: `World.batch` there), one
    row of bytes each, checksums included."""
    n = len(elapsed)
    out = np.empty((n, len(stream.template)), dtype=np.uint8)
    if not n:  # (a set slower than one sample per block)
        return out
    out[:] = stream.template
    nav = _sim.FILTER.get(sim.device, {})
    for field in stream.fields:
        values: Dict[str, Any] = {}
        for attr, units in field.units.items():  # _plausible: clocks from the elapsed time
            current = getattr(field.template, attr, None)
            if isinstance(current, float) or (isinstance(current, list) and current and isinstance(current[0], float)):
                values[attr] = None  # noise unless the world shows it (checked below)
            elif units in _ELAPSED and isinstance(current, int):
                values[attr] = np.rint(elapsed * _ELAPSED[units])
        for attr, quantity in _sim.WORLD.get(field.cls, ()):
            try:
                got = _shown(field, attr, quantity, world, nav)
            except KeyError as e:
                raise Unsupported(f"world quantity {e}") from None
            if got is not None:
                values[attr] = got
        values.update(_clock_values(sim, field, elapsed, world) or {})
        for attr, value in values.items():
            p = field.params.get(attr)
            if value is None or p is None:
                raise Unsupported(f"{field.cls.__name__}.{attr}")
            column = np.ascontiguousarray(np.asarray(value).reshape(n, -1), dtype=p.dtype)
            out[:, p.offset : p.offset + p.size] = column.view(np.uint8).reshape(n, p.size)
    out[:, -2:] = _checksums(out)
    return out


def write(sim: Any, f: Any, seconds: int, seed: int, garbage_every: int, not_sync: bytes) -> Tuple[int, int, int]:
    """Writes the streams of `sim` (configured, polled at 0) from their next tick to `seconds`
    into `f`, packets of all sets in time order (the plan's order at equal times), 1..16 bytes of
    garbage (never the sync byte) before about one packet in `garbage_every`. Returns (garbage
    bytes, the last packet's length, its data set). Unsupported before anything is written."""
    if not sim.world.batchable():
        raise Unsupported("world")
    # what poll does besides the data sets' samples: none of it here (the fleet's configuration)
    if sim.idle or sim.speed != 1.0 or sim.clocks.jitter_ms or sim.nmea.entries() or set(sim.plan) - set(sim.ticks):
        raise Unsupported("idle, --speed, link jitter, NMEA output or a stream not started")
    streams = [Stream(sim, s, e, sim.ticks[s]) for s, e in sim.plan.items()]
    rng = np.random.default_rng([seed, sim.world.rng.getrandbits(64)])
    junk_bytes = np.frombuffer(not_sync, dtype=np.uint8)
    garbage, last = 0, (0, 0)
    for lo in range(0, seconds, BLOCK_S):
        hi = min(lo + BLOCK_S, seconds)
        parts = []
        for k, s in enumerate(streams):
            # the ticks of [lo, hi) (the last block: to `seconds` included), as the simulator counts them
            end = int(hi * s.rate) - (0 if hi == seconds else 1)
            ticks = s.ticks(end)
            parts.append((k, ticks / s.rate))
        times = np.unique(np.concatenate([e for _, e in parts]))
        if not len(times):
            continue
        world = sim.world.batch(times, rng)
        pieces = []
        for k, elapsed in parts:
            at = np.searchsorted(times, elapsed)
            pieces.append(rows(sim, streams[k], elapsed, _At(world, at)))
        garbage_block, last = _interleave(f, parts, pieces, rng, garbage_every, junk_bytes, last)
        garbage += garbage_block
    return garbage, last[0], streams[last[1]].set if last[0] else -1


class _At(Dict[str, Any]):
    """The world's quantities at some of its samples (`at`: their indices), each taken on first use."""

    def __init__(self, world: Dict[str, Any], at: Any) -> None:
        super().__init__()
        self.world, self.at = world, at

    def __missing__(self, name: str) -> Any:
        value = self[name] = self.world[name][self.at]
        return value

    def get(self, name: str, default: Any = None) -> Any:
        return self[name] if name in self.world else default


def _interleave(
    f: Any, parts: List[Tuple[int, Any]], pieces: List[Any], rng: Any, every: int, junk: Any, last: Tuple[int, int]
) -> Tuple[int, Tuple[int, int]]:
    """Writes one block's packets in time order (the plan's order at equal times) with garbage."""
    when = np.concatenate([e for _, e in parts])
    which = np.concatenate([np.full(len(e), k) for k, e in parts])
    row = np.concatenate([np.arange(len(e)) for _, e in parts])
    order = np.lexsort((which, when))
    if not len(order):
        return 0, last
    which, row = which[order], row[order]
    lengths = np.array([p.shape[1] for p in pieces])[which]
    junk_len = np.where(rng.integers(0, every, len(order)) == 0, rng.integers(1, 17, len(order)), 0)
    starts = np.cumsum(junk_len + lengths) - lengths  # each packet's first byte
    out = np.empty(int(starts[-1] + lengths[-1]), dtype=np.uint8)
    for k, p in enumerate(pieces):
        mine = which == k
        out[starts[mine][:, None] + np.arange(p.shape[1])] = p[row[mine]]
    total = int(junk_len.sum())
    if total:
        at = np.repeat(starts - junk_len, junk_len) + (
            np.arange(total) - np.repeat(np.cumsum(junk_len) - junk_len, junk_len)
        )
        out[at] = junk[rng.integers(0, len(junk), total)]
    f.write(out.data)
    return total, (int(lengths[-1]), int(which[-1]))
