"""Filter Command Set (descriptor set 0x0D, command).

Configure, initialise and aid the navigation (Kalman) filter: reset and run it, give it an initial
attitude or heading, set frame transformations and antenna offsets, choose its GNSS and heading
sources, feed it external measurements and tune its noise models.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import codec as _c
from . import types as _t


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


@_dc.dataclass
class VehicleDynamicsMode(_c.Field):
    """Vehicle dynamics mode (set 0x0D, descriptor 0x10, command).

    Set, read, save, load or reset the vehicle dynamics mode of the filter.

    Functions: write, read, save, load, default. Responses: 0x80 vehicle_dynamics_mode_response.
    Sources: 3dm-gx5-45-dcp.txt line 1447. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
    mode: _ty.Optional[_t.VehicleDynamicsMode] = None  # New dynamics mode. (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x10
    NAME = "vehicle_dynamics_mode"
    ROLE = "command"
    _ATTRS = ("function", "mode")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.VehicleDynamicsMode, "u8")))),
    )


@_dc.dataclass
class VehicleDynamicsModeResponse(_c.Field):
    """Vehicle dynamics mode (response) (set 0x0D, descriptor 0x80, response).

    Current vehicle dynamics mode (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1460. Field data: 1 bytes.
    """

    mode: _t.VehicleDynamicsMode = _t.VehicleDynamicsMode.PORTABLE  # Current dynamics mode.

    SET = 0x0D
    DESCRIPTOR = 0x80
    NAME = "vehicle_dynamics_mode_response"
    ROLE = "response"
    _ATTRS = ("mode",)
    _OPS = (_c.Run(_c.P("mode", _c.enum(_t.VehicleDynamicsMode, "u8"))),)


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
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
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


@_dc.dataclass
class SensorToVehicleOffset(_c.Field):
    """Sensor to vehicle frame offset (set 0x0D, descriptor 0x12, command).

    Offset from the sensor to the vehicle reference point, in the sensor frame, added to the
    estimated LLH position. Not a lever arm: no inertial compensation. Magnitude at most 10 m.

    Functions: write, read, save, load, default. Responses: 0x82 sensor_to_vehicle_offset_response.
    Sources: 3dm-gx5-45-dcp.txt line 1485. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
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
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
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


@_dc.dataclass
class EstimationControl(_c.Field):
    """Estimation control flags (set 0x0D, descriptor 0x14, command).

    Select which optional parameters the Kalman filter estimates.

    Functions: write, read, save, load, default. Responses: 0x84 estimation_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1517. Field data: 1..3 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
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


@_dc.dataclass
class GnssSourceControl(_c.Field):
    """GNSS source control (set 0x0D, descriptor 0x15, command).

    Choose the source of GNSS updates to the filter. Changing it while running may put the filter
    back in its init state until data from the new source arrives.

    Functions: write, read, save, load, default. Responses: 0x86 gnss_source_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1531; 3dm-cv7-ins-docs.txt line 8293. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
    source: _ty.Optional[_t.FilterGnssSource] = None  # GNSS source. (sent for: write)

    SET = 0x0D
    DESCRIPTOR = 0x15
    NAME = "gnss_source_control"
    ROLE = "command"
    _ATTRS = ("function", "source")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.FilterGnssSource, "u8")))),
    )


@_dc.dataclass
class GnssSourceControlResponse(_c.Field):
    """GNSS source control (response) (set 0x0D, descriptor 0x86, response).

    Current GNSS source (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1539; 3dm-cv7-ins-docs.txt line 8308. Field data: 1 bytes.
    """

    source: _t.FilterGnssSource = _t.FilterGnssSource.ALL_INTERNAL  # GNSS source.

    SET = 0x0D
    DESCRIPTOR = 0x86
    NAME = "gnss_source_control_response"
    ROLE = "response"
    _ATTRS = ("source",)
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.FilterGnssSource, "u8"))),)


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
    type: _t.ExternalHeadingType = _t.ExternalHeadingType.TRUE_HEADING  # True or magnetic heading.

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


@_dc.dataclass
class HeadingUpdateControl(_c.Field):
    """Heading update control (set 0x0D, descriptor 0x18, command).

    Select the aiding source(s) of filter heading updates.

    Functions: write, read, save, load, default. Responses: 0x87 heading_update_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1562. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
    # Heading aiding source (the manual's "Enable Flag"). (sent for: write)
    source: _ty.Optional[_t.HeadingUpdateSource] = None

    SET = 0x0D
    DESCRIPTOR = 0x18
    NAME = "heading_update_control"
    ROLE = "command"
    _ATTRS = ("function", "source")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.HeadingUpdateSource, "u8")))),
    )


