"""The simulator's world and navigation filter (docs/simulator-world.md, issue 29).

1. In process (the sans-I/O `Simulator` and `sim_world`): every output derived from one scenario
   (specific force with gravity, rotation rate, magnetometer, pressure, GNSS and filter), the
   filter state machine per device and its valid flags, aiding consumed and refused.
2. End to end, the two application flows of the issue over a pseudo-terminal and TCP at --speed
   20: the CV7-INS with external aiding and the GX5-45 with its internal GNSS, each until full
   navigation, then navigation data checked against the scenario. FLOWS names the session APIs
   the flows run in; a language is added by giving it a runner (its typed API or session tool).
"""

from __future__ import annotations

import importlib
import json
import math
import subprocess
import time

import pytest

from tests.conformance.test_simulator import (
    ROOT,
    SESSION_LANGUAGES,
    TRANSPORTS,
    Sim,
    listen_for,
    open_device,
    pump_for,
    results,
    session_tool,
)
from tests.helpers.generated import python_package

pkg = python_package("mipcodec")
sim_mod = importlib.import_module("mipcodec.sim")
world_mod = importlib.import_module("mipcodec.sim.world")
t = pkg.types
SPEED = 10.0  # simulated seconds per real second: fast, with room for a busy machine


# ------------------------------------------------------------------------------- in process
def sample(sim, set_id: int, descriptor: int, at: float):
    """One data value at simulated time `at` (the simulator started at 0)."""
    sim.sim_time(0.0)
    return sim._data_value(set_id, descriptor, at / sim.speed)


def command(sim, value, now: float):
    """Feeds one command at real time `now`; the (time, ack code, reply fields) answered."""
    raw = pkg.codec.framing.PacketBuilder(value.SET).add(value).build()
    out = []
    for when, data in sim.feed(raw, now):
        packet = pkg.codec.packets.decode_packet(data)
        if packet.set == value.SET:
            fields = [f.value for f in packet.fields]
            out.append((when, int(getattr(fields[0], sim_mod._meta.ACK_CODE)), fields[1:]))
    return out


def test_static_world_is_consistent() -> None:
    sim = sim_mod.Simulator("gx5_45", seed=3, scenario="static")
    accel = sample(sim, 0x80, 0x04, 1.0).scaled_accel
    assert abs(math.sqrt(sum(a * a for a in accel)) - 1.0) < 0.01  # 1 g of specific force, in g
    assert accel[2] < -0.99
    gyro = sample(sim, 0x80, 0x05, 1.0).scaled_gyro
    assert all(abs(g) < 0.02 for g in gyro)  # no rotation: the bias only
    mag = sample(sim, 0x80, 0x06, 1.0).scaled_mag
    assert abs(math.atan2(-mag[1], mag[0]) - math.radians(30.0 - 2.0)) < 0.05  # heading 30 deg, declination 2
    pressure = sample(sim, 0x80, 0x17, 1.0).scaled_pressure
    assert abs(pressure - world_mod.pressure_mbar(372.0)) < 0.1 and 960 < pressure < 975
    assert sample(sim, 0x81, 0x09, 2.5).tow == pytest.approx(world_mod.GPS_TOW0 + 2.5)


def test_circle_world_and_gyro_bias_capture() -> None:
    sim = sim_mod.Simulator("gx5_45", seed=1, scenario="circle")
    v, radius = 5.0, 50.0
    accel = sample(sim, 0x80, 0x04, 4.0).scaled_accel
    assert abs(accel[1] - v * v / radius / world_mod.GRAVITY) < 0.005  # centripetal, to the right
    gyro = sample(sim, 0x80, 0x05, 4.0).scaled_gyro
    assert abs(gyro[2] - v / radius) < 0.01
    (when, code, replies), *_ = command(sim, pkg.threedm.CaptureGyroBias(averaging_time_ms=2000), 0.0)
    assert code == 0 and when == pytest.approx(2.0)  # after the capture time (speed 1)
    bias = replies[0].bias
    assert bias == pytest.approx(list(sim.world.gyro_bias), abs=1e-4)
    after = sample(sim, 0x80, 0x05, 4.0).scaled_gyro
    assert abs(after[0]) < 1e-3 and abs(after[2] - v / radius) < 1e-3  # compensated from then on
    fast = sim_mod.Simulator("cv7_ins", scenario="static", speed=10)
    (when, code, _), *_ = command(fast, pkg.threedm.CaptureGyroBias(averaging_time_ms=2000), 0.0)
    assert code == 0 and when == pytest.approx(0.2)


