"""The simulated fleet (issue 41, runtime fleet.py, docs/fleet.md): reproducible logs, sized as
asked, and a manifest whose expectations (computed by fleet.py from the simulation's parameters)
equal an independent count of the logs with the package's own parser and decoder.

The independent count: every packet the parser finds, by data set; each sample's UTC date from the
GPS week and time of week its own packet carries (leap seconds: 18, IERS Bulletin C, since
2017-01-01), counted whether its valid flags are set or not and separately when they are; the
filter state of each filter status field; the bytes the parser skipped (the garbage); and for the
truncated log, the partial packet the parser still holds at the end of the file."""

from __future__ import annotations

import datetime
import hashlib
import importlib
import json
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest

from tests.helpers.generated import GENERATED_PYTHON, python_package

pkg = python_package("mipcodec")
fleet = importlib.import_module("mipcodec.fleet")
framing = importlib.import_module("mipcodec.codec.framing")
packets = importlib.import_module("mipcodec.codec.packets")

LEAP = 18
GPS_EPOCH = datetime.datetime(1980, 1, 6)
# The fields carrying the packet's GPS time, per (model, set): (descriptor, time attribute names)
GPS_FIELDS = {
    ("gx5_45", 0x80): 0x12,
    ("gx5_45", 0x82): 0x11,
    ("gx5_45", 0x81): 0x09,
    ("cv7_ins", 0x80): 0xD3,
    ("cv7_ins", 0x82): 0xD3,
    ("cv7_ins", 0x91): 0xD3,
}
SECONDS = 75  # per device: outages are 5..7 s, both kinds of filter mode change happen


