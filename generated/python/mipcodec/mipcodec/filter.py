"""Filter Command Set (descriptor set 0x0D, command).

Configure, initialise and aid the navigation (Kalman) filter: reset and run it, give it an initial
attitude or heading, set frame transformations and antenna offsets, choose its GNSS and heading
sources, feed it external measurements and tune its noise models.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class ResetFilter(_c.Field):
    """Reset filter (set 0x0D, descriptor 0x01, command).

    Put the filter back into its initialisation state. With auto-initialisation disabled, an initial
    attitude or heading must then be given before it runs again.

    Sources: 3dm-gx5-45-dcp.txt line 1409; 3dm-cv7-ins-docs.txt line 8242. Field data: 0 bytes.
    """

    SET = 0x0D
    DESCRIPTOR = 0x01
    NAME = "reset_filter"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class SetInitialAttitude(_c.Field):
    """Set initial attitude (set 0x0D, descriptor 0x02, command).

    Initialise the filter attitude from Euler angles of the sensor body frame relative to the local
    NED frame. Only accepted in the INIT state.

    Sources: 3dm-gx5-45-dcp.txt line 1421. Field data: 12 bytes.
    """

    roll: float = 0.0  # Roll angle, in [-pi, pi]. [rad]
    pitch: float = 0.0  # Pitch angle, in [-pi/2, pi/2]. [rad]
    heading: float = 0.0  # Heading (yaw) angle, in [-pi, pi]. [rad]

    SET = 0x0D
    DESCRIPTOR = 0x02
    NAME = "set_initial_attitude"
    ROLE = "command"
    _ATTRS = ("roll", "pitch", "heading")
    _OPS = (_c.Run(_c.P("roll", _c.F32), _c.P("pitch", _c.F32), _c.P("heading", _c.F32)),)


@_c.slotted
@_dc.dataclass
class SetInitialHeading(_c.Field):
    """Set initial heading (set 0x0D, descriptor 0x03, command).

    Initialise the filter heading; roll and pitch come from the accelerometers. GX5-45: only
    accepted in the INIT state. CV7: the heading estimate is reset to this value, unless
    magnetometer aiding is enabled, in which case the magnetic heading is used instead.

    Sources: 3dm-gx5-45-dcp.txt line 1434; 3dm-cv7-ins-docs.txt line 8253. Field data: 4 bytes.
    """

    heading: float = 0.0  # Initial heading, in [-pi, pi]. [rad]

    SET = 0x0D
    DESCRIPTOR = 0x03
    NAME = "set_initial_heading"
    ROLE = "command"
    _ATTRS = ("heading",)
    _OPS = (_c.Run(_c.P("heading", _c.F32)),)


@_c.slotted
@_dc.dataclass
class RunFilter(_c.Field):
    """Run navigation filter (set 0x0D, descriptor 0x05, command).

    Start the filter by hand when the initialisation configuration asks it to wait for a run
    command; until then it stays in initialisation mode.

    Sources: 3dm-cv7-ins-docs.txt line 8265. Field data: 0 bytes.
    """

    SET = 0x0D
    DESCRIPTOR = 0x05
    NAME = "run_filter"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class VehicleDynamicsMode(_c.Field):
    """Vehicle dynamics mode (set 0x0D, descriptor 0x10, command).

    Set, read, save, load or reset the vehicle dynamics mode of the filter.

    Functions: write, read, save, load, default. Responses: 0x80 vehicle_dynamics_mode_response.
    Sources: 3dm-gx5-45-dcp.txt line 1447. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    mode: _ty.Optional[_ty.Union[_t.VehicleDynamicsMode, int]] = None  # New dynamics mode. (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x10
    NAME = "vehicle_dynamics_mode"
    ROLE = "command"
    _ATTRS = ("function", "mode")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.VehicleDynamicsMode, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class VehicleDynamicsModeResponse(_c.Field):
    """Vehicle dynamics mode (response) (set 0x0D, descriptor 0x80, response).

    Current vehicle dynamics mode (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1460. Field data: 1 bytes.
    """

    mode: _ty.Union[_t.VehicleDynamicsMode, int] = _t.VehicleDynamicsMode.PORTABLE  # Current dynamics mode.

    SET = 0x0D
    DESCRIPTOR = 0x80
    NAME = "vehicle_dynamics_mode_response"
    ROLE = "response"
    _ATTRS = ("mode",)
    _OPS = (_c.Run(_c.P("mode", _c.enum(_t.VehicleDynamicsMode, "u8"))),)