def test_trajectory_file(tmp_path) -> None:
    track = tmp_path / "track.txt"
    track.write_text("# t lat lon height roll pitch yaw\n0 46.5197 6.6323 372 0 0 90\n10 46.5197 6.6337 372 0 0 90\n")
    sim = sim_mod.Simulator("gx5_45", scenario=f"file:{track}")
    vel = sample(sim, 0x81, 0x05, 5.0)
    assert abs(vel.velocity[1] - 10.7) < 0.3 and abs(vel.velocity[0]) < 0.3  # east at about 10.7 m/s
    with pytest.raises(ValueError, match="7 numbers"):
        bad = tmp_path / "bad.txt"
        bad.write_text("0 1 2\n")
        sim_mod.Simulator("gx5_45", scenario=f"file:{bad}")
    with pytest.raises(ValueError, match="unknown scenario"):
        sim_mod.Simulator("gx5_45", scenario="orbit")
    with pytest.raises(ValueError, match="speed"):
        sim_mod.Simulator("gx5_45", speed=0)


def test_gx5_filter_states_follow_gnss_and_auto_init() -> None:
    sim = sim_mod.Simulator("gx5_45", scenario="circle")
    state = t.FilterStateGx5
    assert sample(sim, 0x82, 0x10, 0.1).filter_state == state.STARTUP
    status = sample(sim, 0x82, 0x10, 3.0)
    assert status.filter_state == state.INIT and int(status.status_flags) & 0x1000  # attitude not initialized
    assert command(sim, pkg.filter.AutoInitControl(function=1, enable=1), 0.0)[0][1] == 0
    # GX5-45 line 1646: auto-initialization needs a heading source (heading update control: none)
    assert sample(sim, 0x82, 0x10, 3.0).filter_state == state.INIT
    source = t.HeadingUpdateSource.MAGNETOMETER
    assert command(sim, pkg.filter.HeadingUpdateControl(function=1, source=source), 0.0)[0][1] == 0
    assert sample(sim, 0x82, 0x10, 1.0).filter_state == state.INIT  # no fix yet
    assert sample(sim, 0x82, 0x10, 3.0).filter_state == state.RUN_SOLUTION_VALID
    assert int(sample(sim, 0x82, 0x01, 3.0).valid_flags) == 1
    sim.world.gnss_outages.append((5.0, 8.0))
    lost = sample(sim, 0x82, 0x10, 6.0)
    assert lost.filter_state == state.RUN_SOLUTION_ERROR and int(lost.status_flags) & 0x0002
    assert int(sample(sim, 0x82, 0x01, 6.0).valid_flags) == 0
    assert sample(sim, 0x81, 0x0B, 6.0).fix_type == t.GnssFixTypeGx5.FIX_NONE
    assert sample(sim, 0x82, 0x10, 9.0).filter_state == state.RUN_SOLUTION_VALID
    command(sim, pkg.filter.ResetFilter(), 10.0)
    assert sample(sim, 0x82, 0x10, 10.2).filter_state == state.STARTUP


def aiding_time():
    return t.AidingTime(timebase=t.AidingTimebase.TIME_OF_ARRIVAL)