@pytest.fixture(scope="module")
def small(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("fleet")
    fleet.generate(str(out), devices=4, hours=SECONDS / 3600, seed=7)
    return out


def _count(path: Path, model: str) -> dict:
    """An independent count of one log (see the module's docstring)."""
    data = path.read_bytes()
    parser = framing.Parser()
    sets: Counter = Counter()
    dates: Counter = Counter()
    valid_dates: Counter = Counter()
    states: Counter = Counter()
    skipped = 0
    info = None
    for event in parser.feed(data):
        if not isinstance(event, framing.RawPacket):
            skipped += len(event.data)
            continue
        set_id = event.data[2]
        packet = packets.decode_packet(event.data, device=model)
        if set_id == 0x01:
            info = next(f.value.info for f in packet.fields if hasattr(f.value, "info"))
            continue
        if (model, set_id) not in GPS_FIELDS:
            continue
        sets[set_id] += 1
        for f in packet.fields:
            v = f.value
            if f.descriptor == GPS_FIELDS[(model, set_id)]:
                when = GPS_EPOCH + datetime.timedelta(weeks=v.week_number, seconds=v.tow - LEAP)
                dates[(set_id, when.date().isoformat())] += 1
                if int(v.valid_flags):
                    valid_dates[(set_id, when.date().isoformat())] += 1
            if type(v).__name__.startswith("FilterStatus"):
                states[v.filter_state.name.lower()] += 1
    # What is left (not yet a whole packet) when the file ends: flush reports it as skipped.
    tail = sum(len(e.data) for e in parser.flush() if not isinstance(e, framing.RawPacket))
    return {
        "sets": sets,
        "dates": dates,
        "valid_dates": valid_dates,
        "states": states,
        "skipped": skipped,
        "tail": tail,
        "info": info,
    }


def test_manifest_equals_an_independent_count(small: Path) -> None:
    manifest = json.loads((small / "fleet.json").read_text())
    devices = manifest["devices"]
    assert [d["model"] for d in devices] == ["gx5_45", "cv7_ins", "gx5_45", "cv7_ins"]
    assert len({d["serial"] for d in devices}) == 4
    assert len({d["start_utc"] for d in devices}) == 4
    assert sum(len(d["gnss_outages"]) for d in devices) >= 3
    spans_midnight = [d for d in devices if d["start_utc"][:10] != d["end_utc"][:10]]
    assert spans_midnight, "no log spans UTC midnight"
    assert [d["truncated"] for d in devices] == [False, False, False, True]
    for d in devices:
        _check_device(small, d)


def test_sample_by_sample_path(tmp_path: Path, monkeypatch) -> None:
    """Without the batch path (no numpy, or MIPCODEC_FLEET_BATCH=0: the simulator polled every 10
    ms) the logs fit their manifest too; the manifests of both paths differ only in the garbage
    (drawn otherwise) and so the sizes."""
    hours = 25 / 3600  # both devices have outages (at 10 s; at 7 and 15 s), for 5 s each
    batch = fleet.generate(str(tmp_path / "batch"), devices=2, hours=hours, seed=7)
    monkeypatch.setenv("MIPCODEC_FLEET_BATCH", "0")
    manifest = fleet.generate(str(tmp_path / "slow"), devices=2, hours=hours, seed=7)
    assert all(d["gnss_outages"] for d in manifest["devices"])
    for d, b in zip(manifest["devices"], batch["devices"]):
        _check_device(tmp_path / "slow", d)
        assert (tmp_path / "slow" / d["log"]).read_bytes() != (tmp_path / "batch" / b["log"]).read_bytes()
        differ = ("garbage_bytes", "bytes")
        assert {k: v for k, v in d.items() if k not in differ} == {k: v for k, v in b.items() if k not in differ}


def _check_device(directory: Path, d: dict) -> None:
    """One device's log against its manifest entry `d` (the independent count)."""
    path = directory / d["log"]
    got = _count(path, d["model"])
    assert path.stat().st_size == d["bytes"]
    assert got["info"] is not None, f"{d['log']}: no device information reply"
    assert got["info"].serial_number.decode().strip() == d["serial"]
    assert got["info"].firmware_version == d["firmware"]
    for key, stream in d["streams"].items():
        set_id = int(key, 16)
        assert got["sets"][set_id] == stream["samples"], (d["log"], key)
        # A sample's own GPS time dates it only where its flags say valid: before the first fix
        # the simulated devices send their free-running clock (week 0, sim/clocks.py), as the
        # GX5-45's correlation timestamp does before GPS Time Initialized (3dm-gx5-45-dcp.txt
        # line 2159). Every sample is dated once: the dates cover the samples.
        assert sum(stream["samples_per_date"].values()) == stream["samples"], (d["log"], key)
        dated = {day: n for (s, day), n in got["dates"].items() if s == set_id}
        for day, n in stream["samples_gps_valid_per_date"].items():
            assert dated.get(day, 0) >= n, (d["log"], key, day)
        valid = {day: n for (s, day), n in got["valid_dates"].items() if s == set_id and n}
        assert valid == stream["samples_gps_valid_per_date"], (d["log"], key)
    assert dict(got["states"]) == {s: m["samples"] for s, m in d["filter_modes"].items()}, d["log"]
    assert got["skipped"] == d["garbage_bytes"] > 0
    assert (got["tail"] > 0) == d["truncated"], d["log"]
    # The time out of the filter's best mode is the outages (GX5-45) or the outages less the
    # 2 s the CV7 coasts on its IMU (sim_world.NavFilter.TIMEOUT)
    bad = "run_solution_error" if d["model"] == "gx5_45" else "ahrs"
    coast = 0 if d["model"] == "gx5_45" else 2
    outage = sum(o["seconds"] - coast for o in d["gnss_outages"])
    startup = 2 - 1 if d["model"] == "cv7_ins" else 0  # AHRS from SETTLE (1 s) to the first fix (2 s)
    assert d["filter_modes"].get(bad, {"seconds": 0})["seconds"] == outage + startup


def _digest(directory: Path) -> dict:
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in sorted(directory.iterdir())}


def test_same_seed_same_bytes_other_seed_other_bytes(tmp_path: Path) -> None:
    """Also whatever the number of processes (b: one per device, where there are two processors)."""
    for name, seed, jobs in (("a", 3, 1), ("b", 3, 2), ("c", 4, None)):
        fleet.generate(str(tmp_path / name), devices=2, hours=12 / 3600, seed=seed, jobs=jobs)
    a, b, c = (_digest(tmp_path / n) for n in "abc")
    assert a == b
    assert set(a) == set(c) and all(a[k] != c[k] for k in a if k.endswith(".mip"))


