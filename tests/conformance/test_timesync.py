"""Time synchronization (issue 52; docs/timesync.md): the simulated clocks (sim/clocks.py) and
`device timesync` (device/timesync.py).

1. In process, the simulator's clocks against the manuals' statements (the spec's time.sync facts,
   whose manual lines are in spec/mip/protocol.yaml): the reference clock's crystal error, the
   PPS of each source, the GPS Time Update window, the flags with and without a PPS, the link
   delay's order.
2. `timesync` on a virtual clock: the simulator in process, its data delivered at its (delayed)
   send times, the host clock the simulated one (so the drift the host measures is the device's
   crystal error alone, as on a real link; over a socket with --speed the host's real clock would
   run --speed times slower than the simulated one). A 30 s run against the CV7 with --clock-drift
   100 --link-jitter 4 ends synced with a drift within 10 ppm of 100.
3. The command line against the simulator over TCP: a GX5-45 without a fix or a PPS ends with exit
   1 and its reason; a usage error is exit 2.
4. The C tool's timesync (`mipcodec-device`, tools/device/timesync.c) beside the Python command on
   the same simulated device: the GX5-45 without a fix or PPS ends with exit 1 and `no PPS`, the
   CV7 with its receiver's fix ends synced, both printing the same keys and reasons each second;
   usage errors are exit 2 with one line from both.
"""

from __future__ import annotations

import importlib
import json
import os
import re
import subprocess
import sys

import pytest

from tests.conformance.test_device_c import tool  # noqa: F401 (the C tool's fixture)
from tests.conformance.test_simulator import ROOT, Sim
from tests.helpers.generated import python_package

pkg = python_package("mipcodec")
sim_mod = importlib.import_module("mipcodec.sim")
cli = importlib.import_module("mipcodec.device.cli")
timesync = importlib.import_module("mipcodec.device.timesync")
_sim = pkg._sim
FACTS = _sim.TIME_SYNC


class VirtualLink:
    """A transport to a Simulator in process on a virtual clock: a read advances the clock to the
    next byte due (or by its timeout) and returns what the device has sent by then."""

    def __init__(self, sim, start: float = 100.0) -> None:
        self.sim = sim
        self.now = start
        self.pending: list = []
        sim.sim_time(start)

    def clock(self) -> float:
        return self.now

    def write(self, data: bytes) -> None:
        self.pending += self.sim.feed(bytes(data), self.now)

    def read(self, timeout: float) -> bytes:
        deadline = self.now + timeout
        while True:
            self.pending += self.sim.poll(self.now)
            self.pending.sort(key=lambda c: c[0])
            due = 0
            while due < len(self.pending) and self.pending[due][0] <= self.now:
                due += 1
            if due:
                out = b"".join(c[1] for c in self.pending[:due])
                del self.pending[:due]
                return out
            wake = [c[0] for c in self.pending[:1]]
            w = self.sim.next_wakeup(self.now)
            if w is not None:
                wake.append(w)
            nxt = min(wake) if wake else deadline
            if nxt > deadline:
                self.now = deadline
                return b""
            self.now = max(self.now, nxt) + 1e-7  # past the tick (its time rounds either way)

    def close(self) -> None:
        pass


def virtual_run(device: str, seconds: float, *, drift=0.0, jitter=0.0, pps_input=False, outage=None, source=None):
    sim = sim_mod.Simulator(device, 52)
    sim.clocks.drift_ppm, sim.clocks.jitter_ms, sim.clocks.pps_input = drift, jitter, pps_input
    if outage:
        sim.world.gnss_outages.append(outage)
    link = VirtualLink(sim)
    dev = pkg.session.Device(link, device, clock=link.clock)
    conn = cli.Connection(dev, device, {}, None, "virtual")
    lines: list = []
    gps0 = 1_451_865_600.0  # the host's GPS time at the start (any: the updates label edges with it)
    ts = timesync.TimeSync(
        conn, source, True, lines.append, gps_now=lambda: gps0 + link.now, tools=cli.subcommand_tools()
    )
    code = ts.run(seconds)
    return code, [json.loads(x) for x in lines], sim


# ------------------------------------------------------------------------ 1. the clocks in process
def simulator(device: str, drift=0.0, pps_input=False, outage=None):
    sim = sim_mod.Simulator(device, 52)
    sim.clocks.drift_ppm, sim.clocks.pps_input = drift, pps_input
    if outage:
        sim.world.gnss_outages.append(outage)
    sim.sim_time(0.0)  # started at real time 0, speed 1: simulated time = real time
    return sim