def test_cv7_filter_modes_follow_accepted_aiding() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    sim.world.gnss_outages.append((0.0, 1e9))  # no sky: GNSS_POS_VEL takes the external measurements only
    mode = t.FilterModeCv7
    heading = pkg.aiding.TrueHeading(time=aiding_time(), frame_id=1, heading=0.5, uncertainty=0.01, valid_flags=1)
    assert command(sim, heading, 0.0)[0][1] == sim_mod._sim.NACK["invalid_parameter"]  # frame 1 not configured
    frame = pkg.aiding.FrameConfig(
        function=1,
        frame_id=1,
        format=1,
        tracking_enabled=False,
        translation=[0, 0, 0],
        rotation=t.AidingFrameEuler([0, 0, 0]),
    )
    assert command(sim, frame, 0.0)[0][1] == 0
    assert command(sim, heading, 0.1)[0][1] == 0  # acknowledged, but not enabled: not used
    assert sample(sim, 0x82, 0x10, 1.5).filter_state == mode.VERT_GYRO
    for source in (t.AidingMeasurementSource.EXTERNAL_HEADING, t.AidingMeasurementSource.GNSS_POS_VEL):
        command(sim, pkg.filter.AidingMeasurementControl(function=1, source=source, enable=True), 0.2)
    command(sim, heading, 2.0)
    assert sample(sim, 0x82, 0x10, 2.1).filter_state == mode.AHRS
    assert int(sample(sim, 0x82, 0x01, 2.1).valid_flags) == 0 and int(sample(sim, 0x82, 0x05, 2.1).valid_flags) == 1
    ten_m_north = world_mod.ORIGIN[0] + math.degrees(10.0 / world_mod.EARTH_RADIUS)
    position = pkg.aiding.LlhPosition(
        time=aiding_time(), frame_id=1, latitude=ten_m_north, longitude=world_mod.ORIGIN[1], height=372.0,
        uncertainty=[1, 1, 1], valid_flags=7,
    )  # fmt: skip
    velocity = pkg.aiding.NedVelocity(
        time=aiding_time(), frame_id=1, velocity=[0, 0, 0], uncertainty=[0.1] * 3, valid_flags=7
    )
    command(sim, position, 2.2)
    command(sim, velocity, 2.2)
    status = sample(sim, 0x82, 0x10, 2.3)
    assert status.filter_state == mode.FULL_NAV and int(status.status_flags) & 3 == 2  # converging
    llh = sample(sim, 0x82, 0x01, 2.3)
    assert int(llh.valid_flags) == 1
    north = math.radians(llh.latitude - world_mod.ORIGIN[0]) * world_mod.EARTH_RADIUS
    assert 4.5 < north < 5.5  # moved halfway toward the measurement, 10 m north of the truth
    assert int(sample(sim, 0x82, 0x10, 3.5).status_flags) & 3 == 1  # stable
    assert sample(sim, 0x82, 0x10, 5.0).filter_state == mode.VERT_GYRO  # aiding stopped 2 s ago


# ------------------------------------------------------------------------------- end to end
def _truth(tow: float):
    return world_mod.Scenario("circle").truth(tow - world_mod.GPS_TOW0)


def cv7_external_aiding_python(address: str) -> list:
    """The CV7-INS flow of issue 29 through the Python typed API; the navigation samples read."""
    dev = open_device(pkg, address, "cv7_ins")
    try:
        dev.base.ping()
        dev.base.set_to_idle()
        assert dev.base.get_device_info() is not None
        dev.threedm.device_startup_settings.default()
        bias = dev.threedm.capture_gyro_bias(averaging_time_ms=2000)
        assert len(bias.bias) == 3 and any(b != 0 for b in bias.bias)
        assert dev.threedm.get_base_rate(desc_set=0x82).rate == 1000
        fmt = [t.DescriptorRate(descriptor=d, decimation=100) for d in (0x11, 0x10, 0x01, 0x02, 0x05)]
        dev.threedm.message_format.write(desc_set=0x82, descriptors=fmt)
        for frame in (1, 2, 3):  # heading sensor, GNSS antenna, body-frame velocity sensor
            dev.aiding.frame_config.write(
                frame_id=frame, format=t.AidingFrameFormat.EULER, tracking_enabled=False,
                translation=[0.0, 0.0, 0.0], rotation=t.AidingFrameEuler([0.0, 0.0, 0.0]),
            )  # fmt: skip
        for source in (t.AidingMeasurementSource.GNSS_POS_VEL, t.AidingMeasurementSource.EXTERNAL_HEADING):
            dev.filter.aiding_measurement_control.write(source=source, enable=True)
        dev.filter.initialization_configuration.write(
            wait_for_run_command=0, initial_cond_src=t.FilterInitialConditionSource.AUTO_POS_VEL_ATT,
            auto_heading_alignment_selector=t.HeadingAlignmentMethods(0x08), initial_heading=0.0, initial_pitch=0.0,
            initial_roll=0.0, initial_position=[0.0] * 3, initial_velocity=[0.0] * 3, reference_frame_selector=t.FilterReferenceFrame.LLH,
        )  # fmt: skip
        dev.filter.reset_filter()
        dev.base.resume()
        return _navigate(dev, "cv7_ins", aid=True)
    finally:
        dev.transport.close()


