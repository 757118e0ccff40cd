"""Aiding Command Set (descriptor set 0x13, command).

External aiding measurements for the navigation filter, each timestamped and tagged with the aiding
frame it was measured in, plus the definition of those frames (lever arm and rotation relative to
the vehicle frame) and control of how the device acknowledges aiding commands.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class FrameConfig(_c.Field):
    """Frame configuration (set 0x13, descriptor 0x01, command).

    Define an aiding frame: the translation (lever arm) and rotation of an external aiding sensor
    relative to the vehicle frame. Aiding measurements name the frame they were taken in with their
    frame_id. Optionally the filter tracks errors in the frame definition.

    Functions: write, read, save, load, default. Responses: 0x81 frame_config_response. Sources:
    3dm-cv7-ins-docs.txt line 7747. Field data: 2..32 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    frame_id: int = 0  # Reference frame number (at most 4).
    # Format of the rotation (also selects the format a read reports). (sent for: write, read)
    format: _ty.Optional[_ty.Union[_t.AidingFrameFormat, int]] = None
    # If true, the Kalman filter tracks errors in this frame definition. (sent for: write)
    tracking_enabled: _ty.Optional[bool] = None
    # Translation X, Y, Z of the frame in the vehicle frame. [m] (sent for: write)
    translation: _ty.Optional[_ty.List[float]] = None
    # Rotation of the frame, in the given format. (sent for: write)
    rotation: _ty.Optional[_ty.Union[_t.AidingFrameEuler, _t.AidingFrameQuaternion]] = None

    SET = 0x13
    DESCRIPTOR = 0x01
    NAME = "frame_config"
    ROLE = "command"
    _ATTRS = ("function", "frame_id", "format", "tracking_enabled", "translation", "rotation")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("frame_id", _c.U8)),
        _c.Opt(_c.Run(_c.P("format", _c.enum(_t.AidingFrameFormat, "u8")))),
        _c.Opt(_c.Run(_c.P("tracking_enabled", _c.BOOL))),
        _c.Opt(_c.Run(_c.P("translation", _c.F32, 3))),
        _c.Opt(_c.Choice("rotation", _t.AidingFrameRotation, selector="format")),
    )


@_c.slotted
@_dc.dataclass
class FrameConfigResponse(_c.Field):
    """Frame configuration (response) (set 0x13, descriptor 0x81, response).

    Current definition of an aiding frame.

    Sources: 3dm-cv7-ins-docs.txt line 7766. Field data: 27..31 bytes.
    """

    frame_id: int = 0  # Reference frame number.
    format: _ty.Union[_t.AidingFrameFormat, int] = _t.AidingFrameFormat.EULER  # Format of the rotation.
    tracking_enabled: bool = False  # Whether the Kalman filter tracks errors in this frame.
    translation: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Translation X, Y, Z. [m]
    # Rotation, in the given format.
    rotation: _ty.Optional[_ty.Union[_t.AidingFrameEuler, _t.AidingFrameQuaternion]] = None

    SET = 0x13
    DESCRIPTOR = 0x81
    NAME = "frame_config_response"
    ROLE = "response"
    _ATTRS = ("frame_id", "format", "tracking_enabled", "translation", "rotation")
    _OPS = (
        _c.Run(
            _c.P("frame_id", _c.U8),
            _c.P("format", _c.enum(_t.AidingFrameFormat, "u8")),
            _c.P("tracking_enabled", _c.BOOL),
            _c.P("translation", _c.F32, 3),
        ),
        _c.Choice("rotation", _t.AidingFrameRotation, selector="format"),
    )