def value(sim, field: dict, t: float):
    return sim._data_value(field["set"], field["descriptor"], t, t)


def write(sim, name: str, t: float, **values):
    cls = cli._command_classes(name, sim.device)[0]
    command = cls.from_json({"function": 1, **values})
    sim.feed(pkg.codec.framing.PacketBuilder(command.SET).add(command).build(), t)


def update(sim, t: float, field: str, number: int):
    u = FACTS[sim.device]["update"]
    write(sim, u["command"], t, **{u["selector"]: u[field], u["value"]: number})


def test_the_reference_clock_runs_fast_by_the_drift():
    # --clock-drift 100: the device's clock runs fast by 100 ppm against true time: after 1000 s
    # of true time it reads 1000.1 s (the CV7's reference time, ns since power-on; line 1560).
    sim = simulator("cv7_ins", drift=100.0)
    ref = sim._data_value(0xFF, 0xD5, 1000.0, 1000.0)
    assert ref.nanoseconds == 1_000_100_000_000


def test_cv7_receiver_pps_time_valid_only_with_a_fix():
    # The factory source is receiver 1 (line 217); with a receiver's PPS the external time is GPS
    # time without an update (line 1604), valid only while the receiver has a fix. The simulated
    # receiver has its fix from 2 s; an outage from 10 to 20 s.
    facts = FACTS["cv7_ins"]
    sim = simulator("cv7_ins", outage=(10.0, 20.0))
    status, gps = facts["status"], facts["external"][0]
    both = gps["tow_mask"] | gps["week_mask"]
    for t, synced, valid in ((1.5, False, False), (5.25, True, True), (12.5, False, False), (25.5, True, True)):
        s = value(sim, status, t)
        g = value(sim, gps, t)
        assert bool(getattr(s, status["synced"])) is synced, t
        assert (int(g.valid_flags) & both == both) is valid, t
    # Time Sync Status: whole seconds since the last PPS (line 6707): the last one at 9 s (the fix
    # ends at 10 s, when that edge would come), 3.5 s before 12.5 s
    assert getattr(value(sim, status, 12.5), status["last_pps"]) == 3
    assert getattr(value(sim, status, 1.5), status["last_pps"]) == status["last_pps_max"]  # never: saturated
    # with the fix, the time of week is the GPS time (the world's: its start plus t)
    assert value(sim, gps, 5.25).tow == pytest.approx(sim.world.gps_start[1] + 5.25, abs=1e-6)


def test_cv7_gpio_pps_needs_the_input_and_both_updates_inside_the_window():
    facts = FACTS["cv7_ins"]
    gps, ext, status = facts["external"][0], facts["external"][1], facts["status"]
    window = facts["window_ms"] / 1000.0
    # no PPS on the pin: no sync, and an update does nothing (lines 6597, 8160)
    sim = simulator("cv7_ins")
    write(sim, "pps_source", 0.1, source=3)  # GPIO
    update(sim, 3.1, "tow", 1000)
    assert not getattr(value(sim, status, 3.5), status["synced"])
    assert int(value(sim, gps, 3.5).valid_flags) == 0 and sim.clocks.late == 1
    # with the PPS: time of week, then week, each just after an edge
    sim = simulator("cv7_ins", pps_input=True, drift=100.0)
    write(sim, "pps_source", 0.1, source=3)
    assert getattr(value(sim, status, 2.5), status["synced"])
    assert int(value(sim, gps, 2.5).valid_flags) == 0  # synced, time not set yet
    assert int(value(sim, ext, 2.5).valid_flags) == 0
    update(sim, 3.1, "tow", 1000)  # labels the edge at 3 s
    assert int(value(sim, gps, 3.5).valid_flags) == gps["tow_mask"]
    update(sim, 4.1, "week", 2400)
    g = value(sim, gps, 6.25)
    assert int(g.valid_flags) == gps["tow_mask"] | gps["week_mask"]
    # 3 s after the labelled edge, plus 0.25 s on the reference clock (100 ppm fast)
    assert g.week_number == 2400 and g.tow == pytest.approx(1003.25 * 1.0 + 0.25 * 100e-6, abs=1e-9)
    e = value(sim, ext, 6.25)
    assert int(e.valid_flags) == ext["ns_mask"] and e.nanoseconds == round((2400 * 604800 + g.tow) * 1e9)
    # an update later than the window after the edge is not used (the spec's decision)
    update(sim, 7.0 + window + 0.05, "tow", 5000)
    assert sim.clocks.late == 1 and value(sim, gps, 8.5).tow == pytest.approx(1005.5, abs=1e-3)
    # the PPS stops: no sync (line 6707), the time runs on from the last edge on the internal
    # clock (line 983), the flags saying it was set stay
    sim.clocks.pps_input = False
    s = value(sim, status, 9.5)
    assert (
        not getattr(s, status["synced"]) and int(value(sim, gps, 9.5).valid_flags) == gps["tow_mask"] | gps["week_mask"]
    )
    assert int(value(sim, ext, 9.5).valid_flags) == 0