def gx5_internal_gnss_python(address: str) -> list:
    """The GX5-45 flow of issue 29 through the Python typed API; the navigation samples read."""
    dev = open_device(pkg, address, "gx5_45")
    try:
        dev.base.ping()
        dev.base.set_to_idle()
        dev.base.get_device_info()
        dev.threedm.device_startup_settings.default()
        dev.threedm.capture_gyro_bias(averaging_time_ms=1000)
        dev.filter.sensor_to_vehicle_transform.write(roll=0.0, pitch=0.0, yaw=0.0)
        assert dev.threedm.get_gnss_base_rate().rate == 4 and dev.threedm.get_filter_base_rate().rate == 500
        dev.threedm.gnss_message_format.write(descriptors=[t.DescriptorRate(descriptor=0x0B, decimation=1)])
        fmt = [t.DescriptorRate(descriptor=d, decimation=50) for d in (0x11, 0x10, 0x01, 0x02, 0x05)]
        dev.threedm.filter_message_format.write(descriptors=fmt)
        dev.filter.heading_update_control.write(source=t.HeadingUpdateSource.GNSS_VELOCITY_AND_MAGNETOMETER)
        dev.filter.auto_init_control.write(enable=1)
        dev.filter.reset_filter()
        dev.threedm.data_stream_control.write_gx5_45(device_selector=t.Gx5StreamSelector.ESTIMATION_FILTER, enable=1)
        dev.base.resume()
        return _navigate(dev, "gx5_45", aid=False)
    finally:
        dev.transport.close()


def _navigate(dev, device: str, aid: bool) -> list:
    """Waits (aiding every 500 ms simulated when `aid`) for full navigation, then reads 3 s."""
    fix, samples, latest = [], [], {}
    full = t.FilterModeCv7.FULL_NAV if device == "cv7_ins" else t.FilterStateGx5.RUN_SOLUTION_VALID
    dev.on_field(0x81, 0x0B, lambda v, p: fix.append(v.fix_type))

    def on_sample(s) -> None:
        values = {f.name: f.value for f in s.fields}
        latest.update(values)
        if "filter_status" in values and values["filter_status"].filter_state == full:
            samples.append(values)

    dev.on_sample(on_sample)
    deadline = time.monotonic() + 60.0 / SPEED + 10.0
    reached = None
    while time.monotonic() < deadline and len(samples) < 30:
        if aid and "gps_timestamp" in latest:
            tow = latest["gps_timestamp"].tow  # measured then (internal reference time), sent now
            pos, vel, _, euler, _ = _truth(tow)
            stamp = t.AidingTime(
                timebase=t.AidingTimebase.INTERNAL_REFERENCE, nanoseconds=round((tow - world_mod.GPS_TOW0) * 1e9)
            )
            llh = (
                world_mod.ORIGIN[0] + math.degrees(pos[0] / world_mod.EARTH_RADIUS),
                world_mod.ORIGIN[1]
                + math.degrees(pos[1] / (world_mod.EARTH_RADIUS * math.cos(math.radians(world_mod.ORIGIN[0])))),
            )
            at = t.AidingTime(timebase=t.AidingTimebase.TIME_OF_ARRIVAL)
            dev.aiding.true_heading(time=stamp, frame_id=1, heading=euler[2], uncertainty=0.01, valid_flags=1)
            dev.aiding.llh_position(
                time=stamp, frame_id=2, latitude=llh[0], longitude=llh[1], height=372.0, uncertainty=[1.0] * 3,
                valid_flags=t.AidingLlhValidFlags(7),
            )  # fmt: skip
            dev.aiding.ned_velocity(
                time=stamp,
                frame_id=2,
                velocity=list(vel),
                uncertainty=[0.1] * 3,
                valid_flags=t.AidingVectorValidFlags(7),
            )
            dev.aiding.body_frame_velocity(
                time=at,
                frame_id=3,
                velocity=[5.0, 0.0, 0.0],
                uncertainty=[0.1] * 3,
                valid_flags=t.AidingVectorValidFlags(7),
            )
        if samples and reached is None:
            reached = time.monotonic()
        pump_for(dev, 0.5 / SPEED)
    assert samples, f"no full navigation; last {latest.get('filter_status')}"
    if not aid:
        assert t.GnssFixTypeGx5.FIX_3D in fix
    return samples


