"""Estimation Filter Data Set (descriptor set 0x82, data).

Outputs of the navigation (Kalman) filter: its status and timestamp, the estimated position,
velocity and attitude with their 1-sigma uncertainties, the estimated sensor biases, and
bias-compensated inertial quantities.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class LlhPosition(_c.Field):
    """LLH position (set 0x82, descriptor 0x01, data).

    Estimated position as WGS84 geodetic latitude, longitude and height above the ellipsoid.

    Sources: 3dm-gx5-45-dcp.txt line 2380; 3dm-cv7-ins-docs.txt line 4181. Field data: 26 bytes.
    """

    latitude: float = 0.0  # Latitude. [deg]
    longitude: float = 0.0  # Longitude. [deg]
    ellipsoid_height: float = 0.0  # Height above the WGS84 ellipsoid. [m]
    # Whether latitude, longitude and height are valid.
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)

    SET = 0x82
    DESCRIPTOR = 0x01
    NAME = "llh_position"
    ROLE = "data"
    _ATTRS = ("latitude", "longitude", "ellipsoid_height", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("latitude", _c.F64),
            _c.P("longitude", _c.F64),
            _c.P("ellipsoid_height", _c.F64),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class NedVelocity(_c.Field):
    """NED velocity (set 0x82, descriptor 0x02, data).

    Estimated velocity in the local-level north-east-down frame.

    Sources: 3dm-gx5-45-dcp.txt line 2402; 3dm-cv7-ins-docs.txt line 4195. Field data: 14 bytes.
    """

    north: float = 0.0  # North velocity. [m/s]
    east: float = 0.0  # East velocity. [m/s]
    down: float = 0.0  # Down velocity. [m/s]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the velocity is valid.

    SET = 0x82
    DESCRIPTOR = 0x02
    NAME = "ned_velocity"
    ROLE = "data"
    _ATTRS = ("north", "east", "down", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("north", _c.F32),
            _c.P("east", _c.F32),
            _c.P("down", _c.F32),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class AttitudeQuaternion(_c.Field):
    """Attitude quaternion (set 0x82, descriptor 0x03, data).

    Estimated orientation as a quaternion (q0, q1 i, q2 j, q3 k) rotating vectors from the
    earth-fixed local-level (NED) frame into the device (vehicle) frame.

    Sources: 3dm-gx5-45-dcp.txt line 2425; 3dm-cv7-ins-docs.txt line 4209. Field data: 18 bytes.
    """

    # Quaternion (q0, q1, q2, q3); the GX5-45 lists the four floats separately.
    q: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 4)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the quaternion is valid.

    SET = 0x82
    DESCRIPTOR = 0x03
    NAME = "attitude_quaternion"
    ROLE = "data"
    _ATTRS = ("q", "valid_flags")
    _OPS = (_c.Run(_c.P("q", _c.F32, 4), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class AttitudeDcm(_c.Field):
    """Attitude direction cosine matrix (set 0x82, descriptor 0x04, data).

    Estimated orientation as a 3x3 direction cosine matrix, row-major (M11, M12, M13, M21, ...),
    that transforms a vector from the earth-fixed local-level (NED) frame into the device (vehicle)
    frame.

    Sources: 3dm-gx5-45-dcp.txt line 2473; 3dm-cv7-ins-docs.txt line 4221. Field data: 38 bytes.
    """

    # Matrix elements in row-major order; the GX5-45 lists M1,1 ... M3,3 at offsets 0-32.
    dcm: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 9)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the matrix is valid.

    SET = 0x82
    DESCRIPTOR = 0x04
    NAME = "attitude_dcm"
    ROLE = "data"
    _ATTRS = ("dcm", "valid_flags")
    _OPS = (_c.Run(_c.P("dcm", _c.F32, 9), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class EulerAngles(_c.Field):
    """Euler angles (set 0x82, descriptor 0x05, data).

    Estimated roll, pitch and yaw relative to the local-level (NED) frame, in 3-2-1 (yaw-pitch-roll,
    aircraft) order.

    Sources: 3dm-gx5-45-dcp.txt line 2451; 3dm-cv7-ins-docs.txt line 4233. Field data: 14 bytes.
    """

    roll: float = 0.0  # Roll angle. [rad]
    pitch: float = 0.0  # Pitch angle. [rad]
    yaw: float = 0.0  # Yaw (heading) angle. [rad]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the angles are valid.

    SET = 0x82
    DESCRIPTOR = 0x05
    NAME = "euler_angles"
    ROLE = "data"
    _ATTRS = ("roll", "pitch", "yaw", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("roll", _c.F32),
            _c.P("pitch", _c.F32),
            _c.P("yaw", _c.F32),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class GyroBias(_c.Field):
    """Gyro bias (set 0x82, descriptor 0x06, data).

    Estimated gyro bias, in the sensor frame.

    Sources: 3dm-gx5-45-dcp.txt line 2505; 3dm-cv7-ins-docs.txt line 4247. Field data: 14 bytes.
    """

    bias: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) gyro bias. [rad/s]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the bias is valid.

    SET = 0x82
    DESCRIPTOR = 0x06
    NAME = "gyro_bias"
    ROLE = "data"
    _ATTRS = ("bias", "valid_flags")
    _OPS = (_c.Run(_c.P("bias", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class AccelBias(_c.Field):
    """Accel bias (set 0x82, descriptor 0x07, data).

    Estimated accelerometer bias, in the sensor frame.

    Sources: 3dm-gx5-45-dcp.txt line 2573; 3dm-cv7-ins-docs.txt line 4259. Field data: 14 bytes.
    """

    bias: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) accelerometer bias. [m/s^2]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the bias is valid.

    SET = 0x82
    DESCRIPTOR = 0x07
    NAME = "accel_bias"
    ROLE = "data"
    _ATTRS = ("bias", "valid_flags")
    _OPS = (_c.Run(_c.P("bias", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class LlhPositionUncertainty(_c.Field):
    """LLH position uncertainty (set 0x82, descriptor 0x08, data).

    1-sigma uncertainty of the estimated position, along the local-level north, east and down axes.

    Sources: 3dm-gx5-45-dcp.txt line 2391; 3dm-cv7-ins-docs.txt line 4271. Field data: 14 bytes.
    """

    north: float = 0.0  # North 1-sigma uncertainty. [m]
    east: float = 0.0  # East 1-sigma uncertainty. [m]
    down: float = 0.0  # Down 1-sigma uncertainty. [m]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the uncertainties are valid.

    SET = 0x82
    DESCRIPTOR = 0x08
    NAME = "llh_position_uncertainty"
    ROLE = "data"
    _ATTRS = ("north", "east", "down", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("north", _c.F32),
            _c.P("east", _c.F32),
            _c.P("down", _c.F32),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class NedVelocityUncertainty(_c.Field):
    """NED velocity uncertainty (set 0x82, descriptor 0x09, data).

    1-sigma uncertainty of the estimated velocity, along the local-level north, east and down axes.

    Sources: 3dm-gx5-45-dcp.txt line 2413; 3dm-cv7-ins-docs.txt line 4285. Field data: 14 bytes.
    """

    north: float = 0.0  # North 1-sigma uncertainty. [m/s]
    east: float = 0.0  # East 1-sigma uncertainty. [m/s]
    down: float = 0.0  # Down 1-sigma uncertainty. [m/s]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the uncertainties are valid.

    SET = 0x82
    DESCRIPTOR = 0x09
    NAME = "ned_velocity_uncertainty"
    ROLE = "data"
    _ATTRS = ("north", "east", "down", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("north", _c.F32),
            _c.P("east", _c.F32),
            _c.P("down", _c.F32),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class EulerAnglesUncertainty(_c.Field):
    """Euler angles uncertainty (set 0x82, descriptor 0x0A, data).

    1-sigma uncertainty of the estimated roll, pitch and yaw. The GX5-45 derives these from the
    quaternion uncertainty and flags them invalid when the pitch exceeds +/-70 degrees.

    Sources: 3dm-gx5-45-dcp.txt line 2462; 3dm-cv7-ins-docs.txt line 4299. Field data: 14 bytes.
    """

    roll: float = 0.0  # Roll 1-sigma uncertainty. [rad]
    pitch: float = 0.0  # Pitch 1-sigma uncertainty. [rad]
    yaw: float = 0.0  # Yaw 1-sigma uncertainty. [rad]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the uncertainties are valid.

    SET = 0x82
    DESCRIPTOR = 0x0A
    NAME = "euler_angles_uncertainty"
    ROLE = "data"
    _ATTRS = ("roll", "pitch", "yaw", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("roll", _c.F32),
            _c.P("pitch", _c.F32),
            _c.P("yaw", _c.F32),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class GyroBiasUncertainty(_c.Field):
    """Gyro bias uncertainty (set 0x82, descriptor 0x0B, data).

    1-sigma uncertainty of the estimated gyro bias, in the sensor frame.

    Sources: 3dm-gx5-45-dcp.txt line 2516; 3dm-cv7-ins-docs.txt line 4313. Field data: 14 bytes.
    """

    # (x, y, z) 1-sigma uncertainty. [rad/s]
    bias_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the uncertainties are valid.

    SET = 0x82
    DESCRIPTOR = 0x0B
    NAME = "gyro_bias_uncertainty"
    ROLE = "data"
    _ATTRS = ("bias_uncertainty", "valid_flags")
    _OPS = (_c.Run(_c.P("bias_uncertainty", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class AccelBiasUncertainty(_c.Field):
    """Accel bias uncertainty (set 0x82, descriptor 0x0C, data).

    1-sigma uncertainty of the estimated accelerometer bias, in the sensor frame.

    Sources: 3dm-gx5-45-dcp.txt line 2585; 3dm-cv7-ins-docs.txt line 4325. Field data: 14 bytes.
    """

    # (x, y, z) 1-sigma uncertainty. [m/s^2]
    bias_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the uncertainties are valid.

    SET = 0x82
    DESCRIPTOR = 0x0C
    NAME = "accel_bias_uncertainty"
    ROLE = "data"
    _ATTRS = ("bias_uncertainty", "valid_flags")
    _OPS = (_c.Run(_c.P("bias_uncertainty", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class LinearAccel(_c.Field):
    """Linear acceleration (set 0x82, descriptor 0x0D, data).

    Filter-compensated acceleration with the estimated gravity removed, in the vehicle frame
    (GX5-45: in the sensor frame when no sensor-to-vehicle rotation is set).

    Sources: 3dm-gx5-45-dcp.txt line 2562; 3dm-cv7-ins-docs.txt line 4337. Field data: 14 bytes.
    """

    accel: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) linear acceleration. [m/s^2]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the acceleration is valid.

    SET = 0x82
    DESCRIPTOR = 0x0D
    NAME = "linear_accel"
    ROLE = "data"
    _ATTRS = ("accel", "valid_flags")
    _OPS = (_c.Run(_c.P("accel", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class CompAngularRate(_c.Field):
    """Compensated angular rate (set 0x82, descriptor 0x0E, data).

    Angular rate with the estimated gyro bias removed, in the vehicle frame (GX5-45: in the sensor
    frame when no sensor-to-vehicle rotation is set).

    Sources: 3dm-gx5-45-dcp.txt line 2494; 3dm-cv7-ins-docs.txt line 4351. Field data: 14 bytes.
    """

    gyro: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) angular rate. [rad/s]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the angular rate is valid.

    SET = 0x82
    DESCRIPTOR = 0x0E
    NAME = "comp_angular_rate"
    ROLE = "data"
    _ATTRS = ("gyro", "valid_flags")
    _OPS = (_c.Run(_c.P("gyro", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class Wgs84GravityMagnitude(_c.Field):
    """WGS84 local gravity magnitude (set 0x82, descriptor 0x0F, data).

    Magnitude of the local gravity from the WGS84 gravity model (valid for altitudes up to 20 km).
    GX5-45 only.

    Sources: 3dm-gx5-45-dcp.txt line 2652. Field data: 6 bytes.
    """

    gravity_magnitude: float = 0.0  # Local gravity magnitude. [m/s^2]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the gravity value is valid.

    SET = 0x82
    DESCRIPTOR = 0x0F
    NAME = "wgs84_gravity_magnitude"
    ROLE = "data"
    _ATTRS = ("gravity_magnitude", "valid_flags")
    _OPS = (_c.Run(_c.P("gravity_magnitude", _c.F32), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class FilterStatus_gx5_45(_c.Field):
    """Filter status (set 0x82, descriptor 0x10, data), device gx5_45.

    Filter state (or mode), dynamics mode and status flags. All three are device-specific: the same
    numbers mean different things on the GX5-45 and on the CV7.

    Sources: 3dm-gx5-45-dcp.txt line 2356. Field data: 6 bytes.
    """

    filter_state: _ty.Union[_t.FilterStateGx5, int] = _t.FilterStateGx5.STARTUP  # Filter state.
    # Vehicle dynamics mode.
    dynamics_mode: _ty.Union[_t.FilterDynamicsModeGx5, int] = _t.FilterDynamicsModeGx5.PORTABLE
    # Status flags; their meaning depends on the filter state.
    status_flags: _t.FilterStatusFlagsGx5 = _t.FilterStatusFlagsGx5(0)

    SET = 0x82
    DESCRIPTOR = 0x10
    NAME = "filter_status"
    ROLE = "data"
    DEVICE = "gx5_45"
    _ATTRS = ("filter_state", "dynamics_mode", "status_flags")
    _OPS = (
        _c.Run(
            _c.P("filter_state", _c.enum(_t.FilterStateGx5, "u16")),
            _c.P("dynamics_mode", _c.enum(_t.FilterDynamicsModeGx5, "u16")),
            _c.P("status_flags", _c.flags(_t.FilterStatusFlagsGx5)),
        ),
    )


@_c.slotted
@_dc.dataclass
class FilterStatus_cv7_ins(_c.Field):
    """Filter status (set 0x82, descriptor 0x10, data), device cv7_ins.

    Filter state (or mode), dynamics mode and status flags. All three are device-specific: the same
    numbers mean different things on the GX5-45 and on the CV7.

    Sources: 3dm-cv7-ins-docs.txt line 4363. Field data: 6 bytes.
    """

    filter_state: _ty.Union[_t.FilterModeCv7, int] = _t.FilterModeCv7.INIT  # Filter mode reached (Filter States page).
    dynamics_mode: _ty.Union[_t.FilterDynamicsModeCv7, int] = _t.FilterDynamicsModeCv7.DEFAULT  # Dynamics mode.
    status_flags: _t.FilterStatusFlagsCv7 = _t.FilterStatusFlagsCv7(0)  # Filter condition and warning flags.

    SET = 0x82
    DESCRIPTOR = 0x10
    NAME = "filter_status"
    ROLE = "data"
    DEVICE = "cv7_ins"
    _ATTRS = ("filter_state", "dynamics_mode", "status_flags")
    _OPS = (
        _c.Run(
            _c.P("filter_state", _c.enum(_t.FilterModeCv7, "u16")),
            _c.P("dynamics_mode", _c.enum(_t.FilterDynamicsModeCv7, "u16")),
            _c.P("status_flags", _c.flags(_t.FilterStatusFlagsCv7)),
        ),
    )


@_c.slotted
@_dc.dataclass
class GpsTimestamp(_c.Field):
    """GPS timestamp (set 0x82, descriptor 0x11, data).

    GPS time of the filter solution in this packet. The CV7 notes that it may be deprecated in
    favour of the shared GPS timestamp field (0xD3).

    Sources: 3dm-gx5-45-dcp.txt line 2370; 3dm-cv7-ins-docs.txt line 4420. Field data: 12 bytes.
    """

    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number since 1980. [weeks]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the time is valid.

    SET = 0x82
    DESCRIPTOR = 0x11
    NAME = "gps_timestamp"
    ROLE = "data"
    _ATTRS = ("tow", "week_number", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("tow", _c.F64), _c.P("week_number", _c.U16), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))
        ),
    )


@_c.slotted
@_dc.dataclass
class QuaternionAttitudeUncertainty(_c.Field):
    """Quaternion attitude uncertainty (set 0x82, descriptor 0x12, data).

    1-sigma uncertainty of the attitude quaternion, one value per quaternion element
    (dimensionless).

    Sources: 3dm-gx5-45-dcp.txt line 2439; 3dm-cv7-ins-docs.txt line 4433. Field data: 18 bytes.
    """

    q: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 4)  # 1-sigma uncertainty of (q0, q1, q2, q3).
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Whether the uncertainties are valid.

    SET = 0x82
    DESCRIPTOR = 0x12
    NAME = "quaternion_attitude_uncertainty"
    ROLE = "data"
    _ATTRS = ("q", "valid_flags")
    _OPS = (_c.Run(_c.P("q", _c.F32, 4), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class GravityVector(_c.Field):
    """Gravity vector (set 0x82, descriptor 0x13, data).

    Estimated gravity vector. GX5-45: in the sensor frame, or in the vehicle frame when a
    sensor-to-vehicle transformation is set; CV7: in the vehicle frame.

    Sources: 3dm-gx5-45-dcp.txt line 2641; 3dm-cv7-ins-docs.txt line 4445. Field data: 14 bytes.
    """

    gravity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) gravity. [m/s^2]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Gravity vector valid.

    SET = 0x82
    DESCRIPTOR = 0x13
    NAME = "gravity_vector"
    ROLE = "data"
    _ATTRS = ("gravity", "valid_flags")
    _OPS = (_c.Run(_c.P("gravity", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class HeadingUpdateState(_c.Field):
    """Heading update source state (set 0x82, descriptor 0x14, data).

    The last heading update the filter received: heading (relative to true north), its uncertainty
    and the sources in use.

    Sources: 3dm-gx5-45-dcp.txt line 2663. Field data: 12 bytes.
    """

    heading: float = 0.0  # Heading, from true north. [rad]
    heading_uncertainty: float = 0.0  # 1-sigma heading uncertainty. [rad]
    # Heading update sources in use (may be combined).
    source: _t.FilterHeadingSourceFlags = _t.FilterHeadingSourceFlags(0)
    # Whether a heading update arrived within 2 seconds.
    valid_flags: _t.FilterHeadingUpdateValidFlags = _t.FilterHeadingUpdateValidFlags(0)

    SET = 0x82
    DESCRIPTOR = 0x14
    NAME = "heading_update_state"
    ROLE = "data"
    _ATTRS = ("heading", "heading_uncertainty", "source", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("heading", _c.F32),
            _c.P("heading_uncertainty", _c.F32),
            _c.P("source", _c.flags(_t.FilterHeadingSourceFlags)),
            _c.P("valid_flags", _c.flags(_t.FilterHeadingUpdateValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class MagneticModel(_c.Field):
    """Magnetic model solution (set 0x82, descriptor 0x15, data).

    Earth magnetic field at the current position from the World Magnetic Model (GX5-45: WMM 2010),
    in the NED frame; needs a valid GNSS position. Invalid while the model is being recalculated and
    when GNSS is unavailable.

    Sources: 3dm-gx5-45-dcp.txt line 2675; 3dm-cv7-ins-docs.txt line 4457. Field data: 22 bytes.
    """

    intensity_north: float = 0.0  # North component of the field. [gauss]
    intensity_east: float = 0.0  # East component of the field. [gauss]
    intensity_down: float = 0.0  # Down component of the field. [gauss]
    inclination: float = 0.0  # Inclination (dip) angle. [rad]
    declination: float = 0.0  # Declination angle. [rad]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Model solution valid.

    SET = 0x82
    DESCRIPTOR = 0x15
    NAME = "magnetic_model"
    ROLE = "data"
    _ATTRS = ("intensity_north", "intensity_east", "intensity_down", "inclination", "declination", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("intensity_north", _c.F32),
            _c.P("intensity_east", _c.F32),
            _c.P("intensity_down", _c.F32),
            _c.P("inclination", _c.F32),
            _c.P("declination", _c.F32),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class GyroScaleFactor(_c.Field):
    """Gyro scale factor (set 0x82, descriptor 0x16, data).

    Estimated gyro scale factor errors in the sensor body frame.

    Sources: 3dm-gx5-45-dcp.txt line 2527. Field data: 14 bytes.
    """

    # (x, y, z) scale factor, as a fraction (percent / 100). [%/100]
    scale_factor: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Scale factor values valid.

    SET = 0x82
    DESCRIPTOR = 0x16
    NAME = "gyro_scale_factor"
    ROLE = "data"
    _ATTRS = ("scale_factor", "valid_flags")
    _OPS = (_c.Run(_c.P("scale_factor", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class AccelScaleFactor(_c.Field):
    """Accelerometer scale factor (set 0x82, descriptor 0x17, data).

    Estimated accelerometer scale factor errors in the sensor body frame.

    Sources: 3dm-gx5-45-dcp.txt line 2597. Field data: 14 bytes.
    """

    # (x, y, z) scale factor, as a fraction (percent / 100). [%/100]
    scale_factor: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Scale factor values valid.

    SET = 0x82
    DESCRIPTOR = 0x17
    NAME = "accel_scale_factor"
    ROLE = "data"
    _ATTRS = ("scale_factor", "valid_flags")
    _OPS = (_c.Run(_c.P("scale_factor", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class GyroScaleFactorUncertainty(_c.Field):
    """Gyro scale factor uncertainty (set 0x82, descriptor 0x18, data).

    1-sigma uncertainty of the estimated gyro scale factors, sensor body frame.

    Sources: 3dm-gx5-45-dcp.txt line 2538. Field data: 14 bytes.
    """

    # (x, y, z) 1-sigma uncertainty. [%/100]
    scale_factor_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Uncertainties valid.

    SET = 0x82
    DESCRIPTOR = 0x18
    NAME = "gyro_scale_factor_uncertainty"
    ROLE = "data"
    _ATTRS = ("scale_factor_uncertainty", "valid_flags")
    _OPS = (
        _c.Run(_c.P("scale_factor_uncertainty", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),
    )


@_c.slotted
@_dc.dataclass
class AccelScaleFactorUncertainty(_c.Field):
    """Accelerometer scale factor uncertainty (set 0x82, descriptor 0x19, data).

    1-sigma uncertainty of the estimated accelerometer scale factors, sensor body frame.

    Sources: 3dm-gx5-45-dcp.txt line 2608. Field data: 14 bytes.
    """

    # (x, y, z) 1-sigma uncertainty. [%/100]
    scale_factor_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Uncertainties valid.

    SET = 0x82
    DESCRIPTOR = 0x19
    NAME = "accel_scale_factor_uncertainty"
    ROLE = "data"
    _ATTRS = ("scale_factor_uncertainty", "valid_flags")
    _OPS = (
        _c.Run(_c.P("scale_factor_uncertainty", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),
    )


@_c.slotted
@_dc.dataclass
class CompensatedAccel(_c.Field):
    """Compensated acceleration (set 0x82, descriptor 0x1C, data).

    Acceleration with the filter's bias estimate removed (gravity included; 0x0D is the linear
    acceleration without gravity). GX5-45: sensor frame, or vehicle frame when a sensor-to-vehicle
    transformation is set; CV7: vehicle frame.

    Sources: 3dm-gx5-45-dcp.txt line 2549; 3dm-cv7-ins-docs.txt line 4473. Field data: 14 bytes.
    """

    accel: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) compensated acceleration. [m/s^2]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Compensated accelerations valid.

    SET = 0x82
    DESCRIPTOR = 0x1C
    NAME = "compensated_accel"
    ROLE = "data"
    _ATTRS = ("accel", "valid_flags")
    _OPS = (_c.Run(_c.P("accel", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class StandardAtmosphere(_c.Field):
    """Standard atmosphere model (set 0x82, descriptor 0x20, data).

    US 1976 Standard Atmosphere values at the current altitude; needs a valid GNSS location (invalid
    while GNSS is unavailable).

    Sources: 3dm-gx5-45-dcp.txt line 2628. Field data: 22 bytes.
    """

    geometric_altitude: float = 0.0  # Geometric altitude. [m]
    geopotential_altitude: float = 0.0  # Geopotential altitude. [m]
    temperature: float = 0.0  # Standard temperature. [degC]
    pressure: float = 0.0  # Standard pressure. [mbar]
    density: float = 0.0  # Standard air density. [kg/m^3]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Atmosphere model solution valid.

    SET = 0x82
    DESCRIPTOR = 0x20
    NAME = "standard_atmosphere"
    ROLE = "data"
    _ATTRS = ("geometric_altitude", "geopotential_altitude", "temperature", "pressure", "density", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("geometric_altitude", _c.F32),
            _c.P("geopotential_altitude", _c.F32),
            _c.P("temperature", _c.F32),
            _c.P("pressure", _c.F32),
            _c.P("density", _c.F32),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class PressureAltitude(_c.Field):
    """Pressure altitude (set 0x82, descriptor 0x21, data).

    Altitude from the pressure sensor through the US 1976 Standard Atmosphere model; needs a valid
    pressure reading. The model supports pressures down to 0.0037 mbar (84,852 m).

    Sources: 3dm-gx5-45-dcp.txt line 2619; 3dm-cv7-ins-docs.txt line 4485. Field data: 6 bytes.
    """

    pressure_altitude: float = 0.0  # Pressure altitude. [m]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Pressure altitude valid.

    SET = 0x82
    DESCRIPTOR = 0x21
    NAME = "pressure_altitude"
    ROLE = "data"
    _ATTRS = ("pressure_altitude", "valid_flags")
    _OPS = (_c.Run(_c.P("pressure_altitude", _c.F32), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class MagAutoHardIronOffset(_c.Field):
    """Magnetometer auto hard iron offset (set 0x82, descriptor 0x25, data).

    Offset vector the filter adds to the hard iron offset to compensate in-run magnetometer bias
    errors.

    Sources: 3dm-gx5-45-dcp.txt line 2689. Field data: 14 bytes.
    """

    hard_iron_offset: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) offset. [gauss]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Vector valid.

    SET = 0x82
    DESCRIPTOR = 0x25
    NAME = "mag_auto_hard_iron_offset"
    ROLE = "data"
    _ATTRS = ("hard_iron_offset", "valid_flags")
    _OPS = (_c.Run(_c.P("hard_iron_offset", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class MagAutoSoftIronMatrix(_c.Field):
    """Magnetometer auto soft iron matrix (set 0x82, descriptor 0x26, data).

    Matrix the filter applies to the soft iron calibration matrix to compensate in-run magnetometer
    errors.

    Sources: 3dm-gx5-45-dcp.txt line 2711. Field data: 38 bytes.
    """

    # M11..M33, row-major (dimensionless).
    soft_iron_matrix: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 9)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Matrix valid.

    SET = 0x82
    DESCRIPTOR = 0x26
    NAME = "mag_auto_soft_iron_matrix"
    ROLE = "data"
    _ATTRS = ("soft_iron_matrix", "valid_flags")
    _OPS = (_c.Run(_c.P("soft_iron_matrix", _c.F32, 9), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class MagAutoHardIronOffsetUncertainty(_c.Field):
    """Magnetometer auto hard iron offset uncertainty (set 0x82, descriptor 0x28, data).

    1-sigma uncertainty of the auto hard iron offset (0x82,0x25).

    Sources: 3dm-gx5-45-dcp.txt line 2700. Field data: 14 bytes.
    """

    # (x, y, z) 1-sigma uncertainty. [gauss]
    hard_iron_offset_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Vector valid.

    SET = 0x82
    DESCRIPTOR = 0x28
    NAME = "mag_auto_hard_iron_offset_uncertainty"
    ROLE = "data"
    _ATTRS = ("hard_iron_offset_uncertainty", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("hard_iron_offset_uncertainty", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))
        ),
    )


@_c.slotted
@_dc.dataclass
class MagAutoSoftIronMatrixUncertainty(_c.Field):
    """Magnetometer auto soft iron matrix uncertainty (set 0x82, descriptor 0x29, data).

    1-sigma uncertainty of each element of the auto soft iron matrix (0x82,0x26).

    Sources: 3dm-gx5-45-dcp.txt line 2728. Field data: 38 bytes.
    """

    # 1-sigma uncertainty of M11..M33, row-major (dimensionless).
    soft_iron_matrix_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 9)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Matrix valid.

    SET = 0x82
    DESCRIPTOR = 0x29
    NAME = "mag_auto_soft_iron_matrix_uncertainty"
    ROLE = "data"
    _ATTRS = ("soft_iron_matrix_uncertainty", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("soft_iron_matrix_uncertainty", _c.F32, 9), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))
        ),
    )


@_c.slotted
@_dc.dataclass
class GnssAntennaOffsetCorrection(_c.Field):
    """GNSS antenna offset correction (set 0x82, descriptor 0x30, data).

    Estimated correction of the GNSS antenna offset (the vector from the IMU to the antenna), in the
    sensor body frame.

    Sources: 3dm-gx5-45-dcp.txt line 2745. Field data: 14 bytes.
    """

    offset: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) offset correction. [m]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Offset correction values valid.

    SET = 0x82
    DESCRIPTOR = 0x30
    NAME = "gnss_antenna_offset_correction"
    ROLE = "data"
    _ATTRS = ("offset", "valid_flags")
    _OPS = (_c.Run(_c.P("offset", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class GnssAntennaOffsetCorrectionUncertainty(_c.Field):
    """GNSS antenna offset correction uncertainty (set 0x82, descriptor 0x31, data).

    1-sigma uncertainty of the GNSS antenna offset correction, sensor body frame.

    Sources: 3dm-gx5-45-dcp.txt line 2756. Field data: 14 bytes.
    """

    # (x, y, z) 1-sigma uncertainty. [m]
    offset_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Uncertainties valid.

    SET = 0x82
    DESCRIPTOR = 0x31
    NAME = "gnss_antenna_offset_correction_uncertainty"
    ROLE = "data"
    _ATTRS = ("offset_uncertainty", "valid_flags")
    _OPS = (_c.Run(_c.P("offset_uncertainty", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class MultiAntennaOffsetCorrection(_c.Field):
    """Multi-antenna offset correction (set 0x82, descriptor 0x34, data).

    Estimated correction of one GNSS antenna's offset, in the vehicle frame; added to the stored
    offset vector to compensate errors in its definition.

    Sources: 3dm-cv7-ins-docs.txt line 4497. Field data: 15 bytes.
    """

    receiver_id: int = 0  # Receiver to which the antenna is attached.
    offset: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) offset correction. [m]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Offset correction valid.

    SET = 0x82
    DESCRIPTOR = 0x34
    NAME = "multi_antenna_offset_correction"
    ROLE = "data"
    _ATTRS = ("receiver_id", "offset", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("receiver_id", _c.U8),
            _c.P("offset", _c.F32, 3),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class MultiAntennaOffsetCorrectionUncertainty(_c.Field):
    """Multi-antenna offset correction uncertainty (set 0x82, descriptor 0x35, data).

    1-sigma uncertainty of one GNSS antenna's offset correction, vehicle frame.

    Sources: 3dm-cv7-ins-docs.txt line 4512. Field data: 15 bytes.
    """

    receiver_id: int = 0  # Receiver to which the antenna is attached.
    # (x, y, z) 1-sigma uncertainty. [m]
    offset_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Uncertainties valid.

    SET = 0x82
    DESCRIPTOR = 0x35
    NAME = "multi_antenna_offset_correction_uncertainty"
    ROLE = "data"
    _ATTRS = ("receiver_id", "offset_uncertainty", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("receiver_id", _c.U8),
            _c.P("offset_uncertainty", _c.F32, 3),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class EcefPositionUncertainty(_c.Field):
    """ECEF position uncertainty (set 0x82, descriptor 0x36, data).

    1-sigma position uncertainty in the ECEF frame.

    Sources: 3dm-cv7-ins-docs.txt line 4525. Field data: 14 bytes.
    """

    # (x, y, z) 1-sigma uncertainty. [m]
    position_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Uncertainties valid.

    SET = 0x82
    DESCRIPTOR = 0x36
    NAME = "ecef_position_uncertainty"
    ROLE = "data"
    _ATTRS = ("position_uncertainty", "valid_flags")
    _OPS = (_c.Run(_c.P("position_uncertainty", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class EcefVelocityUncertainty(_c.Field):
    """ECEF velocity uncertainty (set 0x82, descriptor 0x37, data).

    1-sigma velocity uncertainty in the ECEF frame.

    Sources: 3dm-cv7-ins-docs.txt line 4537. Field data: 14 bytes.
    """

    # (x, y, z) 1-sigma uncertainty. [m/s]
    velocity_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Uncertainties valid.

    SET = 0x82
    DESCRIPTOR = 0x37
    NAME = "ecef_velocity_uncertainty"
    ROLE = "data"
    _ATTRS = ("velocity_uncertainty", "valid_flags")
    _OPS = (_c.Run(_c.P("velocity_uncertainty", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class EcefPosition(_c.Field):
    """ECEF position (set 0x82, descriptor 0x40, data).

    Estimated position in the ECEF frame.

    Sources: 3dm-cv7-ins-docs.txt line 4549. Field data: 26 bytes.
    """

    position: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) ECEF position. [m]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Position valid.

    SET = 0x82
    DESCRIPTOR = 0x40
    NAME = "ecef_position"
    ROLE = "data"
    _ATTRS = ("position", "valid_flags")
    _OPS = (_c.Run(_c.P("position", _c.F64, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class EcefVelocity(_c.Field):
    """ECEF velocity (set 0x82, descriptor 0x41, data).

    Estimated velocity in the ECEF frame.

    Sources: 3dm-cv7-ins-docs.txt line 4561. Field data: 14 bytes.
    """

    velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) ECEF velocity. [m/s]
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Velocity valid.

    SET = 0x82
    DESCRIPTOR = 0x41
    NAME = "ecef_velocity"
    ROLE = "data"
    _ATTRS = ("velocity", "valid_flags")
    _OPS = (_c.Run(_c.P("velocity", _c.F32, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class NedRelativePosition(_c.Field):
    """NED relative position (set 0x82, descriptor 0x42, data).

    Estimated position relative to the reference position set with Relative Position Configuration
    (0x0D,0x55), as north, east, down.

    Sources: 3dm-cv7-ins-docs.txt line 4573. Field data: 26 bytes.
    """

    # (north, east, down) position relative to the reference. [m]
    relative_position: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Relative position valid.

    SET = 0x82
    DESCRIPTOR = 0x42
    NAME = "ned_relative_position"
    ROLE = "data"
    _ATTRS = ("relative_position", "valid_flags")
    _OPS = (_c.Run(_c.P("relative_position", _c.F64, 3), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class GnssPositionAidingStatus(_c.Field):
    """GNSS position aiding status (set 0x82, descriptor 0x43, data).

    How the filter is using the position measurements of one GNSS receiver.

    Sources: 3dm-cv7-ins-docs.txt line 4585. Field data: 15 bytes.
    """

    receiver_id: int = 0  # GNSS receiver the status refers to.
    time_of_week: float = 0.0  # GPS time of week of the last GNSS aiding measurement. [s]
    status: _t.FilterGnssAidingStatusFlags = _t.FilterGnssAidingStatusFlags(0)  # Aiding measurement status.
    reserved: _ty.List[int] = _dc.field(default_factory=lambda: [0] * 8)  # Reserved.

    SET = 0x82
    DESCRIPTOR = 0x43
    NAME = "gnss_position_aiding_status"
    ROLE = "data"
    _ATTRS = ("receiver_id", "time_of_week", "status", "reserved")
    _OPS = (
        _c.Run(
            _c.P("receiver_id", _c.U8),
            _c.P("time_of_week", _c.F32),
            _c.P("status", _c.flags(_t.FilterGnssAidingStatusFlags)),
            _c.P("reserved", _c.U8, 8),
        ),
    )


@_c.slotted
@_dc.dataclass
class AidingMeasurementSummary(_c.Field):
    """Aiding measurement summary (set 0x82, descriptor 0x46, data).

    Summary of one aiding measurement over the measurement interval ending at the given time:
    whether it is enabled and used, and any warnings.

    Sources: 3dm-cv7-ins-docs.txt line 4616. Field data: 7 bytes.
    """

    time_of_week: float = 0.0  # GPS time of week at the end of the measurement interval. [s]
    source: int = 0  # Measurement source (not described by the manual).
    # Which aiding measurement is summarised.
    type: _ty.Union[_t.FilterAidingMeasurementType, int] = _t.FilterAidingMeasurementType.GNSS
    # Measurement state and warnings.
    indicator: _t.FilterAidingMeasurementIndicator = _t.FilterAidingMeasurementIndicator(0)

    SET = 0x82
    DESCRIPTOR = 0x46
    NAME = "aiding_measurement_summary"
    ROLE = "data"
    _ATTRS = ("time_of_week", "source", "type", "indicator")
    _OPS = (
        _c.Run(
            _c.P("time_of_week", _c.F32),
            _c.P("source", _c.U8),
            _c.P("type", _c.enum(_t.FilterAidingMeasurementType, "u8")),
            _c.P("indicator", _c.flags(_t.FilterAidingMeasurementIndicator)),
        ),
    )


@_c.slotted
@_dc.dataclass
class OdometerScaleFactorError(_c.Field):
    """Odometer scale factor error (set 0x82, descriptor 0x47, data).

    Estimated odometer scale factor error; the total scale factor is the user scale factor times (1
    + this error).

    Sources: 3dm-cv7-ins-docs.txt line 4654. Field data: 6 bytes.
    """

    scale_factor_error: float = 0.0  # Scale factor error (dimensionless).
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Estimate valid.

    SET = 0x82
    DESCRIPTOR = 0x47
    NAME = "odometer_scale_factor_error"
    ROLE = "data"
    _ATTRS = ("scale_factor_error", "valid_flags")
    _OPS = (_c.Run(_c.P("scale_factor_error", _c.F32), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))),)


@_c.slotted
@_dc.dataclass
class OdometerScaleFactorErrorUncertainty(_c.Field):
    """Odometer scale factor error uncertainty (set 0x82, descriptor 0x48, data).

    1-sigma uncertainty of the odometer scale factor error.

    Sources: 3dm-cv7-ins-docs.txt line 4667. Field data: 6 bytes.
    """

    scale_factor_error_uncertainty: float = 0.0  # 1-sigma uncertainty (dimensionless).
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Uncertainty valid.

    SET = 0x82
    DESCRIPTOR = 0x48
    NAME = "odometer_scale_factor_error_uncertainty"
    ROLE = "data"
    _ATTRS = ("scale_factor_error_uncertainty", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("scale_factor_error_uncertainty", _c.F32), _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags))
        ),
    )


@_c.slotted
@_dc.dataclass
class GnssDualAntennaStatus(_c.Field):
    """GNSS dual antenna status (set 0x82, descriptor 0x49, data).

    State of the GNSS dual-antenna heading measurement the filter last used.

    Sources: 3dm-cv7-ins-docs.txt line 4679. Field data: 17 bytes.
    """

    time_of_week: float = 0.0  # GPS time of week of the last dual-antenna aiding measurement. [s]
    heading: float = 0.0  # Dual-antenna heading. [rad]
    heading_uncertainty: float = 0.0  # 1-sigma heading uncertainty. [rad]
    fix_type: _ty.Union[_t.FilterDualAntennaFixType, int] = _t.FilterDualAntennaFixType.FIX_NONE  # Fix type.
    # Receiver and antenna-offset validity.
    status_flags: _t.FilterDualAntennaStatusFlags = _t.FilterDualAntennaStatusFlags(0)
    valid_flags: _t.FilterOutputValidFlags = _t.FilterOutputValidFlags(0)  # Field valid.

    SET = 0x82
    DESCRIPTOR = 0x49
    NAME = "gnss_dual_antenna_status"
    ROLE = "data"
    _ATTRS = ("time_of_week", "heading", "heading_uncertainty", "fix_type", "status_flags", "valid_flags")
    _OPS = (
        _c.Run(
            _c.P("time_of_week", _c.F32),
            _c.P("heading", _c.F32),
            _c.P("heading_uncertainty", _c.F32),
            _c.P("fix_type", _c.enum(_t.FilterDualAntennaFixType, "u8")),
            _c.P("status_flags", _c.flags(_t.FilterDualAntennaStatusFlags)),
            _c.P("valid_flags", _c.flags(_t.FilterOutputValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class AidingFrameConfigError(_c.Field):
    """Aiding frame configuration error (set 0x82, descriptor 0x50, data).

    Estimated error of one user aiding frame configuration (Aiding Frame Configuration, 0x13,0x01),
    used to compensate small errors in it.

    Sources: 3dm-cv7-ins-docs.txt line 4705. Field data: 29 bytes.
    """

    frame_id: int = 0  # Aiding reference frame id (as in 0x13,0x01).
    translation: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Translation error, X, Y, Z. [m]
    attitude: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 4)  # Attitude error quaternion.

    SET = 0x82
    DESCRIPTOR = 0x50
    NAME = "aiding_frame_config_error"
    ROLE = "data"
    _ATTRS = ("frame_id", "translation", "attitude")
    _OPS = (_c.Run(_c.P("frame_id", _c.U8), _c.P("translation", _c.F32, 3), _c.P("attitude", _c.F32, 4)),)


@_c.slotted
@_dc.dataclass
class AidingFrameConfigErrorUncertainty(_c.Field):
    """Aiding frame configuration error uncertainty (set 0x82, descriptor 0x51, data).

    1-sigma uncertainty of the estimated aiding frame configuration error (0x82,0x50).

    Sources: 3dm-cv7-ins-docs.txt line 4718. Field data: 25 bytes.
    """

    frame_id: int = 0  # Aiding reference frame id (as in 0x13,0x01).
    # 1-sigma translation uncertainty, X, Y, Z. [m]
    translation_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    # 1-sigma attitude uncertainty, X, Y, Z. [rad]
    attitude_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x82
    DESCRIPTOR = 0x51
    NAME = "aiding_frame_config_error_uncertainty"
    ROLE = "data"
    _ATTRS = ("frame_id", "translation_uncertainty", "attitude_uncertainty")
    _OPS = (
        _c.Run(
            _c.P("frame_id", _c.U8), _c.P("translation_uncertainty", _c.F32, 3), _c.P("attitude_uncertainty", _c.F32, 3)
        ),
    )


FIELDS: tuple[type[_c.Field], ...] = (
    LlhPosition,
    NedVelocity,
    AttitudeQuaternion,
    AttitudeDcm,
    EulerAngles,
    GyroBias,
    AccelBias,
    LlhPositionUncertainty,
    NedVelocityUncertainty,
    EulerAnglesUncertainty,
    GyroBiasUncertainty,
    AccelBiasUncertainty,
    LinearAccel,
    CompAngularRate,
    Wgs84GravityMagnitude,
    FilterStatus_gx5_45,
    FilterStatus_cv7_ins,
    GpsTimestamp,
    QuaternionAttitudeUncertainty,
    GravityVector,
    HeadingUpdateState,
    MagneticModel,
    GyroScaleFactor,
    AccelScaleFactor,
    GyroScaleFactorUncertainty,
    AccelScaleFactorUncertainty,
    CompensatedAccel,
    StandardAtmosphere,
    PressureAltitude,
    MagAutoHardIronOffset,
    MagAutoSoftIronMatrix,
    MagAutoHardIronOffsetUncertainty,
    MagAutoSoftIronMatrixUncertainty,
    GnssAntennaOffsetCorrection,
    GnssAntennaOffsetCorrectionUncertainty,
    MultiAntennaOffsetCorrection,
    MultiAntennaOffsetCorrectionUncertainty,
    EcefPositionUncertainty,
    EcefVelocityUncertainty,
    EcefPosition,
    EcefVelocity,
    NedRelativePosition,
    GnssPositionAidingStatus,
    AidingMeasurementSummary,
    OdometerScaleFactorError,
    OdometerScaleFactorErrorUncertainty,
    GnssDualAntennaStatus,
    AidingFrameConfigError,
    AidingFrameConfigErrorUncertainty,
)
