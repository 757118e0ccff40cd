"""IMU Data Message (descriptor set 0xA2, data).

Scaled inertial measurements, pressure, temperature and GPS-correlated time.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class ScaledAccel(_c.Field):
    """Scaled acceleration vector (set 0xA2, descriptor 0x81, data).

    X, Y and Z acceleration in g.

    Sources: ms-cip-doc00419-revM.txt line 1271; ms-cip-doc00419-revM.txt line 1275. Field data: 12
    bytes.
    """

    accel: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Acceleration [x, y, z]. [g]

    SET = 0xA2
    DESCRIPTOR = 0x81
    NAME = "scaled_accel"
    ROLE = "data"
    _ATTRS = ("accel",)
    _OPS = (_c.Run(_c.P("accel", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class ScaledGyro(_c.Field):
    """Scaled angular rate vector (set 0xA2, descriptor 0x82, data).

    X, Y and Z angular rate in degrees per second.

    Sources: ms-cip-doc00419-revM.txt line 1301; ms-cip-doc00419-revM.txt line 1305. Field data: 12
    bytes.
    """

    gyro: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Angular rate [x, y, z]. [deg/s]

    SET = 0xA2
    DESCRIPTOR = 0x82
    NAME = "scaled_gyro"
    ROLE = "data"
    _ATTRS = ("gyro",)
    _OPS = (_c.Run(_c.P("gyro", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class ScaledMag(_c.Field):
    """Scaled magnetic field vector (set 0xA2, descriptor 0x83, data).

    X, Y and Z magnetic field in gauss.

    Sources: ms-cip-doc00419-revM.txt line 1331; ms-cip-doc00419-revM.txt line 1335. Field data: 12
    bytes.
    """

    mag: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Magnetic field [x, y, z]. [gauss]

    SET = 0xA2
    DESCRIPTOR = 0x83
    NAME = "scaled_mag"
    ROLE = "data"
    _ATTRS = ("mag",)
    _OPS = (_c.Run(_c.P("mag", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class DeltaTheta(_c.Field):
    """Scaled delta theta vector (set 0xA2, descriptor 0x84, data).

    X, Y and Z change in angle in radians.

    Sources: ms-cip-doc00419-revM.txt line 1361; ms-cip-doc00419-revM.txt line 1365. Field data: 12
    bytes.
    """

    delta_theta: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Change in angle [x, y, z]. [rad]

    SET = 0xA2
    DESCRIPTOR = 0x84
    NAME = "delta_theta"
    ROLE = "data"
    _ATTRS = ("delta_theta",)
    _OPS = (_c.Run(_c.P("delta_theta", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class DeltaVelocity(_c.Field):
    """Scaled delta velocity vector (set 0xA2, descriptor 0x85, data).

    X, Y and Z change in velocity in metres per second.

    Sources: ms-cip-doc00419-revM.txt line 1391; ms-cip-doc00419-revM.txt line 1395. Field data: 12
    bytes.
    """

    # Change in velocity [x, y, z]. [m/s]
    delta_velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0xA2
    DESCRIPTOR = 0x85
    NAME = "delta_velocity"
    ROLE = "data"
    _ATTRS = ("delta_velocity",)
    _OPS = (_c.Run(_c.P("delta_velocity", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class ScaledPressure(_c.Field):
    """Scaled pressure (set 0xA2, descriptor 0x86, data).

    Atmospheric pressure in millibar.

    Sources: ms-cip-doc00419-revM.txt line 1421; ms-cip-doc00419-revM.txt line 1425. Field data: 4
    bytes.
    """

    pressure: float = 0.0  # Pressure. [mbar]

    SET = 0xA2
    DESCRIPTOR = 0x86
    NAME = "scaled_pressure"
    ROLE = "data"
    _ATTRS = ("pressure",)
    _OPS = (_c.Run(_c.P("pressure", _c.F32)),)


@_c.slotted
@_dc.dataclass
class ScaledTemperature(_c.Field):
    """Scaled temperature (set 0xA2, descriptor 0x87, data).

    IMU temperature in degrees Celsius.

    Sources: ms-cip-doc00419-revM.txt line 1443; ms-cip-doc00419-revM.txt line 1447. Field data: 4
    bytes.
    """

    temperature: float = 0.0  # Temperature. [degC]

    SET = 0xA2
    DESCRIPTOR = 0x87
    NAME = "scaled_temperature"
    ROLE = "data"
    _ATTRS = ("temperature",)
    _OPS = (_c.Run(_c.P("temperature", _c.F32)),)


@_c.slotted
@_dc.dataclass
class GpsCorrelatedTime(_c.Field):
    """GPS correlated time (set 0xA2, descriptor 0x88, data).

    GPS time of the sample: seconds of the week (precision follows the output rate, 5 ms at 200 Hz),
    week number, and the correlation flags.

    Sources: ms-cip-doc00419-revM.txt line 1465; ms-cip-doc00419-revM.txt line 1493. Field data: 12
    bytes.
    """

    seconds: float = 0.0  # GPS seconds of the week. [s]
    week: int = 0  # GPS week number. [weeks]
    flags: _t.GpsTimeFlags = _t.GpsTimeFlags(0)  # GPS correlated time flags.

    SET = 0xA2
    DESCRIPTOR = 0x88
    NAME = "gps_correlated_time"
    ROLE = "data"
    _ATTRS = ("seconds", "week", "flags")
    _OPS = (_c.Run(_c.P("seconds", _c.F64), _c.P("week", _c.U16), _c.P("flags", _c.flags(_t.GpsTimeFlags))),)


@_c.slotted
@_dc.dataclass
class ScaledAuxAccel(_c.Field):
    """Scaled aux accel vector (set 0xA2, descriptor 0x89, data).

    X, Y and Z acceleration of the auxiliary accelerometer in g.

    Sources: ms-cip-doc00419-revM.txt line 1519; ms-cip-doc00419-revM.txt line 1523. Field data: 12
    bytes.
    """

    accel: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Auxiliary acceleration [x, y, z]. [g]

    SET = 0xA2
    DESCRIPTOR = 0x89
    NAME = "scaled_aux_accel"
    ROLE = "data"
    _ATTRS = ("accel",)
    _OPS = (_c.Run(_c.P("accel", _c.F32, 3)),)


FIELDS: tuple[type[_c.Field], ...] = (
    ScaledAccel,
    ScaledGyro,
    ScaledMag,
    DeltaTheta,
    DeltaVelocity,
    ScaledPressure,
    ScaledTemperature,
    GpsCorrelatedTime,
    ScaledAuxAccel,
)