FLOWS = {"cv7_ins": {"python": cv7_external_aiding_python}, "gx5_45": {"python": gx5_internal_gnss_python}}


@pytest.mark.parametrize("transport", TRANSPORTS)
@pytest.mark.parametrize(("device", "lang"), [(d, lang) for d, runners in FLOWS.items() for lang in runners])
def test_application_flow_reaches_full_navigation(device: str, lang: str, transport: str) -> None:
    with Sim("mip", device, listen_for(transport), "--scenario", "circle", "--speed", str(SPEED), "--seed", "5") as sim:
        samples = FLOWS[device][lang](sim.address)
    assert len(samples) >= 30
    for s in samples:
        pos, vel, _, euler, _ = _truth(s["gps_timestamp"].tow)
        llh = s["llh_position"]
        north = math.radians(llh.latitude - world_mod.ORIGIN[0]) * world_mod.EARTH_RADIUS
        east = (
            math.radians(llh.longitude - world_mod.ORIGIN[1]) * world_mod.EARTH_RADIUS * math.cos(math.radians(46.5197))
        )
        assert abs(north - pos[0]) < 1.0 and abs(east - pos[1]) < 1.0, (north, east, pos)
        assert abs(math.hypot(north, east - 50.0) - 50.0) < 1.0  # on the circle
        ned = s["ned_velocity"]
        assert abs(ned.north - vel[0]) < 0.1 and abs(ned.east - vel[1]) < 0.1
        yaw_error = (s["euler_angles"].yaw - euler[2] + math.pi) % (2 * math.pi) - math.pi
        assert abs(yaw_error) < 0.02 and int(s["euler_angles"].valid_flags) == 1
        assert int(llh.valid_flags) == 1
    tows = [s["gps_timestamp"].tow for s in samples]
    assert all(b > a for a, b in zip(tows, tows[1:]))  # GPS time advances with the simulated clock
    assert tows[-1] - tows[0] >= 2.5  # 30 samples at 10 Hz of simulated time


def test_baud_rate_change_over_the_pty() -> None:
    """With --baud, comm port speed is acknowledged at the old rate; then only a host at the new
    rate is understood (a host left at the old one times out)."""
    session = importlib.import_module("mipcodec.session")
    transport = importlib.import_module("mipcodec.session.transport")
    with Sim("mip", "cv7_ins", "pty", "--baud") as sim:
        dev = session.Device(transport.open_transport(sim.address, 115200), device="cv7_ins", timeout_ms=300)
        try:
            dev.base.ping()
            dev.base.comm_port_speed.write(port=1, baud=921600)  # acknowledged at 115200
            with pytest.raises(session.CommandTimeout):
                dev.base.ping()
        finally:
            dev.transport.close()
        dev = session.Device(transport.open_transport(sim.address, 921600), device="cv7_ins", timeout_ms=300)
        try:
            dev.base.ping()
            assert dev.base.comm_port_speed.read(port=1).baud == 921600
        finally:
            dev.transport.close()