@_dc.dataclass
class HeadingUpdateControlResponse(_c.Field):
    """Heading update control (response) (set 0x0D, descriptor 0x87, response).

    Current heading update source (reply to read).

    Sources: 3dm-gx5-45-dcp.txt line 1579. Field data: 1 bytes.
    """

    source: _t.HeadingUpdateSource = _t.HeadingUpdateSource.NONE  # Heading aiding source.

    SET = 0x0D
    DESCRIPTOR = 0x87
    NAME = "heading_update_control_response"
    ROLE = "response"
    _ATTRS = ("source",)
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.HeadingUpdateSource, "u8"))),)


@_dc.dataclass
class AutoInitControl(_c.Field):
    """Auto-initialization control (set 0x0D, descriptor 0x19, command).

    Enable or disable automatic filter initialisation at startup (needs a valid heading source;
    otherwise use Set initial heading or Set initial attitude).

    Functions: write, read, save, load, default. Responses: 0x88 auto_init_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1642. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
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


@_dc.dataclass
class AccelNoise(_c.Field):
    """Accelerometer noise standard deviation (set 0x0D, descriptor 0x1A, command).

    Expected accelerometer (process) noise, 1-sigma per axis, used to tune the filter. Each value
    must be greater than 0.

    Functions: write, read, save, load, default. Responses: 0x89 accel_noise_response. Sources:
    3dm-gx5-45-dcp.txt line 1704; 3dm-cv7-ins-docs.txt line 8336. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
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


@_dc.dataclass
class GyroNoise(_c.Field):
    """Gyroscope noise standard deviation (set 0x0D, descriptor 0x1B, command).

    Expected gyro (process) noise, 1-sigma per axis, used to tune the filter. Each value must be
    greater than 0.

    Functions: write, read, save, load, default. Responses: 0x8A gyro_noise_response. Sources:
    3dm-gx5-45-dcp.txt line 1749; 3dm-cv7-ins-docs.txt line 8353. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
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


@_dc.dataclass
class AccelBiasModel(_c.Field):
    """Accelerometer bias model parameters (set 0x0D, descriptor 0x1C, command).

    First-order (Gauss-Markov) accelerometer bias model: time constant inverse (beta) and bias noise
    1-sigma per axis. Noise values must be greater than 0.

    Functions: write, read, save, load, default. Responses: 0x8B accel_bias_model_response. Sources:
    3dm-gx5-45-dcp.txt line 1733; 3dm-cv7-ins-docs.txt line 8370. Field data: 1..25 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
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


@_dc.dataclass
class GyroBiasModel(_c.Field):
    """Gyroscope bias model parameters (set 0x0D, descriptor 0x1D, command).

    First-order (Gauss-Markov) gyro bias model: time constant inverse (beta) and bias noise 1-sigma
    per axis. Noise values must be greater than 0.

    Functions: write, read, save, load, default. Responses: 0x8C gyro_bias_model_response. Sources:
    3dm-gx5-45-dcp.txt line 1764; 3dm-cv7-ins-docs.txt line 8389. Field data: 1..25 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
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


@_dc.dataclass
class ZuptControl(_c.Field):
    """Zero velocity update (ZUPT) control (set 0x0D, descriptor 0x1E, command).

    Enable zero-velocity updates, applied when the GNSS velocity magnitude is at or below the
    threshold. Negative thresholds are NACKed.

    Functions: write, read, save, load, default. Responses: 0x8D zupt_control_response. Sources:
    3dm-gx5-45-dcp.txt line 1807. Field data: 1..6 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _t.FunctionSelector = _t.FunctionSelector.WRITE
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
    type: _t.ExternalHeadingType = _t.ExternalHeadingType.TRUE_HEADING  # True or magnetic heading.

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


FIELDS: tuple = (
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
)
