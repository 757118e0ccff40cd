"""GNSS Receiver 2 Data Set (descriptor set 0x92, data).

Data from the second internal GNSS receiver: position, velocity, time, fix and hardware state,
clock, leap seconds and SBAS status. Base rate 5 Hz.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class LlhPosition(_c.Field):
    """GNSS LLH position (set 0x92, descriptor 0x03, data).

    Receiver position in the WGS84 geodetic frame (latitude, longitude, heights) with accuracy
    estimates.

    Sources: 3dm-cv7-ins-docs.txt line 5675. Field data: 42 bytes.
    """

    latitude: float = 0.0  # Latitude (WGS84). [deg]
    longitude: float = 0.0  # Longitude (WGS84). [deg]
    ellipsoid_height: float = 0.0  # Height above the WGS84 ellipsoid. [m]
    msl_height: float = 0.0  # Height above mean sea level. [m]
    horizontal_accuracy: float = 0.0  # Horizontal position accuracy estimate. [m]
    vertical_accuracy: float = 0.0  # Vertical position accuracy estimate. [m]
    valid_flags: _t.GnssLlhPositionValidFlags = _t.GnssLlhPositionValidFlags(0)  # Which values are valid.

    SET = 0x92
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
    """GNSS ECEF position (set 0x92, descriptor 0x04, data).

    Receiver position in the Earth-centred, Earth-fixed frame with its accuracy estimate.

    Sources: 3dm-cv7-ins-docs.txt line 5702. Field data: 30 bytes.
    """

    position: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) ECEF position. [m]
    position_accuracy: float = 0.0  # Position accuracy estimate. [m]
    valid_flags: _t.GnssEcefPositionValidFlags = _t.GnssEcefPositionValidFlags(0)  # Which values are valid.

    SET = 0x92
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
    """GNSS NED velocity (set 0x92, descriptor 0x05, data).

    Receiver velocity in the north-east-down frame, with 3D and ground speed, heading and accuracy
    estimates.

    Sources: 3dm-cv7-ins-docs.txt line 5721. Field data: 34 bytes.
    """

    velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (north, east, down) velocity. [m/s]
    speed: float = 0.0  # 3D speed. [m/s]
    ground_speed: float = 0.0  # Horizontal (ground) speed. [m/s]
    heading: float = 0.0  # Heading (direction of travel). [deg]
    speed_accuracy: float = 0.0  # Speed accuracy estimate. [m/s]
    heading_accuracy: float = 0.0  # Heading accuracy estimate. [deg]
    valid_flags: _t.GnssNedVelocityValidFlags = _t.GnssNedVelocityValidFlags(0)  # Which values are valid.

    SET = 0x92
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
    """GNSS ECEF velocity (set 0x92, descriptor 0x06, data).

    Receiver velocity in the Earth-centred, Earth-fixed frame with its accuracy estimate.

    Sources: 3dm-cv7-ins-docs.txt line 5748. Field data: 18 bytes.
    """

    velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) ECEF velocity. [m/s]
    velocity_accuracy: float = 0.0  # Velocity accuracy estimate. [m/s]
    valid_flags: _t.GnssEcefVelocityValidFlags = _t.GnssEcefVelocityValidFlags(0)  # Which values are valid.

    SET = 0x92
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
    """GNSS dilution of precision (set 0x92, descriptor 0x07, data).

    Geometric, position, horizontal, vertical, time, northing and easting DOP of the current
    solution.

    Sources: 3dm-cv7-ins-docs.txt line 5767. Field data: 30 bytes.
    """

    gdop: float = 0.0  # Geometric DOP.
    pdop: float = 0.0  # Position DOP.
    hdop: float = 0.0  # Horizontal DOP.
    vdop: float = 0.0  # Vertical DOP.
    tdop: float = 0.0  # Time DOP.
    ndop: float = 0.0  # Northing DOP.
    edop: float = 0.0  # Easting DOP.
    valid_flags: _t.GnssDopValidFlags = _t.GnssDopValidFlags(0)  # Which values are valid.

    SET = 0x92
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
    """GNSS UTC time (set 0x92, descriptor 0x08, data).

    UTC date and time of the GNSS solution, with a flag telling whether the leap seconds are known.

    Sources: 3dm-cv7-ins-docs.txt line 5798. Field data: 13 bytes.
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

    SET = 0x92
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
class GpsTime(_c.Field):
    """GNSS GPS time (set 0x92, descriptor 0x09, data).

    GPS time of week and week number of the GNSS solution.

    Sources: 3dm-cv7-ins-docs.txt line 5825. Field data: 12 bytes.
    """

    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number (since 1980). [weeks]
    valid_flags: _t.GnssGpsTimeValidFlags = _t.GnssGpsTimeValidFlags(0)  # Which values are valid.

    SET = 0x92
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
class FixInfo(_c.Field):
    """GNSS fix information (set 0x92, descriptor 0x0B, data).

    Fix type (including RTK float/fixed and differential), number of satellites used and corrections
    applied.

    Sources: 3dm-cv7-ins-docs.txt line 5845. Field data: 6 bytes.
    """

    fix_type: _ty.Union[_t.GnssFixTypeCv7, int] = _t.GnssFixTypeCv7.FIX_3D  # Type of fix.
    num_sv: int = 0  # Number of satellites used in the solution.
    fix_flags: _t.GnssFixFlags = _t.GnssFixFlags(0)  # Corrections used.
    valid_flags: _t.GnssFixInfoValidFlags = _t.GnssFixInfoValidFlags(0)  # Which values are valid.

    SET = 0x92
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
class HardwareStatus(_c.Field):
    """GNSS hardware status (set 0x92, descriptor 0x0D, data).

    Power state of the receiver, state of the antenna connection and whether the antenna is powered.

    Sources: 3dm-cv7-ins-docs.txt line 5878. Field data: 5 bytes.
    """

    # Receiver power state (GX5-45: sensor state).
    receiver_state: _ty.Union[_t.GnssReceiverState, int] = _t.GnssReceiverState.OFF
    antenna_state: _ty.Union[_t.GnssAntennaState, int] = _t.GnssAntennaState.INIT  # Antenna connection state.
    antenna_power: _ty.Union[_t.GnssAntennaPower, int] = _t.GnssAntennaPower.OFF  # Antenna power state.
    valid_flags: _t.GnssHardwareStatusValidFlags = _t.GnssHardwareStatusValidFlags(0)  # Which values are valid.

    SET = 0x92
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
class ClockInfo2(_c.Field):
    """GNSS clock information 2 (set 0x92, descriptor 0x10, data).

    Receiver clock bias and drift, with an accuracy estimate for each.

    Sources: 3dm-cv7-ins-docs.txt line 5911. Field data: 34 bytes.
    """

    bias: float = 0.0  # Receiver clock bias. [s]
    drift: float = 0.0  # Receiver clock drift. [s/s]
    bias_accuracy_estimate: float = 0.0  # Clock bias accuracy estimate. [s]
    drift_accuracy_estimate: float = 0.0  # Clock drift accuracy estimate. [s/s]
    valid_flags: _t.GnssClockInfo2ValidFlags = _t.GnssClockInfo2ValidFlags(0)  # Which values are valid.

    SET = 0x92
    DESCRIPTOR = 0x10
    NAME = "clock_info_2"
    ROLE = "data"
    _ATTRS = ("bias", "drift", "bias_accuracy_estimate", "drift_accuracy_estimate", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("bias", _c.F64),
            _c.P("drift", _c.F64),
            _c.P("bias_accuracy_estimate", _c.F64),
            _c.P("drift_accuracy_estimate", _c.F64),
            _c.P("valid_flags", _c.flags(_t.GnssClockInfo2ValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class GpsLeapSeconds(_c.Field):
    """GPS leap seconds (set 0x92, descriptor 0x11, data).

    Number of leap seconds between GPS time and UTC.

    Sources: 3dm-cv7-ins-docs.txt line 5935. Field data: 3 bytes.
    """

    leap_seconds: int = 0  # GPS - UTC leap seconds. [s]
    valid_flags: _t.GnssLeapSecondsValidFlags = _t.GnssLeapSecondsValidFlags(0)  # Validity of the leap seconds.

    SET = 0x92
    DESCRIPTOR = 0x11
    NAME = "gps_leap_seconds"
    ROLE = "data"
    _ATTRS = ("leap_seconds", "valid_flags")
    _OPS = (_c.Run(_c.P("leap_seconds", _c.U8), _c.P("valid_flags", _c.flags(_t.GnssLeapSecondsValidFlags))),)


@_c.slotted
@_dc.dataclass
class SbasInfo(_c.Field):
    """SBAS information (set 0x92, descriptor 0x12, data).

    SBAS system and satellite in use, number of corrections and the service status, with the GPS
    time.

    Sources: 3dm-cv7-ins-docs.txt line 5951. Field data: 16 bytes.
    """

    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number (since 1980). [weeks]
    sbas_system: _ty.Union[_t.GnssSbasSystem, int] = _t.GnssSbasSystem.UNKNOWN  # SBAS system.
    sbas_id: int = 0  # SBAS satellite id.
    count: int = 0  # Number of SBAS corrections.
    sbas_status: _t.GnssSbasStatus = _t.GnssSbasStatus(0)  # Status of the SBAS service.
    valid_flags: _t.GnssSbasInfoValidFlags = _t.GnssSbasInfoValidFlags(0)  # Which values are valid.

    SET = 0x92
    DESCRIPTOR = 0x12
    NAME = "sbas_info"
    ROLE = "data"
    _ATTRS = ("tow", "week_number", "sbas_system", "sbas_id", "count", "sbas_status", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("tow", _c.F64),
            _c.P("week_number", _c.U16),
            _c.P("sbas_system", _c.enum(_t.GnssSbasSystem, "u8")),
            _c.P("sbas_id", _c.U8),
            _c.P("count", _c.U8),
            _c.P("sbas_status", _c.flags(_t.GnssSbasStatus)),
            _c.P("valid_flags", _c.flags(_t.GnssSbasInfoValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class SatelliteStatus(_c.Field):
    """Satellite status (set 0x92, descriptor 0x20, data).

    Sky position and health of one satellite; one field per satellite in view.

    Sources: 3dm-cv7-ins-docs.txt line 5989. Field data: 25 bytes.
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

    SET = 0x92
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


@_c.slotted
@_dc.dataclass
class Raw(_c.Field):
    """Raw observation (set 0x92, descriptor 0x22, data).

    Raw pseudorange, carrier phase and Doppler of one signal; one field per tracked signal.

    Sources: 3dm-cv7-ins-docs.txt line 6026. Field data: 61 bytes.
    """

    index: int = 0  # Index of this field among the raw observation fields of this epoch.
    count: int = 0  # Number of raw observation fields in this epoch.
    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number since 1980. [weeks]
    # Receiver number (1, 2, ...), or the reference station id when the measurement comes from RTCM.
    receiver_id: int = 0
    tracking_channel: int = 0  # Receiver channel tracking this satellite.
    gnss_id: _ty.Union[_t.GnssConstellationId, int] = _t.GnssConstellationId.UNKNOWN  # Constellation of the satellite.
    satellite_id: int = 0  # Satellite number within its constellation.
    signal_id: _ty.Union[_t.GnssSignalId, int] = _t.GnssSignalId.UNKNOWN  # Signal the observation is made on.
    signal_strength: float = 0.0  # Carrier-to-noise density ratio. [dB-Hz]
    quality: _ty.Union[_t.GnssSignalQuality, int] = _t.GnssSignalQuality.NONE  # Tracking state of the signal.
    pseudorange: float = 0.0  # Pseudorange. [m]
    carrier_phase: float = 0.0  # Carrier phase, in carrier periods. [cycles]
    doppler: float = 0.0  # Doppler shift. [Hz]
    range_uncert: float = 0.0  # Uncertainty of the pseudorange. [m]
    phase_uncert: float = 0.0  # Uncertainty of the carrier phase, in carrier periods. [cycles]
    doppler_uncert: float = 0.0  # Uncertainty of the Doppler shift. [Hz]
    # Minimum time the carrier phase has been continuously locked; the largest value reported depends on the receiver.
    # [s]
    lock_time: float = 0.0
    valid_flags: _t.GnssRawValidFlags = _t.GnssRawValidFlags(0)  # Which parameters are valid.

    SET = 0x92
    DESCRIPTOR = 0x22
    NAME = "raw"
    ROLE = "data"
    _ATTRS = (
        "index",
        "count",
        "tow",
        "week_number",
        "receiver_id",
        "tracking_channel",
        "gnss_id",
        "satellite_id",
        "signal_id",
        "signal_strength",
        "quality",
        "pseudorange",
        "carrier_phase",
        "doppler",
        "range_uncert",
        "phase_uncert",
        "doppler_uncert",
        "lock_time",
        "valid_flags",
    )
    _OPS = (
        _c.Run(
            _c.P("index", _c.U8),
            _c.P("count", _c.U8),
            _c.P("tow", _c.F64),
            _c.P("week_number", _c.U16),
            _c.P("receiver_id", _c.U16),
            _c.P("tracking_channel", _c.U8),
            _c.P("gnss_id", _c.enum(_t.GnssConstellationId, "u8")),
            _c.P("satellite_id", _c.U8),
            _c.P("signal_id", _c.enum(_t.GnssSignalId, "u8")),
            _c.P("signal_strength", _c.F32),
            _c.P("quality", _c.enum(_t.GnssSignalQuality, "u8")),
            _c.P("pseudorange", _c.F64),
            _c.P("carrier_phase", _c.F64),
            _c.P("doppler", _c.F32),
            _c.P("range_uncert", _c.F32),
            _c.P("phase_uncert", _c.F32),
            _c.P("doppler_uncert", _c.F32),
            _c.P("lock_time", _c.F32),
            _c.P("valid_flags", _c.flags(_t.GnssRawValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class GpsEphemeris(_c.Field):
    """GPS ephemeris (set 0x92, descriptor 0x61, data).

    Broadcast ephemeris of one GPS satellite; one field per satellite.

    Sources: 3dm-cv7-ins-docs.txt line 6162. Field data: 218 bytes.
    """

    index: int = 0  # Index of this field among the ephemeris fields of this epoch.
    count: int = 0  # Number of ephemeris fields in this epoch.
    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number since 1980. [weeks]
    satellite_id: int = 0  # Satellite number within its constellation.
    health: int = 0  # Satellite and signal health.
    iodc: int = 0  # Issue of data, clock: changes whenever the clock data change; lines up data from different sources.
    iode: int = 0  # Issue of data, ephemeris.
    t_oc: float = 0.0  # Reference time of the clock data. [s]
    af0: float = 0.0  # Clock bias. [s]
    af1: float = 0.0  # Clock drift. [s/s]
    af2: float = 0.0  # Clock drift rate. [s/s^2]
    t_gd: float = 0.0  # Group delay. [s]
    isc_l1ca: float = 0.0  # Inter-signal correction, L1. [s]
    isc_l2c: float = 0.0  # Inter-signal correction, L2 (or L5 when valid_flags.isc_l5 is set). [s]
    t_oe: float = 0.0  # Reference time of the ephemeris. [s]
    a: float = 0.0  # Semi-major axis. [m]
    a_dot: float = 0.0  # Rate of the semi-major axis. [m/s]
    mean_anomaly: float = 0.0  # Mean anomaly at the reference time. [rad]
    delta_mean_motion: float = 0.0  # Mean motion difference from the computed value. [rad/s]
    delta_mean_motion_dot: float = 0.0  # Rate of the mean motion difference. [rad/s^2]
    eccentricity: float = 0.0  # Orbit eccentricity (dimensionless).
    argument_of_perigee: float = 0.0  # Argument of perigee. [rad]
    omega: float = 0.0  # Longitude of the ascending node. [rad]
    omega_dot: float = 0.0  # Rate of right ascension. [rad/s]
    inclination: float = 0.0  # Inclination angle. [rad]
    inclination_dot: float = 0.0  # Rate of the inclination angle. [rad/s]
    c_ic: float = 0.0  # Harmonic correction term, cosine, to the inclination. [rad]
    c_is: float = 0.0  # Harmonic correction term, sine, to the inclination. [rad]
    c_uc: float = 0.0  # Harmonic correction term, cosine, to the argument of latitude. [rad]
    c_us: float = 0.0  # Harmonic correction term, sine, to the argument of latitude. [rad]
    c_rc: float = 0.0  # Harmonic correction term, cosine, to the orbit radius. [m]
    c_rs: float = 0.0  # Harmonic correction term, sine, to the orbit radius. [m]
    # Which data are valid, and how isc_l2c is to be read.
    valid_flags: _t.GnssEphemerisValidFlags = _t.GnssEphemerisValidFlags(0)

    SET = 0x92
    DESCRIPTOR = 0x61
    NAME = "gps_ephemeris"
    ROLE = "data"
    _ATTRS = (
        "index",
        "count",
        "tow",
        "week_number",
        "satellite_id",
        "health",
        "iodc",
        "iode",
        "t_oc",
        "af0",
        "af1",
        "af2",
        "t_gd",
        "isc_l1ca",
        "isc_l2c",
        "t_oe",
        "a",
        "a_dot",
        "mean_anomaly",
        "delta_mean_motion",
        "delta_mean_motion_dot",
        "eccentricity",
        "argument_of_perigee",
        "omega",
        "omega_dot",
        "inclination",
        "inclination_dot",
        "c_ic",
        "c_is",
        "c_uc",
        "c_us",
        "c_rc",
        "c_rs",
        "valid_flags",
    )
    _OPS = (
        _c.Run(
            _c.P("index", _c.U8),
            _c.P("count", _c.U8),
            _c.P("tow", _c.F64),
            _c.P("week_number", _c.U16),
            _c.P("satellite_id", _c.U8),
            _c.P("health", _c.U8),
            _c.P("iodc", _c.U8),
            _c.P("iode", _c.U8),
            _c.P("t_oc", _c.F64),
            _c.P("af0", _c.F64),
            _c.P("af1", _c.F64),
            _c.P("af2", _c.F64),
            _c.P("t_gd", _c.F64),
            _c.P("isc_l1ca", _c.F64),
            _c.P("isc_l2c", _c.F64),
            _c.P("t_oe", _c.F64),
            _c.P("a", _c.F64),
            _c.P("a_dot", _c.F64),
            _c.P("mean_anomaly", _c.F64),
            _c.P("delta_mean_motion", _c.F64),
            _c.P("delta_mean_motion_dot", _c.F64),
            _c.P("eccentricity", _c.F64),
            _c.P("argument_of_perigee", _c.F64),
            _c.P("omega", _c.F64),
            _c.P("omega_dot", _c.F64),
            _c.P("inclination", _c.F64),
            _c.P("inclination_dot", _c.F64),
            _c.P("c_ic", _c.F64),
            _c.P("c_is", _c.F64),
            _c.P("c_uc", _c.F64),
            _c.P("c_us", _c.F64),
            _c.P("c_rc", _c.F64),
            _c.P("c_rs", _c.F64),
            _c.P("valid_flags", _c.flags(_t.GnssEphemerisValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class GlonassEphemeris(_c.Field):
    """GLONASS ephemeris (set 0x92, descriptor 0x62, data).

    Broadcast ephemeris of one GLONASS satellite; one field per satellite.

    Sources: 3dm-cv7-ins-docs.txt line 6216. Field data: 102 bytes.
    """

    index: int = 0  # Index of this field among the ephemeris fields of this epoch.
    count: int = 0  # Number of ephemeris fields in this epoch.
    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number since 1980. [weeks]
    satellite_id: int = 0  # Satellite number within the constellation.
    freq_number: int = 0  # GLONASS frequency channel number (-7 to 24).
    tk: int = 0  # Start time of the frame within the current day. [s]
    tb: int = 0  # Reference time of the ephemeris. [s]
    sat_type: _ty.Union[_t.GnssGlonassSatelliteType, int] = _t.GnssGlonassSatelliteType.GLONASS  # Satellite type.
    gamma: float = 0.0  # Relative deviation of the carrier frequency from nominal (dimensionless).
    tau_n: float = 0.0  # Satellite time correction relative to GLONASS time. [s]
    x: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Satellite position in the PZ-90 frame. [m]
    v: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Satellite velocity in the PZ-90 frame. [m/s]
    # Satellite acceleration due to perturbations, PZ-90 frame. [m/s^2]
    a: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    health: int = 0  # Satellite health word Bn; non-zero means a malfunction.
    p: int = 0  # Satellite operation mode (see the GLONASS ICD).
    nt: int = 0  # Day number within the four-year period. [days]
    delta_tau_n: float = 0.0  # Time difference between the L2 and L1 transmissions. [s]
    ft: int = 0  # User range accuracy index (see the GLONASS ICD).
    en: int = 0  # Age of the current information. [days]
    p1: int = 0  # Interval between adjacent values of tb. [min]
    p2: int = 0  # 1 if tb is odd, 0 if even.
    p3: int = 0  # Number of satellites in the almanac of this frame.
    p4: int = 0  # Non-zero when ephemeris parameters are present.
    valid_flags: _t.GnssGlonassEphemerisValidFlags = _t.GnssGlonassEphemerisValidFlags(0)  # Which data are valid.

    SET = 0x92
    DESCRIPTOR = 0x62
    NAME = "glonass_ephemeris"
    ROLE = "data"
    _ATTRS = (
        "index",
        "count",
        "tow",
        "week_number",
        "satellite_id",
        "freq_number",
        "tk",
        "tb",
        "sat_type",
        "gamma",
        "tau_n",
        "x",
        "v",
        "a",
        "health",
        "p",
        "nt",
        "delta_tau_n",
        "ft",
        "en",
        "p1",
        "p2",
        "p3",
        "p4",
        "valid_flags",
    )
    _OPS = (
        _c.Run(
            _c.P("index", _c.U8),
            _c.P("count", _c.U8),
            _c.P("tow", _c.F64),
            _c.P("week_number", _c.U16),
            _c.P("satellite_id", _c.U8),
            _c.P("freq_number", _c.S8),
            _c.P("tk", _c.U32),
            _c.P("tb", _c.U32),
            _c.P("sat_type", _c.enum(_t.GnssGlonassSatelliteType, "u8")),
            _c.P("gamma", _c.F64),
            _c.P("tau_n", _c.F64),
            _c.P("x", _c.F64, 3),
            _c.P("v", _c.F32, 3),
            _c.P("a", _c.F32, 3),
            _c.P("health", _c.U8),
            _c.P("p", _c.U8),
            _c.P("nt", _c.U8),
            _c.P("delta_tau_n", _c.F32),
            _c.P("ft", _c.U8),
            _c.P("en", _c.U8),
            _c.P("p1", _c.U8),
            _c.P("p2", _c.U8),
            _c.P("p3", _c.U8),
            _c.P("p4", _c.U8),
            _c.P("valid_flags", _c.flags(_t.GnssGlonassEphemerisValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class GalileoEphemeris(_c.Field):
    """Galileo ephemeris (set 0x92, descriptor 0x63, data).

    Broadcast ephemeris of one Galileo satellite; one field per satellite.

    Sources: 3dm-cv7-ins-docs.txt line 6255. Field data: 218 bytes.
    """

    index: int = 0  # Index of this field among the ephemeris fields of this epoch.
    count: int = 0  # Number of ephemeris fields in this epoch.
    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number since 1980. [weeks]
    satellite_id: int = 0  # Satellite number within its constellation.
    health: int = 0  # Satellite and signal health.
    iodc: int = 0  # Issue of data, clock: changes whenever the clock data change; lines up data from different sources.
    iode: int = 0  # Issue of data, ephemeris.
    t_oc: float = 0.0  # Reference time of the clock data. [s]
    af0: float = 0.0  # Clock bias. [s]
    af1: float = 0.0  # Clock drift. [s/s]
    af2: float = 0.0  # Clock drift rate. [s/s^2]
    t_gd: float = 0.0  # Group delay. [s]
    isc_l1ca: float = 0.0  # Inter-signal correction, L1. [s]
    isc_l2c: float = 0.0  # Inter-signal correction, L2 (or L5 when valid_flags.isc_l5 is set). [s]
    t_oe: float = 0.0  # Reference time of the ephemeris. [s]
    a: float = 0.0  # Semi-major axis. [m]
    a_dot: float = 0.0  # Rate of the semi-major axis. [m/s]
    mean_anomaly: float = 0.0  # Mean anomaly at the reference time. [rad]
    delta_mean_motion: float = 0.0  # Mean motion difference from the computed value. [rad/s]
    delta_mean_motion_dot: float = 0.0  # Rate of the mean motion difference. [rad/s^2]
    eccentricity: float = 0.0  # Orbit eccentricity (dimensionless).
    argument_of_perigee: float = 0.0  # Argument of perigee. [rad]
    omega: float = 0.0  # Longitude of the ascending node. [rad]
    omega_dot: float = 0.0  # Rate of right ascension. [rad/s]
    inclination: float = 0.0  # Inclination angle. [rad]
    inclination_dot: float = 0.0  # Rate of the inclination angle. [rad/s]
    c_ic: float = 0.0  # Harmonic correction term, cosine, to the inclination. [rad]
    c_is: float = 0.0  # Harmonic correction term, sine, to the inclination. [rad]
    c_uc: float = 0.0  # Harmonic correction term, cosine, to the argument of latitude. [rad]
    c_us: float = 0.0  # Harmonic correction term, sine, to the argument of latitude. [rad]
    c_rc: float = 0.0  # Harmonic correction term, cosine, to the orbit radius. [m]
    c_rs: float = 0.0  # Harmonic correction term, sine, to the orbit radius. [m]
    # Which data are valid, and how isc_l2c is to be read.
    valid_flags: _t.GnssEphemerisValidFlags = _t.GnssEphemerisValidFlags(0)

    SET = 0x92
    DESCRIPTOR = 0x63
    NAME = "galileo_ephemeris"
    ROLE = "data"
    _ATTRS = (
        "index",
        "count",
        "tow",
        "week_number",
        "satellite_id",
        "health",
        "iodc",
        "iode",
        "t_oc",
        "af0",
        "af1",
        "af2",
        "t_gd",
        "isc_l1ca",
        "isc_l2c",
        "t_oe",
        "a",
        "a_dot",
        "mean_anomaly",
        "delta_mean_motion",
        "delta_mean_motion_dot",
        "eccentricity",
        "argument_of_perigee",
        "omega",
        "omega_dot",
        "inclination",
        "inclination_dot",
        "c_ic",
        "c_is",
        "c_uc",
        "c_us",
        "c_rc",
        "c_rs",
        "valid_flags",
    )
    _OPS = (
        _c.Run(
            _c.P("index", _c.U8),
            _c.P("count", _c.U8),
            _c.P("tow", _c.F64),
            _c.P("week_number", _c.U16),
            _c.P("satellite_id", _c.U8),
            _c.P("health", _c.U8),
            _c.P("iodc", _c.U8),
            _c.P("iode", _c.U8),
            _c.P("t_oc", _c.F64),
            _c.P("af0", _c.F64),
            _c.P("af1", _c.F64),
            _c.P("af2", _c.F64),
            _c.P("t_gd", _c.F64),
            _c.P("isc_l1ca", _c.F64),
            _c.P("isc_l2c", _c.F64),
            _c.P("t_oe", _c.F64),
            _c.P("a", _c.F64),
            _c.P("a_dot", _c.F64),
            _c.P("mean_anomaly", _c.F64),
            _c.P("delta_mean_motion", _c.F64),
            _c.P("delta_mean_motion_dot", _c.F64),
            _c.P("eccentricity", _c.F64),
            _c.P("argument_of_perigee", _c.F64),
            _c.P("omega", _c.F64),
            _c.P("omega_dot", _c.F64),
            _c.P("inclination", _c.F64),
            _c.P("inclination_dot", _c.F64),
            _c.P("c_ic", _c.F64),
            _c.P("c_is", _c.F64),
            _c.P("c_uc", _c.F64),
            _c.P("c_us", _c.F64),
            _c.P("c_rc", _c.F64),
            _c.P("c_rs", _c.F64),
            _c.P("valid_flags", _c.flags(_t.GnssEphemerisValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class BeidouEphemeris(_c.Field):
    """BeiDou ephemeris (set 0x92, descriptor 0x64, data).

    Broadcast ephemeris of one BeiDou satellite; one field per satellite.

    Sources: 3dm-cv7-ins-docs.txt line 6308. Field data: 218 bytes.
    """

    index: int = 0  # Index of this field among the ephemeris fields of this epoch.
    count: int = 0  # Number of ephemeris fields in this epoch.
    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number since 1980. [weeks]
    satellite_id: int = 0  # Satellite number within its constellation.
    health: int = 0  # Satellite and signal health.
    iodc: int = 0  # Issue of data, clock: changes whenever the clock data change; lines up data from different sources.
    iode: int = 0  # Issue of data, ephemeris.
    t_oc: float = 0.0  # Reference time of the clock data. [s]
    af0: float = 0.0  # Clock bias. [s]
    af1: float = 0.0  # Clock drift. [s/s]
    af2: float = 0.0  # Clock drift rate. [s/s^2]
    t_gd: float = 0.0  # Group delay. [s]
    isc_l1ca: float = 0.0  # Inter-signal correction, L1. [s]
    isc_l2c: float = 0.0  # Inter-signal correction, L2 (or L5 when valid_flags.isc_l5 is set). [s]
    t_oe: float = 0.0  # Reference time of the ephemeris. [s]
    a: float = 0.0  # Semi-major axis. [m]
    a_dot: float = 0.0  # Rate of the semi-major axis. [m/s]
    mean_anomaly: float = 0.0  # Mean anomaly at the reference time. [rad]
    delta_mean_motion: float = 0.0  # Mean motion difference from the computed value. [rad/s]
    delta_mean_motion_dot: float = 0.0  # Rate of the mean motion difference. [rad/s^2]
    eccentricity: float = 0.0  # Orbit eccentricity (dimensionless).
    argument_of_perigee: float = 0.0  # Argument of perigee. [rad]
    omega: float = 0.0  # Longitude of the ascending node. [rad]
    omega_dot: float = 0.0  # Rate of right ascension. [rad/s]
    inclination: float = 0.0  # Inclination angle. [rad]
    inclination_dot: float = 0.0  # Rate of the inclination angle. [rad/s]
    c_ic: float = 0.0  # Harmonic correction term, cosine, to the inclination. [rad]
    c_is: float = 0.0  # Harmonic correction term, sine, to the inclination. [rad]
    c_uc: float = 0.0  # Harmonic correction term, cosine, to the argument of latitude. [rad]
    c_us: float = 0.0  # Harmonic correction term, sine, to the argument of latitude. [rad]
    c_rc: float = 0.0  # Harmonic correction term, cosine, to the orbit radius. [m]
    c_rs: float = 0.0  # Harmonic correction term, sine, to the orbit radius. [m]
    # Which data are valid, and how isc_l2c is to be read.
    valid_flags: _t.GnssEphemerisValidFlags = _t.GnssEphemerisValidFlags(0)

    SET = 0x92
    DESCRIPTOR = 0x64
    NAME = "beidou_ephemeris"
    ROLE = "data"
    _ATTRS = (
        "index",
        "count",
        "tow",
        "week_number",
        "satellite_id",
        "health",
        "iodc",
        "iode",
        "t_oc",
        "af0",
        "af1",
        "af2",
        "t_gd",
        "isc_l1ca",
        "isc_l2c",
        "t_oe",
        "a",
        "a_dot",
        "mean_anomaly",
        "delta_mean_motion",
        "delta_mean_motion_dot",
        "eccentricity",
        "argument_of_perigee",
        "omega",
        "omega_dot",
        "inclination",
        "inclination_dot",
        "c_ic",
        "c_is",
        "c_uc",
        "c_us",
        "c_rc",
        "c_rs",
        "valid_flags",
    )
    _OPS = (
        _c.Run(
            _c.P("index", _c.U8),
            _c.P("count", _c.U8),
            _c.P("tow", _c.F64),
            _c.P("week_number", _c.U16),
            _c.P("satellite_id", _c.U8),
            _c.P("health", _c.U8),
            _c.P("iodc", _c.U8),
            _c.P("iode", _c.U8),
            _c.P("t_oc", _c.F64),
            _c.P("af0", _c.F64),
            _c.P("af1", _c.F64),
            _c.P("af2", _c.F64),
            _c.P("t_gd", _c.F64),
            _c.P("isc_l1ca", _c.F64),
            _c.P("isc_l2c", _c.F64),
            _c.P("t_oe", _c.F64),
            _c.P("a", _c.F64),
            _c.P("a_dot", _c.F64),
            _c.P("mean_anomaly", _c.F64),
            _c.P("delta_mean_motion", _c.F64),
            _c.P("delta_mean_motion_dot", _c.F64),
            _c.P("eccentricity", _c.F64),
            _c.P("argument_of_perigee", _c.F64),
            _c.P("omega", _c.F64),
            _c.P("omega_dot", _c.F64),
            _c.P("inclination", _c.F64),
            _c.P("inclination_dot", _c.F64),
            _c.P("c_ic", _c.F64),
            _c.P("c_is", _c.F64),
            _c.P("c_uc", _c.F64),
            _c.P("c_us", _c.F64),
            _c.P("c_rc", _c.F64),
            _c.P("c_rs", _c.F64),
            _c.P("valid_flags", _c.flags(_t.GnssEphemerisValidFlags)),
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
    FixInfo,
    HardwareStatus,
    ClockInfo2,
    GpsLeapSeconds,
    SbasInfo,
    SatelliteStatus,
    Raw,
    GpsEphemeris,
    GlonassEphemeris,
    GalileoEphemeris,
    BeidouEphemeris,
)