@_c.slotted
@_dc.dataclass
class SensorToVehicleTransform(_c.Field):
    """Sensor to vehicle frame transformation (set 0x0D, descriptor 0x11, command).

    Euler angles (roll, pitch, yaw) of the rotation from the sensor body frame to the vehicle frame.
    Applies to the scaled IMU vectors, delta theta/velocity and the filter's orientation, linear
    acceleration, angular rate and gravity outputs.

    Functions: write, read, save, load, default. Responses: 0x81
    sensor_to_vehicle_transform_response. Sources: 3dm-gx5-45-dcp.txt line 1469. Field data: 1..13
    bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    roll: _ty.Optional[float] = None  # Roll angle of the sensor-to-vehicle rotation. [rad] (sent for: write)
    pitch: _ty.Optional[float] = None  # Pitch angle of the sensor-to-vehicle rotation. [rad] (sent for: write)
    yaw: _ty.Optional[float] = None  # Yaw angle of the sensor-to-vehicle rotation. [rad] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x11
    NAME = "sensor_to_vehicle_transform"
    ROLE = "command"
    _ATTRS = ("function", "roll", "pitch", "yaw")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("roll", _c.F32))),
        _c.Opt(_c.Run(_c.P("pitch", _c.F32))),
        _c.Opt(_c.Run(_c.P("yaw", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class SensorToVehicleTransformResponse(_c.Field):
    """Sensor to vehicle frame transformation (response) (set 0x0D, descriptor 0x81, response).

    Current sensor-to-vehicle Euler angles (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1478. Field data: 12 bytes.
    """

    roll: float = 0.0  # Roll angle. [rad]
    pitch: float = 0.0  # Pitch angle. [rad]
    yaw: float = 0.0  # Yaw angle. [rad]

    SET = 0x0D
    DESCRIPTOR = 0x81
    NAME = "sensor_to_vehicle_transform_response"
    ROLE = "response"
    _ATTRS = ("roll", "pitch", "yaw")
    _OPS = (_c.Run(_c.P("roll", _c.F32), _c.P("pitch", _c.F32), _c.P("yaw", _c.F32)),)


@_c.slotted
@_dc.dataclass
class SensorToVehicleOffset(_c.Field):
    """Sensor to vehicle frame offset (set 0x0D, descriptor 0x12, command).

    Offset from the sensor to the vehicle reference point, in the sensor frame, added to the
    estimated LLH position. Not a lever arm: no inertial compensation. Magnitude at most 10 m.

    Functions: write, read, save, load, default. Responses: 0x82 sensor_to_vehicle_offset_response.
    Sources: 3dm-gx5-45-dcp.txt line 1485. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    offset: _ty.Optional[_ty.List[float]] = None  # (x, y, z) offset in the sensor body frame. [m] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x12
    NAME = "sensor_to_vehicle_offset"
    ROLE = "command"
    _ATTRS = ("function", "offset")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("offset", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class SensorToVehicleOffsetResponse(_c.Field):
    """Sensor to vehicle frame offset (response) (set 0x0D, descriptor 0x82, response).

    Current sensor-to-vehicle offset (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1491. Field data: 12 bytes.
    """

    # (x, y, z) offset in the sensor body frame. [m]
    offset: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0D
    DESCRIPTOR = 0x82
    NAME = "sensor_to_vehicle_offset_response"
    ROLE = "response"
    _ATTRS = ("offset",)
    _OPS = (_c.Run(_c.P("offset", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class AntennaOffset(_c.Field):
    """GNSS antenna offset (set 0x0D, descriptor 0x13, command).

    Offset from the sensor origin to the GNSS antenna RF (phase) centre; magnitude at most 10 m.
    GX5-45 (5-series): expressed in the sensor frame. CV7 (7-series): expressed in the vehicle
    frame; also used for NMEA input over GPIO.

    Functions: write, read, save, load, default. Responses: 0x83 antenna_offset_response. Sources:
    3dm-gx5-45-dcp.txt line 1500; 3dm-cv7-ins-docs.txt line 8276. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # (x, y, z) antenna offset (sensor frame on GX5-45, vehicle frame on CV7). [m] (sent for: write)
    offset: _ty.Optional[_ty.List[float]] = None

    SET = 0x0D
    DESCRIPTOR = 0x13
    NAME = "antenna_offset"
    ROLE = "command"
    _ATTRS = ("function", "offset")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("offset", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class AntennaOffsetResponse(_c.Field):
    """GNSS antenna offset (response) (set 0x0D, descriptor 0x83, response).

    Current antenna offset (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1510; 3dm-cv7-ins-docs.txt line 8286. Field data: 12 bytes.
    """

    offset: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) antenna offset. [m]

    SET = 0x0D
    DESCRIPTOR = 0x83
    NAME = "antenna_offset_response"
    ROLE = "response"
    _ATTRS = ("offset",)
    _OPS = (_c.Run(_c.P("offset", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class EstimationControl(_c.Field):
    """Estimation control flags (set 0x0D, descriptor 0x14, command).

    Select which optional parameters the Kalman filter estimates.

    Functions: write, read, save, load, default. Responses: 0x84 estimation_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1517. Field data: 1..3 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    flags: _ty.Optional[_t.EstimationControlFlags] = None  # States to estimate. (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x14
    NAME = "estimation_control"
    ROLE = "command"
    _ATTRS = ("function", "flags")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("flags", _c.flags(_t.EstimationControlFlags)))),
    )


@_c.slotted
@_dc.dataclass
class EstimationControlResponse(_c.Field):
    """Estimation control flags (response) (set 0x0D, descriptor 0x84, response).

    Current estimation control flags (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1523. Field data: 2 bytes.
    """

    flags: _t.EstimationControlFlags = _t.EstimationControlFlags(0)  # States being estimated.

    SET = 0x0D
    DESCRIPTOR = 0x84
    NAME = "estimation_control_response"
    ROLE = "response"
    _ATTRS = ("flags",)
    _OPS = (_c.Run(_c.P("flags", _c.flags(_t.EstimationControlFlags))),)


@_c.slotted
@_dc.dataclass
class GnssSourceControl(_c.Field):
    """GNSS source control (set 0x0D, descriptor 0x15, command).

    Choose the source of GNSS updates to the filter. Changing it while running may put the filter
    back in its init state until data from the new source arrives.

    Functions: write, read, save, load, default. Responses: 0x86 gnss_source_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1531; 3dm-cv7-ins-docs.txt line 8293. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    source: _ty.Optional[_ty.Union[_t.FilterGnssSource, int]] = None  # GNSS source. (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x15
    NAME = "gnss_source_control"
    ROLE = "command"
    _ATTRS = ("function", "source")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.FilterGnssSource, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class GnssSourceControlResponse(_c.Field):
    """GNSS source control (response) (set 0x0D, descriptor 0x86, response).

    Current GNSS source (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1539; 3dm-cv7-ins-docs.txt line 8308. Field data: 1 bytes.
    """

    source: _ty.Union[_t.FilterGnssSource, int] = _t.FilterGnssSource.ALL_INTERNAL  # GNSS source.

    SET = 0x0D
    DESCRIPTOR = 0x86
    NAME = "gnss_source_control_response"
    ROLE = "response"
    _ATTRS = ("source",)
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.FilterGnssSource, "u8"))),)


@_c.slotted
@_dc.dataclass
class ExternalGnssUpdate(_c.Field):
    """External GNSS update (set 0x0D, descriptor 0x16, command).

    Give the filter one GNSS measurement from an external receiver. Only used (otherwise ignored or
    NACKed) when the GNSS source is external; at most 20 Hz.

    Sources: 3dm-gx5-45-dcp.txt line 1548. Field data: 70 bytes.
    """

    gps_tow: float = 0.0  # GPS time of week. [s]
    gps_week: int = 0  # GPS week number. [weeks]
    latitude: float = 0.0  # Latitude. [deg]
    longitude: float = 0.0  # Longitude. [deg]
    height: float = 0.0  # Height above the WGS84 ellipsoid. [m]
    velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (north, east, down) velocity. [m/s]
    # (north, east, down) position 1-sigma uncertainty. [m]
    position_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    # (north, east, down) velocity 1-sigma uncertainty. [m/s]
    velocity_uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0D
    DESCRIPTOR = 0x16
    NAME = "external_gnss_update"
    ROLE = "command"
    _ATTRS = (
        "gps_tow",
        "gps_week",
        "latitude",
        "longitude",
        "height",
        "velocity",
        "position_uncertainty",
        "velocity_uncertainty",
    )
    _OPS = (
        _c.Run(
            _c.P("gps_tow", _c.F64),
            _c.P("gps_week", _c.U16),
            _c.P("latitude", _c.F64),
            _c.P("longitude", _c.F64),
            _c.P("height", _c.F64),
            _c.P("velocity", _c.F32, 3),
            _c.P("position_uncertainty", _c.F32, 3),
            _c.P("velocity_uncertainty", _c.F32, 3),
        ),
    )


@_c.slotted
@_dc.dataclass
class ExternalHeadingUpdate(_c.Field):
    """External heading update (set 0x0D, descriptor 0x17, command).

    Give the filter one heading measurement (sensor frame relative to NED) from an external source.
    Only used when external heading aiding is enabled, otherwise NACKed; uncertainties of 0 or less
    are NACKed; a true (or magnetic) heading is NACKed when the declination source is invalid (see
    the manuals for which model refuses which).

    Sources: 3dm-gx5-45-dcp.txt line 1588; 3dm-cv7-ins-docs.txt line 8322. Field data: 9 bytes.
    """

    heading: float = 0.0  # Heading angle, within +-pi. [rad]
    heading_uncertainty: float = 0.0  # Heading 1-sigma uncertainty; must be greater than 0. [rad]
    type: _ty.Union[_t.ExternalHeadingType, int] = _t.ExternalHeadingType.TRUE_HEADING  # True or magnetic heading.

    SET = 0x0D
    DESCRIPTOR = 0x17
    NAME = "external_heading_update"
    ROLE = "command"
    _ATTRS = ("heading", "heading_uncertainty", "type")
    _OPS = (
        _c.Run(
            _c.P("heading", _c.F32),
            _c.P("heading_uncertainty", _c.F32),
            _c.P("type", _c.enum(_t.ExternalHeadingType, "u8")),
        ),
    )


@_c.slotted
@_dc.dataclass
class HeadingUpdateControl(_c.Field):
    """Heading update control (set 0x0D, descriptor 0x18, command).

    Select the aiding source(s) of filter heading updates.

    Functions: write, read, save, load, default. Responses: 0x87 heading_update_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1562. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Heading aiding source (the manual's "Enable Flag"). (sent for: write)
    source: _ty.Optional[_ty.Union[_t.HeadingUpdateSource, int]] = None

    SET = 0x0D
    DESCRIPTOR = 0x18
    NAME = "heading_update_control"
    ROLE = "command"
    _ATTRS = ("function", "source")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.HeadingUpdateSource, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class HeadingUpdateControlResponse(_c.Field):
    """Heading update control (response) (set 0x0D, descriptor 0x87, response).

    Current heading update source (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1579. Field data: 1 bytes.
    """

    source: _ty.Union[_t.HeadingUpdateSource, int] = _t.HeadingUpdateSource.NONE  # Heading aiding source.

    SET = 0x0D
    DESCRIPTOR = 0x87
    NAME = "heading_update_control_response"
    ROLE = "response"
    _ATTRS = ("source",)
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.HeadingUpdateSource, "u8"))),)


@_c.slotted
@_dc.dataclass
class AutoInitControl(_c.Field):
    """Auto-initialization control (set 0x0D, descriptor 0x19, command).

    Enable or disable automatic filter initialisation at startup (needs a valid heading source;
    otherwise use Set initial heading or Set initial attitude).

    Functions: write, read, save, load, default. Responses: 0x88 auto_init_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1642. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    enable: _ty.Optional[int] = None  # 0 disables, 1 enables auto-initialisation. (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x19
    NAME = "auto_init_control"
    ROLE = "command"
    _ATTRS = ("function", "enable")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("enable", _c.U8))),
    )


@_c.slotted
@_dc.dataclass
class AutoInitControlResponse(_c.Field):
    """Auto-initialization control (response) (set 0x0D, descriptor 0x88, response).

    Current auto-initialisation setting (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1650. Field data: 1 bytes.
    """

    enable: int = 0  # 0 disabled, 1 enabled.

    SET = 0x0D
    DESCRIPTOR = 0x88
    NAME = "auto_init_control_response"
    ROLE = "response"
    _ATTRS = ("enable",)
    _OPS = (_c.Run(_c.P("enable", _c.U8)),)


@_c.slotted
@_dc.dataclass
class AccelNoise(_c.Field):
    """Accelerometer noise standard deviation (set 0x0D, descriptor 0x1A, command).

    Expected accelerometer (process) noise, 1-sigma per axis, used to tune the filter. Each value
    must be greater than 0.

    Functions: write, read, save, load, default. Responses: 0x89 accel_noise_response. Sources:
    3dm-gx5-45-dcp.txt line 1704; 3dm-cv7-ins-docs.txt line 8336. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    noise: _ty.Optional[_ty.List[float]] = None  # (x, y, z) accelerometer noise 1-sigma. [m/s^2] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x1A
    NAME = "accel_noise"
    ROLE = "command"
    _ATTRS = ("function", "noise")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("noise", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class AccelNoiseResponse(_c.Field):
    """Accelerometer noise standard deviation (response) (set 0x0D, descriptor 0x89, response).

    Current accelerometer noise 1-sigma (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1726; 3dm-cv7-ins-docs.txt line 8346. Field data: 12 bytes.
    """

    # (x, y, z) accelerometer noise 1-sigma. [m/s^2]
    noise: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0D
    DESCRIPTOR = 0x89
    NAME = "accel_noise_response"
    ROLE = "response"
    _ATTRS = ("noise",)
    _OPS = (_c.Run(_c.P("noise", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class GyroNoise(_c.Field):
    """Gyroscope noise standard deviation (set 0x0D, descriptor 0x1B, command).

    Expected gyro (process) noise, 1-sigma per axis, used to tune the filter. Each value must be
    greater than 0.

    Functions: write, read, save, load, default. Responses: 0x8A gyro_noise_response. Sources:
    3dm-gx5-45-dcp.txt line 1749; 3dm-cv7-ins-docs.txt line 8353. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    noise: _ty.Optional[_ty.List[float]] = None  # (x, y, z) gyro noise 1-sigma. [rad/s] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x1B
    NAME = "gyro_noise"
    ROLE = "command"
    _ATTRS = ("function", "noise")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("noise", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class GyroNoiseResponse(_c.Field):
    """Gyroscope noise standard deviation (response) (set 0x0D, descriptor 0x8A, response).

    Current gyro noise 1-sigma (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1755; 3dm-cv7-ins-docs.txt line 8363. Field data: 12 bytes.
    """

    noise: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) gyro noise 1-sigma. [rad/s]

    SET = 0x0D
    DESCRIPTOR = 0x8A
    NAME = "gyro_noise_response"
    ROLE = "response"
    _ATTRS = ("noise",)
    _OPS = (_c.Run(_c.P("noise", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class AccelBiasModel(_c.Field):
    """Accelerometer bias model parameters (set 0x0D, descriptor 0x1C, command).

    First-order (Gauss-Markov) accelerometer bias model: time constant inverse (beta) and bias noise
    1-sigma per axis. Noise values must be greater than 0.

    Functions: write, read, save, load, default. Responses: 0x8B accel_bias_model_response. Sources:
    3dm-gx5-45-dcp.txt line 1733; 3dm-cv7-ins-docs.txt line 8370. Field data: 1..25 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    beta: _ty.Optional[_ty.List[float]] = None  # (x, y, z) accelerometer bias beta. [1/s] (sent for: write)
    noise: _ty.Optional[_ty.List[float]] = None  # (x, y, z) accelerometer bias noise 1-sigma. [m/s^2] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x1C
    NAME = "accel_bias_model"
    ROLE = "command"
    _ATTRS = ("function", "beta", "noise")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("beta", _c.F32, 3))),
        _c.Opt(_c.Run(_c.P("noise", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class AccelBiasModelResponse(_c.Field):
    """Accelerometer bias model parameters (response) (set 0x0D, descriptor 0x8B, response).

    Current accelerometer bias model (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1741; 3dm-cv7-ins-docs.txt line 8381. Field data: 24 bytes.
    """

    beta: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) accelerometer bias beta. [1/s]
    # (x, y, z) accelerometer bias noise 1-sigma. [m/s^2]
    noise: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0D
    DESCRIPTOR = 0x8B
    NAME = "accel_bias_model_response"
    ROLE = "response"
    _ATTRS = ("beta", "noise")
    _OPS = (_c.Run(_c.P("beta", _c.F32, 3), _c.P("noise", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class GyroBiasModel(_c.Field):
    """Gyroscope bias model parameters (set 0x0D, descriptor 0x1D, command).

    First-order (Gauss-Markov) gyro bias model: time constant inverse (beta) and bias noise 1-sigma
    per axis. Noise values must be greater than 0.

    Functions: write, read, save, load, default. Responses: 0x8C gyro_bias_model_response. Sources:
    3dm-gx5-45-dcp.txt line 1764; 3dm-cv7-ins-docs.txt line 8389. Field data: 1..25 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    beta: _ty.Optional[_ty.List[float]] = None  # (x, y, z) gyro bias beta. [1/s] (sent for: write)
    noise: _ty.Optional[_ty.List[float]] = None  # (x, y, z) gyro bias noise 1-sigma. [rad/s] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x1D
    NAME = "gyro_bias_model"
    ROLE = "command"
    _ATTRS = ("function", "beta", "noise")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("beta", _c.F32, 3))),
        _c.Opt(_c.Run(_c.P("noise", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class GyroBiasModelResponse(_c.Field):
    """Gyroscope bias model parameters (response) (set 0x0D, descriptor 0x8C, response).

    Current gyro bias model (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1770; 3dm-cv7-ins-docs.txt line 8400. Field data: 24 bytes.
    """

    beta: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) gyro bias beta. [1/s]
    noise: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # (x, y, z) gyro bias noise 1-sigma. [rad/s]

    SET = 0x0D
    DESCRIPTOR = 0x8C
    NAME = "gyro_bias_model_response"
    ROLE = "response"
    _ATTRS = ("beta", "noise")
    _OPS = (_c.Run(_c.P("beta", _c.F32, 3), _c.P("noise", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class ZuptControl(_c.Field):
    """Zero velocity update (ZUPT) control (set 0x0D, descriptor 0x1E, command).

    Enable zero-velocity updates, applied when the GNSS velocity magnitude is at or below the
    threshold. Negative thresholds are NACKed.

    Functions: write, read, save, load, default. Responses: 0x8D zupt_control_response. Sources:
    3dm-gx5-45-dcp.txt line 1807. Field data: 1..6 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    enable: _ty.Optional[int] = None  # 0 disables, 1 enables ZUPTs. (sent for: write)
    # Velocity magnitude at or below which a ZUPT is applied. [m/s] (sent for: write)
    threshold: _ty.Optional[float] = None

    SET = 0x0D
    DESCRIPTOR = 0x1E
    NAME = "zupt_control"
    ROLE = "command"
    _ATTRS = ("function", "enable", "threshold")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("enable", _c.U8))),
        _c.Opt(_c.Run(_c.P("threshold", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class ZuptControlResponse(_c.Field):
    """Zero velocity update control (response) (set 0x0D, descriptor 0x8D, response).

    Current ZUPT setting (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1814. Field data: 5 bytes.
    """

    enable: int = 0  # 0 disabled, 1 enabled.
    threshold: float = 0.0  # ZUPT velocity threshold. [m/s]

    SET = 0x0D
    DESCRIPTOR = 0x8D
    NAME = "zupt_control_response"
    ROLE = "response"
    _ATTRS = ("enable", "threshold")
    _OPS = (_c.Run(_c.P("enable", _c.U8), _c.P("threshold", _c.F32)),)


@_c.slotted
@_dc.dataclass
class ExternalHeadingUpdateWithTime(_c.Field):
    """External heading update with timestamp (set 0x0D, descriptor 0x1F, command).

    External heading measurement tagged with the GPS time it was taken; more accurate than 0x0D,0x17
    under high angular rates. Same acceptance rules as 0x0D,0x17; at most 20 Hz on the GX5-45.

    Sources: 3dm-gx5-45-dcp.txt line 1601; 3dm-cv7-ins-docs.txt line 8408. Field data: 19 bytes.
    """

    gps_tow: float = 0.0  # GPS time of week of the measurement. [s]
    gps_week: int = 0  # GPS week number (not modulo 1024). [weeks]
    heading: float = 0.0  # Heading angle from true north, within +-pi. [rad]
    heading_uncertainty: float = 0.0  # Heading 1-sigma uncertainty; must be greater than 0. [rad]
    type: _ty.Union[_t.ExternalHeadingType, int] = _t.ExternalHeadingType.TRUE_HEADING  # True or magnetic heading.

    SET = 0x0D
    DESCRIPTOR = 0x1F
    NAME = "external_heading_update_with_time"
    ROLE = "command"
    _ATTRS = ("gps_tow", "gps_week", "heading", "heading_uncertainty", "type")
    _OPS = (
        _c.Run(
            _c.P("gps_tow", _c.F64),
            _c.P("gps_week", _c.U16),
            _c.P("heading", _c.F32),
            _c.P("heading_uncertainty", _c.F32),
            _c.P("type", _c.enum(_t.ExternalHeadingType, "u8")),
        ),
    )


@_c.slotted
@_dc.dataclass
class ZeroAngularRateUpdateControl(_c.Field):
    """Zero angular rate update control (set 0x0D, descriptor 0x20, command).

    Control the zero angular rate update: when the magnitude of the angular rate vector is at or
    below the threshold, the filter applies a zero angular rate update. Negative thresholds are
    NACK'd.

    Functions: write, read, save, load, default. Responses: 0x8E
    zero_angular_rate_update_control_response. Sources: 3dm-gx5-45-dcp.txt line 1821;
    3dm-cv7-ins-docs.txt line 8424. Field data: 1..6 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    enable: _ty.Optional[int] = None  # 0 disables, 1 enables the update. (sent for: write)
    # Angular rate magnitude at or below which the update is applied. [rad/s] (sent for: write)
    threshold: _ty.Optional[float] = None

    SET = 0x0D
    DESCRIPTOR = 0x20
    NAME = "zero_angular_rate_update_control"
    ROLE = "command"
    _ATTRS = ("function", "enable", "threshold")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("enable", _c.U8))),
        _c.Opt(_c.Run(_c.P("threshold", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class ZeroAngularRateUpdateControlResponse(_c.Field):
    """Zero angular rate update control (response) (set 0x0D, descriptor 0x8E, response).

    Current zero angular rate update settings.

    Sources: 3dm-gx5-45-dcp.txt line 1828; 3dm-cv7-ins-docs.txt line 8435. Field data: 5 bytes.
    """

    enable: int = 0  # 0 disabled, 1 enabled.
    threshold: float = 0.0  # Angular rate threshold. [rad/s]

    SET = 0x0D
    DESCRIPTOR = 0x8E
    NAME = "zero_angular_rate_update_control_response"
    ROLE = "response"
    _ATTRS = ("enable", "threshold")
    _OPS = (_c.Run(_c.P("enable", _c.U8), _c.P("threshold", _c.F32)),)


@_c.slotted
@_dc.dataclass
class TareOrientation(_c.Field):
    """Tare orientation (set 0x0D, descriptor 0x21, command).

    Use the current orientation relative to NED as the sensor-to-vehicle transformation for the
    selected axes. The filter must be initialized with a valid attitude, otherwise the command is
    NACK'd. Read is not supported.

    Functions: write, save, load, default. Sources: 3dm-gx5-45-dcp.txt line 1835. Field data: 1..2
    bytes.
    """

    # Function selector (one of: write, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    axes: _ty.Optional[_t.TareAxes] = None  # Axes to tare; 0 resets all axes. (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x21
    NAME = "tare_orientation"
    ROLE = "command"
    _ATTRS = ("function", "axes")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("axes", _c.flags(_t.TareAxes)))),
    )


@_c.slotted
@_dc.dataclass
class CommandedZupt(_c.Field):
    """Commanded zero velocity update (set 0x0D, descriptor 0x22, command).

    Apply a zero velocity update now (at most 20 Hz).

    Sources: 3dm-gx5-45-dcp.txt line 1850. Field data: 0 bytes.
    """

    SET = 0x0D
    DESCRIPTOR = 0x22
    NAME = "commanded_zupt"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class CommandedZeroAngularRateUpdate(_c.Field):
    """Commanded zero angular rate update (set 0x0D, descriptor 0x23, command).

    Apply a zero angular rate update now (at most 10 Hz).

    Sources: 3dm-gx5-45-dcp.txt line 1863. Field data: 0 bytes.
    """

    SET = 0x0D
    DESCRIPTOR = 0x23
    NAME = "commanded_zero_angular_rate_update"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class MagCaptureAutoCalibration(_c.Field):
    """Magnetometer capture auto calibration (set 0x0D, descriptor 0x27, command).

    Capture the current auto-calibration, fold it into the fixed hard and soft iron coefficients and
    reset the auto-calibration. Function save stores the coefficients as startup settings (like
    saving 0x0C,0x3A and 0x0C,0x3B).

    Functions: write, save. Sources: 3dm-gx5-45-dcp.txt line 1984. Field data: 1 bytes.
    """

    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE  # Function selector (one of: write, save)

    SET = 0x0D
    DESCRIPTOR = 0x27
    NAME = "mag_capture_auto_calibration"
    ROLE = "command"
    _ATTRS = ("function",)
    _OPS = (_c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),)


@_c.slotted
@_dc.dataclass
class GravityNoiseStdDev(_c.Field):
    """Gravity noise standard deviation (set 0x0D, descriptor 0x28, command).

    Expected gravity noise (1-sigma) per axis, used to tune the filter. Each value must be greater
    than 0.

    Functions: write, read, save, load, default. Responses: 0x93 gravity_noise_std_dev_response.
    Sources: 3dm-gx5-45-dcp.txt line 1670; 3dm-cv7-ins-docs.txt line 8443. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    noise: _ty.Optional[_ty.List[float]] = None  # Gravity noise 1-sigma (x, y, z). [g] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x28
    NAME = "gravity_noise_std_dev"
    ROLE = "command"
    _ATTRS = ("function", "noise")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("noise", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class GravityNoiseStdDevResponse(_c.Field):
    """Gravity noise standard deviation (response) (set 0x0D, descriptor 0x93, response).

    Current gravity noise 1-sigma values.

    Sources: 3dm-gx5-45-dcp.txt line 1684; 3dm-cv7-ins-docs.txt line 8453. Field data: 12 bytes.
    """

    noise: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Gravity noise 1-sigma (x, y, z). [g]

    SET = 0x0D
    DESCRIPTOR = 0x93
    NAME = "gravity_noise_std_dev_response"
    ROLE = "response"
    _ATTRS = ("noise",)
    _OPS = (_c.Run(_c.P("noise", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class PressureAltitudeNoiseStdDev(_c.Field):
    """Pressure altitude noise standard deviation (set 0x0D, descriptor 0x29, command).

    Expected pressure altitude noise (1-sigma). Lower values make the height estimate follow
    pressure changes faster but more exposed to air pressure fluctuations. Must be greater than 0.

    Functions: write, read, save, load, default. Responses: 0x94
    pressure_altitude_noise_std_dev_response. Sources: 3dm-gx5-45-dcp.txt line 1692. Field data:
    1..5 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    noise: _ty.Optional[float] = None  # Pressure altitude noise 1-sigma. [m] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x29
    NAME = "pressure_altitude_noise_std_dev"
    ROLE = "command"
    _ATTRS = ("function", "noise")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("noise", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class PressureAltitudeNoiseStdDevResponse(_c.Field):
    """Pressure altitude noise standard deviation (response) (set 0x0D, descriptor 0x94, response).

    Current pressure altitude noise 1-sigma.

    Sources: 3dm-gx5-45-dcp.txt line 1698. Field data: 4 bytes.
    """

    noise: float = 0.0  # Pressure altitude noise 1-sigma. [m]

    SET = 0x0D
    DESCRIPTOR = 0x94
    NAME = "pressure_altitude_noise_std_dev_response"
    ROLE = "response"
    _ATTRS = ("noise",)
    _OPS = (_c.Run(_c.P("noise", _c.F32)),)


@_c.slotted
@_dc.dataclass
class HardIronOffsetNoise(_c.Field):
    """Hard iron offset process noise (set 0x0D, descriptor 0x2B, command).

    Expected hard iron offset process noise (1-sigma) per axis, used to tune the magnetometer
    auto-calibration states. Each value must be greater than 0.

    Functions: write, read, save, load, default. Responses: 0x96 hard_iron_offset_noise_response.
    Sources: 3dm-gx5-45-dcp.txt line 1777. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    noise: _ty.Optional[_ty.List[float]] = None  # Hard iron offset noise 1-sigma (x, y, z). [gauss] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x2B
    NAME = "hard_iron_offset_noise"
    ROLE = "command"
    _ATTRS = ("function", "noise")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("noise", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class HardIronOffsetNoiseResponse(_c.Field):
    """Hard iron offset process noise (response) (set 0x0D, descriptor 0x96, response).

    Current hard iron offset process noise.

    Sources: 3dm-gx5-45-dcp.txt line 1783. Field data: 12 bytes.
    """

    # Hard iron offset noise 1-sigma (x, y, z). [gauss]
    noise: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0D
    DESCRIPTOR = 0x96
    NAME = "hard_iron_offset_noise_response"
    ROLE = "response"
    _ATTRS = ("noise",)
    _OPS = (_c.Run(_c.P("noise", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class SoftIronMatrixNoise(_c.Field):
    """Soft iron matrix process noise (set 0x0D, descriptor 0x2C, command).

    Expected soft iron matrix process noise (1-sigma), one value per matrix element, row by row
    (m11, m12, m13, m21, ... m33). Each value must be greater than 0.

    Functions: write, read, save, load, default. Responses: 0x97 soft_iron_matrix_noise_response.
    Sources: 3dm-gx5-45-dcp.txt line 1790. Field data: 1..37 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    noise: _ty.Optional[_ty.List[float]] = None  # Soft iron matrix noise 1-sigma, row-major m11..m33. (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x2C
    NAME = "soft_iron_matrix_noise"
    ROLE = "command"
    _ATTRS = ("function", "noise")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("noise", _c.F32, 9))),
    )


@_c.slotted
@_dc.dataclass
class SoftIronMatrixNoiseResponse(_c.Field):
    """Soft iron matrix process noise (response) (set 0x0D, descriptor 0x97, response).

    Current soft iron matrix process noise.

    Sources: 3dm-gx5-45-dcp.txt line 1796. Field data: 36 bytes.
    """

    # Soft iron matrix noise 1-sigma, row-major m11..m33.
    noise: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 9)

    SET = 0x0D
    DESCRIPTOR = 0x97
    NAME = "soft_iron_matrix_noise_response"
    ROLE = "response"
    _ATTRS = ("noise",)
    _OPS = (_c.Run(_c.P("noise", _c.F32, 9)),)


@_c.slotted
@_dc.dataclass
class MagNoiseStdDev(_c.Field):
    """Magnetometer noise standard deviation (set 0x0D, descriptor 0x42, command).

    Expected magnetometer noise (1-sigma) per axis, used to tune the filter. Each value must be
    greater than 0.

    Functions: write, read, save, load, default. Responses: 0xB1 mag_noise_std_dev_response.
    Sources: 3dm-gx5-45-dcp.txt line 1657. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    noise: _ty.Optional[_ty.List[float]] = None  # Magnetometer noise 1-sigma (x, y, z). [gauss] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x42
    NAME = "mag_noise_std_dev"
    ROLE = "command"
    _ATTRS = ("function", "noise")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("noise", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class MagNoiseStdDevResponse(_c.Field):
    """Magnetometer noise standard deviation (response) (set 0x0D, descriptor 0xB1, response).

    Current magnetometer noise 1-sigma values.

    Sources: 3dm-gx5-45-dcp.txt line 1663. Field data: 12 bytes.
    """

    # Magnetometer noise 1-sigma (x, y, z). [gauss]
    noise: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0D
    DESCRIPTOR = 0xB1
    NAME = "mag_noise_std_dev_response"
    ROLE = "response"
    _ATTRS = ("noise",)
    _OPS = (_c.Run(_c.P("noise", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class DeclinationSource(_c.Field):
    """Declination source (set 0x0D, descriptor 0x43, command).

    Source of the local magnetic declination used to convert between magnetic and true north. With a
    valid declination the device reports heading relative to true north.

    Functions: write, read, save, load, default. Responses: 0xB2 declination_source_response.
    Sources: 3dm-gx5-45-dcp.txt line 1876; 3dm-cv7-ins-docs.txt line 8460. Field data: 1..6 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    source: _ty.Optional[_ty.Union[_t.MagneticParamSource, int]] = None  # Declination source. (sent for: write)
    # Manual declination angle (used when source is manual). [rad] (sent for: write)
    declination: _ty.Optional[float] = None

    SET = 0x0D
    DESCRIPTOR = 0x43
    NAME = "declination_source"
    ROLE = "command"
    _ATTRS = ("function", "source", "declination")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.MagneticParamSource, "u8")))),
        _c.Opt(_c.Run(_c.P("declination", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class DeclinationSourceResponse(_c.Field):
    """Declination source (response) (set 0x0D, descriptor 0xB2, response).

    Current declination source and angle.

    Sources: 3dm-gx5-45-dcp.txt line 1882; 3dm-cv7-ins-docs.txt line 8475. Field data: 5 bytes.
    """

    source: _ty.Union[_t.MagneticParamSource, int] = _t.MagneticParamSource.NONE  # Declination source.
    declination: float = 0.0  # Declination angle. [rad]

    SET = 0x0D
    DESCRIPTOR = 0xB2
    NAME = "declination_source_response"
    ROLE = "response"
    _ATTRS = ("source", "declination")
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.MagneticParamSource, "u8")), _c.P("declination", _c.F32)),)


@_c.slotted
@_dc.dataclass
class GravityMagnitudeAdaptiveMeasurement(_c.Field):
    """Gravity magnitude error adaptive measurement (set 0x0D, descriptor 0x44, command).

    Configure the gravity (accelerometer) magnitude error adaptive measurement, which rejects or
    de-weights gravity-vector aiding while the measured acceleration magnitude is off. The filter
    and limit parameters are used only in fixed mode and may be left out: with only the function and
    mode, the other values keep their previous settings.

    Functions: write, read, save, load, default. Responses: 0xB3
    gravity_magnitude_adaptive_measurement_response. Sources: 3dm-gx5-45-dcp.txt line 1938. Field
    data: 1..26 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Disabled, fixed or auto-adaptive. (sent for: write)
    mode: _ty.Optional[_ty.Union[_t.AdaptiveMeasurementMode, int]] = None
    frequency: _ty.Optional[float] = None  # Low-pass filter cutoff frequency. [Hz] (sent for: write)
    low_limit: _ty.Optional[float] = None  # Low limit. [m/s^2] (sent for: write)
    high_limit: _ty.Optional[float] = None  # High limit. [m/s^2] (sent for: write)
    low_limit_uncertainty: _ty.Optional[float] = None  # Low limit uncertainty, 1-sigma. [m/s^2] (sent for: write)
    high_limit_uncertainty: _ty.Optional[float] = None  # High limit uncertainty, 1-sigma. [m/s^2] (sent for: write)
    minimum_uncertainty: _ty.Optional[float] = None  # Minimum uncertainty, 1-sigma. [m/s^2] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x44
    NAME = "gravity_magnitude_adaptive_measurement"
    ROLE = "command"
    _ATTRS = (
        "function",
        "mode",
        "frequency",
        "low_limit",
        "high_limit",
        "low_limit_uncertainty",
        "high_limit_uncertainty",
        "minimum_uncertainty",
    )
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.AdaptiveMeasurementMode, "u8")))),
        _c.Opt(_c.Run(_c.P("frequency", _c.F32))),
        _c.Opt(_c.Run(_c.P("low_limit", _c.F32))),
        _c.Opt(_c.Run(_c.P("high_limit", _c.F32))),
        _c.Opt(_c.Run(_c.P("low_limit_uncertainty", _c.F32))),
        _c.Opt(_c.Run(_c.P("high_limit_uncertainty", _c.F32))),
        _c.Opt(_c.Run(_c.P("minimum_uncertainty", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class GravityMagnitudeAdaptiveMeasurementResponse(_c.Field):
    """Gravity magnitude error adaptive measurement (response) (set 0x0D, descriptor 0xB3, response).

    Current gravity magnitude adaptive measurement settings.

    Sources: 3dm-gx5-45-dcp.txt line 1947. Field data: 25 bytes.
    """

    # Disabled, fixed or auto-adaptive.
    mode: _ty.Union[_t.AdaptiveMeasurementMode, int] = _t.AdaptiveMeasurementMode.DISABLED
    frequency: float = 0.0  # Low-pass filter cutoff frequency. [Hz]
    low_limit: float = 0.0  # Low limit. [m/s^2]
    high_limit: float = 0.0  # High limit. [m/s^2]
    low_limit_uncertainty: float = 0.0  # Low limit uncertainty, 1-sigma. [m/s^2]
    high_limit_uncertainty: float = 0.0  # High limit uncertainty, 1-sigma. [m/s^2]
    minimum_uncertainty: float = 0.0  # Minimum uncertainty, 1-sigma. [m/s^2]

    SET = 0x0D
    DESCRIPTOR = 0xB3
    NAME = "gravity_magnitude_adaptive_measurement_response"
    ROLE = "response"
    _ATTRS = (
        "mode",
        "frequency",
        "low_limit",
        "high_limit",
        "low_limit_uncertainty",
        "high_limit_uncertainty",
        "minimum_uncertainty",
    )
    _OPS = (
        _c.Run(
            _c.P("mode", _c.enum(_t.AdaptiveMeasurementMode, "u8")),
            _c.P("frequency", _c.F32),
            _c.P("low_limit", _c.F32),
            _c.P("high_limit", _c.F32),
            _c.P("low_limit_uncertainty", _c.F32),
            _c.P("high_limit_uncertainty", _c.F32),
            _c.P("minimum_uncertainty", _c.F32),
        ),
    )


@_c.slotted
@_dc.dataclass
class MagMagnitudeAdaptiveMeasurement(_c.Field):
    """Magnetometer magnitude error adaptive measurement (set 0x0D, descriptor 0x45, command).

    Configure the magnetometer magnitude error adaptive measurement, which rejects magnetometer
    readings whose magnitude is outside the fixed or internally computed limits. The filter and
    limit parameters may be left out: with only the function and mode, the other values keep their
    previous settings.

    Functions: write, read, save, load, default. Responses: 0xB4
    mag_magnitude_adaptive_measurement_response. Sources: 3dm-gx5-45-dcp.txt line 1953. Field data:
    1..26 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Disabled, fixed or auto-adaptive. (sent for: write)
    mode: _ty.Optional[_ty.Union[_t.AdaptiveMeasurementMode, int]] = None
    frequency: _ty.Optional[float] = None  # Low-pass filter cutoff frequency. [Hz] (sent for: write)
    low_limit: _ty.Optional[float] = None  # Low limit. [gauss] (sent for: write)
    high_limit: _ty.Optional[float] = None  # High limit. [gauss] (sent for: write)
    low_limit_uncertainty: _ty.Optional[float] = None  # Low limit uncertainty, 1-sigma. [gauss] (sent for: write)
    high_limit_uncertainty: _ty.Optional[float] = None  # High limit uncertainty, 1-sigma. [gauss] (sent for: write)
    minimum_uncertainty: _ty.Optional[float] = None  # Minimum uncertainty, 1-sigma. [gauss] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x45
    NAME = "mag_magnitude_adaptive_measurement"
    ROLE = "command"
    _ATTRS = (
        "function",
        "mode",
        "frequency",
        "low_limit",
        "high_limit",
        "low_limit_uncertainty",
        "high_limit_uncertainty",
        "minimum_uncertainty",
    )
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.AdaptiveMeasurementMode, "u8")))),
        _c.Opt(_c.Run(_c.P("frequency", _c.F32))),
        _c.Opt(_c.Run(_c.P("low_limit", _c.F32))),
        _c.Opt(_c.Run(_c.P("high_limit", _c.F32))),
        _c.Opt(_c.Run(_c.P("low_limit_uncertainty", _c.F32))),
        _c.Opt(_c.Run(_c.P("high_limit_uncertainty", _c.F32))),
        _c.Opt(_c.Run(_c.P("minimum_uncertainty", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class MagMagnitudeAdaptiveMeasurementResponse(_c.Field):
    """Magnetometer magnitude error adaptive measurement (response) (set 0x0D, descriptor 0xB4,
    response).

    Current magnetometer magnitude adaptive measurement settings.

    Sources: 3dm-gx5-45-dcp.txt line 1962. Field data: 25 bytes.
    """

    # Disabled, fixed or auto-adaptive.
    mode: _ty.Union[_t.AdaptiveMeasurementMode, int] = _t.AdaptiveMeasurementMode.DISABLED
    frequency: float = 0.0  # Low-pass filter cutoff frequency. [Hz]
    low_limit: float = 0.0  # Low limit. [gauss]
    high_limit: float = 0.0  # High limit. [gauss]
    low_limit_uncertainty: float = 0.0  # Low limit uncertainty, 1-sigma. [gauss]
    high_limit_uncertainty: float = 0.0  # High limit uncertainty, 1-sigma. [gauss]
    minimum_uncertainty: float = 0.0  # Minimum uncertainty, 1-sigma. [gauss]

    SET = 0x0D
    DESCRIPTOR = 0xB4
    NAME = "mag_magnitude_adaptive_measurement_response"
    ROLE = "response"
    _ATTRS = (
        "mode",
        "frequency",
        "low_limit",
        "high_limit",
        "low_limit_uncertainty",
        "high_limit_uncertainty",
        "minimum_uncertainty",
    )
    _OPS = (
        _c.Run(
            _c.P("mode", _c.enum(_t.AdaptiveMeasurementMode, "u8")),
            _c.P("frequency", _c.F32),
            _c.P("low_limit", _c.F32),
            _c.P("high_limit", _c.F32),
            _c.P("low_limit_uncertainty", _c.F32),
            _c.P("high_limit_uncertainty", _c.F32),
            _c.P("minimum_uncertainty", _c.F32),
        ),
    )


@_c.slotted
@_dc.dataclass
class MagDipAngleAdaptiveMeasurement(_c.Field):
    """Magnetometer dip angle error adaptive measurement (set 0x0D, descriptor 0x46, command).

    Configure the magnetometer dip angle error adaptive measurement, which rejects magnetometer
    readings whose dip angle error exceeds the limit. Ignored while an auto-adaptive magnetometer or
    gravity magnitude mode is selected. Only disabled (0) and fixed (1) are documented.

    Functions: write, read, save, load, default. Responses: 0xB5
    mag_dip_angle_adaptive_measurement_response. Sources: 3dm-gx5-45-dcp.txt line 1968. Field data:
    1..18 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Disabled (0) or fixed (1). (sent for: write)
    mode: _ty.Optional[_ty.Union[_t.AdaptiveMeasurementMode, int]] = None
    frequency: _ty.Optional[float] = None  # Low-pass filter cutoff frequency. [Hz] (sent for: write)
    high_limit: _ty.Optional[float] = None  # High limit of the dip angle error. [rad] (sent for: write)
    high_limit_uncertainty: _ty.Optional[float] = None  # High limit uncertainty, 1-sigma. [rad] (sent for: write)
    minimum_uncertainty: _ty.Optional[float] = None  # Minimum uncertainty, 1-sigma. [rad] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x46
    NAME = "mag_dip_angle_adaptive_measurement"
    ROLE = "command"
    _ATTRS = ("function", "mode", "frequency", "high_limit", "high_limit_uncertainty", "minimum_uncertainty")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.AdaptiveMeasurementMode, "u8")))),
        _c.Opt(_c.Run(_c.P("frequency", _c.F32))),
        _c.Opt(_c.Run(_c.P("high_limit", _c.F32))),
        _c.Opt(_c.Run(_c.P("high_limit_uncertainty", _c.F32))),
        _c.Opt(_c.Run(_c.P("minimum_uncertainty", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class MagDipAngleAdaptiveMeasurementResponse(_c.Field):
    """Magnetometer dip angle error adaptive measurement (response) (set 0x0D, descriptor 0xB5,
    response).

    Current dip angle adaptive measurement settings.

    Sources: 3dm-gx5-45-dcp.txt line 1975. Field data: 17 bytes.
    """

    mode: _ty.Union[_t.AdaptiveMeasurementMode, int] = _t.AdaptiveMeasurementMode.DISABLED  # Disabled (0) or fixed (1).
    frequency: float = 0.0  # Low-pass filter cutoff frequency. [Hz]
    high_limit: float = 0.0  # High limit of the dip angle error. [rad]
    high_limit_uncertainty: float = 0.0  # High limit uncertainty, 1-sigma. [rad]
    minimum_uncertainty: float = 0.0  # Minimum uncertainty, 1-sigma. [rad]

    SET = 0x0D
    DESCRIPTOR = 0xB5
    NAME = "mag_dip_angle_adaptive_measurement_response"
    ROLE = "response"
    _ATTRS = ("mode", "frequency", "high_limit", "high_limit_uncertainty", "minimum_uncertainty")
    _OPS = (
        _c.Run(
            _c.P("mode", _c.enum(_t.AdaptiveMeasurementMode, "u8")),
            _c.P("frequency", _c.F32),
            _c.P("high_limit", _c.F32),
            _c.P("high_limit_uncertainty", _c.F32),
            _c.P("minimum_uncertainty", _c.F32),
        ),
    )


@_c.slotted
@_dc.dataclass
class AltitudeAidingControl(_c.Field):
    """Altitude aiding control (set 0x0D, descriptor 0x47, command).

    Select the altitude aiding input. GNSS is always the primary altitude; the aiding input improves
    it and bridges GNSS outages. Pressure altitude depends on weather and location and can vary by
    more than 40 m.

    Functions: write, read, save, load, default. Responses: 0xB7 altitude_aiding_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1628. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Altitude aiding input (0 disabled, 1 pressure). (sent for: write)
    source: _ty.Optional[_ty.Union[_t.AltitudeAidingSource, int]] = None

    SET = 0x0D
    DESCRIPTOR = 0x47
    NAME = "altitude_aiding_control"
    ROLE = "command"
    _ATTRS = ("function", "source")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.AltitudeAidingSource, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class AltitudeAidingControlResponse(_c.Field):
    """Altitude aiding control (response) (set 0x0D, descriptor 0xB7, response).

    Current altitude aiding input.

    Sources: 3dm-gx5-45-dcp.txt line 1635. Field data: 1 bytes.
    """

    source: _ty.Union[_t.AltitudeAidingSource, int] = _t.AltitudeAidingSource.NONE  # Altitude aiding input.

    SET = 0x0D
    DESCRIPTOR = 0xB7
    NAME = "altitude_aiding_control_response"
    ROLE = "response"
    _ATTRS = ("source",)
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.AltitudeAidingSource, "u8"))),)


@_c.slotted
@_dc.dataclass
class PitchRollAidingControl(_c.Field):
    """Pitch/roll aiding control (set 0x0D, descriptor 0x4B, command).

    Select the pitch/roll aiding input. Pitch and roll always come from the GNSS-corrected inertial
    solution; the aiding input improves it at low dynamics and during GNSS outages.

    Functions: write, read, save, load, default. Responses: 0xBB pitch_roll_aiding_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1615. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Pitch/roll aiding input (0 disabled, 1 gravity vector). (sent for: write)
    source: _ty.Optional[_ty.Union[_t.PitchRollAidingSource, int]] = None

    SET = 0x0D
    DESCRIPTOR = 0x4B
    NAME = "pitch_roll_aiding_control"
    ROLE = "command"
    _ATTRS = ("function", "source")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.PitchRollAidingSource, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class PitchRollAidingControlResponse(_c.Field):
    """Pitch/roll aiding control (response) (set 0x0D, descriptor 0xBB, response).

    Current pitch/roll aiding input.

    Sources: 3dm-gx5-45-dcp.txt line 1621. Field data: 1 bytes.
    """

    source: _ty.Union[_t.PitchRollAidingSource, int] = _t.PitchRollAidingSource.NONE  # Pitch/roll aiding input.

    SET = 0x0D
    DESCRIPTOR = 0xBB
    NAME = "pitch_roll_aiding_control_response"
    ROLE = "response"
    _ATTRS = ("source",)
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.PitchRollAidingSource, "u8"))),)


@_c.slotted
@_dc.dataclass
class InclinationSource(_c.Field):
    """Inclination source (set 0x0D, descriptor 0x4C, command).

    Source of the local magnetic inclination (dip angle), which matters for the magnetometer
    auto-calibration; without an accurate source, leave auto-calibration off.

    Functions: write, read, save, load, default. Responses: 0xBC inclination_source_response.
    Sources: 3dm-gx5-45-dcp.txt line 1890. Field data: 1..6 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    source: _ty.Optional[_ty.Union[_t.MagneticParamSource, int]] = None  # Inclination source. (sent for: write)
    # Manual inclination angle (used when source is manual). [rad] (sent for: write)
    inclination: _ty.Optional[float] = None

    SET = 0x0D
    DESCRIPTOR = 0x4C
    NAME = "inclination_source"
    ROLE = "command"
    _ATTRS = ("function", "source", "inclination")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.MagneticParamSource, "u8")))),
        _c.Opt(_c.Run(_c.P("inclination", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class InclinationSourceResponse(_c.Field):
    """Inclination source (response) (set 0x0D, descriptor 0xBC, response).

    Current inclination source and angle.

    Sources: 3dm-gx5-45-dcp.txt line 1900. Field data: 5 bytes.
    """

    source: _ty.Union[_t.MagneticParamSource, int] = _t.MagneticParamSource.NONE  # Inclination source.
    inclination: float = 0.0  # Inclination angle. [rad]

    SET = 0x0D
    DESCRIPTOR = 0xBC
    NAME = "inclination_source_response"
    ROLE = "response"
    _ATTRS = ("source", "inclination")
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.MagneticParamSource, "u8")), _c.P("inclination", _c.F32)),)


@_c.slotted
@_dc.dataclass
class MagneticFieldMagnitudeSource(_c.Field):
    """Magnetic field magnitude source (set 0x0D, descriptor 0x4D, command).

    Source of the local magnetic field magnitude, used by the magnetometer auto-calibration and the
    magnetometer magnitude adaptive measurement. Source none uses a fixed 0.5 gauss.

    Functions: write, read, save, load, default. Responses: 0xBD
    magnetic_field_magnitude_source_response. Sources: 3dm-gx5-45-dcp.txt line 1907. Field data:
    1..6 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    source: _ty.Optional[_ty.Union[_t.MagneticParamSource, int]] = None  # Magnitude source. (sent for: write)
    # Manual field magnitude (used when source is manual). [gauss] (sent for: write)
    magnitude: _ty.Optional[float] = None

    SET = 0x0D
    DESCRIPTOR = 0x4D
    NAME = "magnetic_field_magnitude_source"
    ROLE = "command"
    _ATTRS = ("function", "source", "magnitude")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.MagneticParamSource, "u8")))),
        _c.Opt(_c.Run(_c.P("magnitude", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class MagneticFieldMagnitudeSourceResponse(_c.Field):
    """Magnetic field magnitude source (response) (set 0x0D, descriptor 0xBD, response).

    Current magnetic field magnitude source and value.

    Sources: 3dm-gx5-45-dcp.txt line 1931. Field data: 5 bytes.
    """

    source: _ty.Union[_t.MagneticParamSource, int] = _t.MagneticParamSource.NONE  # Magnitude source.
    magnitude: float = 0.0  # Field magnitude. [gauss]

    SET = 0x0D
    DESCRIPTOR = 0xBD
    NAME = "magnetic_field_magnitude_source_response"
    ROLE = "response"
    _ATTRS = ("source", "magnitude")
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.MagneticParamSource, "u8")), _c.P("magnitude", _c.F32)),)


@_c.slotted
@_dc.dataclass
class AidingMeasurementControl(_c.Field):
    """Aiding measurement control (set 0x0D, descriptor 0x50, command).

    Enable or disable an internal aiding measurement source. The source is sent with every function;
    ALL (0xFFFF) applies save, load and default to every source.

    Functions: write, read, save, load, default. Responses: 0xD0
    aiding_measurement_control_response. Sources: 3dm-cv7-ins-docs.txt line 8491. Field data: 3..4
    bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Aiding measurement source.
    source: _ty.Union[_t.AidingMeasurementSource, int] = _t.AidingMeasurementSource.GNSS_POS_VEL
    enable: _ty.Optional[bool] = None  # Whether the source is used. (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x50
    NAME = "aiding_measurement_control"
    ROLE = "command"
    _ATTRS = ("function", "source", "enable")
    _OPS = (
        _c.Run(
            _c.P("function", _c.enum(_t.FunctionSelector, "u8")),
            _c.P("source", _c.enum(_t.AidingMeasurementSource, "u16")),
        ),
        _c.Opt(_c.Run(_c.P("enable", _c.BOOL))),
    )


@_c.slotted
@_dc.dataclass
class AidingMeasurementControlResponse(_c.Field):
    """Aiding measurement control (response) (set 0x0D, descriptor 0xD0, response).

    Whether an aiding measurement source is enabled.

    Sources: 3dm-cv7-ins-docs.txt line 8515. Field data: 3 bytes.
    """

    # Aiding measurement source.
    source: _ty.Union[_t.AidingMeasurementSource, int] = _t.AidingMeasurementSource.GNSS_POS_VEL
    enable: bool = False  # Whether the source is used.

    SET = 0x0D
    DESCRIPTOR = 0xD0
    NAME = "aiding_measurement_control_response"
    ROLE = "response"
    _ATTRS = ("source", "enable")
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.AidingMeasurementSource, "u16")), _c.P("enable", _c.BOOL)),)


@_c.slotted
@_dc.dataclass
class InitializationConfiguration(_c.Field):
    """Navigation filter initialization (set 0x0D, descriptor 0x52, command).

    Source and values of the initial conditions (position, velocity, attitude) of the navigation
    filter. Every parameter is always sent; the initial condition source decides which of the user
    values are used, and the reference frame selector gives the units of the position (ECEF: m; LLH:
    deg, deg, m) and the frame of the velocity.

    Functions: write, read, save, load, default. Responses: 0xD2
    initialization_configuration_response. Sources: 3dm-cv7-ins-docs.txt line 8535;
    3dm-cv7-ins-docs.txt line 496. Field data: 1..41 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Non-zero: initialize the filter only after a Run Navigation Filter (0x0D,0x05) command. (sent for: write)
    wait_for_run_command: _ty.Optional[int] = None
    # Which initial conditions are automatic and which user-specified. (sent for: write)
    initial_cond_src: _ty.Optional[_ty.Union[_t.FilterInitialConditionSource, int]] = None
    # Allowed automatic heading alignment methods. (sent for: write)
    auto_heading_alignment_selector: _ty.Optional[_t.HeadingAlignmentMethods] = None
    initial_heading: _ty.Optional[float] = None  # User-specified initial heading. [deg] (sent for: write)
    initial_pitch: _ty.Optional[float] = None  # User-specified initial pitch. [deg] (sent for: write)
    initial_roll: _ty.Optional[float] = None  # User-specified initial roll. [deg] (sent for: write)
    # User-specified initial position (ECEF m, or LLH deg/deg/m, per reference_frame_selector). (sent for: write)
    initial_position: _ty.Optional[_ty.List[float]] = None
    # User-specified initial velocity, in the frame chosen by reference_frame_selector. [m/s] (sent for: write)
    initial_velocity: _ty.Optional[_ty.List[float]] = None
    # Frame of the initial position and velocity. (sent for: write)
    reference_frame_selector: _ty.Optional[_ty.Union[_t.FilterReferenceFrame, int]] = None

    SET = 0x0D
    DESCRIPTOR = 0x52
    NAME = "initialization_configuration"
    ROLE = "command"
    _ATTRS = (
        "function",
        "wait_for_run_command",
        "initial_cond_src",
        "auto_heading_alignment_selector",
        "initial_heading",
        "initial_pitch",
        "initial_roll",
        "initial_position",
        "initial_velocity",
        "reference_frame_selector",
    )
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("wait_for_run_command", _c.U8))),
        _c.Opt(_c.Run(_c.P("initial_cond_src", _c.enum(_t.FilterInitialConditionSource, "u8")))),
        _c.Opt(_c.Run(_c.P("auto_heading_alignment_selector", _c.flags(_t.HeadingAlignmentMethods)))),
        _c.Opt(_c.Run(_c.P("initial_heading", _c.F32))),
        _c.Opt(_c.Run(_c.P("initial_pitch", _c.F32))),
        _c.Opt(_c.Run(_c.P("initial_roll", _c.F32))),
        _c.Opt(_c.Run(_c.P("initial_position", _c.F32, 3))),
        _c.Opt(_c.Run(_c.P("initial_velocity", _c.F32, 3))),
        _c.Opt(_c.Run(_c.P("reference_frame_selector", _c.enum(_t.FilterReferenceFrame, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class InitializationConfigurationResponse(_c.Field):
    """Navigation filter initialization (response) (set 0x0D, descriptor 0xD2, response).

    Current initial condition configuration.

    Sources: 3dm-cv7-ins-docs.txt line 8568. Field data: 40 bytes.
    """

    wait_for_run_command: int = 0  # Non-zero: wait for the run command.
    # Initial condition source.
    initial_cond_src: _ty.Union[_t.FilterInitialConditionSource, int] = _t.FilterInitialConditionSource.AUTO_POS_VEL_ATT
    # Allowed automatic heading alignment methods.
    auto_heading_alignment_selector: _t.HeadingAlignmentMethods = _t.HeadingAlignmentMethods(0)
    initial_heading: float = 0.0  # User-specified initial heading. [deg]
    initial_pitch: float = 0.0  # User-specified initial pitch. [deg]
    initial_roll: float = 0.0  # User-specified initial roll. [deg]
    # User-specified initial position (ECEF m, or LLH deg/deg/m).
    initial_position: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    # User-specified initial velocity. [m/s]
    initial_velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    # Frame of the initial position and velocity.
    reference_frame_selector: _ty.Union[_t.FilterReferenceFrame, int] = _t.FilterReferenceFrame.ECEF

    SET = 0x0D
    DESCRIPTOR = 0xD2
    NAME = "initialization_configuration_response"
    ROLE = "response"
    _ATTRS = (
        "wait_for_run_command",
        "initial_cond_src",
        "auto_heading_alignment_selector",
        "initial_heading",
        "initial_pitch",
        "initial_roll",
        "initial_position",
        "initial_velocity",
        "reference_frame_selector",
    )
    _OPS = (
        _c.Run(
            _c.P("wait_for_run_command", _c.U8),
            _c.P("initial_cond_src", _c.enum(_t.FilterInitialConditionSource, "u8")),
            _c.P("auto_heading_alignment_selector", _c.flags(_t.HeadingAlignmentMethods)),
            _c.P("initial_heading", _c.F32),
            _c.P("initial_pitch", _c.F32),
            _c.P("initial_roll", _c.F32),
            _c.P("initial_position", _c.F32, 3),
            _c.P("initial_velocity", _c.F32, 3),
            _c.P("reference_frame_selector", _c.enum(_t.FilterReferenceFrame, "u8")),
        ),
    )


@_c.slotted
@_dc.dataclass
class AdaptiveFilterControl(_c.Field):
    """Adaptive filter control (set 0x0D, descriptor 0x53, command).

    Basic setup of the auto-adaptive filter: how aggressively it adjusts its statistical models, and
    how long measurements may be rejected before it enters recovery mode.

    Functions: write, read, save, load, default. Responses: 0xD3 adaptive_filter_control_response.
    Sources: 3dm-cv7-ins-docs.txt line 8598; 3dm-cv7-ins-docs.txt line 490. Field data: 1..4 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Auto-adaptive operating level. (sent for: write)
    level: _ty.Optional[_ty.Union[_t.AdaptiveFilterLevel, int]] = None
    time_limit: _ty.Optional[int] = None  # Longest measurement rejection before recovery mode. [ms] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x53
    NAME = "adaptive_filter_control"
    ROLE = "command"
    _ATTRS = ("function", "level", "time_limit")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("level", _c.enum(_t.AdaptiveFilterLevel, "u8")))),
        _c.Opt(_c.Run(_c.P("time_limit", _c.U16))),
    )


@_c.slotted
@_dc.dataclass
class AdaptiveFilterControlResponse(_c.Field):
    """Adaptive filter control (response) (set 0x0D, descriptor 0xD3, response).

    Current adaptive filter settings.

    Sources: 3dm-cv7-ins-docs.txt line 8609. Field data: 3 bytes.
    """

    level: _ty.Union[_t.AdaptiveFilterLevel, int] = _t.AdaptiveFilterLevel.OFF  # Auto-adaptive operating level.
    time_limit: int = 0  # Longest measurement rejection before recovery mode. [ms]

    SET = 0x0D
    DESCRIPTOR = 0xD3
    NAME = "adaptive_filter_control_response"
    ROLE = "response"
    _ATTRS = ("level", "time_limit")
    _OPS = (_c.Run(_c.P("level", _c.enum(_t.AdaptiveFilterLevel, "u8")), _c.P("time_limit", _c.U16)),)


@_c.slotted
@_dc.dataclass
class MultiAntennaOffset(_c.Field):
    """GNSS multi-antenna offset (set 0x0D, descriptor 0x54, command).

    Antenna lever arm of one GNSS receiver, in the vehicle frame, for devices with several antennas.
    The offset magnitude is limited to 10 m.

    Functions: write, read, save, load, default. Responses: 0xD4 multi_antenna_offset_response.
    Sources: 3dm-cv7-ins-docs.txt line 8617. Field data: 2..14 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    receiver_id: int = 0  # Receiver: 1, 2, ...
    # Antenna lever arm in the vehicle frame. [m] (sent for: write)
    antenna_offset: _ty.Optional[_ty.List[float]] = None

    SET = 0x0D
    DESCRIPTOR = 0x54
    NAME = "multi_antenna_offset"
    ROLE = "command"
    _ATTRS = ("function", "receiver_id", "antenna_offset")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("receiver_id", _c.U8)),
        _c.Opt(_c.Run(_c.P("antenna_offset", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class MultiAntennaOffsetResponse(_c.Field):
    """GNSS multi-antenna offset (response) (set 0x0D, descriptor 0xD4, response).

    Current antenna lever arm of a receiver.

    Sources: 3dm-cv7-ins-docs.txt line 8628. Field data: 13 bytes.
    """

    receiver_id: int = 0  # Receiver: 1, 2, ...
    # Antenna lever arm in the vehicle frame. [m]
    antenna_offset: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0D
    DESCRIPTOR = 0xD4
    NAME = "multi_antenna_offset_response"
    ROLE = "response"
    _ATTRS = ("receiver_id", "antenna_offset")
    _OPS = (_c.Run(_c.P("receiver_id", _c.U8), _c.P("antenna_offset", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class RelativePositionConfiguration(_c.Field):
    """Relative position configuration (set 0x0D, descriptor 0x55, command).

    Reference location of the filter's relative position outputs.

    Functions: write, read, save, load, default. Responses: 0xD5
    relative_position_configuration_response. Sources: 3dm-cv7-ins-docs.txt line 8636. Field data:
    1..27 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # 0 automatic (RTK base station), 1 manual. (sent for: write)
    source: _ty.Optional[_ty.Union[_t.RelativePositionSource, int]] = None
    # Frame of the reference coordinates. (sent for: write)
    reference_frame_selector: _ty.Optional[_ty.Union[_t.FilterReferenceFrame, int]] = None
    # Reference location (ECEF m, or LLH deg/deg/m). (sent for: write)
    reference_coordinates: _ty.Optional[_ty.List[float]] = None

    SET = 0x0D
    DESCRIPTOR = 0x55
    NAME = "relative_position_configuration"
    ROLE = "command"
    _ATTRS = ("function", "source", "reference_frame_selector", "reference_coordinates")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.RelativePositionSource, "u8")))),
        _c.Opt(_c.Run(_c.P("reference_frame_selector", _c.enum(_t.FilterReferenceFrame, "u8")))),
        _c.Opt(_c.Run(_c.P("reference_coordinates", _c.F64, 3))),
    )


@_c.slotted
@_dc.dataclass
class RelativePositionConfigurationResponse(_c.Field):
    """Relative position configuration (response) (set 0x0D, descriptor 0xD5, response).

    Current relative position reference.

    Sources: 3dm-cv7-ins-docs.txt line 8651. Field data: 26 bytes.
    """

    # 0 automatic (RTK base station), 1 manual.
    source: _ty.Union[_t.RelativePositionSource, int] = _t.RelativePositionSource.AUTO
    # Frame of the reference coordinates.
    reference_frame_selector: _ty.Union[_t.FilterReferenceFrame, int] = _t.FilterReferenceFrame.ECEF
    # Reference location (ECEF m, or LLH deg/deg/m).
    reference_coordinates: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0D
    DESCRIPTOR = 0xD5
    NAME = "relative_position_configuration_response"
    ROLE = "response"
    _ATTRS = ("source", "reference_frame_selector", "reference_coordinates")
    _OPS = (
        _c.Run(
            _c.P("source", _c.enum(_t.RelativePositionSource, "u8")),
            _c.P("reference_frame_selector", _c.enum(_t.FilterReferenceFrame, "u8")),
            _c.P("reference_coordinates", _c.F64, 3),
        ),
    )


@_c.slotted
@_dc.dataclass
class ReferencePointLeverArm(_c.Field):
    """Reference point lever arm (set 0x0D, descriptor 0x56, command).

    Lever arm from the sensor to the filter's reference point, in the vehicle frame. Moving the
    reference point offsets the filter position and velocity outputs according to attitude and
    angular rate. Limited to 10 m for the vehicle reference point.

    Functions: write, read, save, load, default. Responses: 0xD6 reference_point_lever_arm_response.
    Sources: 3dm-cv7-ins-docs.txt line 8665. Field data: 1..14 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Reference point; reserved, must be 1 (vehicle). (sent for: write)
    ref_point_sel: _ty.Optional[_ty.Union[_t.ReferencePointSelector, int]] = None
    lever_arm_offset: _ty.Optional[_ty.List[float]] = None  # Lever arm in the vehicle frame. [m] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x56
    NAME = "reference_point_lever_arm"
    ROLE = "command"
    _ATTRS = ("function", "ref_point_sel", "lever_arm_offset")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("ref_point_sel", _c.enum(_t.ReferencePointSelector, "u8")))),
        _c.Opt(_c.Run(_c.P("lever_arm_offset", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class ReferencePointLeverArmResponse(_c.Field):
    """Reference point lever arm (response) (set 0x0D, descriptor 0xD6, response).

    Current reference point lever arm.

    Sources: 3dm-cv7-ins-docs.txt line 8678. Field data: 13 bytes.
    """

    ref_point_sel: _ty.Union[_t.ReferencePointSelector, int] = _t.ReferencePointSelector.VEH  # Reference point.
    # Lever arm in the vehicle frame. [m]
    lever_arm_offset: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0D
    DESCRIPTOR = 0xD6
    NAME = "reference_point_lever_arm_response"
    ROLE = "response"
    _ATTRS = ("ref_point_sel", "lever_arm_offset")
    _OPS = (
        _c.Run(_c.P("ref_point_sel", _c.enum(_t.ReferencePointSelector, "u8")), _c.P("lever_arm_offset", _c.F32, 3)),
    )


@_c.slotted
@_dc.dataclass
class SpeedLeverArm(_c.Field):
    """Measurement speed lever arm (set 0x0D, descriptor 0x61, command).

    Lever arm of the speed measurement point (e.g. an odometer on one wheel), in the vehicle frame,
    used to compensate the speed difference caused by vehicle rotation.

    Functions: write, read, save, load, default. Responses: 0xE1 speed_lever_arm_response. Sources:
    3dm-cv7-ins-docs.txt line 8688. Field data: 2..14 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    source: int = 0  # Speed source; reserved, must be 1.
    lever_arm_offset: _ty.Optional[_ty.List[float]] = None  # Lever arm in the vehicle frame. [m] (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x61
    NAME = "speed_lever_arm"
    ROLE = "command"
    _ATTRS = ("function", "source", "lever_arm_offset")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("source", _c.U8)),
        _c.Opt(_c.Run(_c.P("lever_arm_offset", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class SpeedLeverArmResponse(_c.Field):
    """Measurement speed lever arm (response) (set 0x0D, descriptor 0xE1, response).

    Current speed measurement lever arm.

    Sources: 3dm-cv7-ins-docs.txt line 8699. Field data: 13 bytes.
    """

    source: int = 0  # Speed source (1).
    # Lever arm in the vehicle frame. [m]
    lever_arm_offset: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0D
    DESCRIPTOR = 0xE1
    NAME = "speed_lever_arm_response"
    ROLE = "response"
    _ATTRS = ("source", "lever_arm_offset")
    _OPS = (_c.Run(_c.P("source", _c.U8), _c.P("lever_arm_offset", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class WheeledVehicleConstraintControl(_c.Field):
    """Wheeled vehicle constraint control (set 0x0D, descriptor 0x63, command).

    Enable the wheeled vehicle kinematic constraint: velocity is assumed to lie along the vehicle X
    axis. Helps heading for ground vehicles, especially with intermittent GNSS.

    Functions: write, read, save, load, default. Responses: 0xE3
    wheeled_vehicle_constraint_control_response. Sources: 3dm-cv7-ins-docs.txt line 8707. Field
    data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    enable: _ty.Optional[int] = None  # 0 disables, 1 enables the constraint. (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x63
    NAME = "wheeled_vehicle_constraint_control"
    ROLE = "command"
    _ATTRS = ("function", "enable")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("enable", _c.U8))),
    )


@_c.slotted
@_dc.dataclass
class WheeledVehicleConstraintControlResponse(_c.Field):
    """Wheeled vehicle constraint control (response) (set 0x0D, descriptor 0xE3, response).

    Whether the wheeled vehicle constraint is enabled.

    Sources: 3dm-cv7-ins-docs.txt line 8717. Field data: 1 bytes.
    """

    enable: int = 0  # 0 disabled, 1 enabled.

    SET = 0x0D
    DESCRIPTOR = 0xE3
    NAME = "wheeled_vehicle_constraint_control_response"
    ROLE = "response"
    _ATTRS = ("enable",)
    _OPS = (_c.Run(_c.P("enable", _c.U8)),)


@_c.slotted
@_dc.dataclass
class GnssAntennaCalibrationControl(_c.Field):
    """GNSS antenna offset calibration control (set 0x0D, descriptor 0x64, command).

    Enable tracking of the GNSS antenna lever arm error, up to the given maximum offset error (CV7:
    default 0.1 m, at most 0.5 m).

    Functions: write, read, save, load, default. Responses: 0xE4
    gnss_antenna_calibration_control_response. Sources: 3dm-cv7-ins-docs.txt line 8724;
    3dm-cv7-ins-docs.txt line 265. Field data: 1..6 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    enable: _ty.Optional[int] = None  # 0 disables, 1 enables lever arm error tracking. (sent for: write)
    # Largest absolute lever arm offset error in the vehicle frame. [m] (sent for: write)
    max_offset: _ty.Optional[float] = None

    SET = 0x0D
    DESCRIPTOR = 0x64
    NAME = "gnss_antenna_calibration_control"
    ROLE = "command"
    _ATTRS = ("function", "enable", "max_offset")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("enable", _c.U8))),
        _c.Opt(_c.Run(_c.P("max_offset", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class GnssAntennaCalibrationControlResponse(_c.Field):
    """GNSS antenna offset calibration control (response) (set 0x0D, descriptor 0xE4, response).

    Current antenna lever arm calibration settings.

    Sources: 3dm-cv7-ins-docs.txt line 8735. Field data: 5 bytes.
    """

    enable: int = 0  # 0 disabled, 1 enabled.
    max_offset: float = 0.0  # Largest absolute lever arm offset error. [m]

    SET = 0x0D
    DESCRIPTOR = 0xE4
    NAME = "gnss_antenna_calibration_control_response"
    ROLE = "response"
    _ATTRS = ("enable", "max_offset")
    _OPS = (_c.Run(_c.P("enable", _c.U8), _c.P("max_offset", _c.F32)),)


FIELDS: tuple[type[_c.Field], ...] = (
    ResetFilter,
    SetInitialAttitude,
    SetInitialHeading,
    RunFilter,
    VehicleDynamicsMode,
    VehicleDynamicsModeResponse,
    SensorToVehicleTransform,
    SensorToVehicleTransformResponse,
    SensorToVehicleOffset,
    SensorToVehicleOffsetResponse,
    AntennaOffset,
    AntennaOffsetResponse,
    EstimationControl,
    EstimationControlResponse,
    GnssSourceControl,
    GnssSourceControlResponse,
    ExternalGnssUpdate,
    ExternalHeadingUpdate,
    HeadingUpdateControl,
    HeadingUpdateControlResponse,
    AutoInitControl,
    AutoInitControlResponse,
    AccelNoise,
    AccelNoiseResponse,
    GyroNoise,
    GyroNoiseResponse,
    AccelBiasModel,
    AccelBiasModelResponse,
    GyroBiasModel,
    GyroBiasModelResponse,
    ZuptControl,
    ZuptControlResponse,
    ExternalHeadingUpdateWithTime,
    ZeroAngularRateUpdateControl,
    ZeroAngularRateUpdateControlResponse,
    TareOrientation,
    CommandedZupt,
    CommandedZeroAngularRateUpdate,
    MagCaptureAutoCalibration,
    GravityNoiseStdDev,
    GravityNoiseStdDevResponse,
    PressureAltitudeNoiseStdDev,
    PressureAltitudeNoiseStdDevResponse,
    HardIronOffsetNoise,
    HardIronOffsetNoiseResponse,
    SoftIronMatrixNoise,
    SoftIronMatrixNoiseResponse,
    MagNoiseStdDev,
    MagNoiseStdDevResponse,
    DeclinationSource,
    DeclinationSourceResponse,
    GravityMagnitudeAdaptiveMeasurement,
    GravityMagnitudeAdaptiveMeasurementResponse,
    MagMagnitudeAdaptiveMeasurement,
    MagMagnitudeAdaptiveMeasurementResponse,
    MagDipAngleAdaptiveMeasurement,
    MagDipAngleAdaptiveMeasurementResponse,
    AltitudeAidingControl,
    AltitudeAidingControlResponse,
    PitchRollAidingControl,
    PitchRollAidingControlResponse,
    InclinationSource,
    InclinationSourceResponse,
    MagneticFieldMagnitudeSource,
    MagneticFieldMagnitudeSourceResponse,
    AidingMeasurementControl,
    AidingMeasurementControlResponse,
    InitializationConfiguration,
    InitializationConfigurationResponse,
    AdaptiveFilterControl,
    AdaptiveFilterControlResponse,
    MultiAntennaOffset,
    MultiAntennaOffsetResponse,
    RelativePositionConfiguration,
    RelativePositionConfigurationResponse,
    ReferencePointLeverArm,
    ReferencePointLeverArmResponse,
    SpeedLeverArm,
    SpeedLeverArmResponse,
    WheeledVehicleConstraintControl,
    WheeledVehicleConstraintControlResponse,
    GnssAntennaCalibrationControl,
    GnssAntennaCalibrationControlResponse,
)
