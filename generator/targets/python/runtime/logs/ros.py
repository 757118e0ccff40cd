"""ROS 2 messages of a log's data fields, without ROS installed (docs/mcap.md): the message
definitions (`ros2msg` schema text, by their ROS names), the little-endian CDR encoder, and the one
mapping table from MIP data fields to `sensor_msgs/msg/Imu`, `MagneticField`, `NavSatFix`,
`TimeReference` and `nav_msgs/msg/Odometry`.

**CDR** (OMG XCDR version 1, as ROS 2's rmw implementations write it): a 4-byte encapsulation
header `00 01 00 00` (CDR_LE), then the fields in definition order, each primitive aligned to its
own size (1, 2, 4, 8 bytes) counted from the end of the header; a string is a uint32 length that
counts its terminating NUL, its UTF-8 bytes and the NUL; a fixed array (`float64[9]`) its elements
only; a sequence (`T[]`) a uint32 count then its elements; a nested message its fields in place.

**Axes** (REP-103): the MIP sensor and vehicle frames are x forward, y right, z down; ROS body
frames are x forward, y left, z up: y and z are negated (a rotation of pi about x). Earth frames:
MIP's NED, ROS's ENU (REP-105's `odom`): east = NED y, north = NED x, up = -NED z.

**Units** come from the IR (`_columns`: the unit of each column): a column whose unit this table
does not know how to convert to SI is an error when the table is read, not a silent factor.
"""

from __future__ import annotations

import math
import struct
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

from .. import _columns

STANDARD_GRAVITY = 9.80665  # m/s^2 per g (the CGPM's standard value; the spec's accelerations are in g)
# unit (as the spec writes it) -> factor to SI
TO_SI: Dict[str, float] = {
    "g": STANDARD_GRAVITY,
    "rad/s": 1.0,
    "deg/s": math.pi / 180,
    "rad": 1.0,
    "gauss": 1e-4,  # tesla per gauss
    "deg": 1.0,  # NavSatFix keeps degrees
    "m": 1.0,
    "m/s": 1.0,
    "s": 1.0,
    "weeks": 1.0,
}