def test_cv7_generated_pps_runs_on_the_reference_clock():
    # GENERATED: "zero drift between the internal and external times" (line 1600): its edges are
    # the reference clock's whole seconds.
    facts = FACTS["cv7_ins"]
    sim = simulator("cv7_ins", drift=1000.0)
    write(sim, "pps_source", 0.1, source=4)
    n, at = sim.clocks.last_edge(5.5)
    assert n == 5 and at == pytest.approx(5 / 1.001)
    assert getattr(value(sim, facts["status"], 5.5), facts["status"]["synced"])


def test_gx5_45_flags_with_and_without_pps():
    c = FACTS["gx5_45"]["correlation"]
    # no fix, no PPS on pin 7: no flag; the timestamp runs on the IMU's clock (line 2165)
    sim = simulator("gx5_45", drift=50.0, outage=(0.0, 100.0))
    update(sim, 3.1, "tow", 1000)
    v = value(sim, c, 5.0)
    assert int(v.valid_flags) == 0 and v.week_number == 0 and v.tow == pytest.approx(5.0 * (1 + 50e-6))
    # a PPS on pin 7: PPS Beacon Good; the first applied update initializes (and toggles refresh)
    sim = simulator("gx5_45", pps_input=True, outage=(0.0, 100.0))
    assert int(value(sim, c, 2.5).valid_flags) == c["pps"]
    update(sim, 3.1, "tow", 1000)
    update(sim, 3.2, "week", 2400)  # a second refresh: the toggle back
    assert int(value(sim, c, 3.15).valid_flags) == c["pps"] | c["refresh"] | c["initialized"]
    v = value(sim, c, 4.5)
    assert int(v.valid_flags) == c["pps"] | c["initialized"]
    assert (v.week_number, v.tow) == (2400, pytest.approx(1001.5))
    # the receiver's fix (from 2 s without an outage): PPS good, initialized with its GPS time
    sim = simulator("gx5_45")
    assert int(value(sim, c, 1.0).valid_flags) == 0
    assert int(value(sim, c, 2.5).valid_flags) == c["pps"] | c["refresh"] | c["initialized"]


def test_link_jitter_delays_each_packet_in_order():
    sim = simulator("cv7_ins")
    sim.clocks.jitter_ms = 4.0
    chunks = [(k * 0.001, bytes([k])) for k in range(200)]  # 1 kHz: delays overlap the next packets
    out = sim.clocks.delay(chunks, 1.0)
    assert [c[1] for c in out] == [c[1] for c in chunks]
    assert all(b[0] >= a[0] for a, b in zip(out, out[1:]))
    assert all(0.0 <= o[0] - c[0] <= 0.004 + 1e-12 or o[0] == p[0] for c, o, p in zip(chunks, out, [out[0]] + out))


# ------------------------------------------------------------------- 2. timesync on a virtual clock
def test_timesync_cv7_drift_100_jitter_4_ends_synced_with_the_drift():
    code, lines, _ = virtual_run("cv7_ins", 30.0, drift=100.0, jitter=4.0)
    assert code == 0 and len(lines) == 30
    last = lines[-1]
    assert last["synced"] and last["pps"] and last["time_valid"] and "reason" not in last
    assert abs(last["drift_ppm"] - 100.0) < 10.0
    assert 0.0 <= last["jitter_ms"] <= 4.0
    assert lines[0]["reason"] == "no PPS"  # the receiver's first fix comes at 2 s


def test_timesync_gpio_pps_sends_updates_inside_the_window():
    code, lines, sim = virtual_run("cv7_ins", 5.0, pps_input=True, source="gpio")
    assert code == 0 and lines[-1]["synced"] and lines[-1]["updates"] >= 3 and sim.clocks.late == 0


def test_timesync_updates_outside_the_window(monkeypatch):
    monkeypatch.setattr(timesync, "UPDATE_AFTER_S", 0.8)  # a host that sends late after the edge
    code, lines, sim = virtual_run("gx5_45", 5.0, pps_input=True, outage=(0.0, 100.0))
    assert code == 1 and lines[-1]["reason"] == "updates outside the window" and sim.clocks.late >= 3