@_c.slotted
@_dc.dataclass
class EchoControl(_c.Field):
    """Echo control (set 0x13, descriptor 0x1F, command).

    Control how the device answers aiding measurement commands: no ack, normal ack/nack, or echoing
    the aiding data back (useful for logging and post-processing).

    Functions: write, read, save, load, default. Responses: 0x9F echo_control_response. Sources:
    3dm-cv7-ins-docs.txt line 7791; 3dm-cv7-ins-docs.txt line 749. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    mode: _ty.Optional[_ty.Union[_t.AidingEchoMode, int]] = None  # How aiding commands are answered. (sent for: write)

    SET = 0x13
    DESCRIPTOR = 0x1F
    NAME = "echo_control"
    ROLE = "command"
    _ATTRS = ("function", "mode")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.AidingEchoMode, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class EchoControlResponse(_c.Field):
    """Echo control (response) (set 0x13, descriptor 0x9F, response).

    Current aiding echo mode.

    Sources: 3dm-cv7-ins-docs.txt line 7806. Field data: 1 bytes.
    """

    mode: _ty.Union[_t.AidingEchoMode, int] = _t.AidingEchoMode.SUPPRESS_ACK  # How aiding commands are answered.

    SET = 0x13
    DESCRIPTOR = 0x9F
    NAME = "echo_control_response"
    ROLE = "response"
    _ATTRS = ("mode",)
    _OPS = (_c.Run(_c.P("mode", _c.enum(_t.AidingEchoMode, "u8"))),)


@_c.slotted
@_dc.dataclass
class EcefPosition(_c.Field):
    """ECEF position (set 0x13, descriptor 0x21, command).

    Position aiding measurement in the WGS84 Earth-centred, Earth-fixed frame.

    Sources: 3dm-cv7-ins-docs.txt line 7819; 3dm-cv7-ins-docs.txt line 755. Field data: 49 bytes.
    """

    time: _t.AidingTime = _dc.field(default_factory=_t.AidingTime)  # Timestamp of the measurement.
    frame_id: int = 0  # Aiding frame the measurement was taken in (see frame_config).
    position: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # ECEF position X, Y, Z. [m]
    # ECEF position 1-sigma uncertainty; not 0 for a valid axis. [m]
    uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.AidingVectorValidFlags = _t.AidingVectorValidFlags(0)  # Valid axes; invalid axes are ignored.

    SET = 0x13
    DESCRIPTOR = 0x21
    NAME = "ecef_position"
    ROLE = "command"
    _ATTRS = ("time", "frame_id", "position", "uncertainty", "valid_flags")
    _OPS = (
        _c.Nested("time", _t.AidingTime),
        _c.Run(
            _c.P("frame_id", _c.U8),
            _c.P("position", _c.F64, 3),
            _c.P("uncertainty", _c.F32, 3),
            _c.P("valid_flags", _c.flags(_t.AidingVectorValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class LlhPosition(_c.Field):
    """LLH position (set 0x13, descriptor 0x22, command).

    Geodetic position aiding measurement: WGS84 latitude, longitude and height above the ellipsoid,
    with uncertainty in north, east, down components. With latitude and longitude marked invalid it
    aids height only.

    Sources: 3dm-cv7-ins-docs.txt line 7841; 3dm-cv7-ins-docs.txt line 759. Field data: 49 bytes.
    """

    time: _t.AidingTime = _dc.field(default_factory=_t.AidingTime)  # Timestamp of the measurement.
    frame_id: int = 0  # Aiding frame the measurement was taken in.
    latitude: float = 0.0  # WGS84 latitude. [deg]
    longitude: float = 0.0  # WGS84 longitude. [deg]
    height: float = 0.0  # Height above the WGS84 ellipsoid. [m]
    # 1-sigma uncertainty in north, east, down (the table prints no unit); not 0 for a valid component. [m]
    uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.AidingLlhValidFlags = _t.AidingLlhValidFlags(0)  # Valid components; invalid ones are ignored.

    SET = 0x13
    DESCRIPTOR = 0x22
    NAME = "llh_position"
    ROLE = "command"
    _ATTRS = ("time", "frame_id", "latitude", "longitude", "height", "uncertainty", "valid_flags")
    _OPS = (
        _c.Nested("time", _t.AidingTime),
        _c.Run(
            _c.P("frame_id", _c.U8),
            _c.P("latitude", _c.F64),
            _c.P("longitude", _c.F64),
            _c.P("height", _c.F64),
            _c.P("uncertainty", _c.F32, 3),
            _c.P("valid_flags", _c.flags(_t.AidingLlhValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class HeightAboveEllipsoid(_c.Field):
    """Height above ellipsoid (set 0x13, descriptor 0x23, command).

    Height aiding measurement above the WGS84 ellipsoid.

    Sources: 3dm-cv7-ins-docs.txt line 7866. Field data: 21 bytes.
    """

    time: _t.AidingTime = _dc.field(default_factory=_t.AidingTime)  # Timestamp of the measurement.
    frame_id: int = 0  # Aiding frame the measurement was taken in.
    height: float = 0.0  # Height above the ellipsoid. [m]
    uncertainty: float = 0.0  # 1-sigma uncertainty. [m]
    valid_flags: int = 0  # Valid flags; 0 means the measurement is ignored (no bits are defined).

    SET = 0x13
    DESCRIPTOR = 0x23
    NAME = "height_above_ellipsoid"
    ROLE = "command"
    _ATTRS = ("time", "frame_id", "height", "uncertainty", "valid_flags")
    _OPS = (
        _c.Nested("time", _t.AidingTime),
        _c.Run(
            _c.P("frame_id", _c.U8), _c.P("height", _c.F32), _c.P("uncertainty", _c.F32), _c.P("valid_flags", _c.U16)
        ),
    )


@_c.slotted
@_dc.dataclass
class EcefVelocity(_c.Field):
    """ECEF velocity (set 0x13, descriptor 0x28, command).

    Velocity aiding measurement in the WGS84 ECEF frame. Not for body-fixed sensors such as radar
    (use body frame velocity).

    Sources: 3dm-cv7-ins-docs.txt line 7882; 3dm-cv7-ins-docs.txt line 769. Field data: 37 bytes.
    """

    time: _t.AidingTime = _dc.field(default_factory=_t.AidingTime)  # Timestamp of the measurement.
    frame_id: int = 0  # Aiding frame the measurement was taken in.
    velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # ECEF velocity X, Y, Z. [m/s]
    # ECEF velocity 1-sigma uncertainty; not 0 for a valid axis. [m/s]
    uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.AidingVectorValidFlags = _t.AidingVectorValidFlags(0)  # Valid axes; invalid axes are ignored.

    SET = 0x13
    DESCRIPTOR = 0x28
    NAME = "ecef_velocity"
    ROLE = "command"
    _ATTRS = ("time", "frame_id", "velocity", "uncertainty", "valid_flags")
    _OPS = (
        _c.Nested("time", _t.AidingTime),
        _c.Run(
            _c.P("frame_id", _c.U8),
            _c.P("velocity", _c.F32, 3),
            _c.P("uncertainty", _c.F32, 3),
            _c.P("valid_flags", _c.flags(_t.AidingVectorValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class NedVelocity(_c.Field):
    """NED velocity (set 0x13, descriptor 0x29, command).

    Velocity aiding measurement in the local north-east-down frame. Not for body-fixed sensors (use
    body frame velocity).

    Sources: 3dm-cv7-ins-docs.txt line 7904; 3dm-cv7-ins-docs.txt line 773. Field data: 37 bytes.
    """

    time: _t.AidingTime = _dc.field(default_factory=_t.AidingTime)  # Timestamp of the measurement.
    frame_id: int = 0  # Aiding frame the measurement was taken in.
    velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # NED velocity (north, east, down). [m/s]
    # NED velocity 1-sigma uncertainty; not 0 for a valid axis. [m/s]
    uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    # Valid components (x = north, y = east, z = down).
    valid_flags: _t.AidingVectorValidFlags = _t.AidingVectorValidFlags(0)

    SET = 0x13
    DESCRIPTOR = 0x29
    NAME = "ned_velocity"
    ROLE = "command"
    _ATTRS = ("time", "frame_id", "velocity", "uncertainty", "valid_flags")
    _OPS = (
        _c.Nested("time", _t.AidingTime),
        _c.Run(
            _c.P("frame_id", _c.U8),
            _c.P("velocity", _c.F32, 3),
            _c.P("uncertainty", _c.F32, 3),
            _c.P("valid_flags", _c.flags(_t.AidingVectorValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class BodyFrameVelocity(_c.Field):
    """Body frame velocity (set 0x13, descriptor 0x2A, command).

    Velocity aiding measurement in a frame fixed to the vehicle (the aiding frame given by
    frame_id), e.g. pre-processed radar, lidar, wheel-speed or air-speed velocity. Up to four such
    sensors.

    Sources: 3dm-cv7-ins-docs.txt line 7926; 3dm-cv7-ins-docs.txt line 777. Field data: 37 bytes.
    """

    time: _t.AidingTime = _dc.field(default_factory=_t.AidingTime)  # Timestamp of the measurement.
    frame_id: int = 0  # Aiding frame the measurement was taken in (must be > 0).
    # Velocity X, Y, Z in the aiding frame. [m/s]
    velocity: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    # 1-sigma uncertainty; not 0 (or negative) for a valid axis. [m/s]
    uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.AidingVectorValidFlags = _t.AidingVectorValidFlags(0)  # Valid axes; invalid axes are ignored.

    SET = 0x13
    DESCRIPTOR = 0x2A
    NAME = "body_frame_velocity"
    ROLE = "command"
    _ATTRS = ("time", "frame_id", "velocity", "uncertainty", "valid_flags")
    _OPS = (
        _c.Nested("time", _t.AidingTime),
        _c.Run(
            _c.P("frame_id", _c.U8),
            _c.P("velocity", _c.F32, 3),
            _c.P("uncertainty", _c.F32, 3),
            _c.P("valid_flags", _c.flags(_t.AidingVectorValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class TrueHeading(_c.Field):
    """True heading (set 0x13, descriptor 0x31, command).

    Heading aiding measurement relative to true north (e.g. dual-antenna GNSS compass).

    Sources: 3dm-cv7-ins-docs.txt line 7950; 3dm-cv7-ins-docs.txt line 805. Field data: 21 bytes.
    """

    time: _t.AidingTime = _dc.field(default_factory=_t.AidingTime)  # Timestamp of the measurement.
    frame_id: int = 0  # Aiding frame the measurement was taken in.
    heading: float = 0.0  # True heading, within +/- pi. [rad]
    uncertainty: float = 0.0  # 1-sigma uncertainty; not 0 unless the valid flags are 0. [rad]
    valid_flags: int = 0  # Valid flags; 0 means the measurement is ignored (no bits are defined).

    SET = 0x13
    DESCRIPTOR = 0x31
    NAME = "true_heading"
    ROLE = "command"
    _ATTRS = ("time", "frame_id", "heading", "uncertainty", "valid_flags")
    _OPS = (
        _c.Nested("time", _t.AidingTime),
        _c.Run(
            _c.P("frame_id", _c.U8), _c.P("heading", _c.F32), _c.P("uncertainty", _c.F32), _c.P("valid_flags", _c.U16)
        ),
    )


@_c.slotted
@_dc.dataclass
class MagneticField(_c.Field):
    """Magnetic field (set 0x13, descriptor 0x32, command).

    Magnetic field aiding measurement from a calibrated external magnetometer, in the aiding frame
    given by frame_id.

    Sources: 3dm-cv7-ins-docs.txt line 7966; 3dm-cv7-ins-docs.txt line 809. Field data: 37 bytes.
    """

    time: _t.AidingTime = _dc.field(default_factory=_t.AidingTime)  # Timestamp of the measurement.
    frame_id: int = 0  # Aiding frame the measurement was taken in (must be > 0).
    magnetic_field: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)  # Magnetic field X, Y, Z. [gauss]
    # 1-sigma uncertainty; not 0 for a valid axis. [gauss]
    uncertainty: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)
    valid_flags: _t.AidingVectorValidFlags = _t.AidingVectorValidFlags(0)  # Valid axes; invalid axes are ignored.

    SET = 0x13
    DESCRIPTOR = 0x32
    NAME = "magnetic_field"
    ROLE = "command"
    _ATTRS = ("time", "frame_id", "magnetic_field", "uncertainty", "valid_flags")
    _OPS = (
        _c.Nested("time", _t.AidingTime),
        _c.Run(
            _c.P("frame_id", _c.U8),
            _c.P("magnetic_field", _c.F32, 3),
            _c.P("uncertainty", _c.F32, 3),
            _c.P("valid_flags", _c.flags(_t.AidingVectorValidFlags)),
        ),
    )


@_c.slotted
@_dc.dataclass
class Pressure(_c.Field):
    """Pressure (set 0x13, descriptor 0x33, command).

    Static air pressure aiding measurement, to constrain altitude drift during GNSS outages.

    Sources: 3dm-cv7-ins-docs.txt line 7988; 3dm-cv7-ins-docs.txt line 833. Field data: 21 bytes.
    """

    time: _t.AidingTime = _dc.field(default_factory=_t.AidingTime)  # Timestamp of the measurement.
    frame_id: int = 0  # Aiding frame the measurement was taken in.
    pressure: float = 0.0  # Static pressure. [mbar]
    uncertainty: float = 0.0  # 1-sigma uncertainty; not 0 unless the valid flags are 0. [mbar]
    valid_flags: int = 0  # Valid flags; 0 means the measurement is ignored (no bits are defined).

    SET = 0x13
    DESCRIPTOR = 0x33
    NAME = "pressure"
    ROLE = "command"
    _ATTRS = ("time", "frame_id", "pressure", "uncertainty", "valid_flags")
    _OPS = (
        _c.Nested("time", _t.AidingTime),
        _c.Run(
            _c.P("frame_id", _c.U8), _c.P("pressure", _c.F32), _c.P("uncertainty", _c.F32), _c.P("valid_flags", _c.U16)
        ),
    )


FIELDS: tuple[type[_c.Field], ...] = (
    FrameConfig,
    FrameConfigResponse,
    EchoControl,
    EchoControlResponse,
    EcefPosition,
    LlhPosition,
    HeightAboveEllipsoid,
    EcefVelocity,
    NedVelocity,
    BodyFrameVelocity,
    TrueHeading,
    MagneticField,
    Pressure,
)
