"""NMEA-0183 out and in of the simulated device (docs/simulator-world.md "NMEA"; spec simulation
`nmea`, generated into `_sim.NMEA`): the sentences its NMEA message format asks for, built from the
simulated world at their source data set's ticks and written whole between MIP packets, the rate
limits and bad entries NACKed; and the NMEA sentences a host interleaves with MIP on the main
port, grouped into updates by their timestamps and mirrored into the external GNSS data set.

The manual gives the sentences, talker IDs, sources, rate limits and the proprietary PMSRA/PMSRR
layouts; the rest of each sentence is NMEA-0183. Every choice the manual leaves open is a note of
the spec's `simulation.nmea` (listed in docs/errata.md).
"""

from __future__ import annotations

import datetime
import math
from functools import reduce
from typing import Any, Dict, List, Optional, Tuple

from .. import _session, _sim, registry
from ..codec.framing import PacketBuilder
from .world import GPS_EPOCH_DAYS, GRAVITY, LEAP_SECONDS

Chunk = Tuple[float, bytes]
LATE_WINDOW = 1.0  # seconds of real time: older sentences are dropped, as the MIP data are
KNOTS = 1852.0 / 3600.0  # m/s in a knot
HDOP = 0.9  # the GGA horizontal dilution of precision (the world has no satellite geometry)
GSV_SYSTEMS = (("GP", 8), ("GA", 6))  # the receiver's satellites in view: GPS and Galileo
# GGA fix quality (NMEA-0183) <-> the fix type members of the external data set
QUALITY_FIX = {0: "fix_none", 1: "fix_3d", 2: "fix_differential", 4: "fix_rtk_fixed", 5: "fix_rtk_float"}
# The sentences of an update that carry its timestamp (field index of hhmmss.ss)
STAMPED = {"GGA": 1, "GLL": 5, "RMC": 1, "ZDA": 1}
# Filter-sourced sentences that need the attitude (the others need the navigation solution)
ATTITUDE_SENTENCES = ("HDT", "PMSRA")
EPOCH = datetime.date(1970, 1, 1)


def checksum(body: str) -> int:
    """The NMEA-0183 checksum: the XOR of the characters between '$' and '*'."""
    return reduce(lambda a, b: a ^ b, body.encode("ascii"), 0)


def sentence(body: str) -> bytes:
    """A whole sentence: '$', the body, '*', two upper-case hex digits, CR LF."""
    return f"${body}*{checksum(body):02X}\r\n".encode("ascii")


def split(data: bytes) -> Optional[List[str]]:
    """The fields of a sentence (address first), None when it is not one with a good checksum."""
    text = data.decode("ascii", "replace").strip()
    if len(text) < 4 or text[0] not in "$!" or text[-3] != "*":
        return None
    body = text[1:-3]
    try:
        if int(text[-2:], 16) != checksum(body):
            return None
    except ValueError:
        return None
    return body.split(",")


def _utc(q: Dict[str, Any]) -> Tuple[Tuple[int, int, int], str]:
    """The date (year, month, day) and the time hhmmss.ss of the world's GPS time, in UTC (the
    GPS time less the leap seconds), rounded to the hundredth of a second the sentences carry."""
    unix = GPS_EPOCH_DAYS * 86400.0 + q["gps_week"] * 604800.0 + q["gps_tow"] - LEAP_SECONDS
    centis = round(unix * 100.0)
    days, rest = divmod(centis, 8640000)
    seconds, hundredths = divmod(rest, 100)
    hms = f"{seconds // 3600:02d}{seconds % 3600 // 60:02d}{seconds % 60:02d}.{hundredths:02d}"
    day = EPOCH + datetime.timedelta(days=int(days))
    return (day.year, day.month, day.day), hms


def _angle(value: float, degrees_digits: int, hemispheres: str) -> str:
    """ddmm.mmmmm (latitude, 2 digits) or dddmm.mmmmm (longitude, 3), and its hemisphere."""
    a = abs(value)
    d = int(a)
    m = round((a - d) * 60.0, 5)
    if m >= 60.0:
        d, m = d + 1, 0.0
    return f"{d:0{degrees_digits}d}{m:08.5f},{hemispheres[0] if value >= 0 else hemispheres[1]}"


