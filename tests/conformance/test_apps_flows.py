"""The manuals' getting-started flows as application programs in every language (issue 35), run
against the simulator until the state the manual describes, their data checked against the
scenario's truth.

The programs are tests/apps/<lang>/<name>.<ext> (contract: tests/apps/README.md), run by
`tests/lang/<lang>.sh app NAME ARGS...`:
- gx5_continuous: GX5-45 continuous data WITHOUT Enable/Disable Continuous Data Stream (the
  streams are on by default, 3dm-gx5-45-dcp.txt section 2.4.1 step 5), until the filter state is
  "run, solution valid";
- gx5_polling: GX5-45 polling (section 2.4.2), the device left idle, until "run, solution valid";
- cv7_ahrs: CV7-GNSS/INS on its magnetometer only, until AHRS mode (and never full navigation:
  no position source);
- cv7_gnss_ins --antennas 1|2: CV7-GNSS/INS on its internal GNSS (magnetometer or dual-antenna
  heading), until full navigation.

Every flow runs in every language over TCP, and over a pseudo-terminal in one language per flow
(PTY_LANG, rotating so each language's serial path runs at least once): 4 x 5 + 5 runs at
--speed 10 on the circle scenario. A language whose program is missing fails
(test_every_program_builds_and_prints_its_usage), it is never skipped. Each run must end with exit
0 as soon as its samples are printed (well before its deadline), with the device information lines,
the state lines ending in the manual's state before the first sample, and the samples checked
against the truth.

Tolerances, from the simulated world (docs/simulator-world.md "Quantities"): the filter outputs
are the truth plus 5 cm / 1 cm/s / 1-2 mrad, moved halfway toward each accepted measurement; the
internal GNSS measurements are the truth plus 0.5 m horizontal / 0.8 m vertical noise, so the
position is within the contract's "few metres" (2 m) and the velocity within 0.2 m/s of the truth
at the sample's GPS time; the attitude (heading from the magnetometer, the dual antenna or the
GX5-45's heading source) within 0.05 rad (about 3 degrees).
"""

from __future__ import annotations

import json
import math
import socket
import time

import pytest

from tests.conformance.test_simulator import SESSION_LANGUAGES, TRANSPORTS, Sim, listen_for
from tests.conformance.test_simulator_world import SPEED, _truth, run_app, t, world_mod

LANGS = SESSION_LANGUAGES  # python, c, cpp, rust: every language has every program
SAMPLES = 20
DEADLINE_S = 60  # the programs' own deadline (real time): far above the few seconds a flow takes
POSITION_M = 2.0
VELOCITY_MPS = 0.2
ANGLE_RAD = 0.05

# flow -> (program, device, extra arguments)
FLOWS = {
    "gx5_continuous": ("gx5_continuous", "gx5_45", ()),
    "gx5_polling": ("gx5_polling", "gx5_45", ()),
    "cv7_ahrs": ("cv7_ahrs", "cv7_ins", ()),
    "cv7_gnss_ins_1": ("cv7_gnss_ins", "cv7_ins", ("--antennas", "1")),
    "cv7_gnss_ins_2": ("cv7_gnss_ins", "cv7_ins", ("--antennas", "2")),
}
PROGRAMS = sorted({program for program, _, _ in FLOWS.values()})
# The one language per flow that also runs it over a pseudo-terminal.
PTY_LANG = {flow: LANGS[i % len(LANGS)] for i, flow in enumerate(FLOWS)}
assert set(PTY_LANG.values()) == set(LANGS)
RUNS = [(flow, lang, "tcp") for flow in FLOWS for lang in LANGS] + [(flow, PTY_LANG[flow], "pty") for flow in FLOWS]
assert set(TRANSPORTS) == {"tcp", "pty"}


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("program", PROGRAMS)
def test_every_program_builds_and_prints_its_usage(program: str, lang: str) -> None:
    """Builds the program (where the language builds) and runs it without arguments: exit 2 with
    its usage. A missing program fails here (the runner's `no application ...`, not a usage)."""
    r = run_app(lang, program, timeout=1800)
    assert r.returncode == 2, (r.returncode, r.stderr)
    assert f"usage: {program}" in r.stderr, r.stderr
    assert "Traceback" not in r.stderr and r.stdout == "", (r.stdout, r.stderr)


