"""GNSS External Data Set (descriptor set 0x94, data).

Data of an external GNSS receiver whose NMEA sentences are fed to the device, re-emitted as MIP
fields. A parameter the NMEA input does not supply has its valid flag cleared; the timestamps are
those of the NMEA sentences. Sent as the data is received (base rate 0).
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class LlhPosition(_c.Field):
    """GNSS LLH position (set 0x94, descriptor 0x03, data).

    External receiver position in the WGS84 geodetic frame (latitude, longitude, heights) with
    accuracy estimates.

    Sources: 3dm-cv7-ins-docs.txt line 4830. Field data: 42 bytes.
    """

    latitude: float = 0.0  # Latitude (WGS84). [deg]
    longitude: float = 0.0  # Longitude (WGS84). [deg]
    ellipsoid_height: float = 0.0  # Height above the WGS84 ellipsoid. [m]
    msl_height: float = 0.0  # Height above mean sea level. [m]
    horizontal_accuracy: float = 0.0  # Horizontal position accuracy estimate. [m]
    vertical_accuracy: float = 0.0  # Vertical position accuracy estimate. [m]
    valid_flags: _t.GnssLlhPositionValidFlags = _t.GnssLlhPositionValidFlags(0)  # Which values are valid.

    SET = 0x94
    DESCRIPTOR = 0x03
    NAME = "llh_position"
    ROLE = "data"
    _ATTRS = (
        "latitude",
        "longitude",
        "ellipsoid_height",
        "msl_height",
        "horizontal_accuracy",
        "vertical_accuracy",
        "valid_flags",
    )
    _OPS = (
        _c.Run(
            _c.P("latitude", _c.F64),
            _c.P("longitude", _c.F64),
            _c.P("ellipsoid_height", _c.F64),
            _c.P("msl_height", _c.F64),
            _c.P("horizontal_accuracy", _c.F32),
            _c.P("vertical_accuracy", _c.F32),
            _c.P("valid_flags", _c.flags(_t.GnssLlhPositionValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class NedVelocity(_c.Field):
    """GNSS NED velocity (set 0x94, descriptor 0x05, data).

    External receiver velocity in the north-east-down frame, with 3D and ground speed, heading and
    accuracy estimates.

    Sources: 3dm-cv7-ins-docs.txt line 4856; 3dm-cv7-ins-docs.txt line 572. Field data: 34 bytes.
    """

    velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (north, east, down) velocity. [m/s]
    speed: float = 0.0  # 3D speed. [m/s]
    ground_speed: float = 0.0  # Horizontal (ground) speed. [m/s]
    heading: float = 0.0  # Heading (direction of travel). [deg]
    speed_accuracy: float = 0.0  # Speed accuracy estimate. [m/s]
    heading_accuracy: float = 0.0  # Heading accuracy estimate. [deg]
    valid_flags: _t.GnssNedVelocityValidFlags = _t.GnssNedVelocityValidFlags(0)  # Which values are valid.

    SET = 0x94
    DESCRIPTOR = 0x05
    NAME = "ned_velocity"
    ROLE = "data"
    _ATTRS = ("velocity", "speed", "ground_speed", "heading", "speed_accuracy", "heading_accuracy", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("velocity", _c.F32, 3),
            _c.P("speed", _c.F32),
            _c.P("ground_speed", _c.F32),
            _c.P("heading", _c.F32),
            _c.P("speed_accuracy", _c.F32),
            _c.P("heading_accuracy", _c.F32),
            _c.P("valid_flags", _c.flags(_t.GnssNedVelocityValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class UtcTime(_c.Field):
    """GNSS UTC time (set 0x94, descriptor 0x08, data).

    UTC date and time from the external receiver, with a flag telling whether the leap seconds are
    known.

    Sources: 3dm-cv7-ins-docs.txt line 4885. Field data: 13 bytes.
    """

    year: int = 0  # Year.
    month: int = 0  # Month (1-12).
    day: int = 0  # Day of the month (1-31).
    hour: int = 0  # Hour (0-23).
    minute: int = 0  # Minute (0-59).
    second: int = 0  # Second (0-59).
    millisecond: int = 0  # Millisecond (0-999). [ms]
    # Validity of the date/time and of the leap seconds.
    valid_flags: _t.GnssUtcTimeValidFlagsCv7 = _t.GnssUtcTimeValidFlagsCv7(0)

    SET = 0x94
    DESCRIPTOR = 0x08
    NAME = "utc_time"
    ROLE = "data"
    _ATTRS = ("year", "month", "day", "hour", "minute", "second", "millisecond", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("year", _c.U16),
            _c.P("month", _c.U8),
            _c.P("day", _c.U8),
            _c.P("hour", _c.U8),
            _c.P("minute", _c.U8),
            _c.P("second", _c.U8),
            _c.P("millisecond", _c.U32),
            _c.P("valid_flags", _c.flags(_t.GnssUtcTimeValidFlagsCv7)),
        ),
    )


@_c.slotted
@_dc.dataclass
class FixInfo(_c.Field):
    """GNSS fix information (set 0x94, descriptor 0x0B, data).

    Fix type, number of satellites used and corrections applied, from the external receiver.

    Sources: 3dm-cv7-ins-docs.txt line 4910; 3dm-cv7-ins-docs.txt line 669. Field data: 6 bytes.
    """

    fix_type: _ty.Union[_t.GnssFixTypeCv7, int] = _t.GnssFixTypeCv7.FIX_3D  # Type of fix.
    num_sv: int = 0  # Number of satellites used in the solution.
    fix_flags: _t.GnssFixFlags = _t.GnssFixFlags(0)  # Corrections used.
    valid_flags: _t.GnssFixInfoValidFlags = _t.GnssFixInfoValidFlags(0)  # Which values are valid.

    SET = 0x94
    DESCRIPTOR = 0x0B
    NAME = "fix_info"
    ROLE = "data"
    _ATTRS = ("fix_type", "num_sv", "fix_flags", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("fix_type", _c.enum(_t.GnssFixTypeCv7, "u8")),
            _c.P("num_sv", _c.U8),
            _c.P("fix_flags", _c.flags(_t.GnssFixFlags)),
            _c.P("valid_flags", _c.flags(_t.GnssFixInfoValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class SatelliteStatus(_c.Field):
    """Satellite status (set 0x94, descriptor 0x20, data).

    Sky position and health of one satellite reported by the external receiver; one field per
    satellite.

    Sources: 3dm-cv7-ins-docs.txt line 4943. Field data: 25 bytes.
    """

    index: int = 0  # Index of this field among the satellite status fields of this epoch.
    count: int = 0  # Number of satellite status fields in this epoch.
    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number since 1980. [weeks]
    gnss_id: _ty.Union[_t.GnssConstellationId, int] = _t.GnssConstellationId.UNKNOWN  # Constellation of the satellite.
    satellite_id: int = 0  # Satellite number within its constellation.
    elevation: float = 0.0  # Elevation of the satellite seen from the receiver. [deg]
    azimuth: float = 0.0  # Azimuth of the satellite seen from the receiver. [deg]
    health: bool = False  # True if the satellite is healthy.
    valid_flags: _t.GnssSatelliteStatusValidFlags = _t.GnssSatelliteStatusValidFlags(0)  # Which parameters are valid.

    SET = 0x94
    DESCRIPTOR = 0x20
    NAME = "satellite_status"
    ROLE = "data"
    _ATTRS = (
        "index",
        "count",
        "tow",
        "week_number",
        "gnss_id",
        "satellite_id",
        "elevation",
        "azimuth",
        "health",
        "valid_flags",
    )
    _OPS = (
        _c.Run(
            _c.P("index", _c.U8),
            _c.P("count", _c.U8),
            _c.P("tow", _c.F64),
            _c.P("week_number", _c.U16),
            _c.P("gnss_id", _c.enum(_t.GnssConstellationId, "u8")),
            _c.P("satellite_id", _c.U8),
            _c.P("elevation", _c.F32),
            _c.P("azimuth", _c.F32),
            _c.P("health", _c.BOOL),
            _c.P("valid_flags", _c.flags(_t.GnssSatelliteStatusValidFlags)),
        ),
    )


FIELDS: tuple[type[_c.Field], ...] = (LlhPosition, NedVelocity, UtcTime, FixInfo, SatelliteStatus)
