"""A simulated fleet (issue 41, docs/fleet.md): the raw logs several simulated devices write, for
tests and benchmarks of the dataset, Spark and DuckDB tooling.

    python -m mipcodec.fleet --out DIR [--devices N] [--hours H] [--seed S] [--size BYTES] [--jobs N]

writes DIR/<NAME>.mip per device and DIR/fleet.json, the manifest of what was simulated. The
devices are the package's simulator (`sim.Simulator`, driven in process with an injected clock:
no socket, no real time), so the same arguments give the same bytes; with numpy, its data streams
are written block by block by fleet_batch.py from the same plan, world and layouts (other noise
draws, so other bytes than the sample-by-sample path). Device k:

- model: GX5-45 for even k, CV7-INS for odd k; serial number `6232-1010k` / `6284.17040k`
  (the simulator's --serial identity), scenario `circle` for k % 4 in (0, 1), else `static`;
- start: day 2026-03-14 + k // 2 at 08:00 UTC plus a seeded number of minutes (even k), or
  centred on that day's UTC midnight (odd k: its log spans midnight);
- what a logging host records: the device information reply (0x01,0x03), the replies to the
  configuration it sends (message formats, filter aiding, stream enables), then the data streams
  of STREAMS (sensor, filter with filter status, GNSS; each with the GPS time fields the time
  model reads: 0x80,0x12 / 0x82,0x11 / 0x81,0x09 on the GX5-45, shared 0xD3 and the device's
  reference timestamp 0xD5 on the CV7), the packets of all sets in time order;
- GNSS outages (k % 3 == 0: one, k % 3 == 1: two, else none), which change the filter's mode;
- between packets, now and then, 1..16 bytes of garbage (never the sync byte 0x75);
- the last device's log is truncated inside its last packet.

The manifest's expectations (samples per stream and per UTC date, seconds and samples in each
filter mode) are computed from these parameters and the simulated world's documented constants
(sim_world: GNSS_FIX_AFTER, NavFilter.SETTLE and TIMEOUT), not by decoding the logs.
"""

from __future__ import annotations

import argparse
import datetime
import importlib
import json
import math
import os
import random
import sys
from fractions import Fraction
from typing import Any, Dict, List, Optional, Sequence, Tuple

from . import _sim, registry
from ._protocol import SET_OFFSET
from .codec.framing import PacketBuilder
from .codec.stdio import closed_stdout
from .sim import Simulator, parse_identity
from .sim.world import GNSS_FIX_AFTER, NavFilter, gps_start_of_utc

MODELS = ("gx5_45", "cv7_ins")
# Per model: data set -> (output rate in Hz, descriptors streamed). Rates divide the base rates
# (_sim.BASE_RATES: GX5-45 500/4/500 Hz, CV7 1000/1000/5 Hz).
STREAMS: Dict[str, Dict[int, Tuple[int, Tuple[int, ...]]]] = {
    "gx5_45": {
        0x80: (100, (0x04, 0x05, 0x12)),  # scaled accel, scaled gyro, GPS correlation timestamp
        0x82: (50, (0x10, 0x11, 0x01, 0x0D)),  # filter status, GPS timestamp, LLH position, linear accel
        0x81: (4, (0x09, 0x03)),  # GPS time, LLH position
    },
    "cv7_ins": {
        0x80: (100, (0xD3, 0xD5, 0x04, 0x05)),  # shared GPS time, reference time, scaled accel and gyro
        0x82: (50, (0xD3, 0xD5, 0x10, 0x11, 0x01, 0x0D)),  # ... filter status, GPS timestamp, LLH, linear accel
        0x91: (1, (0xD3, 0x09, 0x11)),  # shared GPS time, GPS time, GPS leap seconds
    },
}
FIRST_DAY = datetime.date(2026, 3, 14)
# Seconds of simulated time between two polls: the fastest stream's period. The world is stateful
# (the filter follows its aiding) and a poll builds its samples set by set, so a longer step would
# evaluate one set's later samples before another set's earlier ones.
POLL_STEP = Fraction(1, 100)
GARBAGE_EVERY = 997  # about one packet in this many is preceded by garbage
MIN_SECONDS = 10  # the shortest log (--size too small for a device gets this much)
MANIFEST = "fleet.json"