def _degrees(field: str, hemisphere: str) -> Optional[float]:
    """A latitude or longitude field of NMEA (ddmm.mmm / dddmm.mmm) in signed degrees."""
    if not field or "." not in field:
        return None
    cut = field.index(".") - 2
    try:
        value = float(field[:cut] or 0) + float(field[cut:]) / 60.0
    except ValueError:
        return None
    return -value if hemisphere in ("S", "W") else value


def _float(field: str) -> Optional[float]:
    try:
        return float(field) if field else None
    except ValueError:
        return None


class NmeaPort:
    """The NMEA side of the simulated device's port (one per Simulator)."""

    def __init__(self, sim: Any) -> None:
        self.sim = sim
        self.ticks: Dict[int, int] = {}  # entry index -> last tick sent
        self.format: Any = None  # the format setting the ticks belong to
        self.updates: List[Dict[str, Any]] = []  # NMEA input: updates received, oldest first
        self.received = 0  # sentences of the input accepted (its statistics)

    # ------------------------------------------------------------------------------ output
    def origin(self, set_id: int) -> Optional[str]:
        for kind, (sets, _) in _sim.NMEA.get("origins", {}).items():
            if set_id in sets:
                return str(kind)
        return None

    def refuse(self, command: Any) -> Optional[int]:
        """The NACK code refusing a format write or a poll with a bad entry (None: accepted): an
        unknown sentence or talker, a source not applicable, a rate above its source's limit."""
        role = _sim.NMEA_COMMANDS.get(type(command))
        if role is None:
            return None
        kind, attr = role
        fn = getattr(command, "function", None)
        if kind == "format" and fn is not None and int(fn) not in (_function("write"), _function("write_no_ack")):
            return None
        table = _sim.NMEA
        listed = getattr(command, attr, None) or []
        if kind == "poll" and not listed and not self.entries():
            return int(table["nack"])  # no format given and none stored (line 6796)
        for entry in listed:
            if self.entry_error(entry, kind == "poll") is not None:
                return int(table["nack"])
        return None

    def entry_error(self, entry: Any, poll: bool = False) -> Optional[str]:
        """Why an NmeaMessage entry is refused (None: it is accepted)."""
        table = _sim.NMEA
        roles = table["entry"]
        code = int(getattr(entry, roles["sentence"]))
        talker = int(getattr(entry, roles["talker"]))
        set_id = int(getattr(entry, roles["source"]))
        decimation = int(getattr(entry, roles["decimation"]))
        known = table["sentences"].get(code)
        if known is None:
            return f"sentence code {code} unknown"
        name, configurable, sources = known
        if configurable and talker not in table["talkers"]:
            return f"talker code {talker} unknown"
        if not configurable and talker != 0:
            return f"{name} has no talker ID to choose"
        kind = self.origin(set_id)
        if kind not in sources:
            return f"{name} cannot come from data set 0x{set_id:02X}"
        if poll:
            return None
        rate = self.sim.base_rates.get(set_id, 0)
        if decimation == 0 or not rate:
            return f"{name}: no rate (decimation {decimation}, base rate {rate} Hz)"
        if rate / decimation > table["origins"][kind][1]:
            return f"{name}: {rate / decimation:g} Hz above {table['origins'][kind][1]:g} Hz"
        return None

    def entries(self) -> List[Tuple[int, int, int, int]]:
        """(sentence, talker, source set, decimation) of the current NMEA message format."""
        value = None
        for v in self.sim.current.values():
            if _sim.NMEA_COMMANDS.get(type(v), ("",))[0] == "format":
                value = v
        if value is not self.format:
            self.format, self.ticks = value, {}
        if value is None:
            return []
        return [self._entry(e) for e in getattr(value, _sim.NMEA_COMMANDS[type(value)][1], None) or []]

    def _entry(self, e: Any) -> Tuple[int, int, int, int]:
        roles = _sim.NMEA["entry"]
        return tuple(int(getattr(e, roles[k])) for k in ("sentence", "talker", "source", "decimation"))  # type: ignore[return-value]

    def poll(self, now: float) -> List[Chunk]:
        """The sentences due by `now`, each at its tick's time (an idle device sends none)."""
        sim = self.sim
        entries = self.entries()
        if not entries:
            return []
        sim_now = sim.sim_time(now)
        out: List[Chunk] = []
        for i, (code, talker, set_id, dec) in enumerate(entries):
            rate = sim.base_rates.get(set_id, 0)
            if not rate or dec <= 0:
                continue
            tick_now = int(sim_now * rate)
            last = self.ticks.get(i, tick_now - 1)
            self.ticks[i] = tick_now
            if sim.idle or tick_now <= last:
                continue
            first = max(last + 1, tick_now - max(1, int(rate * sim.speed * LATE_WINDOW)) + 1)
            for tick in range(-(-first // dec) * dec, tick_now + 1, dec):
                t = sim.start_time + tick / rate / sim.speed
                out.extend((t, s) for s in self.build(code, talker, set_id, tick / rate))
        out.sort(key=lambda c: c[0])
        return out

    def next_wakeup(self) -> Optional[float]:
        sim = self.sim
        if sim.start_time is None:
            return None
        due = [
            sim.start_time + (self.ticks.get(i, 0) + 1) / sim.base_rates[s] / sim.speed
            for i, (_, _, s, d) in enumerate(self.entries())
            if sim.base_rates.get(s) and d > 0
        ]
        return min(due) if due else None

    def poll_command(self, command: Any, now: float) -> List[Chunk]:
        """Poll NMEA Data: each listed sentence once, else those of the stored format (line 1072)."""
        role = _sim.NMEA_COMMANDS.get(type(command))
        if role is None or role[0] != "poll":
            return []
        listed = [self._entry(e) for e in getattr(command, role[1], None) or []] or self.entries()
        elapsed = self.sim.sim_time(now)
        return [
            (now + 0.001, s) for code, talker, set_id, _ in listed for s in self.build(code, talker, set_id, elapsed)
        ]

    def build(self, code: int, talker: int, set_id: int, elapsed: float) -> List[bytes]:
        """The sentences of one entry at simulated time `elapsed` ([] while its data is invalid)."""
        known = _sim.NMEA["sentences"].get(code)
        kind = self.origin(set_id)
        if known is None or kind is None:
            return []
        name = known[0]
        q = self.sim.world_at(elapsed)  # the world of the MIP data of the same tick
        if kind == "gnss" and not q["gnss_fix"]:
            return []
        if kind == "gnss" and name == "HDT" and not q["dual_heading_uncertainty"]:
            return []  # no dual-antenna heading: both receivers fixed, the antenna offsets set
        if kind == "filter" and not q["filter_valid_" + ("attitude" if name in ATTITUDE_SENTENCES else "navigation")]:
            return []
        prefix = _sim.NMEA["talkers"].get(talker, "GN")
        return [
            sentence(b) for b in _bodies(name, prefix, kind, q, self.sim.world.rtk(elapsed) if kind == "gnss" else "")
        ]

    # ------------------------------------------------------------------------------ input
    def receive(self, data: bytes, now: float) -> List[Chunk]:
        """An NMEA sentence from the host (the parser's Nmea event): grouped into updates by its
        timestamp; the external data set's packet of each update once the next has begun."""
        table = _sim.NMEA.get("input")
        fields = split(data)
        if table is None or fields is None or len(fields[0]) < 3:
            return []
        name = fields[0][-3:]  # the talker ID is ignored (line 1084)
        if name not in table["sentences"]:
            return []
        self.received += 1
        stamp = fields[STAMPED[name]] if name in STAMPED and len(fields) > STAMPED[name] else None
        if stamp and (not self.updates or self.updates[-1].get("stamp") not in (None, stamp)):
            self.updates.append({"stamp": stamp})
        elif not self.updates:
            self.updates.append({})
        update = self.updates[-1]
        update.setdefault("stamp", stamp or None)
        update[name] = fields
        out: List[Chunk] = []
        while len(self.updates) >= int(table["updates"]):
            out.extend((now, p) for p in self.mirror(self.updates.pop(0)))
        return out

    def mirror(self, update: Dict[str, Any]) -> List[bytes]:
        """The external data set's packet of one update (its formatted fields; none while it is
        not formatted or its stream is off)."""
        table = _sim.NMEA["input"]
        set_id = int(table["set"])
        descriptors = [d for d, _ in getattr(self.sim, "unpaced", {}).get(set_id, [])]
        if self.sim.idle or not descriptors:
            return []
        builder = PacketBuilder(set_id)
        added = 0
        for d in descriptors:
            classes = registry.lookup(set_id, d) or ()
            cls = next((c for c in classes if getattr(c, "DEVICE", None) in (None, self.sim.device)), None)
            if cls is None:
                continue
            value = cls()
            try:
                _fill(value, update)
            except (ValueError, IndexError):  # a field NMEA-0183 does not allow: what it gave, not valid
                pass
            try:
                builder.add_field(d, value.encode())
            except (TypeError, ValueError):
                continue
            added += 1
        return [builder.build()] if added else []


def _function(name: str) -> Optional[int]:
    """The value of a function selector by name (write, read, ...)."""
    return next((v for v, n in _session.FUNCTION_NAMES.items() if n == name), None)


def _bodies(name: str, talker: str, kind: str, q: Dict[str, Any], rtk: str) -> List[str]:
    """The sentence bodies (between '$' and '*') of `name` from the world's quantities."""
    utc, hms = _utc(q)
    gnss = kind == "gnss"
    lat = q["gnss_latitude" if gnss else "latitude"]
    lon = q["gnss_longitude" if gnss else "longitude"]
    height = q["gnss_height" if gnss else "height"]
    vel = q["gnss_velocity_ned" if gnss else "velocity_ned"]
    ground = math.hypot(vel[0], vel[1])
    course = math.degrees(q["course"] if gnss else math.atan2(vel[1], vel[0]) if ground > 0.1 else q["nav_yaw"]) % 360.0
    position = f"{_angle(lat, 2, 'NS')},{_angle(lon, 3, 'EW')}"
    date = f"{utc[2]:02d}{utc[1]:02d}{utc[0] % 100:02d}"  # ddmmyy
    if name == "GGA":
        quality = {"fixed": 4, "float": 5}.get(rtk, 1)
        sv = q["num_sv"] if gnss else 0
        return [f"{talker}GGA,{hms},{position},{quality},{sv:02d},{HDOP:.1f},{height:.3f},M,0.000,M,,"]
    if name == "GLL":
        return [f"{talker}GLL,{position},{hms},A,A"]
    if name == "RMC":
        return [f"{talker}RMC,{hms},A,{position},{ground / KNOTS:.3f},{course:.2f},{date},,,A"]
    if name == "VTG":
        return [f"{talker}VTG,{course:.2f},T,,M,{ground / KNOTS:.3f},N,{ground * 3.6:.3f},K,A"]
    if name == "HDT":
        heading = math.degrees(q["dual_heading"] if gnss else q["nav_yaw"]) % 360.0
        return [f"{talker}HDT,{heading:.2f},T"]
    if name == "ZDA":
        return [f"{talker}ZDA,{hms},{utc[2]:02d},{utc[1]:02d},{utc[0]:04d},00,00"]
    if name == "GST":
        h = q["horizontal_accuracy"] if gnss else q["position_uncertainty"]
        v = q["vertical_accuracy"] if gnss else q["position_uncertainty"]
        return [f"{talker}GST,{hms},{h:.3f},{h:.3f},{h:.3f},0.0,{h:.3f},{h:.3f},{v:.3f}"]
    if name == "GSV":
        return _gsv(int(q["num_sv"]))
    if name == "PMSRA":
        roll, pitch, yaw = (math.degrees(q[k]) for k in ("roll", "pitch", "nav_yaw"))
        return [f"PMSRA,{hms},{roll:.3f},{pitch:.3f},{yaw:.3f}"]
    if name == "PMSRR":
        accel = [a / GRAVITY for a in q["specific_force"]]
        gyro = [math.degrees(g) for g in q["angular_rate"]]  # rad/s in the world (RADIANS)
        return ["PMSRR," + hms + "," + ",".join(f"{x:.6f}" for x in accel + gyro)]
    return []


def _gsv(in_view: int) -> List[str]:
    """GSV groups of at most four satellites per sentence, per constellation (its own talker)."""
    out: List[str] = []
    left = in_view
    for system, most in GSV_SYSTEMS:
        n = min(left, most)
        left -= n
        if n == 0:
            continue
        sats = [(i + 1, 15 + (37 * i) % 70, (47 * i) % 360, 30 + (11 * i) % 20) for i in range(n)]
        total = -(-n // 4)
        for k in range(total):
            group = ",".join(f"{p:02d},{e:02d},{a:03d},{s:02d}" for p, e, a, s in sats[4 * k : 4 * k + 4])
            out.append(f"{system}GSV,{total},{k + 1},{n:02d},{group}")
    return out


def _flags(value: Any, names: List[str]) -> Any:
    """A valid flags bitfield of `value` with the named members set."""
    cls = type(value.valid_flags)
    return cls(sum(int(getattr(cls, n.upper())) for n in names))


def _fill(value: Any, update: Dict[str, Any]) -> None:
    """An external data field from one NMEA update (a parameter NMEA does not give: flag 0)."""
    gga, rmc, gll, vtg, zda = (update.get(k) for k in ("GGA", "RMC", "GLL", "VTG", "ZDA"))
    source: List[str] = []
    name = value.NAME
    stamp = update.get("stamp") or ""
    date = None
    if rmc and len(rmc) > 9 and len(rmc[9]) == 6:
        yy = int(rmc[9][4:6])  # two digits: 80-99 the 1900s (the GPS epoch is 1980), else the 2000s
        date = ((1900 if yy >= 80 else 2000) + yy, int(rmc[9][2:4]), int(rmc[9][0:2]))
    if zda and len(zda) > 4 and zda[4]:
        date = (int(zda[4]), int(zda[3]), int(zda[2]))
    when = _clock(stamp)
    if name == "llh_position":
        if gga is not None and int(_float(gga[6]) or 0) > 0:  # quality 0: no fix
            source, i = gga, 2
        elif rmc is not None and rmc[2] == "A":  # V: void
            source, i = rmc, 3
        elif gll is not None and len(gll) > 6 and gll[6] == "A":
            source, i = gll, 1
        else:
            return
        lat, lon = _degrees(source[i], source[i + 1]), _degrees(source[i + 2], source[i + 3])
        if lat is None or lon is None:
            return
        value.latitude, value.longitude = lat, lon
        flags = ["lat_lon"]
        msl = _float(source[9]) if source is gga else None
        if msl is not None:
            value.msl_height = msl
            flags.append("msl_height")
            separation = _float(source[11])
            if separation is not None:
                value.ellipsoid_height = msl + separation
                flags.append("ellipsoid_height")
        value.valid_flags = _flags(value, flags)
    elif name == "ned_velocity":
        speed = course = None
        if vtg is not None and len(vtg) > 7:  # VTG,course,T,course,M,knots,N,km/h,K
            course = _float(vtg[1])
            kmh, knots = _float(vtg[7]), _float(vtg[5])
            speed = kmh / 3.6 if kmh is not None else knots * KNOTS if knots is not None else None
        elif rmc is not None and rmc[2] == "A":
            knots, course = _float(rmc[7]), _float(rmc[8])
            speed = knots * KNOTS if knots is not None else None
        flags = []
        if speed is not None:
            value.ground_speed = speed
            flags.append("ground_speed")
        if course is not None:
            value.heading = course
            flags.append("heading")
        value.valid_flags = _flags(value, flags)
    elif name == "utc_time":
        if when is None or date is None:
            return
        value.year, value.month, value.day = date
        value.hour, value.minute, value.second, value.millisecond = when
        value.valid_flags = _flags(value, ["gnss_date_time"])
    elif name == "fix_info":
        if gga is None:
            return
        quality = int(_float(gga[6]) or 0)
        enum = type(value.fix_type)
        value.fix_type = getattr(enum, QUALITY_FIX.get(quality, "fix_invalid").upper())
        flags = ["fix_type"]
        if _float(gga[7]) is not None:
            value.num_sv = int(_float(gga[7]) or 0)
            flags.append("num_sv")
        value.valid_flags = _flags(value, flags)
    elif name == "gps_timestamp":
        if when is None or date is None:
            return
        days = _days(*date)
        gps = (
            (days - GPS_EPOCH_DAYS) * 86400.0
            + when[0] * 3600
            + when[1] * 60
            + when[2]
            + when[3] / 1000.0
            + LEAP_SECONDS
        )
        value.week_number, value.tow = int(gps // 604800.0), gps % 604800.0
        value.valid_flags = type(value.valid_flags)(int(type(value.valid_flags).TIME_VALID))


def _clock(stamp: str) -> Optional[Tuple[int, int, int, int]]:
    """hhmmss[.ss] as (hour, minute, second, millisecond)."""
    try:
        return int(stamp[0:2]), int(stamp[2:4]), int(stamp[4:6]), round(float("0" + stamp[6:]) * 1000)
    except (ValueError, IndexError):
        return None


def _days(year: int, month: int, day: int) -> int:
    """Days from 1970-01-01 to a civil date."""
    return (datetime.date(year, month, day) - EPOCH).days
