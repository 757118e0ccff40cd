"""The world a simulated device lives in (docs/simulator-world.md): a seeded scenario giving the
true motion at every simulated time, the quantities every sensor derives from it, and a navigation
filter whose state follows its aiding. Language-neutral physics, no protocol knowledge: sim.py maps
data fields to these quantities through the generated `_sim.WORLD` table.

Scenarios: `static` (on a bench, heading 30 deg), `circle` (a vehicle driving a 50 m circle at
5 m/s, turning right) and `file:PATH` (a trajectory: lines `t lat lon height roll pitch yaw`,
seconds, degrees and metres, whitespace or comma separated, `#` comments; linear interpolation,
velocity and rates from differences).
"""

from __future__ import annotations

import bisect
import copy
import math
import random
from typing import Any, Dict, List, Optional, Sequence, Tuple

from .. import _columns

GRAVITY = 9.80665
EARTH_RADIUS = 6378137.0
ORIGIN = (46.5197, 6.6323, 372.0)  # latitude, longitude (deg), height above the ellipsoid (m)
MAG_NED = (0.2160, 0.0076, 0.4270)  # a fixed field model (gauss): near Lausanne, declination 2 deg
GPS_WEEK = 2400
GPS_TOW0 = 345600.0  # Wednesday 00:00 of week 2400
# The GPS time scale (spec/common/gps_time.yaml through _columns): days from 1970-01-01 to the
# GPS epoch 1980-01-06, and GPS - UTC in the simulated world's time (2026: after the last leap
# second of the table).
GPS_EPOCH_DAYS = _columns.GPS_EPOCH_UNIX_S // 86400
LEAP_SECONDS = _columns.LEAP_TABLE[-1][1]
GNSS_FIX_AFTER = 2.0  # seconds of simulated time a receiver takes to a 3D fix
KINEMATIC_SPEED = 2.0  # m/s: GNSS velocity gives a heading from this speed on (CV7 manual line 533)
MAG_DISTURBANCE = (0.15, 0.10, 0.30)  # gauss, body frame: a magnetic disturbance (--mag-disturbance)
INTERNAL_GAIN = 0.1  # how far each sample of an internal sensor pulls the filter's output toward it
TURN = "velocity_turn"  # no heading aid: the velocity vector's turn observes the heading (not a source)
MAG_ANOMALY = 0.10  # a field magnitude this far (relative) from the model's is rejected as disturbed
# RTK (--rtk-corrections): seconds of corrections and a fix without a break before the receivers
# report RTK float, then RTK fixed (the manuals state no times: the simulator's choice, in the
# order of an RTK receiver's ambiguity resolution)
RTK_FLOAT_AFTER = 3.0
RTK_FIXED_AFTER = 10.0

Vec = Tuple[float, float, float]
# Quantities in radians (every other angle, latitude and longitude, is in degrees)
RADIANS = frozenset(
    (
        "roll",
        "pitch",
        "yaw",
        "nav_yaw",
        "course",
        "angular_rate",
        "true_angular_rate",
        "gyro_bias",
        "attitude_uncertainty",
        "dual_heading",
        "dual_heading_uncertainty",
    )
)


def _rot(roll: float, pitch: float, yaw: float) -> List[List[float]]:
    """The body-to-NED rotation matrix of Euler angles (rad, 3-2-1)."""
    cr, sr, cp, sp, cy, sy = (
        math.cos(roll),
        math.sin(roll),
        math.cos(pitch),
        math.sin(pitch),
        math.cos(yaw),
        math.sin(yaw),
    )
    return [
        [cp * cy, sr * sp * cy - cr * sy, cr * sp * cy + sr * sy],
        [cp * sy, sr * sp * sy + cr * cy, cr * sp * sy - sr * cy],
        [-sp, sr * cp, cr * cp],
    ]


def _to_body(m: List[List[float]], v: Sequence[float]) -> Vec:
    return (
        m[0][0] * v[0] + m[1][0] * v[1] + m[2][0] * v[2],
        m[0][1] * v[0] + m[1][1] * v[1] + m[2][1] * v[2],
        m[0][2] * v[0] + m[1][2] * v[1] + m[2][2] * v[2],
    )


def pressure_mbar(height: float) -> float:
    """The standard atmosphere's pressure at a height (m)."""
    return float(1013.25 * (1.0 - 2.25577e-5 * height) ** 5.25588)


