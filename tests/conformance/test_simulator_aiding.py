"""Internal aiding of the simulated navigation filter (issue 35; docs/simulator-world.md "Internal
aiding"): the filter uses the device's own sensors as its settings say.

Golden values come from the manuals and the scenario definitions, not from the simulator: the
static scenario's heading is 30 deg and the circle's vehicle drives a 50 m circle at 5 m/s
(docs/simulator-world.md); the CV7 modes are init -> vertical gyro -> AHRS (an absolute heading)
-> full navigation (heading, position, velocity) (CV7 manual lines 630-654); AHRS heading may come
from the magnetometer (line 650); the status flags are bits 0-1 condition, 3 heading warning,
4 position warning, 5 velocity warning (lines 660-672); aiding sources are the members of
0x0D,0x50 (line 8500); kinematic alignment takes the heading from the GNSS velocity from 2 m/s on
(line 533); the dual antenna status (0x82,0x49) reports receiver 1/2 data valid and
antenna offsets valid in bits 0-2 and FIX_DA_FIXED = 2 (lines 4679-4700). GX5-45: auto-init needs
a heading source (line 1646), the heading update control's values (line 1564), running with
0x0002 GNSS unavailable, 0x1000 mag bias warning (line 2359), the heading update source state
flags 1 magnetometer, 2 GNSS velocity, 4 external (line 2667).

1. In process (the sans-I/O Simulator): each source, outage and disturbance.
2. End to end over a pty and TCP at --speed 10 through the Python session API: a CV7 AHRS program
   (magnetometer heading) and a CV7 GNSS/INS program (its two receivers, dual antennas) until
   their mode, then the outputs checked against the scenario.
"""

from __future__ import annotations

import math
import subprocess
import time

import pytest

from tests.conformance.test_simulator import SIMULATE, TRANSPORTS, Sim, listen_for, open_device, pump_for
from tests.conformance.test_simulator_world import SPEED, command, pkg, sample, sim_mod, t, world_mod

MODE = t.FilterModeCv7
SOURCE = t.AidingMeasurementSource
HEADING_WARNING, POSITION_WARNING, VELOCITY_WARNING = 1 << 3, 1 << 4, 1 << 5  # CV7 lines 663-666
GX5 = t.FilterStateGx5


def _enable(sim, *sources, at: float = 0.0) -> None:
    for source in sources:
        ack = command(sim, pkg.filter.AidingMeasurementControl(function=1, source=source, enable=True), at)
        assert ack[0][1] == 0


def _antennas(sim, *receivers: int) -> None:
    offsets = {1: [0.5, 0.0, -0.2], 2: [-0.5, 0.0, -0.2]}  # 1 m baseline along the vehicle's x axis
    for r in receivers:
        value = pkg.filter.MultiAntennaOffset(function=1, receiver_id=r, antenna_offset=offsets[r])
        assert command(sim, value, 0.0)[0][1] == 0


def _yaw_error(yaw: float, truth: float) -> float:
    return (yaw - truth + math.pi) % (2 * math.pi) - math.pi


def _north_east(llh) -> tuple:
    lat0 = math.radians(world_mod.ORIGIN[0])
    north = math.radians(llh.latitude - world_mod.ORIGIN[0]) * world_mod.EARTH_RADIUS
    east = math.radians(llh.longitude - world_mod.ORIGIN[1]) * world_mod.EARTH_RADIUS * math.cos(lat0)
    return north, east


def _circle(at: float) -> tuple:
    """The circle scenario's truth written out (50 m radius, 5 m/s, turning right from north)."""
    a = 5.0 / 50.0 * at
    return (50.0 * math.sin(a), 50.0 * (1.0 - math.cos(a))), (5.0 * math.cos(a), 5.0 * math.sin(a)), a