def _mod(name: str) -> Any:
    return importlib.import_module(f"{__package__}.{name}")


def _command(field: Any) -> bytes:
    b = PacketBuilder(field.SET)
    b.add(field)
    return b.build()


def configuration(model: str) -> List[bytes]:
    """What the logging host sends at start: Get Device Information, the message format of each
    stream, the filter's aiding (a heading source and auto-initialisation on the GX5-45; GNSS and
    magnetometer aiding on the CV7), then the streams on."""
    base, threedm, flt, types = _mod("base"), _mod("threedm"), _mod("filter"), _mod("types")
    out = [_command(base.GetDeviceInfo())]
    streams = STREAMS[model]
    old_style = {0x80: threedm.ImuMessageFormat, 0x81: threedm.GnssMessageFormat, 0x82: threedm.FilterMessageFormat}
    for set_id, (hz, descriptors) in streams.items():
        decimation = _sim.BASE_RATES[model][set_id] // hz
        items = [types.DescriptorRate(d, decimation) for d in descriptors]
        if model == "gx5_45":
            out.append(_command(old_style[set_id](num_descriptors=len(items), descriptors=items)))
        else:
            out.append(_command(threedm.MessageFormat(desc_set=set_id, num_descriptors=len(items), descriptors=items)))
    if model == "gx5_45":
        out.append(_command(flt.HeadingUpdateControl(source=1)))  # the magnetometer
        out.append(_command(flt.AutoInitControl(enable=1)))
        out += [_command(threedm.DataStreamControl_gx5_45(device_selector=s, enable=True)) for s in (1, 3)]
    else:
        out.append(_command(flt.AidingMeasurementControl(source=0, enable=True)))  # GNSS position and velocity
        out.append(_command(flt.AidingMeasurementControl(source=4, enable=True)))  # magnetometer heading
        out += [_command(threedm.DataStreamControl_cv7_ins(desc_set=s, enable=True)) for s in streams]
    return out