# ------------------------------------------------------------------------------- the truth
LAT0 = math.radians(world_mod.ORIGIN[0])


def north_east(lat: float, lon: float) -> tuple:
    """Metres north and east of the scenario's origin."""
    north = math.radians(lat - world_mod.ORIGIN[0]) * world_mod.EARTH_RADIUS
    east = math.radians(lon - world_mod.ORIGIN[1]) * world_mod.EARTH_RADIUS * math.cos(LAT0)
    return north, east


def angle_error(a: float, b: float) -> float:
    return abs((a - b + math.pi) % (2 * math.pi) - math.pi)


def check_attitude(s: dict) -> None:
    _, _, _, euler, _ = _truth(s["tow"])
    errors = [angle_error(got, want) for got, want in zip(s["euler"], euler)]
    assert max(errors) < ANGLE_RAD, (s, euler, errors)
    assert s["euler_valid"] == 1, s


def check_position(s: dict) -> None:
    pos, _, _, _, _ = _truth(s["tow"])
    north, east = north_east(s["lat"], s["lon"])
    assert math.hypot(north - pos[0], east - pos[1]) < POSITION_M, (s, pos)
    assert abs(math.hypot(north, east - 50.0) - 50.0) < POSITION_M, s  # on the 50 m circle
    assert abs(s["height"] - (world_mod.ORIGIN[2] - pos[2])) < POSITION_M, (s, pos)
    assert s["llh_valid"] == 1, s


def check_velocity(s: dict) -> None:
    _, vel, _, _, _ = _truth(s["tow"])
    assert all(abs(a - b) < VELOCITY_MPS for a, b in zip(s["vel"], vel)), (s, vel)


# ------------------------------------------------------------------------------- the flows
def check_output(flow: str, stdout: str) -> None:
    lines = stdout.splitlines()
    _, device, extra = FLOWS[flow]
    # Device information first, from the Get Device Info reply (padding stripped).
    identity = [x for x in lines if x.split(" ", 1)[0] in ("model", "serial", "firmware")]
    assert [x.split(" ", 1)[0] for x in identity] == ["model", "serial", "firmware"], lines[:6]
    family = "GX5-45" if device == "gx5_45" else "CV7"
    assert family in identity[0] and identity[0] == identity[0].strip(), identity
    assert identity[1].split(" ", 1)[1].strip() == identity[1].split(" ", 1)[1] != "", identity
    assert identity[2].split(" ", 1)[1].isdigit(), identity
    samples = [json.loads(x) for x in lines if x.startswith("{")]
    assert len(samples) == SAMPLES, stdout
    first_sample = next(i for i, x in enumerate(lines) if x.startswith("{"))
    if device == "gx5_45":
        valid = int(t.FilterStateGx5.RUN_SOLUTION_VALID)
        states = [int(x.split()[1]) for x in lines if x.startswith("state ")]
        assert states and states[-1] == valid, states
        assert lines.index(f"state {valid}") < first_sample, stdout
        assert "imu ok" in lines, stdout  # accelerometer and gyro in one IMU packet
        assert all(set(s) == {"tow", "lat", "lon", "height", "euler", "llh_valid", "euler_valid"} for s in samples)
        for s in samples:
            check_position(s)
            check_attitude(s)
    else:
        modes = [int(x.split()[1]) for x in lines if x.startswith("mode ")]
        final = t.FilterModeCv7.AHRS if flow == "cv7_ahrs" else t.FilterModeCv7.FULL_NAV
        assert modes and modes[-1] == int(final), modes
        assert lines.index(f"mode {int(final)}") < first_sample, stdout
        if flow == "cv7_ahrs":
            assert int(t.FilterModeCv7.FULL_NAV) not in modes, modes  # no position source
            assert all(set(s) == {"tow", "euler", "euler_valid"} for s in samples)
            for s in samples:
                check_attitude(s)
        else:
            for s in samples:
                check_position(s)
                check_velocity(s)
                check_attitude(s)
    tows = [s["tow"] for s in samples]
    assert all(b > a for a, b in zip(tows, tows[1:])), tows  # GPS time advances
    assert tows[-1] - tows[0] >= (SAMPLES - 1) * 0.1 - 0.05, tows  # at least 10 Hz of simulated time