# ------------------------------------------------------------------------------- CV7 in process
def test_cv7_magnetometer_aiding_gives_ahrs() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    assert sample(sim, 0x82, 0x10, 3.0).filter_state == MODE.VERT_GYRO  # no source enabled (factory)
    _enable(sim, SOURCE.MAGNETOMETER)
    command(sim, pkg.filter.ResetFilter(), 0.0)
    assert sample(sim, 0x82, 0x10, 0.5).filter_state == MODE.INIT
    status = sample(sim, 0x82, 0x10, 1.5)
    assert status.filter_state == MODE.AHRS and int(status.status_flags) & HEADING_WARNING == 0
    euler = sample(sim, 0x82, 0x05, 2.0)
    assert int(euler.valid_flags) == 1 and abs(_yaw_error(euler.yaw, math.radians(30.0))) < 0.02
    assert int(sample(sim, 0x82, 0x01, 2.0).valid_flags) == 0  # no position in AHRS
    assert sample(sim, 0x82, 0x10, 6.0).filter_state == MODE.AHRS  # stays: the magnetometer keeps aiding


def test_cv7_internal_gnss_gives_full_navigation_on_the_circle() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="circle", seed=2)
    _enable(sim, SOURCE.GNSS_POS_VEL, SOURCE.MAGNETOMETER)
    assert sample(sim, 0x82, 0x10, 1.5).filter_state == MODE.AHRS  # heading, no fix before 2 s
    for at in [3.0 + 0.1 * i for i in range(40)]:
        status = sample(sim, 0x82, 0x10, at)
        assert status.filter_state == MODE.FULL_NAV
        assert int(status.status_flags) & (POSITION_WARNING | VELOCITY_WARNING) == 0
        (north, east), (vn, ve), yaw = _circle(at)
        got_n, got_e = _north_east(sample(sim, 0x82, 0x01, at))
        assert math.hypot(got_n - north, got_e - east) < 3.0, (at, got_n, got_e, north, east)
        ned = sample(sim, 0x82, 0x02, at)
        assert abs(ned.north - vn) < 0.3 and abs(ned.east - ve) < 0.3
        assert abs(_yaw_error(sample(sim, 0x82, 0x05, at).yaw, yaw)) < 0.03


def test_cv7_dual_antenna_heading_needs_both_receivers_and_the_offsets() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="circle")
    _enable(sim, SOURCE.GNSS_POS_VEL, SOURCE.GNSS_HEADING)
    _antennas(sim, 1)  # receiver 2's offset missing: no dual-antenna heading
    assert sample(sim, 0x82, 0x10, 3.0).filter_state == MODE.VERT_GYRO
    dual = sample(sim, 0x82, 0x49, 3.0)
    assert dual.fix_type == t.FilterDualAntennaFixType.FIX_NONE and int(dual.status_flags) == 0b011
    assert int(dual.valid_flags) == 0
    _antennas(sim, 2)
    assert sample(sim, 0x82, 0x10, 1.0).filter_state == MODE.VERT_GYRO  # receivers without a fix yet
    status = sample(sim, 0x82, 0x10, 3.5)
    assert status.filter_state == MODE.FULL_NAV
    dual = sample(sim, 0x82, 0x49, 3.5)
    assert dual.fix_type == t.FilterDualAntennaFixType.FIX_DA_FIXED and int(dual.status_flags) == 0b111
    assert int(dual.valid_flags) == 1 and abs(_yaw_error(dual.heading, _circle(3.5)[2])) < 0.02
    assert dual.time_of_week == pytest.approx(world_mod.GPS_TOW0 + 3.5, abs=0.01)
    assert abs(_yaw_error(sample(sim, 0x82, 0x05, 3.6).yaw, _circle(3.6)[2])) < 0.03
    assert sample(sim, 0x91, 0x0B, 3.5).fix_type == t.GnssFixTypeCv7.FIX_3D
    assert sample(sim, 0x92, 0x0B, 3.5).fix_type == t.GnssFixTypeCv7.FIX_3D


