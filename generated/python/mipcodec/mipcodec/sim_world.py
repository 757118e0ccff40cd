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

import math
import random
from typing import Any, Dict, List, Optional, Sequence, Tuple

GRAVITY = 9.80665
EARTH_RADIUS = 6378137.0
ORIGIN = (46.5197, 6.6323, 372.0)  # latitude, longitude (deg), height above the ellipsoid (m)
MAG_NED = (0.2160, 0.0076, 0.4270)  # a fixed field model (gauss): near Lausanne, declination 2 deg
GPS_WEEK = 2400
GPS_TOW0 = 345600.0  # Wednesday 00:00 of week 2400
GPS_EPOCH_DAYS = 3657  # days from 1970-01-01 to the GPS epoch 1980-01-06
LEAP_SECONDS = 18
GNSS_FIX_AFTER = 2.0  # seconds of simulated time a receiver takes to a 3D fix

Vec = Tuple[float, float, float]
# Quantities in radians (every other angle, latitude and longitude, is in degrees)
RADIANS = frozenset(
    ("roll", "pitch", "yaw", "course", "angular_rate", "true_angular_rate", "gyro_bias", "attitude_uncertainty")
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
        if name.startswith("file:"):
            self.track = _read_track(name[5:])
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
            i = max(0, min(len(tr) - 2, next((k for k in range(len(tr) - 1) if tr[k + 1][0] >= s), len(tr) - 2)))
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


def _read_track(path: str) -> List[Tuple[float, ...]]:
    rows: List[Tuple[float, ...]] = []
    try:
        with open(path, encoding="utf-8") as f:
            for n, line in enumerate(f, 1):
                line = line.split("#")[0].replace(",", " ").strip()
                if not line:
                    continue
                parts = line.split()
                try:
                    values = tuple(float(p) for p in parts)
                except ValueError:
                    raise ValueError(f"{path}:{n}: expected numbers t lat lon height roll pitch yaw") from None
                if len(values) != 7:
                    raise ValueError(
                        f"{path}:{n}: expected 7 numbers (t lat lon height roll pitch yaw), got {len(values)}"
                    )
                if rows and values[0] <= rows[-1][0]:
                    raise ValueError(f"{path}:{n}: times must increase")
                rows.append(values)
    except OSError as e:
        raise ValueError(f"cannot read scenario {path}: {e.strerror or e}") from None
    if len(rows) < 2:
        raise ValueError(f"{path}: a trajectory needs at least two lines")
    return rows


class NavFilter:
    """The navigation filter's state machine. `profile` (generated `_sim.FILTER`) names the
    device's states and what aids it: "gnss" (internal receiver: init until a fix and an attitude,
    then running; back to error when the fix is lost) or "external" (CV7: init, vertical gyro
    after the IMU settles, AHRS with an accepted heading, full navigation with heading, position
    and velocity; back a mode when an aiding stream stops)."""

    TIMEOUT = 2.0  # seconds without a measurement before the filter stops using it
    SETTLE = 1.0  # seconds of IMU data before the first mode

    def __init__(self, profile: Dict[str, Any]) -> None:
        self.profile = profile
        self.auto_init = bool(profile.get("auto_init", True))
        self.wait_for_run = False
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

    def accept(self, kind: str, t: float) -> None:
        self.accepted[kind] = t

    def _fresh(self, kind: str, t: float) -> bool:
        last = self.accepted.get(kind)
        return last is not None and t - last <= self.TIMEOUT

    def state(self, t: float, gnss_fix: bool) -> Tuple[str, int]:
        """(state name of the device's enum, status flags) at simulated time t."""
        names: List[str] = list(self.profile["states"])
        if self.profile.get("aiding") == "gnss":
            attitude = self.auto_init or self.attitude_set
            if t - self.started < 0.5:
                name, flags = names[0], 0x3000
            elif not self.running and not (attitude and gnss_fix):
                name, flags = names[1], (0 if attitude else 0x1000) | (0 if gnss_fix else 0x2000)
            else:
                self.running = True
                name, flags = (names[2], 0) if gnss_fix else (names[3], 0x0002)  # 0x0002: GNSS unavailable
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
        if name != self.last_state:
            self.mode_since = t
            self.last_state = name
        if self.profile.get("aiding") != "gnss" and name != names[0]:
            flags |= 1 if t - self.mode_since > 1.0 else 2  # bits 0-1: stable / converging
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

    def quantities(self, t: float) -> Dict[str, Any]:
        """Every quantity at simulated time t, in SI units (rad, m, m/s, m/s^2, gauss, mbar, s)."""
        n = self.rng.gauss
        pos, vel, acc, euler, rate = self.scenario.truth(t)
        roll, pitch, yaw = euler
        offsets = self.filter.offsets
        out_pos = [pos[k] + offsets.get("position", (0.0, 0.0, 0.0))[k] for k in range(3)]
        out_vel = [vel[k] + offsets.get("velocity", (0.0, 0.0, 0.0))[k] for k in range(3)]
        out_yaw = yaw + offsets.get("heading", (0.0,))[0]
        c = _rot(roll, pitch, yaw)
        lat0 = math.radians(ORIGIN[0])
        lat = ORIGIN[0] + math.degrees(pos[0] / EARTH_RADIUS)
        lon = ORIGIN[1] + math.degrees(pos[1] / (EARTH_RADIUS * math.cos(lat0)))
        height = ORIGIN[2] - pos[2]
        force = _to_body(c, (acc[0], acc[1], acc[2] - GRAVITY))
        mag = _to_body(c, MAG_NED)
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
        fix = self.gnss_fix(t)
        state, flags = self.filter.state(t, fix)
        tow = GPS_TOW0 + t
        unix = (GPS_EPOCH_DAYS * 86400.0) + GPS_WEEK * 604800.0 + tow - LEAP_SECONDS
        days, secs = divmod(unix, 86400.0)
        y, mo, d = _civil(int(days))
        rlat, rlon = math.radians(lat), math.radians(lon)
        r = EARTH_RADIUS + height
        ecef = (r * math.cos(rlat) * math.cos(rlon), r * math.cos(rlat) * math.sin(rlon), r * math.sin(rlat))
        gnss_err = (n(0.0, 0.5), n(0.0, 0.5), n(0.0, 0.8))
        nav_err = 0.05
        speed = math.hypot(vel[0], vel[1])
        return {
            "specific_force": tuple(f + n(0.0, 0.002) for f in force),
            "angular_rate": tuple(g + n(0.0, 1e-4) for g in gyro),
            "true_angular_rate": rate,
            "magnetic_field": tuple(m + n(0.0, 1e-4) for m in mag),
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
            "gnss_velocity_ned": tuple(v + n(0.0, 0.05) for v in vel),
            "speed": speed,
            "course": math.atan2(vel[1], vel[0]) if speed > 0.1 else yaw,
            "ecef_position": ecef,
            "horizontal_accuracy": 1.2,
            "vertical_accuracy": 2.0,
            "position_uncertainty": 0.3,
            "velocity_uncertainty": 0.05,
            "attitude_uncertainty": 0.005,
            "gps_tow": tow,
            "gps_week": GPS_WEEK,
            "utc": (y, mo, d, int(secs // 3600), int(secs % 3600 // 60), int(secs % 60), int(secs * 1000 % 1000)),
            "gnss_fix": fix,
            "num_sv": 14 if fix else 0,
            "filter_state": state,
            "filter_flags": flags,
            "filter_valid_attitude": self.filter.valid(state, "attitude"),
            "filter_valid_navigation": self.filter.valid(state, "navigation"),
            "gyro_bias": self.captured_bias,
        }


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