class Scenario:
    """The true motion: `truth(t)` -> (north, east, down offsets from ORIGIN in m, NED velocity,
    NED acceleration, (roll, pitch, yaw) in rad, body angular rate in rad/s)."""

    def __init__(self, name: str = "static") -> None:
        self.name = name
        self.track: List[Tuple[float, ...]] = []
        self.times: List[float] = []  # the track's times, for bisection
        if name.startswith("file:"):
            self.track = _read_track(name[5:])
            self.times = [row[0] for row in self.track]
        elif name not in ("static", "circle"):
            raise ValueError(f"unknown scenario {name!r} (expected static, circle or file:PATH)")

    def truth(self, t: float) -> Tuple[Vec, Vec, Vec, Vec, Vec]:
        if self.name == "circle":
            radius, speed = 50.0, 5.0
            w = speed / radius
            a = w * t
            pos = (radius * math.sin(a), radius * (1.0 - math.cos(a)), 0.0)
            vel = (speed * math.cos(a), speed * math.sin(a), 0.0)
            acc = (-speed * w * math.sin(a), speed * w * math.cos(a), 0.0)
            yaw = math.atan2(math.sin(a), math.cos(a))
            return pos, vel, acc, (0.0, 0.0, yaw), (0.0, 0.0, w)
        if self.track:
            return self._from_track(t)
        return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, math.radians(30.0)), (0.0, 0.0, 0.0)

    def _from_track(self, t: float) -> Tuple[Vec, Vec, Vec, Vec, Vec]:
        def at(s: float) -> Tuple[Vec, Vec]:
            tr = self.track
            s = min(max(s, tr[0][0]), tr[-1][0])
            i = max(0, min(len(tr) - 2, bisect.bisect_left(self.times, s, 1) - 1))
            a, b = tr[i], tr[min(i + 1, len(tr) - 1)]
            f = 0.0 if b[0] == a[0] else (s - a[0]) / (b[0] - a[0])
            row = [a[k] + f * (b[k] - a[k]) for k in range(7)]
            lat0 = math.radians(ORIGIN[0])
            north = math.radians(row[1] - ORIGIN[0]) * EARTH_RADIUS
            east = math.radians(row[2] - ORIGIN[1]) * EARTH_RADIUS * math.cos(lat0)
            return (north, east, ORIGIN[2] - row[3]), (math.radians(row[4]), math.radians(row[5]), math.radians(row[6]))

        h = 0.05
        (p0, e0), (p1, e1), (p2, _) = at(t - h), at(t), at(t + h)
        vel = tuple((p2[k] - p0[k]) / (2 * h) for k in range(3))
        acc = tuple((p2[k] - 2 * p1[k] + p0[k]) / (h * h) for k in range(3))
        rate = tuple((e1[k] - e0[k]) / h for k in range(3))
        return p1, vel, acc, e1, rate  # type: ignore[return-value]

    def truth_many(self, ts: Any) -> Tuple[Any, Any, Any, Any, Any]:
        """`truth` at many times at once (a numpy array `ts`): arrays of shape (N, 3), the same
        formulas element by element (the batch path of the fleet generator, fleet_batch.py).
        A trajectory file has no batch form: NotImplementedError (the caller takes `truth`)."""
        import numpy as np

        n = len(ts)
        if self.name == "circle":
            radius, speed = 50.0, 5.0
            w = speed / radius
            a = w * ts
            sin, cos = np.sin(a), np.cos(a)
            zero = np.zeros(n)
            pos = np.stack([radius * sin, radius * (1.0 - cos), zero], axis=1)
            vel = np.stack([speed * cos, speed * sin, zero], axis=1)
            acc = np.stack([-speed * w * sin, speed * w * cos, zero], axis=1)
            euler = np.stack([zero, zero, np.arctan2(sin, cos)], axis=1)
            rate = np.tile([0.0, 0.0, w], (n, 1))
            return pos, vel, acc, euler, rate
        if self.track:
            raise NotImplementedError("a trajectory file has no batch form")
        still = np.zeros((n, 3))
        return still, still, still, np.tile([0.0, 0.0, math.radians(30.0)], (n, 1)), still


MAX_TRACK_BYTES = 16 << 20  # a trajectory file is read no further than 16 MiB


def _read_track(path: str) -> List[Tuple[float, ...]]:
    """The rows of a trajectory file: finite numbers, times increasing, latitude -90..90 and
    longitude -180..180 degrees, at most MAX_TRACK_BYTES (a larger or endless file, such as
    /dev/zero, is refused without reading it whole); ValueError names the file and line."""
    try:
        with open(path, "rb") as f:
            data = f.read(MAX_TRACK_BYTES + 1)
    except OSError as e:
        raise ValueError(f"cannot read scenario {path}: {e.strerror or e}") from None
    if len(data) > MAX_TRACK_BYTES:
        raise ValueError(f"{path}: larger than {MAX_TRACK_BYTES >> 20} MiB (the most a trajectory file holds)")
    rows: List[Tuple[float, ...]] = []
    for n, raw in enumerate(data.split(b"\n"), 1):
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError:
            raise ValueError(f"{path}:{n}: not UTF-8 text") from None
        line = text.split("#")[0].replace(",", " ").strip()
        if not line:
            continue
        parts = line.split()
        try:
            values = tuple(float(p) for p in parts)
        except ValueError:
            raise ValueError(f"{path}:{n}: expected numbers t lat lon height roll pitch yaw") from None
        if len(values) != 7:
            raise ValueError(f"{path}:{n}: expected 7 numbers (t lat lon height roll pitch yaw), got {len(values)}")
        if not all(math.isfinite(v) for v in values):
            raise ValueError(f"{path}:{n}: expected finite numbers (no nan or inf)")
        if not (-90.0 <= values[1] <= 90.0 and -180.0 <= values[2] <= 180.0):
            raise ValueError(f"{path}:{n}: expected latitude -90..90 and longitude -180..180 degrees")
        if rows and values[0] <= rows[-1][0]:
            raise ValueError(f"{path}:{n}: times must increase")
        rows.append(values)
    if len(rows) < 2:
        raise ValueError(f"{path}: a trajectory needs at least two lines")
    return rows