def test_size_sets_the_durations(tmp_path: Path) -> None:
    target = 1_500_000
    manifest = fleet.generate(str(tmp_path), devices=3, seed=1, size=target)
    total = sum(p.stat().st_size for p in tmp_path.glob("*.mip"))
    assert total == manifest["bytes"]
    # each device stops at a whole second under its share: at most a second of stream less
    assert 0.97 * target <= total <= 1.01 * target, total


def test_command_line(tmp_path: Path) -> None:
    run = [sys.executable, "-m", "mipcodec.fleet"]
    env_path = str(GENERATED_PYTHON / "mipcodec")
    env = {"PYTHONPATH": env_path, "PATH": "/usr/bin:/bin"}
    ok = subprocess.run(
        run + ["--out", str(tmp_path / "f"), "--devices", "1", "--hours", "0.003"],
        capture_output=True,
        text=True,
        env=env,
    )
    assert ok.returncode == 0, ok.stderr
    assert "1 devices" in ok.stdout and (tmp_path / "f" / "fleet.json").exists()
    for bad, why in (
        (["--devices", "0"], "--devices 0: expected at least 1"),
        (["--hours", "-1"], "--hours -1: expected more than 0"),
        (["--size", "lots"], "expected a byte count"),
    ):
        r = subprocess.run(run + ["--out", str(tmp_path / "g")] + bad, capture_output=True, text=True, env=env)
        assert r.returncode == 2, (bad, r.stderr)
        assert why in r.stderr and "Traceback" not in r.stderr, r.stderr


def test_start_utc(capsys) -> None:
    """The simulator's --start-utc: GPS week 2400 starts on Sunday 2026-01-04 (1980-01-06 + 16,800
    days), so 345,600 s into it is 2026-01-08 00:00:00 GPS time, 2026-01-07 23:59:42 UTC (18 leap
    seconds): the world's default start. A time near a week's end rolls the week over."""
    world = importlib.import_module("mipcodec.sim.world")
    sim = importlib.import_module("mipcodec.sim.cli")
    assert world.gps_start_of_utc("2026-01-07T23:59:42Z") == (world.GPS_WEEK, world.GPS_TOW0) == (2400, 345600.0)
    assert world.gps_start_of_utc("2026-01-10T23:59:42") == (2401, 0.0)
    w = world.World()
    w.gps_start = (2400, 604799.5)
    q = w.quantities(1.0)
    assert (q["gps_week"], q["gps_tow"]) == (2401, 0.5)
    for bad in ("yesterday", "2026-01-07T23:59:42+02:00", "1979-12-31T00:00:00"):
        assert sim.main(["--listen", "tcp:127.0.0.1:0", "--start-utc", bad]) == 2
        err = capsys.readouterr().err
        assert err.startswith("python -m mipcodec.sim: --start-utc ") and err.count("\n") == 1, err


def test_world_batch_is_world_quantities() -> None:
    """The batch path's world (World.batch, runtime sim/world.py) gives what World.quantities gives
    sample by sample, noise aside: both worlds configured as a fleet device (the fleet's commands),
    with an outage, their noise set to its mean, on a circle; the filter's states, flags and valid
    outputs the same at every sample (the aiding's offsets: zero with no noise)."""
    np = pytest.importorskip("numpy")
    sim_mod = importlib.import_module("mipcodec.sim")

    class Mean:  # a numpy generator whose draws are the mean
        def normal(self, mu, sigma, size):
            return np.full(size, mu, dtype=float)

    ts = np.arange(0, 1200) / 100.0
    for model in fleet.MODELS:
        worlds = []
        for _ in range(2):
            sim = sim_mod.Simulator(model, 1, scenario="circle")
            for packet in fleet.configuration(model):
                sim.feed(packet, 0.0)
            sim.world.gnss_outages.append((5.0, 8.5))
            sim.world.rng.gauss = lambda mu, sigma: mu
            worlds.append(sim.world)
        assert worlds[0].batchable()
        got = worlds[0].batch(ts, Mean())
        want = [worlds[1].quantities(t) for t in ts.tolist()]
        assert len(set(got["filter_state"].tolist())) >= 3, model  # the outage changes the filter's mode
        for name, values in got.items():
            expect = np.array([q[name] for q in want])
            if values.dtype.kind in "fc":
                assert np.allclose(values, expect, rtol=1e-12, atol=1e-9), (model, name)
            else:
                assert (values == expect).all(), (model, name)
