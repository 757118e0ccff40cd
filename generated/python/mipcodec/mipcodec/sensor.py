"""Sensor (IMU) Data Set (descriptor set 0x80, data).

Calibrated inertial sensor measurements.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import codec as _c


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


@_dc.dataclass
class ScaledGyro(_c.Field):
    """Scaled gyro vector (set 0x80, descriptor 0x05, data).

    Sensed angular rate, temperature compensated, in radians/second, X, Y, Z.

    Sources: 3dm-gx5-45-dcp.txt line 2047; 3dm-cv7-ins-docs.txt line 6401. Field data: 12 bytes.
    """

    scaled_gyro: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) angular rate. [rad/s]

    SET = 0x80
    DESCRIPTOR = 0x05
    NAME = "scaled_gyro"
    ROLE = "data"
    _ATTRS = ("scaled_gyro",)
    _OPS = (_c.Run(_c.P("scaled_gyro", _c.F32, 3)),)


@_dc.dataclass
class ScaledMag(_c.Field):
    """Scaled magnetometer vector (set 0x80, descriptor 0x06, data).

    Sensed magnetic field, temperature compensated, in Gauss, X, Y, Z.

    Sources: 3dm-gx5-45-dcp.txt line 2058; 3dm-cv7-ins-docs.txt line 6412. Field data: 12 bytes.
    """

    scaled_mag: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) magnetic field. [gauss]

    SET = 0x80
    DESCRIPTOR = 0x06
    NAME = "scaled_mag"
    ROLE = "data"
    _ATTRS = ("scaled_mag",)
    _OPS = (_c.Run(_c.P("scaled_mag", _c.F32, 3)),)


FIELDS: tuple = (ScaledAccel, ScaledGyro, ScaledMag)