def test_cv7_gnss_outage_degrades_then_recovers() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="circle")
    sim.world.gnss_outages.append((5.0, 12.0))
    _enable(sim, SOURCE.GNSS_POS_VEL, SOURCE.GNSS_HEADING, SOURCE.MAGNETOMETER)
    _antennas(sim, 1, 2)
    assert sample(sim, 0x82, 0x10, 4.5).filter_state == MODE.FULL_NAV
    coasting = sample(sim, 0x82, 0x10, 5.5)  # within the 2 s timeout: still full navigation, warned
    assert coasting.filter_state == MODE.FULL_NAV
    assert int(coasting.status_flags) & (POSITION_WARNING | VELOCITY_WARNING) == POSITION_WARNING | VELOCITY_WARNING
    assert sample(sim, 0x91, 0x0B, 5.5).fix_type == t.GnssFixTypeCv7.FIX_NONE
    lost = sample(sim, 0x82, 0x10, 8.0)  # position and velocity lost: AHRS on the magnetometer
    assert lost.filter_state == MODE.AHRS and int(lost.status_flags) & 3 == 2  # converging after the change
    assert int(sample(sim, 0x82, 0x01, 8.0).valid_flags) == 0
    assert sample(sim, 0x82, 0x49, 8.0).fix_type == t.FilterDualAntennaFixType.FIX_NONE
    back = sample(sim, 0x82, 0x10, 12.5)
    assert back.filter_state == MODE.FULL_NAV and int(back.status_flags) & (POSITION_WARNING | VELOCITY_WARNING) == 0
    assert int(sample(sim, 0x82, 0x10, 14.0).status_flags) & 3 == 1  # stable again


def test_cv7_magnetic_disturbance_raises_the_heading_warning() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    sim.world.mag_disturbances.append((4.0, 9.0))
    _enable(sim, SOURCE.MAGNETOMETER)
    clean = sample(sim, 0x80, 0x06, 3.0).scaled_mag
    status = sample(sim, 0x82, 0x10, 3.5)
    assert status.filter_state == MODE.AHRS and int(status.status_flags) & HEADING_WARNING == 0
    disturbed = sample(sim, 0x80, 0x06, 4.5).scaled_mag
    assert math.dist(clean, disturbed) > 0.2  # gauss: the magnetometer reads the disturbance
    warned = sample(sim, 0x82, 0x10, 4.5)
    assert warned.filter_state == MODE.AHRS and int(warned.status_flags) & HEADING_WARNING
    # the disturbed readings are rejected: the heading keeps its value, then the mode falls back
    assert abs(_yaw_error(sample(sim, 0x82, 0x05, 4.6).yaw, math.radians(30.0))) < 0.02
    assert sample(sim, 0x82, 0x10, 7.0).filter_state == MODE.VERT_GYRO
    recovered = sample(sim, 0x82, 0x10, 9.5)
    assert recovered.filter_state == MODE.AHRS and int(recovered.status_flags) & HEADING_WARNING == 0


def test_cv7_aiding_source_all_and_disable() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    _enable(sim, SOURCE.ALL)
    assert sample(sim, 0x82, 0x10, 1.5).filter_state == MODE.AHRS  # ALL enables the magnetometer too
    off = pkg.filter.AidingMeasurementControl(function=1, source=SOURCE.ALL, enable=False)
    assert command(sim, off, 0.0)[0][1] == 0
    assert sample(sim, 0x82, 0x10, 4.0).filter_state == MODE.VERT_GYRO  # 2 s after the last heading


def _read_source(sim, source) -> bool:
    ack = command(sim, pkg.filter.AidingMeasurementControl(function=2, source=source), 0.0)
    assert ack[0][1] == 0
    return bool(ack[0][2][0].enable)


def test_cv7_aiding_settings_follow_the_order_of_writes() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    _enable(sim, SOURCE.ALL)
    off = pkg.filter.AidingMeasurementControl(function=1, source=SOURCE.MAGNETOMETER, enable=False)
    assert command(sim, off, 0.0)[0][1] == 0
    # ALL, then the magnetometer off: every source but the magnetometer, as read back one by one
    assert not _read_source(sim, SOURCE.MAGNETOMETER)
    for source in (SOURCE.GNSS_POS_VEL, SOURCE.GNSS_HEADING, SOURCE.ALTIMETER):
        assert _read_source(sim, source), source
    assert sample(sim, 0x82, 0x10, 3.0).filter_state == MODE.VERT_GYRO  # static, no antennas: no heading left
    _enable(sim, SOURCE.ALL)  # ALL written last wins again
    assert _read_source(sim, SOURCE.MAGNETOMETER)
    assert sample(sim, 0x82, 0x10, 3.0).filter_state == MODE.FULL_NAV  # magnetometer heading, GNSS position
    assert command(sim, off, 0.0)[0][1] == 0
    _enable(sim, SOURCE.MAGNETOMETER)  # and the single source written after ALL
    assert _read_source(sim, SOURCE.MAGNETOMETER) and _read_source(sim, SOURCE.GNSS_POS_VEL)