def test_timesync_gx5_45_without_fix_or_pps_virtual():
    code, lines, _ = virtual_run("gx5_45", 4.0, outage=(0.0, 100.0))
    assert code == 1 and lines[-1]["reason"] == "no PPS" and not lines[-1]["pps"]


# ------------------------------------------------------------------- 3. the command line over TCP
def device_cli(*args: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(ROOT / "generated" / "python" / "mipcodec")}
    run = subprocess.run(
        [sys.executable, "-m", "mipcodec", "device", *args], capture_output=True, text=True, env=env, timeout=120
    )
    assert "Traceback" not in run.stderr, run.stderr
    return run


def test_timesync_cli_duration_nan_exits_2():
    # (the GX5-45 without fix or PPS over TCP, and the other usage errors: section 4, both tools)
    assert device_cli("tcp:127.0.0.1:9", "timesync", "--duration", "nan").returncode == 2


# ------------------------------------------------------------------- 4. the C tool beside the Python command
def both(tool_path, *args: str) -> tuple:
    """The Python command line's run and the C tool's, one after the other, with the same arguments."""
    py = device_cli(*args)
    c = subprocess.run([str(tool_path), *args], capture_output=True, text=True, timeout=120)
    assert c.returncode >= 0, f"killed by signal {-c.returncode}: {c.stderr}"
    return py, c


def json_lines(run: subprocess.CompletedProcess) -> list:
    return [json.loads(x) for x in run.stdout.splitlines()]


KEYS = ["t", "synced", "pps", "time_valid", "drift_ppm", "offset_ms", "jitter_ms", "updates"]


def test_timesync_c_gx5_45_without_fix_or_pps_exits_1_as_python(tool):  # noqa: F811
    with Sim("mip", "gx5_45", "tcp:127.0.0.1:0", "--speed", "10", "--gnss-outage", "0:1000") as sim:
        py, c = both(tool, sim.address, "timesync", "--duration", "2", "--json")
        text = subprocess.run(
            [str(tool), sim.address, "timesync", "--duration", "1"], capture_output=True, text=True, timeout=60
        )
    for run in (py, c):
        assert run.returncode == 1, run.stderr
        lines = json_lines(run)
        assert len(lines) == 2 and all(list(x) == KEYS + ["reason"] for x in lines), run.stdout
        assert all(not x["synced"] and not x["pps"] and x["reason"] == "no PPS" for x in lines)
        assert lines[-1]["updates"] >= 1  # the host sends updates: the GX5-45 has no receiver source
        assert run.stderr.splitlines()[-1] == "mipcodec-device: not synchronized: no PPS"
    assert text.returncode == 1
    assert re.fullmatch(
        r"t=1\.0s not synced \(no PPS\) pps=no time_valid=no drift=(-|[+-]\d+\.\dppm) "
        r"offset=(-|[+-]\d+\.\d{3}ms) jitter=(-|\d+\.\d{3}ms) updates=\d+\n",
        text.stdout,
    ), text.stdout


def test_timesync_c_cv7_with_a_fix_ends_synced_as_python(tool):  # noqa: F811
    # the receiver's fix from 2 s of simulated time (0.2 s at --speed 10): its PPS and GPS time
    with Sim("mip", "cv7_ins", "tcp:127.0.0.1:0", "--speed", "10") as sim:
        py, c = both(tool, sim.address, "timesync", "--duration", "2", "--json")
    for run in (py, c):
        assert run.returncode == 0, run.stderr
        lines = json_lines(run)
        assert len(lines) == 2 and all(list(x) == KEYS for x in lines), run.stdout
        last = lines[-1]
        assert last["synced"] and last["pps"] and last["time_valid"] and last["updates"] == 0
        # the clock model's estimate (20 s of simulated data): numbers, the bound not negative
        assert all(isinstance(last[k], float) for k in ("drift_ppm", "offset_ms", "jitter_ms"))
        assert last["jitter_ms"] >= 0.0


def test_timesync_c_usage_errors_exit_2_as_python(tool):  # noqa: F811
    with Sim("mip", "gx5_45", "tcp:127.0.0.1:0", "--speed", "10") as sim:
        runs = [
            both(tool, sim.address, "timesync", "--pps-source", "gpio", "--duration", "1"),
            both(tool, sim.address, "timesync", "--duration", "0"),
        ]
    for (py, c), says in zip(runs, ["--pps-source: gx5_45 has no PPS source setting", "--duration 0: expected"]):
        for run in (py, c):
            assert run.returncode == 2 and run.stdout == "", run.stderr
            assert len(run.stderr.splitlines()) == 1 and run.stderr.startswith("mipcodec-device: " + says)