class NavFilter:
    """The navigation filter's state machine. `profile` (generated `_sim.FILTER`) names the
    device's states, what aids it, its status flag masks and its internal aiding:

    - "gnss" (GX5-45: its internal receiver): startup, then initialization until the attitude is
      known (set by a command, or auto-initialization from an available heading source of the
      heading update control) and the receiver has a fix, then running; running with a solution
      error while the fix is lost.
    - "external" (CV7: aiding measurement control): initialization, vertical gyro after the IMU
      settles, AHRS with an absolute heading (external heading, the internal magnetometer or the
      dual-antenna heading), full navigation with heading, position and velocity (external, or
      the internal receivers); back a mode when a source has been silent for TIMEOUT.

    The World feeds the internal sources (`internal`, `heading_sources`) each sample, and sets
    `anomaly` (the magnetometer in use reads a field the model does not explain) and `in_use`."""

    TIMEOUT = 2.0  # seconds without a measurement before the filter stops using it
    SETTLE = 1.0  # seconds of IMU data before the first mode

    def __init__(self, profile: Dict[str, Any]) -> None:
        self.profile = profile
        self.flags: Dict[str, int] = dict(profile.get("flags") or {})
        self.auto_init = bool(profile.get("auto_init", True))
        self.wait_for_run = False
        self.internal: List[str] = []  # enabled internal aiding sources (CV7 aiding measurement control)
        self.heading_sources: List[str] = []  # enabled heading update sources (GX5-45 heading update control)
        self.antennas_ok = False  # both receivers' antenna offsets configured, apart (dual-antenna heading)
        self.anomaly = False
        self.in_use: List[str] = []
        self.reset(0.0)

    def reset(self, t: float) -> None:
        self.started = t
        self.accepted: Dict[str, float] = {}  # aiding kind -> last simulated time accepted
        self.attitude_set = False
        self.running = False
        self.run_command = False
        self.offsets: Dict[str, Tuple[float, ...]] = {}  # output - truth the aiding left (NED m, m/s; rad)
        self.mode_since = t
        self.last_state = ""
        self.turned = 0.0  # rad the velocity vector has turned with a fix (no heading aid: note 3)
        self.turn_t: Optional[float] = None  # when the turn was last sampled

    def accept(self, kind: str, t: float) -> None:
        self.accepted[kind] = t

    def _fresh(self, kind: str, t: float) -> bool:
        last = self.accepted.get(kind)
        return last is not None and t - last <= self.TIMEOUT

    def state(self, t: float, gnss_fix: bool) -> Tuple[str, int]:
        """(state name of the device's enum, status flags) at simulated time t."""
        names: List[str] = list(self.profile["states"])
        bit = self.flags.get
        if self.profile.get("aiding") == "gnss":
            heading = bool(self.in_use) or not self.profile.get("heading")  # no heading control: any
            attitude = self.attitude_set or (self.auto_init and heading)
            if t - self.started < 0.5:
                name, flags = names[0], bit("no_attitude", 0) | bit("no_position_velocity", 0)
            elif not self.running and not (attitude and gnss_fix):
                flags = (0 if attitude else bit("no_attitude", 0)) | (0 if gnss_fix else bit("no_position_velocity", 0))
                name = names[1]
            else:
                self.running = True
                name, flags = (names[2], 0) if gnss_fix else (names[3], bit("gnss_unavailable", 0))
                if self.anomaly:
                    flags |= bit("magnetic_anomaly", 0)
        else:
            heading = self._fresh("heading", t)
            posvel = self._fresh("position", t) and self._fresh("velocity", t)
            if t - self.started < self.SETTLE or (self.wait_for_run and not self.run_command):
                name = names[0]
            elif heading and posvel:
                name = names[3]
            elif heading:
                name = names[2]
            else:
                name = names[1]
            flags = 0
            if name != names[0]:
                if self.anomaly:
                    flags |= bit("heading_warning", 0)
                if name == names[3] and "gnss" in self.internal and not gnss_fix:  # coasting on the IMU
                    flags |= bit("position_warning", 0) | bit("velocity_warning", 0)
        if name != self.last_state:
            self.mode_since = t
            self.last_state = name
        if self.profile.get("aiding") != "gnss" and name != names[0]:
            mask = bit("condition", 3)
            shift = (mask & -mask).bit_length() - 1
            flags |= (1 if t - self.mode_since > 1.0 else 2) << shift  # stable / converging
        return name, flags

    def valid(self, name: str, kind: str) -> bool:
        """Whether an output of `kind` ("attitude", "navigation", "any") is valid in state `name`."""
        names: List[str] = list(self.profile["states"])
        if self.profile.get("aiding") == "gnss":
            return bool(name == names[2])
        if kind == "navigation":
            return bool(name == names[3])
        return bool(name != names[0])