# RTK (CV7 fix types FIX_3D 0, FIX_RTK_FLOAT 5, FIX_RTK_FIXED 6, line 5163; GNSS position aiding
# status 0x82,0x43 bits 1 differential, 2 integer fix, 14 no fix, line 4594; typical 1 sigma
# position uncertainty single point 1.25-2.5 m, RTK float 0.1-0.8 m, RTK fixed 0.01-0.06 m, line
# 2857; an RTK fix is lost with the corrections, line 2801). The times are the simulator's stated
# choice (docs/simulator-world.md "RTK"): RTK float 3 s, RTK fixed 10 s after corrections and a fix.
FIX = t.GnssFixTypeCv7
DIFFERENTIAL, INTEGER_FIX, NO_FIX = 1 << 1, 1 << 2, 1 << 14
RANGES = {FIX.FIX_3D: (1.25, 2.5), FIX.FIX_RTK_FLOAT: (0.1, 0.8), FIX.FIX_RTK_FIXED: (0.01, 0.06)}


def test_cv7_rtk_fix_moves_with_corrections_and_outages() -> None:
    assert (world_mod.RTK_FLOAT_AFTER, world_mod.RTK_FIXED_AFTER) == (3.0, 10.0)
    sim = sim_mod.Simulator("cv7_ins", scenario="circle")
    sim.world.rtk_corrections.append((4.0, 30.0))
    sim.world.gnss_outages.append((20.0, 22.0))
    _enable(sim, SOURCE.GNSS_POS_VEL, SOURCE.GNSS_HEADING)
    _antennas(sim, 1, 2)
    expected = [
        (3.5, FIX.FIX_3D, 0),  # a fix, no corrections yet
        (6.5, FIX.FIX_3D, 0),  # corrections for 2.5 s
        (7.5, FIX.FIX_RTK_FLOAT, DIFFERENTIAL),
        (13.5, FIX.FIX_RTK_FLOAT, DIFFERENTIAL),
        (14.5, FIX.FIX_RTK_FIXED, DIFFERENTIAL | INTEGER_FIX),
        (21.0, FIX.FIX_NONE, NO_FIX),  # the outage: no fix, nothing RTK
        (22.5, FIX.FIX_3D, 0),  # the fix is back, the RTK solution starts over
        (25.5, FIX.FIX_RTK_FLOAT, DIFFERENTIAL),
        (29.5, FIX.FIX_RTK_FLOAT, DIFFERENTIAL),
        (30.5, FIX.FIX_3D, 0),  # corrections stopped
    ]
    for at, fix, status in expected:
        for receiver in (0x91, 0x92):
            assert sample(sim, receiver, 0x0B, at).fix_type == fix, (at, receiver)
        assert int(sample(sim, 0x82, 0x43, at).status) == status, at
        if fix in RANGES:
            low, high = RANGES[fix]
            assert low <= sample(sim, 0x91, 0x03, at).horizontal_accuracy <= high, at
            uncertainty = sample(sim, 0x82, 0x08, at)
            assert low <= uncertainty.north <= high and int(uncertainty.valid_flags) == 1, at
    assert sample(sim, 0x82, 0x08, 20.5).north > RANGES[FIX.FIX_3D][1]  # coasting: worse than single point


def test_cv7_rtk_flags_only_while_the_filter_takes_gnss() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    sim.world.rtk_corrections.append((0.0, 60.0))
    assert sample(sim, 0x91, 0x0B, 13.0).fix_type == FIX.FIX_RTK_FIXED  # the receiver resolves on its own
    assert int(sample(sim, 0x82, 0x43, 13.0).status) == 0  # the filter processes no GNSS


def test_rtk_corrections_option_is_checked() -> None:
    for bad in (["--rtk-corrections", "5"], ["--rtk-corrections", "9:3"]):
        run = subprocess.run([str(SIMULATE), "--listen", "pty", *bad], capture_output=True, text=True, timeout=60)
        assert run.returncode == 2 and "--rtk-corrections" in run.stderr and "Traceback" not in run.stderr, run.stderr
        assert len(run.stderr.strip().splitlines()) == 1