def test_cv7_waits_for_the_run_command_when_configured() -> None:
    sim = sim_mod.Simulator("cv7_ins", scenario="static")
    config = pkg.filter.InitializationConfiguration(
        function=1, wait_for_run_command=1, initial_cond_src=0, auto_heading_alignment_selector=0, initial_heading=0.0,
        initial_pitch=0.0, initial_roll=0.0, initial_position=[0.0] * 3, initial_velocity=[0.0] * 3,
        reference_frame_selector=1,
    )  # fmt: skip
    assert command(sim, config, 0.0)[0][1] == 0
    assert sample(sim, 0x82, 0x10, 3.0).filter_state == t.FilterModeCv7.INIT
    assert command(sim, pkg.filter.RunFilter(), 0.0)[0][1] == 0
    assert sample(sim, 0x82, 0x10, 3.0).filter_state == t.FilterModeCv7.VERT_GYRO


def test_set_to_idle_stops_the_streams_until_resume() -> None:
    sim = sim_mod.Simulator("cv7_ins")
    fmt = pkg.threedm.MessageFormat(
        function=1, desc_set=0x80, num_descriptors=1, descriptors=[t.DescriptorRate(descriptor=4, decimation=10)]
    )
    assert command(sim, fmt, 0.0)[0][1] == 0
    sim.poll(0.0)
    assert len(sim.poll(0.1)) >= 9  # 100 Hz
    command(sim, pkg.base.SetToIdle(), 0.1)
    assert sim.poll(0.3) == []
    command(sim, pkg.base.Resume(), 0.3)
    assert 9 <= len(sim.poll(0.4)) <= 11  # from resume on, not the backlog


def test_world_options_are_checked() -> None:
    import subprocess

    from tests.conformance.test_simulator import SIMULATE

    for bad in (["--speed", "0"], ["--scenario", "moon"], ["--gnss-outage", "5"], ["--gnss-outage", "9:3"]):
        run = subprocess.run([str(SIMULATE), "--listen", "pty", *bad], capture_output=True, text=True, timeout=60)
        assert run.returncode == 2 and run.stderr.strip() and "Traceback" not in run.stderr, (bad, run.stderr)


def _line(set_id: int, descriptor: int, name: str, values: dict | None = None, device: str | None = None) -> str:
    field = {"descriptor": descriptor, "name": name, "values": values or {}}
    if device:
        field["device"] = device
    return json.dumps({"offset": 0, "set": set_id, "fields": [field]}, separators=(",", ":"))


def _rates(descriptors: list, decimation: int) -> dict:
    entries = [{"descriptor": d, "decimation": decimation} for d in descriptors]
    return {"function": 1, "num_descriptors": len(entries), "descriptors": entries}


def gx5_internal_gnss_tool(lang: str, address: str) -> list:
    """The GX5-45 flow through a language's session tool (command lines only, so every language
    of SESSION_LANGUAGES runs it): configure, then wait (replies the simulator drops) while the
    data prints; the filter samples printed in full navigation."""
    lines = [
        _line(0x01, 0x01, "ping"),
        _line(0x01, 0x02, "set_to_idle"),
        _line(0x01, 0x03, "get_device_info"),
        _line(0x0C, 0x30, "device_startup_settings", {"function": 5}, "gx5_45"),
        _line(0x0C, 0x39, "capture_gyro_bias", {"averaging_time_ms": 1000}),
        _line(0x0D, 0x11, "sensor_to_vehicle_transform", {"function": 1, "roll": 0.0, "pitch": 0.0, "yaw": 0.0}),
        _line(0x0C, 0x07, "get_gnss_base_rate"),
        _line(0x0C, 0x0B, "get_filter_base_rate"),
        _line(0x0C, 0x09, "gnss_message_format", _rates([0x0B], 1)),
        _line(0x0C, 0x0A, "filter_message_format", _rates([0x11, 0x10, 0x01, 0x02, 0x05], 50)),
        _line(0x0D, 0x18, "heading_update_control", {"function": 1, "source": 4}),
        _line(0x0D, 0x19, "auto_init_control", {"function": 1, "enable": 1}),
        _line(0x0D, 0x01, "reset_filter"),
        _line(0x0C, 0x11, "data_stream_control", {"function": 1, "device_selector": 3, "enable": 1}, "gx5_45"),
        _line(0x01, 0x06, "resume"),
        *[_line(0x01, 0x04, "get_device_descriptors")] * 3,  # dropped: 3 x 300 ms = 9 s simulated of data
    ]
    out = session_tool(lang, "mip", address, lines, "--device", "gx5_45")
    assert [r["result"] for r in results(out)] == ["ack"] * 15 + ["timeout"] * 3, results(out)
    assert any(
        f["name"] == "fix_info" and f["values"]["num_sv"] > 0 for x in out if x.get("set") == 0x81 for f in x["fields"]
    )
    samples = []
    for x in out:
        if x.get("set") == 0x82:
            values = {f["name"]: f["values"] for f in x["fields"]}
            if values.get("filter_status", {}).get("filter_state") in (2, "run_solution_valid"):
                samples.append(values)
    return samples