class World:
    """The scenario, the sensors' view of it and the filter: `quantities(t)` at simulated time t."""

    def __init__(self, scenario: str = "static", seed: int = 0, profile: Optional[Dict[str, Any]] = None) -> None:
        self.scenario = Scenario(scenario)
        self.rng = random.Random(seed ^ 0x5EED)
        self.gyro_bias: Vec = tuple(self.rng.gauss(0.0, 0.002) for _ in range(3))  # type: ignore[assignment]
        self.captured_bias: Vec = (0.0, 0.0, 0.0)
        self.filter = NavFilter(
            profile or {"aiding": "gnss", "states": ["startup", "init", "run_solution_valid", "run_solution_error"]}
        )
        self.gnss_outages: List[Tuple[float, float]] = []
        self.mag_disturbances: List[Tuple[float, float]] = []
        self.rtk_corrections: List[Tuple[float, float]] = []  # when RTK corrections reach the receivers
        self.gps_start: Tuple[int, float] = (GPS_WEEK, GPS_TOW0)  # GPS week and time of week at t = 0 (--start-utc)

    def capture_gyro_bias(self) -> Vec:
        """The bias a capture measures (the true bias plus a little noise); the gyro output is
        compensated by it from then on."""
        self.captured_bias = tuple(b + self.rng.gauss(0.0, 1e-5) for b in self.gyro_bias)  # type: ignore[assignment]
        return self.captured_bias

    def aid(self, kind: str, t: float, values: Sequence[float], measured: Optional[float] = None) -> None:
        """An accepted aiding measurement arriving at simulated time t, taken at `measured` (its
        internal reference timestamp; default its arrival): the filter uses it, and its outputs
        move halfway toward it (the offset of the measurement from the truth then, weighted)."""
        self.filter.accept(kind, t)
        pos, vel, _, euler, _ = self.scenario.truth(t if measured is None else measured)
        if kind == "heading" and len(values) == 1:
            self.filter.offsets["heading"] = (0.5 * _wrap(values[0] - euler[2]),)
        elif kind == "position" and len(values) == 3:
            lat0 = math.radians(ORIGIN[0])
            north = math.radians(values[0] - ORIGIN[0]) * EARTH_RADIUS
            east = math.radians(values[1] - ORIGIN[1]) * EARTH_RADIUS * math.cos(lat0)
            ned = (north, east, ORIGIN[2] - values[2])
            self.filter.offsets["position"] = tuple(0.5 * (ned[k] - pos[k]) for k in range(3))
        elif kind == "velocity" and len(values) == 3:
            self.filter.offsets["velocity"] = tuple(0.5 * (values[k] - vel[k]) for k in range(3))

    def gnss_fix(self, t: float) -> bool:
        return t >= GNSS_FIX_AFTER and not any(a <= t < b for a, b in self.gnss_outages)

    def rtk(self, t: float) -> str:
        """The receivers' RTK solution at t: "" (none: no fix, or no corrections), "float" or
        "fixed", by how long corrections and a fix have both lasted without a break."""
        if not self.gnss_fix(t):
            return ""
        flowing = [a for a, b in self.rtk_corrections if a <= t < b]
        if not flowing:
            return ""
        since = max([GNSS_FIX_AFTER, min(flowing)] + [b for _, b in self.gnss_outages if b <= t])
        held = t - since
        return "fixed" if held >= RTK_FIXED_AFTER else "float" if held >= RTK_FLOAT_AFTER else ""

    def mag_disturbed(self, t: float) -> bool:
        return any(a <= t < b for a, b in self.mag_disturbances)

    def _turn_observes(self, t: float, fix: bool, vel: Vec, acc: Vec) -> bool:
        """With no heading aid (the heading profile's `without_aids`, GX5-45 Heading Update
        Control note 3): whether the velocity vector's turn observes the heading at t. While the
        receiver has a fix and the horizontal velocity (from min_speed) turns at turn_rate or more,
        the turn adds up; from converge_turn in all, each such sample observes the heading. While
        the filter runs and the velocity vector does not turn, the heading drifts at `drift`
        (rad/s)."""
        nav = self.filter
        rule = (nav.profile.get("heading") or {}).get("without_aids")
        if not rule or nav.heading_sources:
            return False
        dt = 0.0 if nav.turn_t is None else max(0.0, t - nav.turn_t)
        nav.turn_t = t if nav.turn_t is None else max(t, nav.turn_t)
        speed2 = vel[0] * vel[0] + vel[1] * vel[1]
        rate = abs(vel[0] * acc[1] - vel[1] * acc[0]) / speed2 if speed2 >= rule["min_speed"] ** 2 else 0.0
        turning = fix and rate >= rule["turn_rate"]
        if turning:
            nav.turned += rate * dt
            return bool(nav.turned >= rule["converge_turn"])
        if nav.running and dt:
            old = nav.offsets.get("heading", (0.0,))[0]
            nav.offsets["heading"] = (_wrap(old + rule["drift"] * dt),)
        return False

    def _aid_internal(
        self,
        t: float,
        fix: bool,
        pos: Vec,
        vel: Vec,
        yaw: float,
        mag: Vec,
        euler: Vec,
        gnss: Tuple[Vec, Vec],
        acc: Vec = (0.0, 0.0, 0.0),
    ) -> Dict[str, Any]:
        """The device's own sensors aiding the filter at t (the sources its settings enable): the
        magnetometer heading (rejected while the field's magnitude is off the model's), the
        dual-antenna heading (both receivers fixed, antenna offsets configured), the GNSS
        velocity vector as heading (moving at KINEMATIC_SPEED or more), the receivers' position
        and velocity. Each sample pulls the filter's outputs INTERNAL_GAIN of the way toward the
        measurement (a low-pass: the receivers' noise is smoothed). Returns the dual-antenna
        quantities."""
        nav = self.filter
        speed = math.hypot(vel[0], vel[1])
        mag_heading = _mag_heading(mag, euler[0], euler[1])
        anomaly = abs(math.sqrt(sum(m * m for m in mag)) / _MAG_NORM - 1.0) > MAG_ANOMALY
        dual = fix and nav.antennas_ok
        dual_heading = _wrap(yaw + self.rng.gauss(0.0, 0.003))
        available = {
            "magnetometer": not anomaly,
            "dual_antenna": dual,
            "gnss_velocity": fix and speed >= KINEMATIC_SPEED,
            "gnss": fix,
            "pressure": True,
            "external": nav._fresh("external", t),
        }
        headings = {
            "magnetometer": mag_heading,
            "dual_antenna": dual_heading,
            "gnss_velocity": math.atan2(vel[1], vel[0]),
        }
        enabled = list(dict.fromkeys(list(nav.internal) + list(nav.heading_sources)))
        nav.in_use = [s for s in enabled if available.get(s)]
        g = INTERNAL_GAIN
        if self._turn_observes(t, fix, vel, acc):  # no heading aid: the velocity vector's turn
            nav.in_use.append(TURN)
            headings[TURN] = yaw + self.rng.gauss(0.0, 0.003)

        def blend(kind: str, error: Sequence[float]) -> None:
            old = nav.offsets.get(kind, (0.0,) * len(error))
            nav.offsets[kind] = tuple((1.0 - g) * old[k] + g * error[k] for k in range(len(error)))

        for source in nav.in_use:
            if source in headings:
                nav.accept("heading", t)
                blend("heading", (_wrap(headings[source] - yaw),))
            elif source == "gnss":
                nav.accept("position", t)
                nav.accept("velocity", t)
                blend("position", [gnss[0][k] - pos[k] for k in range(3)])
                blend("velocity", [gnss[1][k] - vel[k] for k in range(3)])
        nav.anomaly = anomaly and "magnetometer" in enabled
        return {"dual": dual, "dual_heading": dual_heading, "dual_valid": dual and "dual_antenna" in nav.internal}

    def quantities(self, t: float) -> Dict[str, Any]:
        """Every quantity at simulated time t, in SI units (rad, m, m/s, m/s^2, gauss, mbar, s)."""
        n = self.rng.gauss
        pos, vel, acc, euler, rate = self.scenario.truth(t)
        roll, pitch, yaw = euler
        c = _rot(roll, pitch, yaw)
        mag = _to_body(c, MAG_NED)
        if self.mag_disturbed(t):
            mag = tuple(mag[k] + MAG_DISTURBANCE[k] for k in range(3))  # type: ignore[assignment]
        mag = tuple(m + n(0.0, 1e-4) for m in mag)  # type: ignore[assignment]
        fix = self.gnss_fix(t)
        rtk = self.filter.profile.get("rtk") or {}
        solution = self.rtk(t) if rtk else ""
        sigma = rtk["uncertainty"][solution] if solution else 0.5  # the receivers' horizontal 1 sigma (m)
        gnss_err = (n(0.0, sigma), n(0.0, sigma), n(0.0, 1.6 * sigma))
        gnss_pos = tuple(pos[k] + gnss_err[k] for k in range(3))
        gnss_vel = tuple(v + n(0.0, 0.05) for v in vel)
        dual = self._aid_internal(t, fix, pos, vel, yaw, mag, euler, (gnss_pos, gnss_vel), acc)  # type: ignore[arg-type]
        offsets = self.filter.offsets
        out_pos = [pos[k] + offsets.get("position", (0.0, 0.0, 0.0))[k] for k in range(3)]
        out_vel = [vel[k] + offsets.get("velocity", (0.0, 0.0, 0.0))[k] for k in range(3)]
        out_yaw = yaw + offsets.get("heading", (0.0,))[0]
        lat0 = math.radians(ORIGIN[0])
        lat = ORIGIN[0] + math.degrees(pos[0] / EARTH_RADIUS)
        lon = ORIGIN[1] + math.degrees(pos[1] / (EARTH_RADIUS * math.cos(lat0)))
        height = ORIGIN[2] - pos[2]
        force = _to_body(c, (acc[0], acc[1], acc[2] - GRAVITY))
        gyro = tuple(rate[k] + self.gyro_bias[k] - self.captured_bias[k] for k in range(3))
        cy, sy, cp, sp, cr, sr = (
            math.cos(yaw / 2),
            math.sin(yaw / 2),
            math.cos(pitch / 2),
            math.sin(pitch / 2),
            math.cos(roll / 2),
            math.sin(roll / 2),
        )
        quat = (
            cr * cp * cy + sr * sp * sy,
            sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy,
        )
        state, flags = self.filter.state(t, fix)
        week, tow = self.gps_start[0], self.gps_start[1] + t
        if tow >= 604800.0:  # a later week (a start near the week's end, a long run)
            week, tow = week + int(tow // 604800.0), tow % 604800.0
        unix = (GPS_EPOCH_DAYS * 86400.0) + week * 604800.0 + tow - LEAP_SECONDS
        days, secs = divmod(unix, 86400.0)
        y, mo, d = _civil(int(days))
        rlat, rlon = math.radians(lat), math.radians(lon)
        r = EARTH_RADIUS + height
        ecef = (r * math.cos(rlat) * math.cos(rlon), r * math.cos(rlat) * math.sin(rlon), r * math.sin(rlat))
        nav_err = 0.05
        nav = self.filter
        dual_roles = (nav.profile.get("dual_antenna") or {}).get("flags", {})
        dual_flags = (dual_roles.get("receiver_1", 0) | dual_roles.get("receiver_2", 0) if fix else 0) | (
            dual_roles.get("offsets", 0) if nav.antennas_ok else 0
        )
        dual_fix = (nav.profile.get("dual_antenna") or {}).get("fix", ["", ""])[0 if dual["dual"] else 1]
        in_use = (nav.profile.get("heading") or {}).get("in_use", {})
        gnss_aiding = "gnss" in nav.in_use
        status_roles = rtk.get("aiding_status", {})
        gnss_status = (0 if fix else status_roles.get("no_fix", 0)) | (
            (status_roles.get("corrections", 0) if solution else 0)
            | (status_roles.get("integer_fix", 0) if solution == "fixed" else 0)
            if gnss_aiding
            else 0
        )
        horizontal = sigma if solution else (rtk["uncertainty"]["single"] if rtk else 1.2)
        coasting = horizontal if gnss_aiding else 2.0 * (rtk or {}).get("uncertainty", {}).get("single", 0.0)
        fixes = nav.profile.get("fix")
        fix_type = {"fix_type": rtk["fix"][0 if solution == "float" else 1]} if solution else {}
        if fixes and not fix_type:
            fix_type = {"fix_type": fixes[0 if fix else 1]}
        speed = math.hypot(vel[0], vel[1])
        return {
            "specific_force": tuple(f + n(0.0, 0.002) for f in force),
            "angular_rate": tuple(g + n(0.0, 1e-4) for g in gyro),
            "true_angular_rate": rate,
            "magnetic_field": mag,
            "pressure": pressure_mbar(height) + n(0.0, 0.01),
            "temperature": 25.0 + n(0.0, 0.05),
            "gravity": GRAVITY,
            "gravity_body": _to_body(c, (0.0, 0.0, GRAVITY)),
            "linear_accel": _to_body(c, acc),
            "roll": roll + n(0.0, 1e-3),
            "pitch": pitch + n(0.0, 1e-3),
            "yaw": _wrap(yaw + n(0.0, 2e-3)),
            "nav_yaw": _wrap(out_yaw + n(0.0, 2e-3)),
            "quaternion": quat,
            "dcm": tuple(c[j][i] for i in range(3) for j in range(3)),  # NED-to-body, row-major
            "latitude": ORIGIN[0] + math.degrees((out_pos[0] + n(0.0, nav_err)) / EARTH_RADIUS),
            "longitude": ORIGIN[1] + math.degrees((out_pos[1] + n(0.0, nav_err)) / (EARTH_RADIUS * math.cos(lat0))),
            "height": ORIGIN[2] - out_pos[2] + n(0.0, nav_err),
            "velocity_ned": tuple(v + n(0.0, 0.01) for v in out_vel),
            "gnss_latitude": lat + math.degrees(gnss_err[0] / EARTH_RADIUS),
            "gnss_longitude": lon + math.degrees(gnss_err[1] / EARTH_RADIUS),
            "gnss_height": height + gnss_err[2],
            "gnss_velocity_ned": gnss_vel,
            "speed": speed,
            "course": math.atan2(vel[1], vel[0]) if speed > 0.1 else yaw,
            "ecef_position": ecef,
            "horizontal_accuracy": horizontal,
            "vertical_accuracy": 1.6 * horizontal if rtk else 2.0,
            "position_uncertainty": coasting if rtk and "gnss" in nav.internal else 0.3,
            "velocity_uncertainty": 0.05,
            "attitude_uncertainty": 0.005,
            "gps_tow": tow,
            "gps_week": week,
            "utc": (y, mo, d, int(secs // 3600), int(secs % 3600 // 60), int(secs % 60), int(secs * 1000 % 1000)),
            "gnss_fix": fix,
            **fix_type,
            "gnss_aiding_status": gnss_status,
            "num_sv": 14 if fix else 0,
            "filter_state": state,
            "filter_flags": flags,
            "filter_valid_attitude": self.filter.valid(state, "attitude"),
            "filter_valid_navigation": self.filter.valid(state, "navigation"),
            "gyro_bias": self.captured_bias,
            "dual_heading": dual["dual_heading"],
            "dual_heading_uncertainty": 0.003 if dual["dual"] else 0.0,
            "dual_fix": dual_fix,
            "dual_flags": dual_flags,
            "filter_valid_dual_antenna": dual["dual_valid"],
            "heading_sources": sum(in_use.get(s, 0) for s in nav.in_use),
            "filter_valid_heading_update": any(s in in_use for s in nav.in_use),
        }

    # ------------------------------------------------------------------ batch
    def batchable(self) -> bool:
        """Whether `batch` gives what `quantities` would: a static or circle scenario, no magnetic
        disturbance, no RTK corrections, no dual-antenna heading, at most one heading source and
        no heading from the velocity vector's turn (what the simulated fleet uses)."""
        nav = self.filter
        enabled = list(dict.fromkeys(list(nav.internal) + list(nav.heading_sources)))
        rule = (nav.profile.get("heading") or {}).get("without_aids")
        return (
            not self.scenario.track
            and not self.mag_disturbances
            and not self.rtk_corrections
            and not nav.antennas_ok
            and set(enabled) <= {"magnetometer", "gnss_velocity", "gnss", "pressure"}
            and len(set(enabled) & {"magnetometer", "gnss_velocity"}) <= 1
            and not (rule and not nav.heading_sources)
        )

    def batch(self, ts: Any, rng: Any) -> Dict[str, Any]:
        """The quantities of `quantities` a data stream of the simulated fleet shows, at the
        increasing simulated times `ts` (a numpy array) at once, when `batchable()`: the same
        formulas on arrays, the noise drawn from `rng` (a numpy Generator), the filter's aiding
        as `quantities` applies it each sample, its state from NavFilter itself, the state of
        every sample (runs of unchanged inputs bisected: _states_many).
        Arrays of shape (N,) or (N, 3); filter_state: the state names, an array of str."""
        import numpy as np

        n = len(ts)
        pos, vel, acc, euler, rate = self.scenario.truth_many(ts)
        c = _rot_many(euler[:, 0], euler[:, 1], euler[:, 2])
        mag = np.einsum("nij,i->nj", c, MAG_NED) + rng.normal(0.0, 1e-4, (n, 3))
        fix = ts >= GNSS_FIX_AFTER
        for a, b in self.gnss_outages:
            fix &= ~((ts >= a) & (ts < b))
        rtk = self.filter.profile.get("rtk") or {}
        sigma = 0.5  # no RTK solution: the receivers' horizontal 1 sigma (m), as in quantities
        gnss_err = rng.normal(0.0, 1.0, (n, 3)) * (sigma, sigma, 1.6 * sigma)
        gnss_vel = vel + rng.normal(0.0, 0.05, (n, 3))
        offsets = self._aid_many(ts, fix, pos, vel, euler[:, 2], mag, pos + gnss_err, gnss_vel)
        out_pos = pos + offsets["position"]
        lat0 = math.radians(ORIGIN[0])
        lat = ORIGIN[0] + np.degrees(pos[:, 0] / EARTH_RADIUS)
        lon = ORIGIN[1] + np.degrees(pos[:, 1] / (EARTH_RADIUS * math.cos(lat0)))
        height = ORIGIN[2] - pos[:, 2]
        force = np.einsum("nij,ni->nj", c, acc - (0.0, 0.0, GRAVITY))
        gyro = rate + np.subtract(self.gyro_bias, self.captured_bias)
        week, tow = self.gps_start[0] + np.zeros(n, dtype=np.int64), self.gps_start[1] + ts
        late = tow >= 604800.0
        week[late] += (tow[late] // 604800.0).astype(np.int64)
        tow[late] %= 604800.0
        horizontal = rtk["uncertainty"]["single"] if rtk else 1.2
        return {
            "specific_force": force + rng.normal(0.0, 0.002, (n, 3)),
            "angular_rate": gyro + rng.normal(0.0, 1e-4, (n, 3)),
            "magnetic_field": mag,
            "linear_accel": np.einsum("nij,ni->nj", c, acc),
            "latitude": ORIGIN[0] + np.degrees((out_pos[:, 0] + rng.normal(0.0, 0.05, n)) / EARTH_RADIUS),
            "longitude": ORIGIN[1]
            + np.degrees((out_pos[:, 1] + rng.normal(0.0, 0.05, n)) / (EARTH_RADIUS * math.cos(lat0))),
            "height": ORIGIN[2] - out_pos[:, 2] + rng.normal(0.0, 0.05, n),
            "velocity_ned": vel + offsets["velocity"] + rng.normal(0.0, 0.01, (n, 3)),
            "gnss_latitude": lat + np.degrees(gnss_err[:, 0] / EARTH_RADIUS),
            "gnss_longitude": lon + np.degrees(gnss_err[:, 1] / EARTH_RADIUS),
            "gnss_height": height + gnss_err[:, 2],
            "gnss_velocity_ned": gnss_vel,
            "horizontal_accuracy": np.full(n, horizontal),
            "vertical_accuracy": np.full(n, 1.6 * horizontal if rtk else 2.0),
            "gps_tow": tow,
            "gps_week": week,
            "gnss_fix": fix,
            "num_sv": np.where(fix, 14, 0),
            **offsets["filter"],
        }

    def _aid_many(self, ts: Any, fix: Any, pos: Any, vel: Any, yaw: Any, mag: Any, gnss_pos: Any, gnss_vel: Any) -> Any:
        """`_aid_internal` and the filter's state over `batch`'s samples: the offsets the aiding
        leaves (each sample in use pulls them INTERNAL_GAIN toward the measurement's error), and
        the filter's state, flags and valid outputs (NavFilter.state, called at every sample)."""
        import numpy as np

        nav = self.filter
        enabled = list(dict.fromkeys(list(nav.internal) + list(nav.heading_sources)))
        anomaly = np.abs(np.sqrt((mag * mag).sum(axis=1)) / _MAG_NORM - 1.0) > MAG_ANOMALY
        speed = np.hypot(vel[:, 0], vel[:, 1])
        available = {
            "magnetometer": ~anomaly,
            "gnss_velocity": fix & (speed >= KINEMATIC_SPEED),
            "gnss": fix,
            "pressure": np.ones(len(ts), dtype=bool),
        }
        use = {s: available[s] for s in enabled if s in available}
        heading = next((s for s in enabled if s in ("magnetometer", "gnss_velocity")), None)
        gnss = use.get("gnss", np.zeros(len(ts), dtype=bool))
        out = {
            "position": _blend_many(nav, "position", gnss, gnss_pos - pos),
            "velocity": _blend_many(nav, "velocity", gnss, gnss_vel - vel),
        }
        # (the heading offset shows only in nav_yaw, which batch does not give: left as it was)
        # which sources are in use at each sample (a bit each), whether the magnetometer's anomaly
        # is flagged, then the filter's state and flags through the runs of samples where neither
        # nor the fix changes (_states_many)
        codes = sum((u.astype(np.int64) << j for j, u in enumerate(use.values())), np.zeros(len(ts), dtype=np.int64))
        sources = list(use)
        bits = {"heading": 1 << sources.index(heading) if heading is not None else 0}
        bits["position"] = bits["velocity"] = 1 << sources.index("gnss") if "gnss" in use else 0
        flagged = anomaly & ("magnetometer" in enabled)
        changes = (np.diff(codes) != 0) | (np.diff(fix.astype(np.int8)) != 0) | (np.diff(flagged.astype(np.int8)) != 0)
        bounds = [0, *(np.flatnonzero(changes) + 1).tolist(), len(ts)]
        names: List[str] = []
        flag_list: List[int] = []
        tl = ts.tolist()
        for lo, hi in zip(bounds[:-1], bounds[1:]):
            code = int(codes[lo])
            nav.in_use = [s for j, s in enumerate(sources) if code >> j & 1]
            nav.anomaly = bool(flagged[lo])
            kinds = [k for k, b in bits.items() if code & b]
            _states_many(nav, tl[lo:hi], bool(fix[lo]), kinds, names, flag_list)
        flags = np.array(flag_list, dtype=np.int64)
        states = np.array(names)
        out["filter"] = {
            "filter_state": states,
            "filter_flags": flags,
            "filter_valid_attitude": _valid_many(nav, states, "attitude"),
            "filter_valid_navigation": _valid_many(nav, states, "navigation"),
        }
        return out


def _states_many(
    nav: NavFilter, ts: List[float], fix: bool, kinds: List[str], names: List[str], flags: List[int]
) -> None:
    """NavFilter.state at each time of `ts` (a run of samples where the fix, the sources in use
    and the anomaly hold; each sample re-accepts the measurements of `kinds`), appended to `names`
    and `flags`. While its inputs hold, the filter's state and flags change only as time passes
    thresholds (settling, a source going stale, a mode becoming stable), each once: so where the
    state at a later sample, computed on a copy of the filter, equals the state now, so is every
    sample between, and computing it on the filter leaves the filter as every sample would. The
    first sample whose state differs is found by galloping, then bisection, on copies; there the
    filter is advanced as the sample-by-sample path advances it."""

    def at(target: NavFilter, i: int) -> Tuple[str, int]:
        for kind in kinds:
            target.accepted[kind] = ts[i]
        return target.state(ts[i], fix)

    def probe(i: int) -> Tuple[str, int]:
        other = copy.copy(nav)
        other.accepted = dict(nav.accepted)
        return at(other, i)

    i, n = 0, len(ts)
    while i < n:
        now = at(nav, i)
        names.append(now[0])
        flags.append(now[1])
        same, step = i, 1  # `same`: the last sample known to have the state `now`
        while same + 1 < n:
            j = min(n - 1, same + step)
            if probe(j) != now:
                lo, hi = same, j  # the state changes after lo, at hi at the latest
                while hi - lo > 1:
                    mid = (lo + hi) // 2
                    lo, hi = (mid, hi) if probe(mid) == now else (lo, mid)
                same = lo
                break
            same, step = j, step * 2
        if same > i:
            at(nav, same)  # (the same state: the filter as after every sample up to `same`)
            names.extend([now[0]] * (same - i))
            flags.extend([now[1]] * (same - i))
        i = same + 1


def _valid_many(nav: NavFilter, states: Any, kind: str) -> Any:
    import numpy as np

    names, index = np.unique(states, return_inverse=True)
    return np.array([nav.valid(s, kind) for s in names.tolist()], dtype=bool)[index]


def _blend_many(nav: NavFilter, kind: str, mask: Any, error: Any) -> Any:
    """The offsets of `kind` after each sample when the samples where `mask` is set each pull them
    INTERNAL_GAIN toward `error` (`blend` in `_aid_internal`): an exponential average over those
    samples, held between them; computed in blocks of 64 (a lower-triangular matrix of powers of
    1 - INTERNAL_GAIN). Leaves nav.offsets[kind] at the last one."""
    import numpy as np

    n, width = error.shape
    g = INTERNAL_GAIN
    start = np.asarray(nav.offsets.get(kind, (0.0,) * width), dtype=float)
    idx = np.flatnonzero(mask)
    if not len(idx):
        return np.tile(start, (n, 1))
    e = error[idx]
    block = 64
    k = np.arange(block)
    weights = np.tril(g * (1.0 - g) ** (k[:, None] - k[None, :]))
    decay = (1.0 - g) ** (k + 1)
    blended = np.empty_like(e)
    prev = start
    for b in range(0, len(e), block):
        chunk = e[b : b + block]
        m = len(chunk)
        blended[b : b + m] = weights[:m, :m] @ chunk + decay[:m, None] * prev
        prev = blended[b + m - 1]
    nav.offsets[kind] = tuple(float(x) for x in prev)
    # each sample: the offsets after the last sample in use at or before it (the start before any)
    last = np.searchsorted(idx, np.arange(n), side="right") - 1
    return np.where(last[:, None] >= 0, blended[np.maximum(last, 0)], start)


def _rot_many(roll: Any, pitch: Any, yaw: Any) -> Any:
    """`_rot` of arrays of Euler angles: shape (N, 3, 3)."""
    import numpy as np

    cr, sr, cp, sp, cy, sy = np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw)
    return np.stack(
        [
            np.stack([cp * cy, sr * sp * cy - cr * sy, cr * sp * cy + sr * sy], axis=1),
            np.stack([cp * sy, sr * sp * sy + cr * cy, cr * sp * sy - sr * cy], axis=1),
            np.stack([-sp, sr * cp, cr * cp], axis=1),
        ],
        axis=1,
    )


_MAG_NORM = math.sqrt(sum(m * m for m in MAG_NED))


def gps_start_of_utc(text: str) -> Tuple[int, float]:
    """The GPS week and time of week of a UTC time `YYYY-MM-DDTHH:MM:SS[.fff][Z]` (--start-utc),
    LEAP_SECONDS after it; ValueError says what is wrong."""
    import datetime

    try:
        when = datetime.datetime.fromisoformat(text.strip().removesuffix("Z").removesuffix("z"))
    except ValueError:
        raise ValueError(f"--start-utc {text}: expected a UTC time YYYY-MM-DDTHH:MM:SS[Z]") from None
    if when.tzinfo is not None:
        raise ValueError(f"--start-utc {text}: give the time in UTC (with Z or no offset)")
    epoch = datetime.datetime(1970, 1, 1)
    unix = (when - epoch) / datetime.timedelta(seconds=1)
    gps = unix - GPS_EPOCH_DAYS * 86400.0 + LEAP_SECONDS
    if gps < 0:
        raise ValueError(f"--start-utc {text}: before the GPS epoch (1980-01-06)")
    week = int(gps // 604800.0)
    return week, gps - week * 604800.0


def _mag_heading(mag: Sequence[float], roll: float, pitch: float) -> float:
    """The true heading a body-frame field reading gives at a known roll and pitch: levelled, its
    horizontal direction from magnetic north, plus the model's declination."""
    c = _rot(roll, pitch, 0.0)  # body to the levelled (heading) frame
    x = c[0][0] * mag[0] + c[0][1] * mag[1] + c[0][2] * mag[2]
    y = c[1][0] * mag[0] + c[1][1] * mag[1] + c[1][2] * mag[2]
    return _wrap(math.atan2(-y, x) + math.atan2(MAG_NED[1], MAG_NED[0]))


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def _civil(days: int) -> Tuple[int, int, int]:
    """Year, month, day of a day count from 1970-01-01 (proleptic Gregorian)."""
    z = days + 719468
    era = z // 146097
    doe = z - era * 146097
    yoe = (doe - doe // 1460 + doe // 36524 - doe // 146096) // 365
    doy = doe - (365 * yoe + yoe // 4 - yoe // 100)
    mp = (5 * doy + 2) // 153
    d = doy - (153 * mp + 2) // 5 + 1
    m = mp + 3 if mp < 10 else mp - 9
    return yoe + era * 400 + (1 if m <= 2 else 0), m, d