def _alignment(sim, bits: int) -> None:
    config = pkg.filter.InitializationConfiguration(
        function=1, wait_for_run_command=0, initial_cond_src=0, auto_heading_alignment_selector=bits,
        initial_heading=0.0, initial_pitch=0.0, initial_roll=0.0, initial_position=[0.0] * 3,
        initial_velocity=[0.0] * 3, reference_frame_selector=2,
    )  # fmt: skip
    assert command(sim, config, 0.0)[0][1] == 0


def test_cv7_kinematic_alignment_heading_from_the_gnss_velocity() -> None:
    kinematic = 1 << 1  # HeadingAlignmentMethods bit 1 (CV7 line 8550)
    moving = sim_mod.Simulator("cv7_ins", scenario="circle")
    _enable(moving, SOURCE.GNSS_POS_VEL)
    assert sample(moving, 0x82, 0x10, 3.0).filter_state == MODE.VERT_GYRO  # position, velocity, no heading
    _alignment(moving, kinematic)
    assert sample(moving, 0x82, 0x10, 3.5).filter_state == MODE.FULL_NAV  # 5 m/s: above 2 m/s (line 533)
    assert abs(_yaw_error(sample(moving, 0x82, 0x05, 3.6).yaw, _circle(3.6)[2])) < 0.03
    still = sim_mod.Simulator("cv7_ins", scenario="static")
    _enable(still, SOURCE.GNSS_POS_VEL)
    _alignment(still, kinematic)
    assert sample(still, 0x82, 0x10, 3.5).filter_state == MODE.VERT_GYRO  # not moving: no heading
    without = sim_mod.Simulator("cv7_ins", scenario="circle")
    _alignment(without, kinematic)  # GNSS_POS_VEL not enabled: the filter takes no GNSS
    assert sample(without, 0x82, 0x10, 3.5).filter_state == MODE.VERT_GYRO


# ------------------------------------------------------------------------------- GX5-45 in process
def _gx5(scenario: str, source, auto_init: bool = True):
    sim = sim_mod.Simulator("gx5_45", scenario=scenario)
    assert command(sim, pkg.filter.HeadingUpdateControl(function=1, source=source), 0.0)[0][1] == 0
    if auto_init:
        assert command(sim, pkg.filter.AutoInitControl(function=1, enable=1), 0.0)[0][1] == 0
    return sim


def test_gx5_heading_update_control_gnss_velocity_needs_motion() -> None:
    still = _gx5("static", t.HeadingUpdateSource.GNSS_VELOCITY)
    status = sample(still, 0x82, 0x10, 4.0)
    assert status.filter_state == GX5.INIT and int(status.status_flags) & 0x1000  # attitude not initialized
    moving = _gx5("circle", t.HeadingUpdateSource.GNSS_VELOCITY)
    assert sample(moving, 0x82, 0x10, 1.0).filter_state == GX5.INIT  # no fix, so no velocity yet
    assert sample(moving, 0x82, 0x10, 3.0).filter_state == GX5.RUN_SOLUTION_VALID
    state = sample(moving, 0x82, 0x14, 3.0)
    assert int(state.source) == 2 and int(state.valid_flags) == 1  # GNSS velocity vector in use
    assert abs(_yaw_error(state.heading, _circle(3.0)[2])) < 0.02


def test_gx5_magnetometer_heading_and_disturbance() -> None:
    sim = _gx5("static", t.HeadingUpdateSource.MAGNETOMETER)
    sim.world.mag_disturbances.append((5.0, 7.0))
    assert sample(sim, 0x82, 0x10, 3.0).filter_state == GX5.RUN_SOLUTION_VALID
    assert int(sample(sim, 0x82, 0x14, 3.0).source) == 1
    assert abs(_yaw_error(sample(sim, 0x82, 0x05, 3.0).yaw, math.radians(30.0))) < 0.02
    disturbed = sample(sim, 0x82, 0x10, 6.0)
    assert disturbed.filter_state == GX5.RUN_SOLUTION_VALID and int(disturbed.status_flags) & 0x1000
    state = sample(sim, 0x82, 0x14, 6.0)
    assert int(state.source) == 0 and int(state.valid_flags) == 0  # rejected: no heading update in use
    assert int(sample(sim, 0x82, 0x10, 8.0).status_flags) & 0x1000 == 0