# ------------------------------------------------------------------------------ definitions
# ROS type -> its fields (type, name); the `.msg` text and the encoder both read this table.
PRIMITIVES: Dict[str, Tuple[str, int]] = {
    "bool": ("<B", 1),
    "int8": ("<b", 1),
    "uint8": ("<B", 1),
    "int16": ("<h", 2),
    "uint16": ("<H", 2),
    "int32": ("<i", 4),
    "uint32": ("<I", 4),
    "int64": ("<q", 8),
    "uint64": ("<Q", 8),
    "float32": ("<f", 4),
    "float64": ("<d", 8),
}
MESSAGES: Dict[str, List[Tuple[str, str]]] = {
    "builtin_interfaces/Time": [("int32", "sec"), ("uint32", "nanosec")],
    "std_msgs/Header": [("builtin_interfaces/Time", "stamp"), ("string", "frame_id")],
    "geometry_msgs/Vector3": [("float64", "x"), ("float64", "y"), ("float64", "z")],
    "geometry_msgs/Point": [("float64", "x"), ("float64", "y"), ("float64", "z")],
    "geometry_msgs/Quaternion": [("float64", "x"), ("float64", "y"), ("float64", "z"), ("float64", "w")],
    "geometry_msgs/Pose": [("geometry_msgs/Point", "position"), ("geometry_msgs/Quaternion", "orientation")],
    "geometry_msgs/PoseWithCovariance": [("geometry_msgs/Pose", "pose"), ("float64[36]", "covariance")],
    "geometry_msgs/Twist": [("geometry_msgs/Vector3", "linear"), ("geometry_msgs/Vector3", "angular")],
    "geometry_msgs/TwistWithCovariance": [("geometry_msgs/Twist", "twist"), ("float64[36]", "covariance")],
    "sensor_msgs/Imu": [
        ("std_msgs/Header", "header"),
        ("geometry_msgs/Quaternion", "orientation"),
        ("float64[9]", "orientation_covariance"),
        ("geometry_msgs/Vector3", "angular_velocity"),
        ("float64[9]", "angular_velocity_covariance"),
        ("geometry_msgs/Vector3", "linear_acceleration"),
        ("float64[9]", "linear_acceleration_covariance"),
    ],
    "sensor_msgs/MagneticField": [
        ("std_msgs/Header", "header"),
        ("geometry_msgs/Vector3", "magnetic_field"),
        ("float64[9]", "magnetic_field_covariance"),
    ],
    "sensor_msgs/NavSatStatus": [("int8", "status"), ("uint16", "service")],
    "sensor_msgs/NavSatFix": [
        ("std_msgs/Header", "header"),
        ("sensor_msgs/NavSatStatus", "status"),
        ("float64", "latitude"),
        ("float64", "longitude"),
        ("float64", "altitude"),
        ("float64[9]", "position_covariance"),
        ("uint8", "position_covariance_type"),
    ],
    "sensor_msgs/TimeReference": [
        ("std_msgs/Header", "header"),
        ("builtin_interfaces/Time", "time_ref"),
        ("string", "source"),
    ],
    "nav_msgs/Odometry": [
        ("std_msgs/Header", "header"),
        ("string", "child_frame_id"),
        ("geometry_msgs/PoseWithCovariance", "pose"),
        ("geometry_msgs/TwistWithCovariance", "twist"),
    ],
}
# constants of the definitions (part of the schema text, as ROS's .msg files state them)
CONSTANTS: Dict[str, List[str]] = {
    "sensor_msgs/NavSatStatus": [
        "int8 STATUS_NO_FIX = -1",
        "int8 STATUS_FIX = 0",
        "int8 STATUS_SBAS_FIX = 1",
        "int8 STATUS_GBAS_FIX = 2",
        "uint16 SERVICE_GPS = 1",
        "uint16 SERVICE_GLONASS = 2",
        "uint16 SERVICE_COMPASS = 4",
        "uint16 SERVICE_GALILEO = 8",
    ],
    "sensor_msgs/NavSatFix": [
        "uint8 COVARIANCE_TYPE_UNKNOWN = 0",
        "uint8 COVARIANCE_TYPE_APPROXIMATED = 1",
        "uint8 COVARIANCE_TYPE_DIAGONAL_KNOWN = 2",
        "uint8 COVARIANCE_TYPE_KNOWN = 3",
    ],
}
SEPARATOR = "=" * 80


def schema_name(ros_type: str) -> str:
    """The MCAP schema name of a ROS type: `sensor_msgs/msg/Imu`."""
    pkg, name = ros_type.split("/")
    return f"{pkg}/msg/{name}"


def _base(t: str) -> str:
    return t.split("[")[0]


def _deps(ros_type: str, seen: List[str]) -> List[str]:
    for t, _name in MESSAGES[ros_type]:
        b = _base(t)
        if b in MESSAGES and b not in seen:
            seen.append(b)
            _deps(b, seen)
    return seen


def _msg_text(ros_type: str) -> str:
    lines = CONSTANTS.get(ros_type, []) + [f"{t} {n}" for t, n in MESSAGES[ros_type]]
    return "\n".join(lines) + "\n"


def definition(ros_type: str) -> str:
    """The `ros2msg` schema text: the type's definition, then each type it uses once, after a
    line of 80 `=` and `MSG: pkg/Type` (the format `ros2 bag record` writes)."""
    out = _msg_text(ros_type)
    for dep in _deps(ros_type, []):
        out += f"{SEPARATOR}\nMSG: {dep}\n{_msg_text(dep)}"
    return out


# ------------------------------------------------------------------------------------ CDR
class Cdr:
    """A little-endian CDR writer (see the module's docstring for the rules)."""

    HEADER = b"\x00\x01\x00\x00"

    def __init__(self) -> None:
        self.buf = bytearray()

    def _align(self, n: int) -> None:
        pad = -len(self.buf) % n
        if pad:
            self.buf += b"\x00" * pad

    def primitive(self, t: str, v: Any) -> None:
        fmt, size = PRIMITIVES[t]
        self._align(size)
        self.buf += struct.pack(fmt, int(v) if fmt[1] not in "fd" else float(v))

    def string(self, s: str) -> None:
        data = s.encode("utf-8")
        self.primitive("uint32", len(data) + 1)
        self.buf += data + b"\x00"

    def value(self, t: str, v: Any) -> None:
        if "[" in t:
            base, count = t[:-1].split("[")
            if not count:
                self.primitive("uint32", len(v))
            elif len(v) != int(count):
                raise ValueError(f"{t}: {len(v)} elements")
            for x in v:
                self.value(base, x)
        elif t == "string":
            self.string(v)
        elif t in PRIMITIVES:
            self.primitive(t, v)
        else:
            for ft, name in MESSAGES[t]:
                self.value(ft, v[name])

    def bytes(self) -> bytes:
        return self.HEADER + bytes(self.buf)