# The flows every session language runs through its tool (command lines): the CV7-INS flow needs
# aiding sent every 500 ms while waiting, which the tools' line-by-line input does not do yet
# (the application programs below run it).
TOOL_FLOWS = {"gx5_45": SESSION_LANGUAGES}


@pytest.mark.parametrize("transport", TRANSPORTS)
@pytest.mark.parametrize(("device", "lang"), [(d, lang) for d, langs in TOOL_FLOWS.items() for lang in langs])
def test_application_flow_through_the_session_tool(device: str, lang: str, transport: str) -> None:
    args = ("--scenario", "circle", "--speed", str(SPEED), "--drop", "get_device_descriptors")
    with Sim("mip", device, listen_for(transport), *args) as sim:
        samples = gx5_internal_gnss_tool(lang, sim.address)
    assert len(samples) >= 30, len(samples)
    for s in samples:
        tow = s["gps_timestamp"]["tow"]
        pos, vel, _, euler, _ = _truth(tow)
        llh = s["llh_position"]
        north = math.radians(llh["latitude"] - world_mod.ORIGIN[0]) * world_mod.EARTH_RADIUS
        assert abs(north - pos[0]) < 1.0
        yaw_error = (s["euler_angles"]["yaw"] - euler[2] + math.pi) % (2 * math.pi) - math.pi
        assert abs(yaw_error) < 0.02


def test_aiding_is_compared_with_the_truth_at_its_timestamp() -> None:
    world = world_mod.World("circle")
    pos, _, _, _, _ = world.scenario.truth(1.0)
    lat = world_mod.ORIGIN[0] + math.degrees(pos[0] / world_mod.EARTH_RADIUS)
    lon = world_mod.ORIGIN[1] + math.degrees(pos[1] / (world_mod.EARTH_RADIUS * math.cos(math.radians(46.5197))))
    world.aid("position", 3.0, [lat, lon, 372.0], measured=1.0)  # measured at 1 s, arrived at 3 s
    assert all(abs(o) < 0.01 for o in world.filter.offsets["position"])
    world.aid("position", 3.0, [lat, lon, 372.0])  # time of arrival: 2 s old at 5 m/s
    assert math.hypot(*world.filter.offsets["position"][:2]) > 3.0


# ------------------------------------------------------------------------------- application programs
# The CV7-INS flow as a real application in every language: tests/apps/<lang>/cv7_external_aiding.<ext>,
# run by `tests/lang/<lang>.sh app cv7_external_aiding ARGS...` (its contract: tests/apps/README.md).
# Its aiding sensors are a feed file (what an application reads from its own GNSS receiver and
# heading sensor): one row per 0.1 s of the circle scenario's truth.
APP_LANGS = SESSION_LANGUAGES
FEED_STEP = 0.1
FEED_SECONDS = 600.0