@pytest.mark.parametrize(("flow", "lang", "transport"), RUNS)
def test_flow_reaches_the_manuals_state(flow: str, lang: str, transport: str) -> None:
    program, device, extra = FLOWS[flow]
    built = run_app(lang, program, timeout=1800)  # built before the simulator starts (usage: exit 2)
    assert built.returncode == 2, (built.returncode, built.stderr)
    args = ("--scenario", "circle", "--speed", str(SPEED), "--seed", "5")
    with Sim("mip", device, listen_for(transport), *args) as sim:
        started = time.monotonic()
        r = run_app(lang, program, sim.address, *extra, "--samples", str(SAMPLES), "--deadline-s", str(DEADLINE_S))
        took = time.monotonic() - started
    assert r.returncode == 0, (r.returncode, r.stdout, r.stderr, f"{took:.1f} s")
    assert "Traceback" not in r.stderr, r.stderr
    check_output(flow, r.stdout)
    # "Exit 0 after N samples": at once, not at the deadline (a flow takes a few seconds).
    assert took < DEADLINE_S / 2, f"{lang} {program} exited {took:.1f} s after its start"


# ------------------------------------------------------------------------------- bad input
def failed(r, *words: str) -> None:
    """Exit 1, the last stderr line `error: ...` naming `words`, no traceback, no sample."""
    assert r.returncode == 1, (r.returncode, r.stdout, r.stderr)
    last = r.stderr.strip().splitlines()[-1]
    assert last.startswith("error: ") and all(w.lower() in last.lower() for w in words), r.stderr
    assert "Traceback" not in r.stderr and "{" not in r.stdout, (r.stdout, r.stderr)


BAD_ARGUMENTS = [
    ["tcp:127.0.0.1:1", "extra"],
    ["tcp:127.0.0.1:1", "--samples", "0"],
    ["tcp:127.0.0.1:1", "--deadline-s"],
    ["tcp:127.0.0.1:1", "--rate", "5"],
]


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("program", PROGRAMS)
def test_wrong_arguments_print_the_usage(program: str, lang: str) -> None:
    cases = BAD_ARGUMENTS + ([["tcp:127.0.0.1:1", "--antennas", "3"]] if program == "cv7_gnss_ins" else [])
    for args in cases:
        r = run_app(lang, program, *args)
        assert r.returncode == 2 and f"usage: {program}" in r.stderr, (args, r.returncode, r.stderr)
        assert "Traceback" not in r.stderr and r.stdout == "", (args, r.stdout, r.stderr)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("program", PROGRAMS)
def test_unreachable_address_and_nack_exit_1(program: str, lang: str) -> None:
    with socket.socket() as s:  # a port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    failed(run_app(lang, program, f"tcp:127.0.0.1:{port}"), str(port))
    device = FLOWS[program if program in FLOWS else "cv7_gnss_ins_1"][1]
    with Sim("mip", device, listen_for("tcp"), "--speed", str(SPEED), "--nack", "set_to_idle") as sim:
        r = run_app(lang, program, sim.address, "--deadline-s", "20")
    failed(r, "set_to_idle")