class Device:
    """The plan of one simulated device (what the manifest states about it)."""

    def __init__(self, index: int, seed: int, seconds: int, truncated: bool) -> None:
        rng = random.Random(f"{seed}:{index}")
        self.index = index
        self.model = MODELS[index % 2]
        self.serial = f"6232-{10100 + index:05d}" if self.model == "gx5_45" else f"6284.{170400 + index}"
        self.scenario = "circle" if index % 4 in (0, 1) else "static"
        self.seconds = seconds
        day = datetime.datetime.combine(FIRST_DAY + datetime.timedelta(days=index // 2), datetime.time())
        if index % 2:
            start = day + datetime.timedelta(days=1, seconds=-(seconds // 2))
        else:
            start = day + datetime.timedelta(hours=8, minutes=rng.randrange(0, 120))
        self.start = start
        self.outages: List[Tuple[int, int]] = []
        length = max(5, min(300, seconds // 10))
        at = [0.4] if index % 3 == 0 else [0.2, 0.6] if index % 3 == 1 else []
        for f in at:
            a = max(int(GNSS_FIX_AFTER) + 5, int(seconds * f))
            if a + length < seconds:
                self.outages.append((a, a + length))
        self.truncated = truncated
        self.seed = seed * 1000 + index
        self.name = f"{index:03d}-{self.model}-{self.serial}.mip"

    def utc(self, t: Fraction) -> datetime.datetime:
        return self.start + datetime.timedelta(seconds=float(t))

    def fixed(self) -> List[Tuple[Fraction, Fraction]]:
        """When the receiver has a fix ([from, to) in seconds of the device's time): from
        GNSS_FIX_AFTER on, but for the outages. The GPS time fields are flagged valid then only
        (the simulator's `valid:gnss`), so these are the samples with a valid GPS time."""
        spans, t = [], Fraction(GNSS_FIX_AFTER).limit_denominator(1000)
        for a, b in self.outages:
            spans.append((t, Fraction(a)))
            t = Fraction(b)
        spans.append((t, Fraction(self.seconds) + Fraction(1, 1000)))  # the last sample, at `seconds`
        return spans

    def gps_time_valid(self, set_id: int) -> List[Tuple[Fraction, Fraction]]:
        """When data set `set_id`'s GPS time field is flagged valid ([from, to) in seconds of the
        device's time). The CV7's GPS timestamps (0xFF,0xD3) and the GX5-45's GNSS GPS time are the
        receiver's, valid while it has a fix: `fixed()`. The GX5-45's GPS Correlation Timestamp
        (0x80,0x12) is initialized by the receiver's first fix and then runs on, on the IMU's clock
        through an outage (3dm-gx5-45-dcp.txt line 2159; sim/clocks.py): from the first fix on."""
        correlation = (_sim.TIME_SYNC.get(self.model) or {}).get("correlation")  # spec time.sync
        if correlation is not None and set_id == correlation["set"]:
            first = self.fixed()[0][0]
            return [(first, Fraction(self.seconds) + Fraction(1, 1000))]
        return self.fixed()

    def modes(self) -> List[Tuple[str, Fraction, Fraction]]:
        """(filter state, from, to) in seconds of the device's time: what sim_world.NavFilter does
        with this device's aiding (configuration) and outages. GX5-45 (GNSS-aided): startup for
        0.5 s, initialisation until the receiver's first fix (GNSS_FIX_AFTER; the magnetometer gave
        the attitude before), then running with a valid solution, with a solution error during each
        outage. CV7 (aided by its receiver and magnetometer): initialisation for SETTLE, AHRS
        (magnetometer heading) until the first fix, then full navigation; an outage leaves full
        navigation once position and velocity have been silent longer than TIMEOUT (the last
        measurement is the last sample before the outage, 1/100 s earlier: so from START + TIMEOUT)
        and enters it again with the first fix after it."""
        states = list(_sim.FILTER[self.model]["states"])
        end = Fraction(self.seconds)
        fix = Fraction(GNSS_FIX_AFTER).limit_denominator(1000)
        if self.model == "gx5_45":
            spans = [(states[0], Fraction(0), Fraction(1, 2)), (states[1], Fraction(1, 2), fix)]
            ok, bad, delay = states[2], states[3], Fraction(0)
        else:
            settle = Fraction(NavFilter.SETTLE).limit_denominator(1000)
            spans = [(states[0], Fraction(0), settle), (states[2], settle, fix)]
            ok, bad, delay = states[3], states[2], Fraction(NavFilter.TIMEOUT).limit_denominator(1000)
        t = fix
        merged: List[Tuple[int, int]] = []  # outages that abut (a short log's) are one for the filter
        for a, b in self.outages:
            if merged and merged[-1][1] >= a:
                merged[-1] = (merged[-1][0], max(b, merged[-1][1]))
            else:
                merged.append((a, b))
        for a, b in merged:
            lost = Fraction(a) + delay
            if lost < b:
                spans += [(ok, t, lost), (bad, lost, Fraction(b))]
                t = Fraction(b)
        spans.append((ok, t, end))
        return [(s, lo, min(hi, end)) for s, lo, hi in spans if min(hi, end) > lo]


def _samples(lo: Fraction, hi: Fraction, hz: int) -> int:
    """Samples k / hz (k >= 0 integer) in [lo, hi)."""
    return max(0, math.ceil(hi * hz) - math.ceil(lo * hz))


def _day_bounds(dev: Device) -> List[Tuple[str, Fraction, Fraction]]:
    """The UTC dates the device's span touches: (date, from, to) in seconds of its time."""
    out = []
    day = dev.start.date()
    while True:
        lo = datetime.datetime.combine(day, datetime.time())
        a = Fraction(int((lo - dev.start).total_seconds()))
        b = a + 86400
        if a >= dev.seconds + 1:
            break
        out.append((day.isoformat(), max(a, Fraction(0)), b))
        day += datetime.timedelta(days=1)
    return out


def simulate(dev: Device, out_path: str) -> Dict[str, Any]:
    """Writes the device's log; returns its manifest entry."""
    sim = Simulator(
        dev.model, dev.seed, scenario=dev.scenario, identity=dict([parse_identity(dev.model, "serial", dev.serial)])
    )
    week, tow = gps_start_of_utc(dev.start.isoformat())
    sim.world.gps_start = (week, tow)
    sim.world.gnss_outages.extend((float(a), float(b)) for a, b in dev.outages)
    rng = random.Random(dev.seed ^ 0x6A5BA6E)
    chunks: List[Tuple[float, bytes]] = []
    for packet in configuration(dev.model):
        chunks += sim.feed(packet, 0.0)
    chunks += sim.poll(0.0)  # the streams from tick 0: the samples are at k / rate exactly
    batch = _batch()
    if batch is not None:
        with open(out_path + ".tmp", "wb") as f:
            for _, packet in sorted(chunks, key=lambda c: c[0]):
                f.write(packet)  # the replies and the first samples, as the simulator sent them
            try:
                garbage, last_len, last_set = batch.write(sim, f, dev.seconds, dev.seed, GARBAGE_EVERY, _NOT_SYNC)
            except batch.Unsupported:  # nothing written by it: the sample-by-sample path below
                f.close()
            else:
                size = f.tell()
                if dev.truncated:
                    size -= last_len // 2
                    f.truncate(size)
                f.close()
                os.replace(out_path + ".tmp", out_path)
                return _entry(dev, size, garbage, last_set)
    garbage = 0
    last_set = None
    with open(out_path + ".tmp", "wb") as f:
        now = Fraction(0)
        while True:
            chunks.sort(key=lambda c: c[0])  # the sets' packets interleaved in time, as a device sends them
            for _, packet in chunks:
                if rng.randrange(GARBAGE_EVERY) == 0:
                    junk = bytes(rng.choice(_NOT_SYNC) for _ in range(rng.randint(1, 16)))
                    garbage += len(junk)
                    f.write(junk)
                f.write(packet)
                last_set = packet[2]
            last_len = len(chunks[-1][1]) if chunks else 0
            if now >= dev.seconds:
                break
            now = min(now + POLL_STEP, Fraction(dev.seconds))
            chunks = sim.poll(float(now))
        size = f.tell()
        if dev.truncated:
            size -= last_len // 2
            f.truncate(size)
    os.replace(out_path + ".tmp", out_path)
    return _entry(dev, size, garbage, last_set)


_NOT_SYNC = bytes(b for b in range(256) if b != 0x75)


def _batch() -> Any:
    """The batch path (fleet_batch.py, with numpy: the `export` extra), or None without numpy
    or with MIPCODEC_FLEET_BATCH=0 (the simulator's own sample-by-sample path: slower, other bytes)."""
    if os.environ.get("MIPCODEC_FLEET_BATCH", "1") == "0":
        return None
    try:
        from . import fleet_batch
    except ImportError:
        return None
    return fleet_batch


def _entry(dev: Device, size: int, garbage: int, last_set: Optional[int]) -> Dict[str, Any]:
    end = Fraction(dev.seconds)
    streams = {}
    days = _day_bounds(dev)
    for set_id, (hz, descriptors) in STREAMS[dev.model].items():
        total = _samples(Fraction(0), end, hz) + 1  # k / hz for 0 <= k <= seconds * hz
        per_day = {d: _samples(lo, min(hi, end + Fraction(1, 10 * hz)), hz) for d, lo, hi in days}
        if dev.truncated and set_id == last_set:
            total -= 1  # the cut packet: the last sample of the log
            per_day[days[-1][0]] -= 1
        valid = {
            d: sum(
                _samples(max(lo, a), min(hi, b), hz) for a, b in dev.gps_time_valid(set_id) if min(hi, b) > max(lo, a)
            )
            for d, lo, hi in days
        }
        if dev.truncated and set_id == last_set:
            valid[days[-1][0]] -= 1
        streams[f"0x{set_id:02X}"] = {
            "rate_hz": hz,
            "descriptors": [f"0x{d:02X}" for d in descriptors],
            "samples": total,
            "samples_per_date": {d: n for d, n in per_day.items() if n},
            "samples_gps_valid": sum(valid.values()),
            "samples_gps_valid_per_date": {d: n for d, n in valid.items() if n},
        }
    hz = STREAMS[dev.model][0x82][0]
    modes: Dict[str, Dict[str, Any]] = {}
    for state, lo, hi in dev.modes():
        m = modes.setdefault(state, {"seconds": Fraction(0), "samples": 0})
        m["seconds"] += hi - lo
        m["samples"] += _samples(lo, hi, hz) + (1 if hi == end else 0)
    if dev.truncated and last_set == 0x82:
        modes[dev.modes()[-1][0]]["samples"] -= 1
    identity = _sim.IDENTITY[dev.model]
    iso = "%Y-%m-%dT%H:%M:%S.%fZ"
    return {
        "log": dev.name,
        "model": dev.model,
        "title": _sim.DEVICE_TITLES.get(dev.model, dev.model),
        "serial": dev.serial,
        "firmware": identity.get("firmware"),
        "scenario": dev.scenario,
        "seed": dev.seed,
        "start_utc": dev.start.strftime(iso),
        "end_utc": dev.utc(end).strftime(iso),
        "seconds": dev.seconds,
        "gnss_outages": [
            {"start_s": a, "end_s": b, "start_utc": dev.utc(Fraction(a)).strftime(iso), "seconds": b - a}
            for a, b in dev.outages
        ],
        "streams": streams,
        "filter_modes": {
            s: {"seconds": float(m["seconds"]), "samples": m["samples"]} for s, m in sorted(modes.items())
        },
        "garbage_bytes": garbage,
        "truncated": dev.truncated,
        "bytes": size,
    }


def _bytes_per_second(model: str) -> float:
    """The stream's bytes per second of a model (its packets' sizes times their rates)."""
    sim = Simulator(model, 0)
    chunks: List[Tuple[float, bytes]] = []
    for packet in configuration(model):
        chunks += sim.feed(packet, 0.0)
    chunks += sim.poll(0.0)  # each stream's first sample: a packet of each data set
    sizes = {packet[SET_OFFSET]: len(packet) for _, packet in chunks if packet[SET_OFFSET] in sim.plan}
    return float(sum(n * sim.base_rates[s] / sim.plan[s][0][1] for s, n in sizes.items()))


def _simulate_device(args: Tuple[Device, str]) -> Dict[str, Any]:
    return simulate(*args)


def cpus() -> int:
    """The processors this process may run on (the most --jobs uses)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def generate(
    out: str,
    devices: int = 4,
    hours: float = 1.0,
    seed: int = 0,
    size: Optional[int] = None,
    jobs: Optional[int] = None,
) -> Dict[str, Any]:
    """Writes the fleet into `out` (created if needed); returns the manifest (also fleet.json).
    The devices are simulated by `jobs` processes at once (default 1: a process costs about half
    a second of start-up and gains only on a processor nobody else uses; each device's log is its
    own simulation, so the bytes do not depend on it)."""
    if not all(m in registry.DEVICES for m in MODELS):
        raise ValueError(f"this package simulates no fleet: it has no {' and '.join(MODELS)} devices")
    if devices < 1:
        raise ValueError(f"--devices {devices}: expected at least 1")
    if jobs is not None and jobs < 1:
        raise ValueError(f"--jobs {jobs}: expected at least 1")
    os.makedirs(out, exist_ok=True)
    plans = []
    used = MODELS[: min(devices, len(MODELS))]  # the models of devices 0.. (one device: the first only)
    rates = {m: _bytes_per_second(m) for m in used} if size is not None else {}
    for k in range(devices):
        model = MODELS[k % 2]
        if size is not None:
            seconds = max(MIN_SECONDS, int(size / devices / rates[model]))
        else:
            seconds = max(MIN_SECONDS, int(round(hours * 3600)))
        dev = Device(k, seed, seconds, truncated=k == devices - 1)
        plans.append((dev, os.path.join(out, dev.name)))
    workers = min(len(plans), jobs or 1, cpus())
    if workers > 1:  # processes started afresh (spawn): the caller's threads are not copied
        import multiprocessing
        import site
        from concurrent.futures import ProcessPoolExecutor

        # The workers import this package from where this process found it (maybe not on sys.path).
        where = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        spawn = multiprocessing.get_context("spawn")
        with ProcessPoolExecutor(workers, mp_context=spawn, initializer=site.addsitedir, initargs=(where,)) as pool:
            entries = list(pool.map(_simulate_device, plans))
    else:
        entries = [simulate(dev, path) for dev, path in plans]
    manifest = {
        "generator": f"{__package__}.fleet",
        "seed": seed,
        "devices": entries,
        "bytes": sum(e["bytes"] for e in entries),
        "note": "expectations computed from the simulation's parameters (fleet.py), not by decoding the logs",
    }
    tmp = os.path.join(out, f".{MANIFEST}.tmp")
    with open(tmp, "w") as f:
        json.dump(manifest, f, indent=1, sort_keys=True)
        f.write("\n")
    os.replace(tmp, os.path.join(out, MANIFEST))
    return manifest


def _size(text: str) -> int:
    units = {"k": 1 << 10, "m": 1 << 20, "g": 1 << 30}
    t = text.strip().lower().removesuffix("b").removesuffix("i")
    mult = units.get(t[-1:], 1)
    try:
        value = float(t[:-1] if t[-1:] in units else t) * mult
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r}: expected a byte count (e.g. 5000000, 64M, 1G)") from None
    if not math.isfinite(value) or value <= 0:
        raise argparse.ArgumentTypeError(f"{text!r}: expected a positive byte count")
    return int(value)


def main(argv: Optional[Sequence[str]] = None) -> int:
    p = argparse.ArgumentParser(
        prog=f"python -m {__package__}.fleet",
        description="Write the raw logs of a simulated fleet (reproducible: the same arguments give the same bytes) "
        "and fleet.json, the manifest of what was simulated.",
    )
    p.add_argument("--out", required=True, metavar="DIR", help="directory to write the logs and fleet.json into")
    p.add_argument("--devices", type=int, default=4, help="number of devices (default 4)")
    p.add_argument("--hours", type=float, default=1.0, help="simulated hours per device (default 1)")
    p.add_argument("--seed", type=int, default=0, help="seed (default 0)")
    p.add_argument(
        "--jobs",
        type=int,
        metavar="N",
        help="devices simulated at once, one process each (default 1; at most the processors)",
    )
    p.add_argument(
        "--size",
        type=_size,
        metavar="BYTES",
        help="about this many bytes of logs in all (K, M, G suffixes); sets each device's duration instead of --hours",
    )
    args = p.parse_args(argv)
    if "numpy" not in sys.modules:  # this process's own: the batch path's matrices are small (64 x 64),
        os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # BLAS threads would cost only their start-up
    try:
        if not (math.isfinite(args.hours) and 0 < args.hours <= 24 * 366):
            raise ValueError(f"--hours {args.hours:g}: expected more than 0, at most a year")
        manifest = generate(args.out, args.devices, args.hours, args.seed, args.size, args.jobs)
    except ValueError as e:
        print(f"{p.prog}: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"{p.prog}: {args.out}: {e.strerror or e}", file=sys.stderr)
        return 2
    try:
        for entry in manifest["devices"]:
            print(f"{entry['log']}: {entry['bytes']} bytes, {entry['seconds']} s from {entry['start_utc']}")
        print(f"{os.path.join(args.out, MANIFEST)}: {len(manifest['devices'])} devices, {manifest['bytes']} bytes")
        sys.stdout.flush()
    except BrokenPipeError:  # stdout closed by its reader: quietly, by SIGPIPE (codec.stdio)
        return closed_stdout()
    return 0


if __name__ == "__main__":
    sys.exit(main())
