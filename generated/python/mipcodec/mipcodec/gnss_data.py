"""GNSS Data Set (descriptor set 0x81, data).

Data from the GX5-45's internal GNSS receiver: position, velocity, DOP, time, clock, fix, satellite,
hardware and DGNSS information.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class LlhPosition(_c.Field):
    """LLH position (set 0x81, descriptor 0x03, data).

    Receiver position in the geodetic frame (latitude, longitude, heights) with accuracy estimates.

    Sources: 3dm-gx5-45-dcp.txt line 2183; 3dm-gx5-45-dcp.txt line 689. Field data: 42 bytes.
    """

    latitude: float = 0.0  # Latitude (WGS84). [deg]
    longitude: float = 0.0  # Longitude (WGS84). [deg]
    ellipsoid_height: float = 0.0  # Height above the WGS84 ellipsoid. [m]
    msl_height: float = 0.0  # Height above mean sea level. [m]
    horizontal_accuracy: float = 0.0  # Horizontal position accuracy estimate. [m]
    vertical_accuracy: float = 0.0  # Vertical position accuracy estimate. [m]
    valid_flags: _t.GnssLlhPositionValidFlags = _t.GnssLlhPositionValidFlags(0)  # Which values are valid.

    SET = 0x81
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
class EcefPosition(_c.Field):
    """ECEF position (set 0x81, descriptor 0x04, data).

    Receiver position in the Earth-centred, Earth-fixed frame with its accuracy estimate.

    Sources: 3dm-gx5-45-dcp.txt line 2196; 3dm-gx5-45-dcp.txt line 690. Field data: 30 bytes.
    """

    position: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) ECEF position. [m]
    position_accuracy: float = 0.0  # Position accuracy estimate. [m]
    valid_flags: _t.GnssEcefPositionValidFlags = _t.GnssEcefPositionValidFlags(0)  # Which values are valid.

    SET = 0x81
    DESCRIPTOR = 0x04
    NAME = "ecef_position"
    ROLE = "data"
    _ATTRS = ("position", "position_accuracy", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("position", _c.F64, 3),
            _c.P("position_accuracy", _c.F32),
            _c.P("valid_flags", _c.flags(_t.GnssEcefPositionValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class NedVelocity(_c.Field):
    """NED velocity (set 0x81, descriptor 0x05, data).

    Receiver velocity in the north-east-down frame, with 3D and ground speed, heading and accuracy
    estimates.

    Sources: 3dm-gx5-45-dcp.txt line 2208; 3dm-gx5-45-dcp.txt line 691. Field data: 34 bytes.
    """

    velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (north, east, down) velocity. [m/s]
    speed: float = 0.0  # 3D speed. [m/s]
    ground_speed: float = 0.0  # Horizontal (ground) speed. [m/s]
    heading: float = 0.0  # Heading (direction of travel). [deg]
    speed_accuracy: float = 0.0  # Speed accuracy estimate. [m/s]
    heading_accuracy: float = 0.0  # Heading accuracy estimate. [deg]
    valid_flags: _t.GnssNedVelocityValidFlags = _t.GnssNedVelocityValidFlags(0)  # Which values are valid.

    SET = 0x81
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
class EcefVelocity(_c.Field):
    """ECEF velocity (set 0x81, descriptor 0x06, data).

    Receiver velocity in the Earth-centred, Earth-fixed frame with its accuracy estimate.

    Sources: 3dm-gx5-45-dcp.txt line 2226; 3dm-gx5-45-dcp.txt line 692. Field data: 18 bytes.
    """

    velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) ECEF velocity. [m/s]
    velocity_accuracy: float = 0.0  # Velocity accuracy estimate. [m/s]
    valid_flags: _t.GnssEcefVelocityValidFlags = _t.GnssEcefVelocityValidFlags(0)  # Which values are valid.

    SET = 0x81
    DESCRIPTOR = 0x06
    NAME = "ecef_velocity"
    ROLE = "data"
    _ATTRS = ("velocity", "velocity_accuracy", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("velocity", _c.F32, 3),
            _c.P("velocity_accuracy", _c.F32),
            _c.P("valid_flags", _c.flags(_t.GnssEcefVelocityValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class Dop(_c.Field):
    """DOP data (set 0x81, descriptor 0x07, data).

    Geometric, position, horizontal, vertical, time, northing and easting dilution of precision.

    Sources: 3dm-gx5-45-dcp.txt line 2238; 3dm-gx5-45-dcp.txt line 693. Field data: 30 bytes.
    """

    gdop: float = 0.0  # Geometric DOP.
    pdop: float = 0.0  # Position DOP.
    hdop: float = 0.0  # Horizontal DOP.
    vdop: float = 0.0  # Vertical DOP.
    tdop: float = 0.0  # Time DOP.
    ndop: float = 0.0  # Northing DOP.
    edop: float = 0.0  # Easting DOP.
    valid_flags: _t.GnssDopValidFlags = _t.GnssDopValidFlags(0)  # Which values are valid.

    SET = 0x81
    DESCRIPTOR = 0x07
    NAME = "dop"
    ROLE = "data"
    _ATTRS = ("gdop", "pdop", "hdop", "vdop", "tdop", "ndop", "edop", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("gdop", _c.F32),
            _c.P("pdop", _c.F32),
            _c.P("hdop", _c.F32),
            _c.P("vdop", _c.F32),
            _c.P("tdop", _c.F32),
            _c.P("ndop", _c.F32),
            _c.P("edop", _c.F32),
            _c.P("valid_flags", _c.flags(_t.GnssDopValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class UtcTime(_c.Field):
    """UTC time (set 0x81, descriptor 0x08, data).

    UTC date and time from the GNSS receiver, with separate date and time valid flags.

    Sources: 3dm-gx5-45-dcp.txt line 2255; 3dm-gx5-45-dcp.txt line 694. Field data: 13 bytes.
    """

    year: int = 0  # Year (1999-2099).
    month: int = 0  # Month (1-12).
    day: int = 0  # Day of the month (1-31).
    hour: int = 0  # Hour (0-23).
    minute: int = 0  # Minute (0-59).
    second: int = 0  # Second (0-59).
    millisecond: int = 0  # Millisecond. [ms]
    valid_flags: _t.GnssUtcTimeValidFlagsGx5 = _t.GnssUtcTimeValidFlagsGx5(0)  # Validity of the date and of the time.

    SET = 0x81
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
            _c.P("valid_flags", _c.flags(_t.GnssUtcTimeValidFlagsGx5)),
        ),
    )


@_c.slotted
@_dc.dataclass
class GpsTime(_c.Field):
    """GPS time (set 0x81, descriptor 0x09, data).

    GPS time of week and week number.

    Sources: 3dm-gx5-45-dcp.txt line 2269; 3dm-gx5-45-dcp.txt line 695. Field data: 12 bytes.
    """

    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number (since 1980). [weeks]
    valid_flags: _t.GnssGpsTimeValidFlags = _t.GnssGpsTimeValidFlags(0)  # Which values are valid.

    SET = 0x81
    DESCRIPTOR = 0x09
    NAME = "gps_time"
    ROLE = "data"
    _ATTRS = ("tow", "week_number", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("tow", _c.F64), _c.P("week_number", _c.U16), _c.P("valid_flags", _c.flags(_t.GnssGpsTimeValidFlags))
        ),
    )


@_c.slotted
@_dc.dataclass
class ClockInfo(_c.Field):
    """Clock information (set 0x81, descriptor 0x0A, data).

    GNSS receiver clock bias and drift, with an accuracy estimate.

    Sources: 3dm-gx5-45-dcp.txt line 2279; 3dm-gx5-45-dcp.txt line 696. Field data: 26 bytes.
    """

    bias: float = 0.0  # Receiver clock bias. [s]
    drift: float = 0.0  # Receiver clock drift. [s/s]
    accuracy_estimate: float = 0.0  # Clock accuracy estimate. [s]
    valid_flags: _t.GnssClockInfoValidFlags = _t.GnssClockInfoValidFlags(0)  # Which values are valid.

    SET = 0x81
    DESCRIPTOR = 0x0A
    NAME = "clock_info"
    ROLE = "data"
    _ATTRS = ("bias", "drift", "accuracy_estimate", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("bias", _c.F64),
            _c.P("drift", _c.F64),
            _c.P("accuracy_estimate", _c.F64),
            _c.P("valid_flags", _c.flags(_t.GnssClockInfoValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class FixInfo(_c.Field):
    """GNSS fix information (set 0x81, descriptor 0x0B, data).

    Fix type, number of satellites used and corrections applied.

    Sources: 3dm-gx5-45-dcp.txt line 2292; 3dm-gx5-45-dcp.txt line 697. Field data: 6 bytes.
    """

    fix_type: _ty.Union[_t.GnssFixTypeGx5, int] = _t.GnssFixTypeGx5.FIX_3D  # Type of fix.
    num_sv: int = 0  # Number of satellites used for the solution.
    fix_flags: _t.GnssFixFlags = _t.GnssFixFlags(0)  # Corrections used.
    valid_flags: _t.GnssFixInfoValidFlags = _t.GnssFixInfoValidFlags(0)  # Which values are valid.

    SET = 0x81
    DESCRIPTOR = 0x0B
    NAME = "fix_info"
    ROLE = "data"
    _ATTRS = ("fix_type", "num_sv", "fix_flags", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("fix_type", _c.enum(_t.GnssFixTypeGx5, "u8")),
            _c.P("num_sv", _c.U8),
            _c.P("fix_flags", _c.flags(_t.GnssFixFlags)),
            _c.P("valid_flags", _c.flags(_t.GnssFixInfoValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class SvInfo(_c.Field):
    """Space vehicle information (set 0x81, descriptor 0x0C, data).

    One entry per space vehicle: channel, SV id, carrier-to-noise ratio, azimuth, elevation and
    use/health flags. The entries arrive in a MIP packet of their own, separate from the other GNSS
    fields, one field per vehicle.

    Sources: 3dm-gx5-45-dcp.txt line 2304; 3dm-gx5-45-dcp.txt line 698. Field data: 12 bytes.
    """

    channel: int = 0  # Receiver channel number.
    sv_id: int = 0  # Space vehicle id number.
    carrier_to_noise_ratio: int = 0  # Carrier to noise ratio. [dBHz]
    azimuth: int = 0  # Azimuth, whole degrees. [deg]
    elevation: int = 0  # Elevation, whole degrees. [deg]
    sv_flags: _t.GnssSvFlags = _t.GnssSvFlags(0)  # Use and health of the vehicle.
    valid_flags: _t.GnssSvInfoValidFlags = _t.GnssSvInfoValidFlags(0)  # Which values are valid.

    SET = 0x81
    DESCRIPTOR = 0x0C
    NAME = "sv_info"
    ROLE = "data"
    _ATTRS = ("channel", "sv_id", "carrier_to_noise_ratio", "azimuth", "elevation", "sv_flags", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("channel", _c.U8),
            _c.P("sv_id", _c.U8),
            _c.P("carrier_to_noise_ratio", _c.U16),
            _c.P("azimuth", _c.S16),
            _c.P("elevation", _c.S16),
            _c.P("sv_flags", _c.flags(_t.GnssSvFlags)),
            _c.P("valid_flags", _c.flags(_t.GnssSvInfoValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class HardwareStatus(_c.Field):
    """Hardware status (set 0x81, descriptor 0x0D, data).

    Receiver (sensor) power state, antenna connection state and antenna power. Only produced at 1
    Hz; higher rates have no effect.

    Sources: 3dm-gx5-45-dcp.txt line 2317; 3dm-gx5-45-dcp.txt line 699. Field data: 5 bytes.
    """

    # Receiver power state (GX5-45: sensor state).
    receiver_state: _ty.Union[_t.GnssReceiverState, int] = _t.GnssReceiverState.OFF
    antenna_state: _ty.Union[_t.GnssAntennaState, int] = _t.GnssAntennaState.INIT  # Antenna connection state.
    antenna_power: _ty.Union[_t.GnssAntennaPower, int] = _t.GnssAntennaPower.OFF  # Antenna power state.
    valid_flags: _t.GnssHardwareStatusValidFlags = _t.GnssHardwareStatusValidFlags(0)  # Which values are valid.

    SET = 0x81
    DESCRIPTOR = 0x0D
    NAME = "hardware_status"
    ROLE = "data"
    _ATTRS = ("receiver_state", "antenna_state", "antenna_power", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("receiver_state", _c.enum(_t.GnssReceiverState, "u8")),
            _c.P("antenna_state", _c.enum(_t.GnssAntennaState, "u8")),
            _c.P("antenna_power", _c.enum(_t.GnssAntennaPower, "u8")),
            _c.P("valid_flags", _c.flags(_t.GnssHardwareStatusValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class DgnssInfo(_c.Field):
    """DGNSS information (set 0x81, descriptor 0x0E, data).

    Age of the newest differential correction, base station id and status, and the number of DGNSS
    channels.

    Sources: 3dm-gx5-45-dcp.txt line 2328; 3dm-gx5-45-dcp.txt line 700. Field data: 12 bytes.
    """

    newest_age: float = 0.0  # Age of the newest correction (valid flag: latest age). [s]
    base_station_id: int = 0  # Base station id.
    # Base station status (UDRE scale factor).
    base_station_status: _ty.Union[_t.GnssDgnssBaseStationStatus, int] = _t.GnssDgnssBaseStationStatus.UDRE_SCALE_1_0
    num_channels: int = 0  # Number of DGNSS channels.
    valid_flags: _t.GnssDgnssInfoValidFlags = _t.GnssDgnssInfoValidFlags(0)  # Which values are valid.

    SET = 0x81
    DESCRIPTOR = 0x0E
    NAME = "dgnss_info"
    ROLE = "data"
    _ATTRS = ("newest_age", "base_station_id", "base_station_status", "num_channels", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("newest_age", _c.F32),
            _c.P("base_station_id", _c.S16),
            _c.P("base_station_status", _c.enum(_t.GnssDgnssBaseStationStatus, "s16")),
            _c.P("num_channels", _c.U16),
            _c.P("valid_flags", _c.flags(_t.GnssDgnssInfoValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class DgnssChannelStatus(_c.Field):
    """DGNSS channel status (set 0x81, descriptor 0x0F, data).

    One entry per space vehicle with differential corrections: SV id, correction age, pseudorange
    and pseudorange-rate corrections. One field per active vehicle.

    Sources: 3dm-gx5-45-dcp.txt line 2342; 3dm-gx5-45-dcp.txt line 701. Field data: 15 bytes.
    """

    sv_id: int = 0  # Space vehicle id number.
    age: float = 0.0  # Age of the correction. [s]
    pseudorange_correction: float = 0.0  # Pseudorange correction. [m]
    pseudorange_rate_correction: float = 0.0  # Pseudorange rate correction. [m/s]
    valid_flags: _t.GnssDgnssChannelStatusValidFlags = _t.GnssDgnssChannelStatusValidFlags(0)  # Which values are valid.

    SET = 0x81
    DESCRIPTOR = 0x0F
    NAME = "dgnss_channel_status"
    ROLE = "data"
    _ATTRS = ("sv_id", "age", "pseudorange_correction", "pseudorange_rate_correction", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("sv_id", _c.U8),
            _c.P("age", _c.F32),
            _c.P("pseudorange_correction", _c.F32),
            _c.P("pseudorange_rate_correction", _c.F32),
            _c.P("valid_flags", _c.flags(_t.GnssDgnssChannelStatusValidFlags)),
        ),
    )


FIELDS: tuple[type[_c.Field], ...] = (
    LlhPosition,
    EcefPosition,
    NedVelocity,
    EcefVelocity,
    Dop,
    UtcTime,
    GpsTime,
    ClockInfo,
    FixInfo,
    SvInfo,
    HardwareStatus,
    DgnssInfo,
    DgnssChannelStatus,
)