def encode(ros_type: str, message: Dict[str, Any]) -> bytes:
    """The CDR bytes (with the encapsulation header) of a message given as nested dicts."""
    w = Cdr()
    w.value(ros_type, message)
    return w.bytes()


# ----------------------------------------------------------------------------- conversions
def stamp(t_ns: int) -> Dict[str, int]:
    sec, nanosec = divmod(t_ns, 1_000_000_000)
    return {"sec": sec, "nanosec": nanosec}


def header(t_ns: int, frame_id: str) -> Dict[str, Any]:
    return {"stamp": stamp(t_ns), "frame_id": frame_id}


def flu(v: Sequence[float]) -> Dict[str, float]:
    """A vector in a MIP body frame (x forward, y right, z down) in REP-103's (y left, z up)."""
    return {"x": v[0], "y": -v[1], "z": -v[2]}


def diag(values: Sequence[float], n: int) -> List[float]:
    out = [0.0] * (n * n)
    for i, v in enumerate(values):
        out[i * n + i] = v
    return out


def _mat(q: Sequence[float]) -> List[List[float]]:
    w, x, y, z = q
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]


def _quat(m: List[List[float]]) -> Tuple[float, float, float, float]:
    """(w, x, y, z) of a rotation matrix (Shepperd's method), w >= 0."""
    tr = m[0][0] + m[1][1] + m[2][2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        q = (0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s)
    elif m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2
        q = ((m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s)
    elif m[1][1] > m[2][2]:
        s = math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2
        q = ((m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s)
    else:
        s = math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2
        q = ((m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s)
    return q if q[0] >= 0 else (-q[0], -q[1], -q[2], -q[3])


ENU_FROM_NED = [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]]
FRD_FROM_FLU = [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]


def _mul(a: List[List[float]], b: List[List[float]]) -> List[List[float]]:
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def enu_orientation(q_ned: Sequence[float]) -> Dict[str, float]:
    """A MIP attitude quaternion (w, x, y, z; the vehicle's attitude in NED, so that yaw 90 deg,
    facing east, is (cos 45, 0, 0, sin 45)) as ROS's orientation of the FLU body in ENU:
    R_enu_flu = ENU_FROM_NED . R(q) . FRD_FROM_FLU (facing east is the identity)."""
    norm = math.sqrt(sum(c * c for c in q_ned)) or 1.0
    m = _mul(_mul(ENU_FROM_NED, _mat([c / norm for c in q_ned])), FRD_FROM_FLU)
    w, x, y, z = _quat(m)
    return {"x": x, "y": y, "z": z, "w": w}


def rotate_to_body(q_ned: Sequence[float], v_ned: Sequence[float]) -> Dict[str, float]:
    """An NED vector in the FLU body frame of the attitude q (R(q) maps FRD to NED)."""
    norm = math.sqrt(sum(c * c for c in q_ned)) or 1.0
    m = _mat([c / norm for c in q_ned])
    frd = [sum(m[k][i] * v_ned[k] for k in range(3)) for i in range(3)]
    return flu(frd)


WGS84_A = 6378137.0
WGS84_E2 = 6.69437999014e-3


def enu_offset(origin: Tuple[float, float, float], llh: Tuple[float, float, float]) -> Dict[str, float]:
    """East, north, up in metres of `llh` from `origin` (degrees, degrees, metres) on the local
    tangent plane of the origin (WGS 84 radii of curvature at its latitude: metres-accurate over
    kilometres, the range of an `odom` frame)."""
    lat0 = math.radians(origin[0])
    s = math.sin(lat0)
    n = WGS84_A / math.sqrt(1 - WGS84_E2 * s * s)  # prime vertical
    m = n * (1 - WGS84_E2) / (1 - WGS84_E2 * s * s)  # meridian
    return {
        "x": math.radians(llh[1] - origin[1]) * (n + origin[2]) * math.cos(lat0),
        "y": math.radians(llh[0] - origin[0]) * (m + origin[2]),
        "z": llh[2] - origin[2],
    }


# ------------------------------------------------------------------------------ the mapping
class Values:
    """The values of one packet's data fields as the CSV export gives them (column name -> cell,
    enum names as text), with the IR's unit of each column; `si(name)` in SI units."""

    def __init__(self) -> None:
        self.cells: Dict[str, Any] = {}
        self.units: Dict[str, Optional[str]] = {}
        self.frames: Dict[str, Optional[str]] = {}

    def add(self, key: Tuple[int, int, Optional[str]], cells: List[Any]) -> None:
        specs = _columns.COLUMNS.get(key, ())
        frames = _columns.FRAMES.get(key, (None,) * len(specs))
        for (name, _p, units, _k, _e), cell, frame in zip(specs, cells, frames):
            self.cells.setdefault(name, cell)
            self.units.setdefault(name, units)
            self.frames.setdefault(name, frame)

    def has(self, *names: str) -> bool:
        return all(isinstance(self.cells.get(n), (int, float)) for n in names)

    def si(self, name: str) -> float:
        units = self.units[name]
        if units is not None and units not in TO_SI:
            raise ValueError(f"{name}: no conversion of {units!r} to SI units")
        return float(self.cells[name]) * (TO_SI[units] if units else 1.0)

    def find(self, role: str) -> Optional[str]:
        """The column prefix of a vector `role` (VECTORS) this packet holds, else None."""
        for prefix in VECTORS[role]:
            if self.has(f"{prefix}.x", f"{prefix}.y", f"{prefix}.z"):
                return prefix
        return None

    def vec(self, prefix: str, parts: Sequence[str] = ("x", "y", "z")) -> List[float]:
        return [self.si(f"{prefix}.{p}") for p in parts]

    def frame(self, name: str, device: Optional[str]) -> Optional[str]:
        """The spec's frame of a column for the log's device (`device: frame; ...` texts)."""
        text = self.frames.get(name)
        if text is None or ":" not in text:
            return text
        for part in text.split(";"):
            dev, _, frame = part.strip().partition(":")
            if dev.strip() == device:
                return frame.strip()
        return None


class Topics:
    """Topic names and frame ids (docs/mcap.md; `--topic-prefix`, `--frame NAME=ID`)."""

    FRAMES = {"sensor": "imu_link", "vehicle": "base_link", "odom": "odom", "gnss": "gnss_link"}

    def __init__(self, prefix: str = "", frames: Optional[Dict[str, str]] = None) -> None:
        self.prefix = "/" + prefix.strip("/") if prefix.strip("/") else ""
        self.frames = dict(self.FRAMES)
        for name, value in (frames or {}).items():
            if name not in self.frames:
                raise ValueError(f"--frame: unknown frame {name!r} (one of {', '.join(self.FRAMES)})")
            self.frames[name] = value

    def topic(self, name: str) -> str:
        return f"{self.prefix}/{name}"

    def frame_id(self, spec_frame: Optional[str]) -> str:
        return self.frames["vehicle" if spec_frame == "vehicle" else "sensor"]


# The body-frame vectors of the messages: role -> the column prefixes that hold it (the MIP
# packages' `scaled_accel.x`, the MS-CIP packages' `scaled_accel.accel.x`; the spec's units)
VECTORS: Dict[str, Tuple[str, ...]] = {
    "accel": ("scaled_accel", "scaled_accel.accel"),
    "gyro": ("scaled_gyro", "scaled_gyro.gyro"),
    "mag": ("scaled_mag", "scaled_mag.mag"),
}

# MIP GNSS fix type names (the spec's enums) -> NavSatStatus.status
FIX_STATUS = {
    "fix_3d": 0,
    "fix_2d": 0,
    "fix_differential": 1,
    "fix_rtk_float": 2,
    "fix_rtk_fixed": 2,
}
NO_FIX = -1
# set names (registry.SET_NAMES) whose GNSS fields feed NavSatFix and TimeReference
GNSS_SETS = ("gnss_data", "gnss_receiver_1", "gnss_receiver_2")


Message = Tuple[str, str, Dict[str, Any]]  # topic, ROS type, the message as nested dicts


class Mapper:
    """The ROS messages of one packet: (log_time, (topic, ROS type, message dict)) for each message
    the mapping table makes of its fields, in log order. Stateful for Odometry (its `odom` origin:
    the first valid filter position) and for the Imu's orientation: the filter's attitude of the
    same sample (a filter packet with the same time, before or right after the sensor packet: the
    sample rule of `--join`), so an Imu waits for the next packet before it is given out (`flush`
    gives out the last one)."""

    def __init__(self, topics: Topics, device: Optional[str]) -> None:
        self.topics = topics
        self.device = device
        self.origin: Optional[Tuple[float, float, float]] = None
        self.attitude: Optional[Tuple[int, List[float]]] = None  # the last valid filter attitude (t_ns, q)
        self.held: Optional[Tuple[int, int, Message]] = None  # an Imu waiting: (t_ns, log_time, message)

    def messages(self, set_name: str, v: Values, t_ns: int, log_time: int) -> List[Tuple[int, Message]]:
        out: List[Tuple[int, Message]] = []
        if v.has("attitude_quaternion.q.w") and v.cells.get("attitude_quaternion.valid_flags") != 0:
            self.attitude = (t_ns, v.vec("attitude_quaternion.q", ("w", "x", "y", "z")))
        if self.held is not None and (self.held[0] != t_ns or self._matches(t_ns)):
            out += self.flush()
        for rule in RULES:
            got = rule(self, set_name, v, t_ns)
            if got is None:
                continue
            if got[1] == "sensor_msgs/Imu" and not self._orient(got, t_ns):
                out += self.flush()
                self.held = (t_ns, log_time, got)  # its sample's attitude may come next
                continue
            out.append((log_time, got))
        return out

    def flush(self) -> List[Tuple[int, Message]]:
        """The Imu held (with its sample's attitude if it has come)."""
        if self.held is None:
            return []
        t_ns, log_time, got = self.held
        self.held = None
        self._orient(got, t_ns)
        return [(log_time, got)]

    def _matches(self, t_ns: int) -> bool:
        return self.attitude is not None and self.attitude[0] == t_ns

    def _orient(self, got: Message, t_ns: int) -> bool:
        """The Imu's orientation from the filter attitude of its sample, if known (else as it is:
        none, orientation_covariance[0] = -1)."""
        msg = got[2]
        if msg["orientation_covariance"][0] != -1.0:
            return True
        if self.attitude is None or self.attitude[0] != t_ns:
            return False
        msg["orientation"] = enu_orientation(self.attitude[1])
        msg["orientation_covariance"] = [0.0] * 9  # an estimate, its covariance unknown
        return True

    def imu(self, set_name: str, v: Values, t_ns: int) -> Optional[Message]:
        accel, gyro = v.find("accel"), v.find("gyro")
        if accel is None or gyro is None:
            return None
        covariance_unknown = [0.0] * 9
        orientation = {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}  # none until its sample's attitude (_orient)
        orientation_cov = [-1.0] + [0.0] * 8  # sensor_msgs/Imu: no orientation estimate
        msg = {
            "header": header(t_ns, self.topics.frame_id(v.frame(f"{accel}.x", self.device))),
            "orientation": orientation,
            "orientation_covariance": orientation_cov,
            "angular_velocity": flu(v.vec(gyro)),
            "angular_velocity_covariance": covariance_unknown,
            "linear_acceleration": flu(v.vec(accel)),
            "linear_acceleration_covariance": covariance_unknown,
        }
        return self.topics.topic("imu/data"), "sensor_msgs/Imu", msg

    def mag(self, set_name: str, v: Values, t_ns: int) -> Optional[Message]:
        mag = v.find("mag")
        if mag is None:
            return None
        msg = {
            "header": header(t_ns, self.topics.frame_id(v.frame(f"{mag}.x", self.device))),
            "magnetic_field": flu(v.vec(mag)),
            "magnetic_field_covariance": [0.0] * 9,
        }
        return self.topics.topic("imu/mag"), "sensor_msgs/MagneticField", msg

    def navsatfix(self, set_name: str, v: Values, t_ns: int) -> Optional[Message]:
        if set_name not in GNSS_SETS or not v.has("llh_position.latitude", "llh_position.longitude"):
            return None
        status = 0
        fix = v.cells.get("fix_info.fix_type")
        if fix is not None:
            status = FIX_STATUS.get(str(fix), NO_FIX)
        if v.cells.get("llh_position.valid_flags") == 0:
            status = NO_FIX  # the device flags the position as not valid
        h = v.si("llh_position.horizontal_accuracy") if v.has("llh_position.horizontal_accuracy") else None
        vert = v.si("llh_position.vertical_accuracy") if v.has("llh_position.vertical_accuracy") else None
        known = h is not None and vert is not None
        msg = {
            "header": header(t_ns, self.topics.frames["gnss"]),
            "status": {"status": status, "service": 1},
            "latitude": v.si("llh_position.latitude"),
            "longitude": v.si("llh_position.longitude"),
            "altitude": v.si("llh_position.ellipsoid_height"),
            "position_covariance": diag([h * h, h * h, vert * vert], 3) if known else [0.0] * 9,  # type: ignore[operator]
            "position_covariance_type": 1 if known else 0,  # APPROXIMATED: one horizontal accuracy for east and north
        }
        return self.topics.topic(f"{set_name}/fix"), "sensor_msgs/NavSatFix", msg

    def time_reference(self, set_name: str, v: Values, t_ns: int) -> Optional[Message]:
        if set_name not in GNSS_SETS or not v.has("gps_time.tow", "gps_time.week_number"):
            return None
        gps_ns = v.cells["gps_time.week_number"] * 604_800 * 1_000_000_000 + round(v.si("gps_time.tow") * 1e9)
        msg = {"header": header(t_ns, self.topics.frames["gnss"]), "time_ref": stamp(gps_ns), "source": "gps"}
        return self.topics.topic(f"{set_name}/time_reference"), "sensor_msgs/TimeReference", msg

    def odometry(self, set_name: str, v: Values, t_ns: int) -> Optional[Message]:
        if set_name != "filter_data" or not v.has("llh_position.latitude", "llh_position.longitude"):
            return None
        if v.cells.get("llh_position.valid_flags") == 0:
            return None  # the filter's position is not valid (yet): no pose, and not the odom origin
        llh = (v.si("llh_position.latitude"), v.si("llh_position.longitude"), v.si("llh_position.ellipsoid_height"))
        if self.origin is None:
            self.origin = llh
        have_q = v.has("attitude_quaternion.q.w")
        q = v.vec("attitude_quaternion.q", ("w", "x", "y", "z")) if have_q else None
        pose_cov = [0.0] * 36
        if v.has("llh_position_uncertainty.north"):
            n, e, d = v.vec("llh_position_uncertainty", ("north", "east", "down"))
            pose_cov = diag([e * e, n * n, d * d], 6)
        if q is None:
            pose_cov[21] = -1.0  # orientation unknown (first element of its 3x3 block)
        twist_cov = [0.0] * 36
        linear = {"x": 0.0, "y": 0.0, "z": 0.0}
        if q is not None and v.has("ned_velocity.north"):
            linear = rotate_to_body(q, v.vec("ned_velocity", ("north", "east", "down")))
        else:
            twist_cov[0] = -1.0  # velocity in the body frame unknown
        msg = {
            "header": header(t_ns, self.topics.frames["odom"]),
            "child_frame_id": self.topics.frames["vehicle"],
            "pose": {
                "pose": {
                    "position": enu_offset(self.origin, llh),
                    "orientation": enu_orientation(q) if q else {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0},
                },
                "covariance": pose_cov,
            },
            "twist": {"twist": {"linear": linear, "angular": {"x": 0.0, "y": 0.0, "z": 0.0}}, "covariance": twist_cov},
        }
        return self.topics.topic("odometry/filtered"), "nav_msgs/Odometry", msg


Rule = Callable[[Mapper, str, Values, int], Optional[Message]]
# The mapping table: each rule makes at most one message of a packet's values.
RULES: Tuple[Rule, ...] = (Mapper.imu, Mapper.mag, Mapper.navsatfix, Mapper.time_reference, Mapper.odometry)

__all__ = ["MESSAGES", "Cdr", "encode", "definition", "schema_name", "Mapper", "Topics", "Values", "STANDARD_GRAVITY"]