def test_gx5_external_heading_only_when_chosen() -> None:
    sim = _gx5("static", t.HeadingUpdateSource.MAGNETOMETER, auto_init=False)
    update = pkg.filter.ExternalHeadingUpdate(heading=0.5, heading_uncertainty=0.01, type=1)
    assert command(sim, update, 0.0)[0][1] != 0  # not the heading source: NACKed
    sim = _gx5("static", t.HeadingUpdateSource.EXTERNAL)
    assert sample(sim, 0x82, 0x10, 3.0).filter_state == GX5.INIT  # auto-init waits for a heading
    assert command(sim, update, 3.0)[0][1] == 0
    assert sample(sim, 0x82, 0x10, 3.1).filter_state == GX5.RUN_SOLUTION_VALID
    assert int(sample(sim, 0x82, 0x14, 3.1).source) == 4


def test_mag_disturbance_option_is_checked() -> None:
    for bad in (["--mag-disturbance", "5"], ["--mag-disturbance", "9:3"], ["--mag-disturbance", "a:b"]):
        run = subprocess.run([str(SIMULATE), "--listen", "pty", *bad], capture_output=True, text=True, timeout=60)
        assert run.returncode == 2 and "--mag-disturbance" in run.stderr and "Traceback" not in run.stderr, run.stderr
        assert len(run.stderr.strip().splitlines()) == 1


# ------------------------------------------------------------------------------- end to end
def _run_until(dev, mode, seconds: float) -> list:
    """The filter samples streamed in `mode` (at most 30) within `seconds` of simulated time."""
    samples, latest = [], {}

    def on_sample(s) -> None:
        values = {f.name: f.value for f in s.fields}
        latest.update(values)
        if "filter_status" in values and values["filter_status"].filter_state == mode:
            samples.append(values)

    dev.on_sample(on_sample)
    deadline = time.monotonic() + seconds / SPEED + 10.0
    while time.monotonic() < deadline and len(samples) < 30:
        pump_for(dev, 0.2)
    assert samples, f"never in {mode!r}; last {latest.get('filter_status')}"
    return samples


def _setup(dev, descriptors, sources) -> None:
    dev.base.ping()
    dev.base.set_to_idle()
    dev.threedm.device_startup_settings.default()
    fmt = [t.DescriptorRate(descriptor=d, decimation=100) for d in descriptors]
    dev.threedm.message_format.write(desc_set=0x82, descriptors=fmt)
    for source in sources:
        dev.filter.aiding_measurement_control.write(source=source, enable=True)


def cv7_ahrs_program(address: str) -> list:
    dev = open_device(pkg, address, "cv7_ins")
    try:
        _setup(dev, (0x11, 0x10, 0x05), (SOURCE.MAGNETOMETER,))
        assert dev.filter.aiding_measurement_control.read(source=SOURCE.MAGNETOMETER).enable
        dev.filter.reset_filter()
        dev.base.resume()
        return _run_until(dev, MODE.AHRS, 20.0)
    finally:
        dev.transport.close()


def cv7_gnss_ins_program(address: str) -> list:
    dev = open_device(pkg, address, "cv7_ins")
    try:
        _setup(dev, (0x11, 0x10, 0x01, 0x02, 0x05, 0x49), (SOURCE.GNSS_POS_VEL, SOURCE.GNSS_HEADING))
        dev.filter.multi_antenna_offset.write(receiver_id=1, antenna_offset=[0.5, 0.0, -0.2])
        dev.filter.multi_antenna_offset.write(receiver_id=2, antenna_offset=[-0.5, 0.0, -0.2])
        dev.filter.reset_filter()
        dev.base.resume()
        return _run_until(dev, MODE.FULL_NAV, 30.0)
    finally:
        dev.transport.close()


@pytest.mark.parametrize("transport", TRANSPORTS)
def test_cv7_ahrs_program_reaches_ahrs(transport: str) -> None:
    with Sim("mip", "cv7_ins", listen_for(transport), "--scenario", "static", "--speed", str(SPEED)) as sim:
        samples = cv7_ahrs_program(sim.address)
    assert len(samples) >= 10
    for s in samples:
        euler = s["euler_angles"]
        assert int(euler.valid_flags) == 1 and abs(_yaw_error(euler.yaw, math.radians(30.0))) < 0.02