def write_aiding_feed(path) -> None:
    """Rows `tow ns lat lon height vn ve vd heading bx by bz` (GPS time of week in s, the same time as
    nanoseconds since the device's internal reference epoch, degrees, metres, m/s, radians, m/s)."""
    lat0 = math.radians(world_mod.ORIGIN[0])
    rows = ["# tow ns lat lon height vn ve vd heading bx by bz"]
    for i in range(int(FEED_SECONDS / FEED_STEP) + 1):
        tow = world_mod.GPS_TOW0 + i * FEED_STEP
        pos, vel, _, euler, _ = _truth(tow)
        lat = world_mod.ORIGIN[0] + math.degrees(pos[0] / world_mod.EARTH_RADIUS)
        lon = world_mod.ORIGIN[1] + math.degrees(pos[1] / (world_mod.EARTH_RADIUS * math.cos(lat0)))
        yaw = euler[2]
        body = (
            vel[0] * math.cos(yaw) + vel[1] * math.sin(yaw),
            -vel[0] * math.sin(yaw) + vel[1] * math.cos(yaw),
            vel[2],
        )
        numbers = (tow, round(i * FEED_STEP * 1e9), lat, lon, world_mod.ORIGIN[2] - pos[2], *vel, yaw, *body)
        rows.append(" ".join(repr(float(x)) if not isinstance(x, int) else str(x) for x in numbers))
    path.write_text("\n".join(rows) + "\n")


def run_app(lang: str, name: str, *args: str, timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(ROOT / "tests/lang" / f"{lang}.sh"), "app", name, *args], capture_output=True, text=True, timeout=timeout
    )


@pytest.mark.parametrize("transport", TRANSPORTS)
@pytest.mark.parametrize("lang", APP_LANGS)
def test_cv7_application_program_reaches_full_navigation(lang: str, transport: str, tmp_path) -> None:
    feed = tmp_path / "aiding.txt"
    write_aiding_feed(feed)
    built = run_app(lang, "cv7_external_aiding", timeout=1800)  # builds the program first (usage: exit 2)
    assert built.returncode == 2 and "usage" in built.stderr, built.stderr
    period = str(round(500 / SPEED))  # every 500 ms of simulated time
    args = ("--scenario", "circle", "--speed", str(SPEED), "--seed", "5")
    with Sim("mip", "cv7_ins", listen_for(transport), *args) as sim:
        r = run_app(lang, "cv7_external_aiding", sim.address, str(feed), "--period-ms", period, "--samples", "30")
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    modes = [int(x.split()[1]) for x in lines if x.startswith("mode ")]
    full = int(t.FilterModeCv7.FULL_NAV)
    assert modes and modes[0] == int(t.FilterModeCv7.INIT) and modes[-1] == full, modes  # after the reset
    samples = [json.loads(x) for x in lines if x.startswith("{")]
    assert len(samples) == 30, r.stdout
    assert lines.index(f"mode {full}") < lines.index(next(x for x in lines if x.startswith("{")))
    lat0 = math.radians(world_mod.ORIGIN[0])
    for s in samples:
        pos, vel, _, euler, _ = _truth(s["tow"])
        north = math.radians(s["lat"] - world_mod.ORIGIN[0]) * world_mod.EARTH_RADIUS
        east = math.radians(s["lon"] - world_mod.ORIGIN[1]) * world_mod.EARTH_RADIUS * math.cos(lat0)
        assert abs(north - pos[0]) < 1.0 and abs(east - pos[1]) < 1.0, (s, pos)
        assert abs(math.hypot(north, east - 50.0) - 50.0) < 1.0  # on the circle
        assert abs(s["vel"][0] - vel[0]) < 0.1 and abs(s["vel"][1] - vel[1]) < 0.1, (s, vel)
        yaw_error = (s["euler"][2] - euler[2] + math.pi) % (2 * math.pi) - math.pi
        assert abs(yaw_error) < 0.02, (s, euler)
        assert s["llh_valid"] == 1 and s["euler_valid"] == 1
    tows = [s["tow"] for s in samples]
    assert all(b > a for a, b in zip(tows, tows[1:]))
    assert tows[-1] - tows[0] >= 2.5  # 30 samples at 10 Hz of simulated time
