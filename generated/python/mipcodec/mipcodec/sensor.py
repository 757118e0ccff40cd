"""Sensor (IMU) Data Set (descriptor set 0x80, data).

Calibrated inertial sensor measurements.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class ScaledAccel(_c.Field):
    """Scaled accelerometer vector (set 0x80, descriptor 0x04, data).

    Sensed acceleration, temperature compensated, in g (1 g = 9.80665 m/s^2), X, Y, Z in the sensor
    (GX5-45) or vehicle (CV7) frame.

    Sources: 3dm-gx5-45-dcp.txt line 2035; 3dm-cv7-ins-docs.txt line 6390. Field data: 12 bytes.
    """

    scaled_accel: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) acceleration. [g]

    SET = 0x80
    DESCRIPTOR = 0x04
    NAME = "scaled_accel"
    ROLE = "data"
    _ATTRS = ("scaled_accel",)
    _OPS = (_c.Run(_c.P("scaled_accel", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class ScaledGyro(_c.Field):
    """Scaled gyro vector (set 0x80, descriptor 0x05, data).

    Sensed angular rate, temperature compensated, in radians/second, X, Y, Z.

    Sources: 3dm-gx5-45-dcp.txt line 2044; 3dm-cv7-ins-docs.txt line 6401. Field data: 12 bytes.
    """

    scaled_gyro: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) angular rate. [rad/s]

    SET = 0x80
    DESCRIPTOR = 0x05
    NAME = "scaled_gyro"
    ROLE = "data"
    _ATTRS = ("scaled_gyro",)
    _OPS = (_c.Run(_c.P("scaled_gyro", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class ScaledMag(_c.Field):
    """Scaled magnetometer vector (set 0x80, descriptor 0x06, data).

    Sensed magnetic field, temperature compensated, in Gauss, X, Y, Z.

    Sources: 3dm-gx5-45-dcp.txt line 2054; 3dm-cv7-ins-docs.txt line 6412. Field data: 12 bytes.
    """

    scaled_mag: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) magnetic field. [gauss]

    SET = 0x80
    DESCRIPTOR = 0x06
    NAME = "scaled_mag"
    ROLE = "data"
    _ATTRS = ("scaled_mag",)
    _OPS = (_c.Run(_c.P("scaled_mag", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class DeltaTheta(_c.Field):
    """Delta theta vector (set 0x80, descriptor 0x07, data).

    Time integral of the angular rate over the interval set by the IMU message format (the output
    period), in radians, X, Y, Z in the sensor (GX5-45) or vehicle (CV7) frame.

    Sources: 3dm-gx5-45-dcp.txt line 2072; 3dm-cv7-ins-docs.txt line 6423. Field data: 12 bytes.
    """

    # (x, y, z) integrated angular rate. [rad]
    delta_theta: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x80
    DESCRIPTOR = 0x07
    NAME = "delta_theta"
    ROLE = "data"
    _ATTRS = ("delta_theta",)
    _OPS = (_c.Run(_c.P("delta_theta", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class DeltaVelocity(_c.Field):
    """Delta velocity vector (set 0x80, descriptor 0x08, data).

    Time integral of the sensed (specific) acceleration over the interval set by the IMU message
    format, in g*seconds (multiply by 9.80665 for m/s), X, Y, Z in the sensor (GX5-45) or vehicle
    (CV7) frame.

    Sources: 3dm-gx5-45-dcp.txt line 2082; 3dm-cv7-ins-docs.txt line 6434. Field data: 12 bytes.
    """

    # (x, y, z) integrated acceleration. [g*s]
    delta_velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x80
    DESCRIPTOR = 0x08
    NAME = "delta_velocity"
    ROLE = "data"
    _ATTRS = ("delta_velocity",)
    _OPS = (_c.Run(_c.P("delta_velocity", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class CfOrientationMatrix(_c.Field):
    """Complementary filter orientation matrix (set 0x80, descriptor 0x09, data).

    3x3 orientation (direction cosine) matrix from the complementary filter, rotating a vector from
    the earth-fixed (NED local-level) frame into the sensor (GX5-45) or vehicle (CV7) frame: v_local
    = M * v_earth. Elements sent row-major, M11 M12 M13 M21 ... M33.

    Sources: 3dm-gx5-45-dcp.txt line 2092; 3dm-cv7-ins-docs.txt line 6445. Field data: 36 bytes.
    """

    m: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 9)  # Orientation matrix, row-major (dimensionless).

    SET = 0x80
    DESCRIPTOR = 0x09
    NAME = "cf_orientation_matrix"
    ROLE = "data"
    _ATTRS = ("m",)
    _OPS = (_c.Run(_c.P("m", _c.F32, 9)),)


@_c.slotted
@_dc.dataclass
class CfQuaternion(_c.Field):
    """Complementary filter quaternion (set 0x80, descriptor 0x0A, data).

    Orientation quaternion (q0, q1, q2, q3) from the complementary filter, of the sensor (GX5-45) or
    vehicle (CV7) frame relative to the earth-fixed (NED) frame: v_local = Q^-1 * v_earth * Q.

    Sources: 3dm-gx5-45-dcp.txt line 2115; 3dm-cv7-ins-docs.txt line 6456. Field data: 16 bytes.
    """

    # Quaternion elements q0 (scalar), q1, q2, q3 (dimensionless).
    q: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 4)

    SET = 0x80
    DESCRIPTOR = 0x0A
    NAME = "cf_quaternion"
    ROLE = "data"
    _ATTRS = ("q",)
    _OPS = (_c.Run(_c.P("q", _c.F32, 4)),)


@_c.slotted
@_dc.dataclass
class CfEulerAngles(_c.Field):
    """Complementary filter Euler angles (set 0x80, descriptor 0x0C, data).

    Roll, pitch and yaw (aircraft 3-2-1 order) from the complementary filter, in radians, relative
    to the earth-fixed (NED local-level) frame.

    Sources: 3dm-gx5-45-dcp.txt line 2126; 3dm-cv7-ins-docs.txt line 6468. Field data: 12 bytes.
    """

    roll: float = 0.0  # Roll angle. [rad]
    pitch: float = 0.0  # Pitch angle. [rad]
    yaw: float = 0.0  # Yaw angle. [rad]

    SET = 0x80
    DESCRIPTOR = 0x0C
    NAME = "cf_euler_angles"
    ROLE = "data"
    _ATTRS = ("roll", "pitch", "yaw")
    _OPS = (_c.Run(_c.P("roll", _c.F32), _c.P("pitch", _c.F32), _c.P("yaw", _c.F32)),)


@_c.slotted
@_dc.dataclass
class CfStabilizedNorth(_c.Field):
    """Complementary filter stabilized north vector (set 0x80, descriptor 0x10, data).

    The complementary filter's gyro-stabilized estimate of the geomagnetic field vector (magnetic
    north), in Gauss, in the sensor frame. Equal to the magnetometer reading without magnetic
    interference, but free of transient interference.

    Sources: 3dm-gx5-45-dcp.txt line 2136; 3dm-gx5-45-dcp.txt line 683. Field data: 12 bytes.
    """

    # (x, y, z) stabilized magnetic field estimate. [gauss]
    stabilized_north: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x80
    DESCRIPTOR = 0x10
    NAME = "cf_stabilized_north"
    ROLE = "data"
    _ATTRS = ("stabilized_north",)
    _OPS = (_c.Run(_c.P("stabilized_north", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class CfStabilizedUp(_c.Field):
    """Complementary filter stabilized up vector (set 0x80, descriptor 0x11, data).

    The complementary filter's gyro-stabilized estimate of the gravity vector (vertical), in g, in
    the sensor frame. Equal to the accelerometer reading when stationary, but free of linear
    acceleration.

    Sources: 3dm-gx5-45-dcp.txt line 2146; 3dm-gx5-45-dcp.txt line 684. Field data: 12 bytes.
    """

    # (x, y, z) stabilized gravity estimate. [g]
    stabilized_up: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x80
    DESCRIPTOR = 0x11
    NAME = "cf_stabilized_up"
    ROLE = "data"
    _ATTRS = ("stabilized_up",)
    _OPS = (_c.Run(_c.P("stabilized_up", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class GpsTimestamp(_c.Field):
    """GPS timestamp of sensor data (GX5-45 GPS correlation timestamp) (set 0x80, descriptor 0x12,
    data).

    GPS time of the sensor sample as time of week and week number, with status flags. Without a PPS
    the device runs on its internal clock and the time drifts; expect a jump when the PPS returns.
    The fractional part of the time of week is the time since the last PPS. The CV7 recommends the
    shared GPS timestamp (0xD3) instead.

    Sources: 3dm-gx5-45-dcp.txt line 2156; 3dm-cv7-ins-docs.txt line 6481. Field data: 12 bytes.
    """

    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number since 1980. [weeks]
    # Timestamp status flags (GX5-45: Timestamp Flags).
    valid_flags: _t.SensorGpsTimestampFlags = _t.SensorGpsTimestampFlags(0)

    SET = 0x80
    DESCRIPTOR = 0x12
    NAME = "gps_timestamp"
    ROLE = "data"
    _ATTRS = ("tow", "week_number", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("tow", _c.F64), _c.P("week_number", _c.U16), _c.P("valid_flags", _c.flags(_t.SensorGpsTimestampFlags))
        ),
    )


@_c.slotted
@_dc.dataclass
class TemperatureStatistics(_c.Field):
    """Temperature statistics (set 0x80, descriptor 0x14, data).

    Minimum, maximum and mean sensor temperature since the last power-on or reset, from the MEMS
    sensors or combined with board temperature sensors.

    Sources: 3dm-cv7-ins-docs.txt line 6502. Field data: 12 bytes.
    """

    min_temp: float = 0.0  # Minimum temperature. [degC]
    max_temp: float = 0.0  # Maximum temperature. [degC]
    mean_temp: float = 0.0  # Mean temperature. [degC]

    SET = 0x80
    DESCRIPTOR = 0x14
    NAME = "temperature_statistics"
    ROLE = "data"
    _ATTRS = ("min_temp", "max_temp", "mean_temp")
    _OPS = (_c.Run(_c.P("min_temp", _c.F32), _c.P("max_temp", _c.F32), _c.P("mean_temp", _c.F32)),)


@_c.slotted
@_dc.dataclass
class ScaledPressure(_c.Field):
    """Scaled ambient pressure (set 0x80, descriptor 0x17, data).

    Sensed ambient pressure, temperature compensated, in millibar.

    Sources: 3dm-gx5-45-dcp.txt line 2064; 3dm-cv7-ins-docs.txt line 6515. Field data: 4 bytes.
    """

    scaled_pressure: float = 0.0  # Ambient pressure. [mbar]

    SET = 0x80
    DESCRIPTOR = 0x17
    NAME = "scaled_pressure"
    ROLE = "data"
    _ATTRS = ("scaled_pressure",)
    _OPS = (_c.Run(_c.P("scaled_pressure", _c.F32)),)


@_c.slotted
@_dc.dataclass
class OverrangeStatus(_c.Field):
    """Over-range status (set 0x80, descriptor 0x18, data).

    Which sensor axes are near or beyond their range, per axis (a smaller, faster form of the
    over-range bits of the continuous BIT).

    Sources: 3dm-cv7-ins-docs.txt line 6526; 3dm-cv7-ins-docs.txt line 1403. Field data: 2 bytes.
    """

    status: _t.OverrangeStatusFlags = _t.OverrangeStatusFlags(0)  # Over-range flags, one per axis.

    SET = 0x80
    DESCRIPTOR = 0x18
    NAME = "overrange_status"
    ROLE = "data"
    _ATTRS = ("status",)
    _OPS = (_c.Run(_c.P("status", _c.flags(_t.OverrangeStatusFlags))),)


@_c.slotted
@_dc.dataclass
class OdometerData(_c.Field):
    """Odometer data (set 0x80, descriptor 0x40, data).

    Speed measured by the odometer (wheel encoder) input and its uncertainty.

    Sources: 3dm-cv7-ins-docs.txt line 6550. Field data: 10 bytes.
    """

    speed: float = 0.0  # Average speed over the interval; can be negative with quadrature encoders. [m/s]
    uncertainty: float = 0.0  # Uncertainty of the speed. [m/s]
    valid_flags: _t.OdometerDataValidFlags = _t.OdometerDataValidFlags(0)  # Bit 0 set when the odometer is configured.

    SET = 0x80
    DESCRIPTOR = 0x40
    NAME = "odometer_data"
    ROLE = "data"
    _ATTRS = ("speed", "uncertainty", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("speed", _c.F32), _c.P("uncertainty", _c.F32), _c.P("valid_flags", _c.flags(_t.OdometerDataValidFlags))
        ),
    )


FIELDS: tuple[type[_c.Field], ...] = (
    ScaledAccel,
    ScaledGyro,
    ScaledMag,
    DeltaTheta,
    DeltaVelocity,
    CfOrientationMatrix,
    CfQuaternion,
    CfEulerAngles,
    CfStabilizedNorth,
    CfStabilizedUp,
    GpsTimestamp,
    TemperatureStatistics,
    ScaledPressure,
    OverrangeStatus,
    OdometerData,
)