@pytest.mark.parametrize("transport", TRANSPORTS)
def test_cv7_gnss_ins_program_reaches_full_navigation(transport: str) -> None:
    args = ("--scenario", "circle", "--speed", str(SPEED), "--seed", "7")
    with Sim("mip", "cv7_ins", listen_for(transport), *args) as sim:
        samples = cv7_gnss_ins_program(sim.address)
    assert len(samples) >= 10
    for s in samples:
        at = s["gps_timestamp"].tow - world_mod.GPS_TOW0
        (north, east), (vn, ve), yaw = _circle(at)
        got_n, got_e = _north_east(s["llh_position"])
        assert math.hypot(got_n - north, got_e - east) < 3.0 and int(s["llh_position"].valid_flags) == 1
        assert abs(s["ned_velocity"].north - vn) < 0.3 and abs(s["ned_velocity"].east - ve) < 0.3
        assert abs(_yaw_error(s["euler_angles"].yaw, yaw)) < 0.03
        dual = s["gnss_dual_antenna_status"]
        assert dual.fix_type == t.FilterDualAntennaFixType.FIX_DA_FIXED and int(dual.status_flags) == 0b111


def cv7_rtk_program(address: str) -> dict:
    """Every source but the magnetometer (ALL, then the magnetometer off), both antennas, the
    receiver's fix info and the filter's RTK fields streamed until RTK fixed."""
    dev = open_device(pkg, address, "cv7_ins")
    seen: dict = {"fix": [], "status": [], "uncertainty": [], "state": []}
    try:
        _setup(dev, (0x10, 0x08, 0x43), (SOURCE.ALL,))
        dev.filter.aiding_measurement_control.write(source=SOURCE.MAGNETOMETER, enable=False)
        seen["magnetometer"] = dev.filter.aiding_measurement_control.read(source=SOURCE.MAGNETOMETER).enable
        seen["gnss"] = dev.filter.aiding_measurement_control.read(source=SOURCE.GNSS_POS_VEL).enable
        dev.threedm.message_format.write(desc_set=0x91, descriptors=[t.DescriptorRate(descriptor=0x0B, decimation=1)])
        dev.filter.multi_antenna_offset.write(receiver_id=1, antenna_offset=[0.5, 0.0, -0.2])
        dev.filter.multi_antenna_offset.write(receiver_id=2, antenna_offset=[-0.5, 0.0, -0.2])
        dev.on_field(0x91, 0x0B, lambda v, p: seen["fix"].append(v.fix_type))
        dev.on_field(0x82, 0x43, lambda v, p: seen["status"].append(int(v.status)))
        dev.on_field(0x82, 0x08, lambda v, p: seen["uncertainty"].append(v.north))
        dev.on_field(0x82, 0x10, lambda v, p: seen["state"].append(v.filter_state))
        dev.filter.reset_filter()
        dev.base.resume()
        deadline = time.monotonic() + 30.0 / SPEED + 10.0
        while time.monotonic() < deadline and FIX.FIX_RTK_FIXED not in seen["fix"][-1:]:
            pump_for(dev, 0.2)
        pump_for(dev, 0.3)
        return seen
    finally:
        dev.transport.close()


def test_cv7_rtk_program_over_tcp() -> None:
    args = ("--scenario", "circle", "--speed", str(SPEED), "--rtk-corrections", "0:1000")
    with Sim("mip", "cv7_ins", listen_for("tcp"), *args) as sim:
        seen = cv7_rtk_program(sim.address)
    assert not seen["magnetometer"]
    assert seen["gnss"]
    fixes = [f for i, f in enumerate(seen["fix"]) if i == 0 or seen["fix"][i - 1] != f]
    rtk = [f for f in fixes if f != FIX.FIX_NONE]
    assert rtk == [FIX.FIX_3D, FIX.FIX_RTK_FLOAT, FIX.FIX_RTK_FIXED], fixes  # in that order, none skipped
    assert seen["status"][-1] == DIFFERENTIAL | INTEGER_FIX
    assert 0.01 <= seen["uncertainty"][-1] <= 0.06
    assert seen["state"][-1] == MODE.FULL_NAV  # dual-antenna heading, GNSS position: no magnetometer needed
