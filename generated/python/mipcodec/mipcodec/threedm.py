"""3DM Command Set (descriptor set 0x0C, command).

Device configuration common to MicroStrain inertial sensors.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class EventControl(_c.Field):
    """Event control (set 0x0C, descriptor 0x2B, command).

    Enable, disable or test an event trigger.

    Functions: write, read, save, load, default. Responses: 0xB5 event_control_response. Sources:
    3dm-cv7-ins-docs.txt line 7018. Field data: 2..3 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    instance: int = 0  # Trigger instance; 0 applies to all configured triggers (not for read).
    mode: _ty.Optional[_ty.Union[_t.EventControlMode, int]] = None  # How to change the trigger state. (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x2B
    NAME = "event_control"
    ROLE = "command"
    _ATTRS = ("function", "instance", "mode")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("instance", _c.U8)),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.EventControlMode, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class EventControlResponse(_c.Field):
    """Event control (response) (set 0x0C, descriptor 0xB5, response).

    Current mode of a trigger.

    Sources: 3dm-cv7-ins-docs.txt line 7032. Field data: 2 bytes.
    """

    instance: int = 0  # Trigger instance.
    mode: _ty.Union[_t.EventControlMode, int] = _t.EventControlMode.DISABLED  # Trigger mode.

    SET = 0x0C
    DESCRIPTOR = 0xB5
    NAME = "event_control_response"
    ROLE = "response"
    _ATTRS = ("instance", "mode")
    _OPS = (_c.Run(_c.P("instance", _c.U8), _c.P("mode", _c.enum(_t.EventControlMode, "u8"))),)


@_c.slotted
@_dc.dataclass
class GetEventTriggerStatus(_c.Field):
    """Get event trigger status (set 0x0C, descriptor 0x2C, command).

    Report the type and status of event triggers.

    Responses: 0xB6 event_trigger_status. Sources: 3dm-cv7-ins-docs.txt line 7047. Field data:
    1..253 bytes.
    """

    requested_count: int = 0  # Number of entries requested; 0 requests all trigger slots.
    # Trigger instances to query. (count: requested_count)
    requested_instances: _ty.List[int] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x2C
    NAME = "get_event_trigger_status"
    ROLE = "command"
    _ATTRS = ("requested_count", "requested_instances")
    _OPS = (
        _c.Run(_c.P("requested_count", _c.U8)),
        _c.Counted("requested_instances", _c.U8, count="requested_count", maximum=252),
    )


@_c.slotted
@_dc.dataclass
class EventTriggerStatus(_c.Field):
    """Event trigger status (set 0x0C, descriptor 0xB6, response).

    Status of the requested triggers, in the order requested (increasing if all).

    Sources: 3dm-cv7-ins-docs.txt line 7057. Field data: 1..253 bytes.
    """

    count: int = 0  # Number of entries.
    # The configured triggers. (count: count)
    triggers: _ty.List[_t.TriggerStatusEntry] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0xB6
    NAME = "event_trigger_status"
    ROLE = "response"
    _ATTRS = ("count", "triggers")
    _OPS = (
        _c.Run(_c.P("count", _c.U8)),
        _c.Counted("triggers", _t.TriggerStatusEntry, count="count", maximum=126),
    )


@_c.slotted
@_dc.dataclass
class GetEventActionStatus(_c.Field):
    """Get event action status (set 0x0C, descriptor 0x2D, command).

    Report the type and trigger of event actions.

    Responses: 0xB7 event_action_status. Sources: 3dm-cv7-ins-docs.txt line 7080. Field data: 1..253
    bytes.
    """

    requested_count: int = 0  # Number of entries requested; 0 requests all action slots.
    # Action instances to query. (count: requested_count)
    requested_instances: _ty.List[int] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x2D
    NAME = "get_event_action_status"
    ROLE = "command"
    _ATTRS = ("requested_count", "requested_instances")
    _OPS = (
        _c.Run(_c.P("requested_count", _c.U8)),
        _c.Counted("requested_instances", _c.U8, count="requested_count", maximum=252),
    )


@_c.slotted
@_dc.dataclass
class EventActionStatus(_c.Field):
    """Event action status (set 0x0C, descriptor 0xB7, response).

    Status of the requested actions.

    Sources: 3dm-cv7-ins-docs.txt line 7090. Field data: 1..253 bytes.
    """

    count: int = 0  # Number of entries.
    actions: _ty.List[_t.ActionStatusEntry] = _dc.field(default_factory=list)  # The configured actions. (count: count)

    SET = 0x0C
    DESCRIPTOR = 0xB7
    NAME = "event_action_status"
    ROLE = "response"
    _ATTRS = ("count", "actions")
    _OPS = (
        _c.Run(_c.P("count", _c.U8)),
        _c.Counted("actions", _t.ActionStatusEntry, count="count", maximum=126),
    )


@_c.slotted
@_dc.dataclass
class EventTriggerConfig(_c.Field):
    """Event trigger configuration (set 0x0C, descriptor 0x2E, command).

    Configure an event trigger (GPIO, threshold or combination).

    Functions: write, read, save, load, default. Responses: 0xB8 event_trigger_config_response.
    Sources: 3dm-cv7-ins-docs.txt line 7107. Field data: 2..23 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    instance: int = 0  # Trigger number; 0 applies to all instances for save, load and default.
    type: _ty.Optional[_ty.Union[_t.TriggerType, int]] = None  # Type of trigger. (sent for: write)
    # Parameters of the trigger type. (sent for: write)
    parameters: _ty.Optional[_ty.Union[_t.TriggerGpioParams, _t.ThresholdParams, _t.CombinationParams]] = None

    SET = 0x0C
    DESCRIPTOR = 0x2E
    NAME = "event_trigger_config"
    ROLE = "command"
    _ATTRS = ("function", "instance", "type", "parameters")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("instance", _c.U8)),
        _c.Opt(_c.Run(_c.P("type", _c.enum(_t.TriggerType, "u8")))),
        _c.Opt(_c.Choice("parameters", _t.TriggerParams, selector="type")),
    )


@_c.slotted
@_dc.dataclass
class EventTriggerConfigResponse(_c.Field):
    """Event trigger configuration (response) (set 0x0C, descriptor 0xB8, response).

    Current configuration of a trigger.

    Sources: 3dm-cv7-ins-docs.txt line 7124. Field data: 2..22 bytes.
    """

    instance: int = 0  # Trigger number.
    type: _ty.Union[_t.TriggerType, int] = _t.TriggerType.NONE  # Type of trigger.
    # Parameters of the trigger type.
    parameters: _ty.Optional[_ty.Union[_t.TriggerGpioParams, _t.ThresholdParams, _t.CombinationParams]] = None

    SET = 0x0C
    DESCRIPTOR = 0xB8
    NAME = "event_trigger_config_response"
    ROLE = "response"
    _ATTRS = ("instance", "type", "parameters")
    _OPS = (
        _c.Run(_c.P("instance", _c.U8), _c.P("type", _c.enum(_t.TriggerType, "u8"))),
        _c.Choice("parameters", _t.TriggerParams, selector="type"),
    )


@_c.slotted
@_dc.dataclass
class EventActionConfig(_c.Field):
    """Event action configuration (set 0x0C, descriptor 0x2F, command).

    Configure an event action (GPIO or message) and the trigger that fires it.

    Functions: write, read, save, load, default. Responses: 0xB9 event_action_config_response.
    Sources: 3dm-cv7-ins-docs.txt line 7186. Field data: 2..20 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    instance: int = 0  # Action number; 0 applies to all instances for save, load and default.
    trigger: _ty.Optional[int] = None  # Trigger ID number. (sent for: write)
    type: _ty.Optional[_ty.Union[_t.ActionType, int]] = None  # Type of action. (sent for: write)
    # Parameters of the action type. (sent for: write)
    parameters: _ty.Optional[_ty.Union[_t.ActionGpioParams, _t.MessageParams]] = None

    SET = 0x0C
    DESCRIPTOR = 0x2F
    NAME = "event_action_config"
    ROLE = "command"
    _ATTRS = ("function", "instance", "trigger", "type", "parameters")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("instance", _c.U8)),
        _c.Opt(_c.Run(_c.P("trigger", _c.U8))),
        _c.Opt(_c.Run(_c.P("type", _c.enum(_t.ActionType, "u8")))),
        _c.Opt(_c.Choice("parameters", _t.ActionParams, selector="type")),
    )


@_c.slotted
@_dc.dataclass
class EventActionConfigResponse(_c.Field):
    """Event action configuration (response) (set 0x0C, descriptor 0xB9, response).

    Current configuration of an action.

    Sources: 3dm-cv7-ins-docs.txt line 7203. Field data: 3..19 bytes.
    """

    instance: int = 0  # Action number.
    trigger: int = 0  # Trigger ID number.
    type: _ty.Union[_t.ActionType, int] = _t.ActionType.NONE  # Type of action.
    parameters: _ty.Optional[_ty.Union[_t.ActionGpioParams, _t.MessageParams]] = None  # Parameters of the action type.

    SET = 0x0C
    DESCRIPTOR = 0xB9
    NAME = "event_action_config_response"
    ROLE = "response"
    _ATTRS = ("instance", "trigger", "type", "parameters")
    _OPS = (
        _c.Run(_c.P("instance", _c.U8), _c.P("trigger", _c.U8), _c.P("type", _c.enum(_t.ActionType, "u8"))),
        _c.Choice("parameters", _t.ActionParams, selector="type"),
    )


@_c.slotted
@_dc.dataclass
class DeviceStartupSettings_gx5_45(_c.Field):
    """Device startup settings (set 0x0C, descriptor 0x30, command), device gx5_45.

    Save all current settings as the startup settings, load the saved startup settings, or reset all
    settings to the factory defaults. Saving may briefly disturb data output and can take up to a
    second.

    Functions: read, save, load, default. Sources: 3dm-gx5-45-dcp.txt line 1189. Field data: 1
    bytes.
    """

    # Function selector (one of: read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.READ

    SET = 0x0C
    DESCRIPTOR = 0x30
    NAME = "device_startup_settings"
    ROLE = "command"
    DEVICE = "gx5_45"
    _ATTRS = ("function",)
    _OPS = (_c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),)


@_c.slotted
@_dc.dataclass
class DeviceStartupSettings_cv7_ins(_c.Field):
    """Device startup settings (set 0x0C, descriptor 0x30, command), device cv7_ins.

    Save all current settings as the startup settings, load the saved startup settings, or reset all
    settings to the factory defaults. Saving may briefly disturb data output and can take up to a
    second.

    Functions: save, load, default. Sources: 3dm-cv7-ins-docs.txt line 7255. Field data: 1 bytes.
    """

    # Function selector (one of: save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.SAVE

    SET = 0x0C
    DESCRIPTOR = 0x30
    NAME = "device_startup_settings"
    ROLE = "command"
    DEVICE = "cv7_ins"
    _ATTRS = ("function",)
    _OPS = (_c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),)


@_c.slotted
@_dc.dataclass
class SensorToVehicleEuler(_c.Field):
    """Sensor-to-vehicle frame transformation (Euler) (set 0x0C, descriptor 0x31, command).

    Mounting angles of the sensor in the vehicle frame as roll, pitch and yaw: the transformation of
    vectors from the sensor frame to the vehicle frame (the inverse of the rotation used by older
    products). Applied to the IMU and estimation filter outputs; changing it resets the low-pass,
    complementary and estimation filters. Read-back angles may differ but are equivalent.

    Functions: write, read, save, load, default. Responses: 0xB1 sensor_to_vehicle_euler_response.
    Sources: 3dm-cv7-ins-docs.txt line 7267; 3dm-cv7-ins-docs.txt line 2494. Field data: 1..13
    bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    roll: _ty.Optional[float] = None  # Roll angle. [rad] (sent for: write)
    pitch: _ty.Optional[float] = None  # Pitch angle. [rad] (sent for: write)
    yaw: _ty.Optional[float] = None  # Yaw angle. [rad] (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x31
    NAME = "sensor_to_vehicle_euler"
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
class SensorToVehicleEulerResponse(_c.Field):
    """Sensor-to-vehicle frame transformation (Euler) (response) (set 0x0C, descriptor 0xB1, response).

    Current sensor-to-vehicle transformation as Euler angles.

    Sources: 3dm-cv7-ins-docs.txt line 7281. Field data: 12 bytes.
    """

    roll: float = 0.0  # Roll angle. [rad]
    pitch: float = 0.0  # Pitch angle. [rad]
    yaw: float = 0.0  # Yaw angle. [rad]

    SET = 0x0C
    DESCRIPTOR = 0xB1
    NAME = "sensor_to_vehicle_euler_response"
    ROLE = "response"
    _ATTRS = ("roll", "pitch", "yaw")
    _OPS = (_c.Run(_c.P("roll", _c.F32), _c.P("pitch", _c.F32), _c.P("yaw", _c.F32)),)


@_c.slotted
@_dc.dataclass
class SensorToVehicleQuaternion(_c.Field):
    """Sensor-to-vehicle frame transformation (quaternion) (set 0x0C, descriptor 0x32, command).

    Sensor-to-vehicle transformation as a unit quaternion [w, i, j, k]. Same effects as the Euler
    form; a quaternion read back may differ but is equivalent.

    Functions: write, read, save, load, default. Responses: 0xB2
    sensor_to_vehicle_quaternion_response. Sources: 3dm-cv7-ins-docs.txt line 7290. Field data:
    1..17 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    q: _ty.Optional[_ty.List[float]] = None  # Unit quaternion of the transformation, [w, i, j, k]. (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x32
    NAME = "sensor_to_vehicle_quaternion"
    ROLE = "command"
    _ATTRS = ("function", "q")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("q", _c.F32, 4))),
    )


@_c.slotted
@_dc.dataclass
class SensorToVehicleQuaternionResponse(_c.Field):
    """Sensor-to-vehicle frame transformation (quaternion) (response) (set 0x0C, descriptor 0xB2,
    response).

    Current sensor-to-vehicle transformation as a unit quaternion.

    Sources: 3dm-cv7-ins-docs.txt line 7303. Field data: 16 bytes.
    """

    # Unit quaternion of the transformation, [w, i, j, k].
    q: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 4)

    SET = 0x0C
    DESCRIPTOR = 0xB2
    NAME = "sensor_to_vehicle_quaternion_response"
    ROLE = "response"
    _ATTRS = ("q",)
    _OPS = (_c.Run(_c.P("q", _c.F32, 4)),)


@_c.slotted
@_dc.dataclass
class SensorToVehicleDcm(_c.Field):
    """Sensor-to-vehicle frame transformation (direction cosine matrix) (set 0x0C, descriptor 0x33,
    command).

    Sensor-to-vehicle transformation as a 3x3 direction cosine matrix in row-major order (v_vehicle
    = M v_sensor). Same effects as the Euler form.

    Functions: write, read, save, load, default. Responses: 0xB3 sensor_to_vehicle_dcm_response.
    Sources: 3dm-cv7-ins-docs.txt line 7310; 3dm-cv7-ins-docs.txt line 2530. Field data: 1..37
    bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    dcm: _ty.Optional[_ty.List[float]] = None  # Direction cosine matrix, row-major. (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x33
    NAME = "sensor_to_vehicle_dcm"
    ROLE = "command"
    _ATTRS = ("function", "dcm")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("dcm", _c.F32, 9))),
    )


@_c.slotted
@_dc.dataclass
class SensorToVehicleDcmResponse(_c.Field):
    """Sensor-to-vehicle frame transformation (DCM) (response) (set 0x0C, descriptor 0xB3, response).

    Current sensor-to-vehicle transformation as a row-major direction cosine matrix.

    Sources: 3dm-cv7-ins-docs.txt line 7323. Field data: 36 bytes.
    """

    dcm: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 9)  # Direction cosine matrix, row-major.

    SET = 0x0C
    DESCRIPTOR = 0xB3
    NAME = "sensor_to_vehicle_dcm_response"
    ROLE = "response"
    _ATTRS = ("dcm",)
    _OPS = (_c.Run(_c.P("dcm", _c.F32, 9)),)


@_c.slotted
@_dc.dataclass
class AccelBias_gx5_45(_c.Field):
    """Accelerometer bias (set 0x0C, descriptor 0x37, command), device gx5_45.

    User accelerometer bias in the sensor frame, subtracted from the scaled (calibrated)
    accelerometer output.

    Functions: write, read, save, load, default, write_no_ack. Responses: 0x9A accel_bias_response.
    Sources: 3dm-gx5-45-dcp.txt line 1202. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default, write_no_ack)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    bias: _ty.Optional[_ty.List[float]] = None  # X, Y, Z accelerometer bias. [g] (sent for: write, write_no_ack)

    SET = 0x0C
    DESCRIPTOR = 0x37
    NAME = "accel_bias"
    ROLE = "command"
    DEVICE = "gx5_45"
    _ATTRS = ("function", "bias")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("bias", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class AccelBias_cv7_ins(_c.Field):
    """Accelerometer bias (set 0x0C, descriptor 0x37, command), device cv7_ins.

    User accelerometer bias in the sensor frame, subtracted from the scaled (calibrated)
    accelerometer output.

    Functions: write, read, save, load, default. Responses: 0x9A accel_bias_response. Sources:
    3dm-cv7-ins-docs.txt line 7330. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    bias: _ty.Optional[_ty.List[float]] = None  # X, Y, Z accelerometer bias in the sensor frame. [g] (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x37
    NAME = "accel_bias"
    ROLE = "command"
    DEVICE = "cv7_ins"
    _ATTRS = ("function", "bias")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("bias", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class AccelBiasResponse(_c.Field):
    """Accelerometer bias (response) (set 0x0C, descriptor 0x9A, response).

    Current user accelerometer bias.

    Sources: 3dm-gx5-45-dcp.txt line 1210; 3dm-cv7-ins-docs.txt line 7340. Field data: 12 bytes.
    """

    # X, Y, Z accelerometer bias in the sensor frame. [g]
    bias: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0C
    DESCRIPTOR = 0x9A
    NAME = "accel_bias_response"
    ROLE = "response"
    _ATTRS = ("bias",)
    _OPS = (_c.Run(_c.P("bias", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class GyroBias_gx5_45(_c.Field):
    """Gyro bias (set 0x0C, descriptor 0x38, command), device gx5_45.

    User gyro bias in the sensor frame, subtracted from the scaled (calibrated) angular rate output.

    Functions: write, read, save, load, default, write_no_ack. Responses: 0x9B gyro_bias_response.
    Sources: 3dm-gx5-45-dcp.txt line 1217. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default, write_no_ack)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    bias: _ty.Optional[_ty.List[float]] = None  # X, Y, Z gyro bias. [rad/s] (sent for: write, write_no_ack)

    SET = 0x0C
    DESCRIPTOR = 0x38
    NAME = "gyro_bias"
    ROLE = "command"
    DEVICE = "gx5_45"
    _ATTRS = ("function", "bias")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("bias", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class GyroBias_cv7_ins(_c.Field):
    """Gyro bias (set 0x0C, descriptor 0x38, command), device cv7_ins.

    User gyro bias in the sensor frame, subtracted from the scaled (calibrated) angular rate output.

    Functions: write, read, save, load, default. Responses: 0x9B gyro_bias_response. Sources:
    3dm-cv7-ins-docs.txt line 7347. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    bias: _ty.Optional[_ty.List[float]] = None  # X, Y, Z gyro bias in the sensor frame. [rad/s] (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x38
    NAME = "gyro_bias"
    ROLE = "command"
    DEVICE = "cv7_ins"
    _ATTRS = ("function", "bias")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("bias", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class GyroBiasResponse(_c.Field):
    """Gyro bias (response) (set 0x0C, descriptor 0x9B, response).

    Current user gyro bias; also the reply to Capture Gyro Bias (0x39), carrying the newly captured
    bias.

    Sources: 3dm-gx5-45-dcp.txt line 1225; 3dm-gx5-45-dcp.txt line 1240; 3dm-cv7-ins-docs.txt line
    7357; 3dm-cv7-ins-docs.txt line 7373. Field data: 12 bytes.
    """

    # X, Y, Z gyro bias in the sensor frame. [rad/s]
    bias: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0C
    DESCRIPTOR = 0x9B
    NAME = "gyro_bias_response"
    ROLE = "response"
    _ATTRS = ("bias",)
    _OPS = (_c.Run(_c.P("bias", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class CaptureGyroBias(_c.Field):
    """Capture gyro bias (set 0x0C, descriptor 0x39, command).

    Average the gyro output for the given time and write the result to the gyro bias (in RAM only;
    save it with Gyro Bias 0x38). The device must be stationary, with minimal vibration. The reply
    carries the captured bias (0x9B).

    Responses: 0x9B gyro_bias_response. Sources: 3dm-gx5-45-dcp.txt line 1232; 3dm-cv7-ins-docs.txt
    line 7364. Field data: 2 bytes.
    """

    averaging_time_ms: int = 0  # Sampling time, 1000 to 30000 ms. [ms]

    SET = 0x0C
    DESCRIPTOR = 0x39
    NAME = "capture_gyro_bias"
    ROLE = "command"
    _ATTRS = ("averaging_time_ms",)
    _OPS = (_c.Run(_c.P("averaging_time_ms", _c.U16)),)


@_c.slotted
@_dc.dataclass
class MagHardIronOffset_gx5_45(_c.Field):
    """Magnetometer hard iron offset (set 0x0C, descriptor 0x3A, command), device gx5_45.

    User magnetometer hard iron offset in the sensor frame, subtracted from the scaled magnetometer
    output. Determined from calibration data after installation (MicroStrain tools or in-run
    auto-calibration where supported). Default [0, 0, 0].

    Functions: write, read, save, load, default, write_no_ack. Responses: 0x9C
    mag_hard_iron_offset_response. Sources: 3dm-gx5-45-dcp.txt line 1248. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default, write_no_ack)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    offset: _ty.Optional[_ty.List[float]] = None  # X, Y, Z hard iron offset. [gauss] (sent for: write, write_no_ack)

    SET = 0x0C
    DESCRIPTOR = 0x3A
    NAME = "mag_hard_iron_offset"
    ROLE = "command"
    DEVICE = "gx5_45"
    _ATTRS = ("function", "offset")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("offset", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class MagHardIronOffset_cv7_ins(_c.Field):
    """Magnetometer hard iron offset (set 0x0C, descriptor 0x3A, command), device cv7_ins.

    User magnetometer hard iron offset in the sensor frame, subtracted from the scaled magnetometer
    output. Determined from calibration data after installation (MicroStrain tools or in-run
    auto-calibration where supported). Default [0, 0, 0].

    Functions: write, read, save, load, default. Responses: 0x9C mag_hard_iron_offset_response.
    Sources: 3dm-cv7-ins-docs.txt line 7380. Field data: 1..13 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # X, Y, Z hard iron offset in the sensor frame. [gauss] (sent for: write)
    offset: _ty.Optional[_ty.List[float]] = None

    SET = 0x0C
    DESCRIPTOR = 0x3A
    NAME = "mag_hard_iron_offset"
    ROLE = "command"
    DEVICE = "cv7_ins"
    _ATTRS = ("function", "offset")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("offset", _c.F32, 3))),
    )


@_c.slotted
@_dc.dataclass
class MagHardIronOffsetResponse(_c.Field):
    """Magnetometer hard iron offset (response) (set 0x0C, descriptor 0x9C, response).

    Current magnetometer hard iron offset.

    Sources: 3dm-gx5-45-dcp.txt line 1255; 3dm-cv7-ins-docs.txt line 7390. Field data: 12 bytes.
    """

    # X, Y, Z hard iron offset in the sensor frame. [gauss]
    offset: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 3)

    SET = 0x0C
    DESCRIPTOR = 0x9C
    NAME = "mag_hard_iron_offset_response"
    ROLE = "response"
    _ATTRS = ("offset",)
    _OPS = (_c.Run(_c.P("offset", _c.F32, 3)),)


@_c.slotted
@_dc.dataclass
class MagSoftIronMatrix_gx5_45(_c.Field):
    """Magnetometer soft iron matrix (set 0x0C, descriptor 0x3B, command), device gx5_45.

    User magnetometer soft iron compensation matrix (row-major), applied to the scaled magnetometer
    output. Determined from calibration data after installation. Default: identity.

    Functions: write, read, save, load, default, write_no_ack. Responses: 0x9D
    mag_soft_iron_matrix_response. Sources: 3dm-gx5-45-dcp.txt line 1263. Field data: 1..37 bytes.
    """

    # Function selector (one of: write, read, save, load, default, write_no_ack)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Soft iron matrix m11..m33, row-major (dimensionless). (sent for: write, write_no_ack)
    matrix: _ty.Optional[_ty.List[float]] = None

    SET = 0x0C
    DESCRIPTOR = 0x3B
    NAME = "mag_soft_iron_matrix"
    ROLE = "command"
    DEVICE = "gx5_45"
    _ATTRS = ("function", "matrix")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("matrix", _c.F32, 9))),
    )


@_c.slotted
@_dc.dataclass
class MagSoftIronMatrix_cv7_ins(_c.Field):
    """Magnetometer soft iron matrix (set 0x0C, descriptor 0x3B, command), device cv7_ins.

    User magnetometer soft iron compensation matrix (row-major), applied to the scaled magnetometer
    output. Determined from calibration data after installation. Default: identity.

    Functions: write, read, save, load, default. Responses: 0x9D mag_soft_iron_matrix_response.
    Sources: 3dm-cv7-ins-docs.txt line 7397. Field data: 1..37 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    matrix: _ty.Optional[_ty.List[float]] = None  # Soft iron matrix, row-major (dimensionless). (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x3B
    NAME = "mag_soft_iron_matrix"
    ROLE = "command"
    DEVICE = "cv7_ins"
    _ATTRS = ("function", "matrix")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("matrix", _c.F32, 9))),
    )


@_c.slotted
@_dc.dataclass
class MagSoftIronMatrixResponse(_c.Field):
    """Magnetometer soft iron matrix (response) (set 0x0C, descriptor 0x9D, response).

    Current magnetometer soft iron matrix, row-major.

    Sources: 3dm-gx5-45-dcp.txt line 1269; 3dm-cv7-ins-docs.txt line 7407. Field data: 36 bytes.
    """

    # Soft iron matrix, row-major (dimensionless).
    matrix: _ty.List[float] = _dc.field(default_factory=lambda: [0.0] * 9)

    SET = 0x0C
    DESCRIPTOR = 0x9D
    NAME = "mag_soft_iron_matrix_response"
    ROLE = "response"
    _ATTRS = ("matrix",)
    _OPS = (_c.Run(_c.P("matrix", _c.F32, 9)),)


@_c.slotted
@_dc.dataclass
class ConingScullingEnable(_c.Field):
    """Coning and sculling enable (set 0x0C, descriptor 0x3E, command).

    Enable or disable coning and sculling compensation (enabled by default).

    Functions: write, read, save, load, default. Responses: 0x9E coning_sculling_enable_response.
    Sources: 3dm-gx5-45-dcp.txt line 1280. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # True enables coning and sculling compensation (0x01), false disables it (0x00). (sent for: write)
    enable: _ty.Optional[bool] = None

    SET = 0x0C
    DESCRIPTOR = 0x3E
    NAME = "coning_sculling_enable"
    ROLE = "command"
    _ATTRS = ("function", "enable")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("enable", _c.BOOL))),
    )


@_c.slotted
@_dc.dataclass
class ConingScullingEnableResponse(_c.Field):
    """Coning and sculling enable (response) (set 0x0C, descriptor 0x9E, response).

    Current coning and sculling compensation setting.

    Sources: 3dm-gx5-45-dcp.txt line 1286. Field data: 1 bytes.
    """

    enable: bool = False  # True if coning and sculling compensation is enabled.

    SET = 0x0C
    DESCRIPTOR = 0x9E
    NAME = "coning_sculling_enable_response"
    ROLE = "response"
    _ATTRS = ("enable",)
    _OPS = (_c.Run(_c.P("enable", _c.BOOL)),)


@_c.slotted
@_dc.dataclass
class UartBaudrate(_c.Field):
    """UART baud rate (set 0x0C, descriptor 0x40, command).

    Baud rate of the main communication port (UART1). The ack is sent at the old rate; the new rate
    applies after pending data is sent (up to 250 ms). Send it alone, with the device idle, and wait
    250 ms. GX5-45 rates: 9600, 19200, 115200 (default), 230400, 460800, 921600.

    Functions: write, read, save, load, default. Responses: 0x87 uart_baudrate_response. Sources:
    3dm-gx5-45-dcp.txt line 1293; 3dm-cv7-ins-docs.txt line 7414. Field data: 1..5 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    baud: _ty.Optional[int] = None  # New baud rate; must be a rate the device supports. [bit/s] (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x40
    NAME = "uart_baudrate"
    ROLE = "command"
    _ATTRS = ("function", "baud")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("baud", _c.U32))),
    )


@_c.slotted
@_dc.dataclass
class UartBaudrateResponse(_c.Field):
    """UART baud rate (response) (set 0x0C, descriptor 0x87, response).

    Current baud rate of the main port.

    Sources: 3dm-gx5-45-dcp.txt line 1301; 3dm-cv7-ins-docs.txt line 7424. Field data: 4 bytes.
    """

    baud: int = 0  # Current baud rate. [bit/s]

    SET = 0x0C
    DESCRIPTOR = 0x87
    NAME = "uart_baudrate_response"
    ROLE = "response"
    _ATTRS = ("baud",)
    _OPS = (_c.Run(_c.P("baud", _c.U32)),)


@_c.slotted
@_dc.dataclass
class GpioConfig(_c.Field):
    """GPIO configuration (set 0x0C, descriptor 0x41, command).

    Configure a user GPIO pin: the feature it serves, its behavior within that feature, and its
    electrical mode. Features and pin modes are pin- and device-dependent (User GPIO, line 1272).
    Configure an output feature before the pin (to avoid glitches) and an input pin before its
    feature. Features limited to one pin move to the most recently configured pin.

    Functions: write, read, save, load, default. Responses: 0xC1 gpio_config_response. Sources:
    3dm-cv7-ins-docs.txt line 7431; 3dm-cv7-ins-docs.txt line 1314. Field data: 2..5 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    pin: int = 0  # GPIO pin number from 1; 0 selects all pins for save, load and default.
    feature: _ty.Optional[_ty.Union[_t.GpioFeature, int]] = None  # What the pin is used for. (sent for: write)
    # Role of the pin within the feature (meaning depends on feature). (sent for: write)
    behavior: _ty.Optional[
        _ty.Union[
            _t.GpioBehaviorUnused,
            _t.GpioBehaviorIo,
            _t.GpioBehaviorPps,
            _t.GpioBehaviorEncoder,
            _t.GpioBehaviorTimestamp,
            _t.GpioBehaviorUart,
        ]
    ] = None
    pin_mode: _ty.Optional[_t.GpioPinMode] = None  # Electrical mode of the pin. (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x41
    NAME = "gpio_config"
    ROLE = "command"
    _ATTRS = ("function", "pin", "feature", "behavior", "pin_mode")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("pin", _c.U8)),
        _c.Opt(_c.Run(_c.P("feature", _c.enum(_t.GpioFeature, "u8")))),
        _c.Opt(_c.Choice("behavior", _t.GpioBehavior, selector="feature")),
        _c.Opt(_c.Run(_c.P("pin_mode", _c.flags(_t.GpioPinMode)))),
    )


@_c.slotted
@_dc.dataclass
class GpioConfigResponse(_c.Field):
    """GPIO configuration (response) (set 0x0C, descriptor 0xC1, response).

    Current configuration of a GPIO pin.

    Sources: 3dm-cv7-ins-docs.txt line 7476. Field data: 4..4 bytes.
    """

    pin: int = 0  # GPIO pin number from 1.
    feature: _ty.Union[_t.GpioFeature, int] = _t.GpioFeature.UNUSED  # What the pin is used for.
    # Role of the pin within the feature.
    behavior: _ty.Optional[
        _ty.Union[
            _t.GpioBehaviorUnused,
            _t.GpioBehaviorIo,
            _t.GpioBehaviorPps,
            _t.GpioBehaviorEncoder,
            _t.GpioBehaviorTimestamp,
            _t.GpioBehaviorUart,
        ]
    ] = None
    pin_mode: _t.GpioPinMode = _t.GpioPinMode(0)  # Electrical mode of the pin.

    SET = 0x0C
    DESCRIPTOR = 0xC1
    NAME = "gpio_config_response"
    ROLE = "response"
    _ATTRS = ("pin", "feature", "behavior", "pin_mode")
    _OPS = (
        _c.Run(_c.P("pin", _c.U8), _c.P("feature", _c.enum(_t.GpioFeature, "u8"))),
        _c.Choice("behavior", _t.GpioBehavior, selector="feature"),
        _c.Run(_c.P("pin_mode", _c.flags(_t.GpioPinMode))),
    )


@_c.slotted
@_dc.dataclass
class GpioState(_c.Field):
    """GPIO state (set 0x0C, descriptor 0x42, command).

    Read the physical state of a pin or set its output state. Setting has a visible effect only when
    the pin is an output; save, load and default are not supported (use 0x0C,0x41 to set the initial
    state).

    Functions: write, read. Responses: 0xC2 gpio_state_response. Sources: 3dm-cv7-ins-docs.txt line
    7517. Field data: 2..3 bytes.
    """

    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE  # Function selector (one of: write, read)
    pin: int = 0  # GPIO pin number from 1 (not 0).
    state: _ty.Optional[bool] = None  # Pin state (true = high). (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x42
    NAME = "gpio_state"
    ROLE = "command"
    _ATTRS = ("function", "pin", "state")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("pin", _c.U8)),
        _c.Opt(_c.Run(_c.P("state", _c.BOOL))),
    )


@_c.slotted
@_dc.dataclass
class GpioStateResponse(_c.Field):
    """GPIO state (response) (set 0x0C, descriptor 0xC2, response).

    Physical state of a pin.

    Sources: 3dm-cv7-ins-docs.txt line 7528. Field data: 2 bytes.
    """

    pin: int = 0  # GPIO pin number from 1.
    state: bool = False  # Pin state (true = high).

    SET = 0x0C
    DESCRIPTOR = 0xC2
    NAME = "gpio_state_response"
    ROLE = "response"
    _ATTRS = ("pin", "state")
    _OPS = (_c.Run(_c.P("pin", _c.U8), _c.P("state", _c.BOOL)),)


@_c.slotted
@_dc.dataclass
class OdometerConfig(_c.Field):
    """Odometer configuration (set 0x0C, descriptor 0x43, command).

    Configure the hardware odometer (wheel encoder) interface: mode, scale factor and its
    uncertainty. Distance = pulses / scaling.

    Functions: write, read, save, load, default. Responses: 0xC3 odometer_config_response. Sources:
    3dm-cv7-ins-docs.txt line 7536. Field data: 1..10 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    mode: _ty.Optional[_ty.Union[_t.OdometerMode, int]] = None  # Odometer mode. (sent for: write)
    # Encoder pulses per metre (N / (2 pi R), N pulses per revolution, R wheel radius); negative if the encoder turns
    # backwards. [pulses/m] (sent for: write)
    scaling: _ty.Optional[float] = None
    # 1-sigma uncertainty of the pulses-to-distance scale. [m/m] (sent for: write)
    uncertainty: _ty.Optional[float] = None

    SET = 0x0C
    DESCRIPTOR = 0x43
    NAME = "odometer_config"
    ROLE = "command"
    _ATTRS = ("function", "mode", "scaling", "uncertainty")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("mode", _c.enum(_t.OdometerMode, "u8")))),
        _c.Opt(_c.Run(_c.P("scaling", _c.F32))),
        _c.Opt(_c.Run(_c.P("uncertainty", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class OdometerConfigResponse(_c.Field):
    """Odometer configuration (response) (set 0x0C, descriptor 0xC3, response).

    Current odometer configuration.

    Sources: 3dm-cv7-ins-docs.txt line 7551. Field data: 9 bytes.
    """

    mode: _ty.Union[_t.OdometerMode, int] = _t.OdometerMode.DISABLED  # Odometer mode.
    scaling: float = 0.0  # Encoder pulses per metre. [pulses/m]
    uncertainty: float = 0.0  # 1-sigma uncertainty of the scale. [m/m]

    SET = 0x0C
    DESCRIPTOR = 0xC3
    NAME = "odometer_config_response"
    ROLE = "response"
    _ATTRS = ("mode", "scaling", "uncertainty")
    _OPS = (_c.Run(_c.P("mode", _c.enum(_t.OdometerMode, "u8")), _c.P("scaling", _c.F32), _c.P("uncertainty", _c.F32)),)


@_c.slotted
@_dc.dataclass
class AdvancedLowpassFilter(_c.Field):
    """Advanced low-pass filter settings (set 0x0C, descriptor 0x50, command).

    Per-quantity IIR low-pass filter on the scaled IMU data (0x80: accel 0x04, gyro 0x05, mag 0x06,
    pressure 0x17): bypass it, or set its -3 dB cutoff manually instead of half the reporting rate.
    Deprecated on the CV7 in favour of 0x0C,0x54.

    Functions: write, read, save, load, default. Responses: 0x8B advanced_lowpass_filter_response.
    Sources: 3dm-gx5-45-dcp.txt line 1308; 3dm-cv7-ins-docs.txt line 7565. Field data: 2..7 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Field descriptor in the sensor set (0x80) of the filtered quantity; 0 = all (CV7, not for read).
    target_descriptor: int = 0
    enable: _ty.Optional[bool] = None  # Apply the low-pass filter. (sent for: write)
    # Use the cutoff given below; false sets it to half the reporting rate. (sent for: write)
    manual: _ty.Optional[bool] = None
    # -3 dB cutoff frequency (at most 250 Hz on GX5-45); ignored when not manual. [Hz] (sent for: write)
    frequency: _ty.Optional[int] = None
    reserved: _ty.Optional[int] = None  # Reserved, send 0. (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x50
    NAME = "advanced_lowpass_filter"
    ROLE = "command"
    _ATTRS = ("function", "target_descriptor", "enable", "manual", "frequency", "reserved")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("target_descriptor", _c.U8)),
        _c.Opt(_c.Run(_c.P("enable", _c.BOOL))),
        _c.Opt(_c.Run(_c.P("manual", _c.BOOL))),
        _c.Opt(_c.Run(_c.P("frequency", _c.U16))),
        _c.Opt(_c.Run(_c.P("reserved", _c.U8))),
    )


@_c.slotted
@_dc.dataclass
class AdvancedLowpassFilterResponse(_c.Field):
    """Advanced low-pass filter settings (response) (set 0x0C, descriptor 0x8B, response).

    Current low-pass filter settings of one quantity.

    Sources: 3dm-gx5-45-dcp.txt line 1316; 3dm-cv7-ins-docs.txt line 7579. Field data: 6 bytes.
    """

    target_descriptor: int = 0  # Field descriptor of the filtered quantity.
    enable: bool = False  # True if the filter is enabled.
    manual: bool = False  # True if the cutoff was set manually.
    frequency: int = 0  # -3 dB cutoff frequency (unspecified in automatic mode). [Hz]
    reserved: int = 0  # Reserved; ignore.

    SET = 0x0C
    DESCRIPTOR = 0x8B
    NAME = "advanced_lowpass_filter_response"
    ROLE = "response"
    _ATTRS = ("target_descriptor", "enable", "manual", "frequency", "reserved")
    _OPS = (
        _c.Run(
            _c.P("target_descriptor", _c.U8),
            _c.P("enable", _c.BOOL),
            _c.P("manual", _c.BOOL),
            _c.P("frequency", _c.U16),
            _c.P("reserved", _c.U8),
        ),
    )


@_c.slotted
@_dc.dataclass
class ComplementaryFilter(_c.Field):
    """Complementary filter settings (set 0x0C, descriptor 0x51, command).

    Configure the AHRS complementary filter behind the 0x80 attitude outputs (matrix 0x09,
    quaternion 0x0A, Euler 0x0C): pitch/roll correction from the accelerometer (GX5-45: "up
    compensation") and heading correction from the magnetometer ("north compensation"), each with a
    time constant of 1 to 1000 s (default 10 s; out-of-range values are NACK'd).

    Functions: write, read, save, load, default. Responses: 0x97 complementary_filter_response.
    Sources: 3dm-gx5-45-dcp.txt line 1323; 3dm-cv7-ins-docs.txt line 7591. Field data: 1..11 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    pitch_roll_enable: _ty.Optional[bool] = None  # Enable pitch/roll (up) correction. (sent for: write)
    # Enable heading (north) correction; needs a magnetometer. (sent for: write)
    heading_enable: _ty.Optional[bool] = None
    # Time constant of the pitch/roll correction. [s] (sent for: write)
    pitch_roll_time_constant: _ty.Optional[float] = None
    heading_time_constant: _ty.Optional[float] = None  # Time constant of the heading correction. [s] (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x51
    NAME = "complementary_filter"
    ROLE = "command"
    _ATTRS = ("function", "pitch_roll_enable", "heading_enable", "pitch_roll_time_constant", "heading_time_constant")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("pitch_roll_enable", _c.BOOL))),
        _c.Opt(_c.Run(_c.P("heading_enable", _c.BOOL))),
        _c.Opt(_c.Run(_c.P("pitch_roll_time_constant", _c.F32))),
        _c.Opt(_c.Run(_c.P("heading_time_constant", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class ComplementaryFilterResponse(_c.Field):
    """Complementary filter settings (response) (set 0x0C, descriptor 0x97, response).

    Current complementary filter settings.

    Sources: 3dm-gx5-45-dcp.txt line 1330; 3dm-cv7-ins-docs.txt line 7604. Field data: 10 bytes.
    """

    pitch_roll_enable: bool = False  # Pitch/roll (up) correction enabled.
    heading_enable: bool = False  # Heading (north) correction enabled.
    pitch_roll_time_constant: float = 0.0  # Time constant of the pitch/roll correction. [s]
    heading_time_constant: float = 0.0  # Time constant of the heading correction. [s]

    SET = 0x0C
    DESCRIPTOR = 0x97
    NAME = "complementary_filter_response"
    ROLE = "response"
    _ATTRS = ("pitch_roll_enable", "heading_enable", "pitch_roll_time_constant", "heading_time_constant")
    _OPS = (
        _c.Run(
            _c.P("pitch_roll_enable", _c.BOOL),
            _c.P("heading_enable", _c.BOOL),
            _c.P("pitch_roll_time_constant", _c.F32),
            _c.P("heading_time_constant", _c.F32),
        ),
    )


@_c.slotted
@_dc.dataclass
class SensorRange(_c.Field):
    """Sensor range (set 0x0C, descriptor 0x52, command).

    Select the range (gain) of an IMU sensor; the setting values come from Get Calibrated Sensor
    Ranges (0x0C,0x53). Other values may be NACK'd or give inaccurate data.

    Functions: write, read, save, load, default. Responses: 0xD2 sensor_range_response. Sources:
    3dm-cv7-ins-docs.txt line 7616; 3dm-cv7-ins-docs.txt line 1495. Field data: 2..3 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Sensor to configure; all only for save, load and default.
    sensor: _ty.Union[_t.SensorRangeType, int] = _t.SensorRangeType.ALL
    setting: _ty.Optional[int] = None  # Range setting value (from 0x0C,0x53). (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x52
    NAME = "sensor_range"
    ROLE = "command"
    _ATTRS = ("function", "sensor", "setting")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("sensor", _c.enum(_t.SensorRangeType, "u8"))),
        _c.Opt(_c.Run(_c.P("setting", _c.U8))),
    )


@_c.slotted
@_dc.dataclass
class SensorRangeResponse(_c.Field):
    """Sensor range (response) (set 0x0C, descriptor 0xD2, response).

    Current range setting of a sensor.

    Sources: 3dm-cv7-ins-docs.txt line 7635. Field data: 2 bytes.
    """

    sensor: _ty.Union[_t.SensorRangeType, int] = _t.SensorRangeType.ALL  # Sensor.
    setting: int = 0  # Range setting value.

    SET = 0x0C
    DESCRIPTOR = 0xD2
    NAME = "sensor_range_response"
    ROLE = "response"
    _ATTRS = ("sensor", "setting")
    _OPS = (_c.Run(_c.P("sensor", _c.enum(_t.SensorRangeType, "u8")), _c.P("setting", _c.U8)),)


@_c.slotted
@_dc.dataclass
class GetCalibratedSensorRanges(_c.Field):
    """Get calibrated sensor ranges (set 0x0C, descriptor 0x53, command).

    List the range settings a sensor supports, for use with Sensor Range (0x0C,0x52).

    Responses: 0xD3 calibrated_sensor_ranges. Sources: 3dm-cv7-ins-docs.txt line 7651. Field data: 1
    bytes.
    """

    sensor: _ty.Union[_t.SensorRangeType, int] = _t.SensorRangeType.ALL  # Sensor to query (not all).

    SET = 0x0C
    DESCRIPTOR = 0x53
    NAME = "get_calibrated_sensor_ranges"
    ROLE = "command"
    _ATTRS = ("sensor",)
    _OPS = (_c.Run(_c.P("sensor", _c.enum(_t.SensorRangeType, "u8"))),)


@_c.slotted
@_dc.dataclass
class CalibratedSensorRanges(_c.Field):
    """Calibrated sensor ranges (set 0x0C, descriptor 0xD3, response).

    Supported range settings of a sensor, each with its full-scale value.

    Sources: 3dm-cv7-ins-docs.txt line 7665. Field data: 2..252 bytes.
    """

    sensor: _ty.Union[_t.SensorRangeType, int] = _t.SensorRangeType.ALL  # Sensor from the command.
    num_ranges: int = 0  # Number of supported ranges.
    # Supported (setting, range) pairs. (count: num_ranges)
    ranges: _ty.List[_t.SensorRangeEntry] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0xD3
    NAME = "calibrated_sensor_ranges"
    ROLE = "response"
    _ATTRS = ("sensor", "num_ranges", "ranges")
    _OPS = (
        _c.Run(_c.P("sensor", _c.enum(_t.SensorRangeType, "u8")), _c.P("num_ranges", _c.U8)),
        _c.Counted("ranges", _t.SensorRangeEntry, count="num_ranges", maximum=50),
    )


@_c.slotted
@_dc.dataclass
class LowpassFilter(_c.Field):
    """Low-pass anti-aliasing filter (set 0x0C, descriptor 0x54, command).

    Final low-pass (anti-aliasing) filter of a data quantity (CV7: scaled accel, gyro, mag and
    pressure in 0x80; compensated acceleration, angular rate and linear acceleration in 0x82). In
    automatic mode the cutoff tracks half the quantity's message rate (0x0C,0x0F). For write, save,
    load and default, descriptor set and/or field descriptor may be 0 for all (the field descriptor
    must be 0 if the set is 0).

    Functions: write, read, save, load, default. Responses: 0xD4 lowpass_filter_response. Sources:
    3dm-cv7-ins-docs.txt line 7695; 3dm-cv7-ins-docs.txt line 2700. Field data: 3..9 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    desc_set: int = 0  # Descriptor set of the filtered quantity (0 = all, not for read).
    field_desc: int = 0  # Field descriptor of the filtered quantity (0 = all in the set, not for read).
    enable: _ty.Optional[bool] = None  # Enable the filter. (sent for: write)
    manual: _ty.Optional[bool] = None  # Use the given frequency; false tracks half the message rate. (sent for: write)
    # Cutoff frequency (read back in automatic mode: the actual cutoff). [Hz] (sent for: write)
    frequency: _ty.Optional[float] = None

    SET = 0x0C
    DESCRIPTOR = 0x54
    NAME = "lowpass_filter"
    ROLE = "command"
    _ATTRS = ("function", "desc_set", "field_desc", "enable", "manual", "frequency")
    _OPS = (
        _c.Run(
            _c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("desc_set", _c.U8), _c.P("field_desc", _c.U8)
        ),
        _c.Opt(_c.Run(_c.P("enable", _c.BOOL))),
        _c.Opt(_c.Run(_c.P("manual", _c.BOOL))),
        _c.Opt(_c.Run(_c.P("frequency", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class LowpassFilterResponse(_c.Field):
    """Low-pass anti-aliasing filter (response) (set 0x0C, descriptor 0xD4, response).

    Current anti-aliasing filter settings of a quantity.

    Sources: 3dm-cv7-ins-docs.txt line 7710. Field data: 8 bytes.
    """

    desc_set: int = 0  # Descriptor set of the filtered quantity.
    field_desc: int = 0  # Field descriptor of the filtered quantity.
    enable: bool = False  # True if the filter is enabled.
    manual: bool = False  # True if the frequency was set manually.
    frequency: float = 0.0  # Cutoff frequency (the actual one in automatic mode). [Hz]

    SET = 0x0C
    DESCRIPTOR = 0xD4
    NAME = "lowpass_filter_response"
    ROLE = "response"
    _ATTRS = ("desc_set", "field_desc", "enable", "manual", "frequency")
    _OPS = (
        _c.Run(
            _c.P("desc_set", _c.U8),
            _c.P("field_desc", _c.U8),
            _c.P("enable", _c.BOOL),
            _c.P("manual", _c.BOOL),
            _c.P("frequency", _c.F32),
        ),
    )


@_c.slotted
@_dc.dataclass
class PollImuData(_c.Field):
    """Poll IMU data (set 0x0C, descriptor 0x01, command).

    Poll one IMU data packet (set 0x80) with the stored or the given format.

    Sources: 3dm-gx5-45-dcp.txt line 900. Field data: 2..251 bytes.
    """

    option: _ty.Union[_t.Gx5PollOption, int] = _t.Gx5PollOption.NORMAL  # Whether to send the ACK/NACK.
    num_descriptors: int = 0  # Number of descriptors; 0 uses the stored message format.
    # Descriptors to poll, in output order. (count: num_descriptors)
    descriptors: _ty.List[_t.Gx5PollDescriptor] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x01
    NAME = "poll_imu_data"
    ROLE = "command"
    _ATTRS = ("option", "num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("option", _c.enum(_t.Gx5PollOption, "u8")), _c.P("num_descriptors", _c.U8)),
        _c.Counted("descriptors", _t.Gx5PollDescriptor, count="num_descriptors", maximum=83),
    )


@_c.slotted
@_dc.dataclass
class PollGnssData(_c.Field):
    """Poll GNSS data (set 0x0C, descriptor 0x02, command).

    Poll one GNSS data packet (set 0x81) with the stored or the given format.

    Sources: 3dm-gx5-45-dcp.txt line 915. Field data: 2..251 bytes.
    """

    option: _ty.Union[_t.Gx5PollOption, int] = _t.Gx5PollOption.NORMAL  # Whether to send the ACK/NACK.
    num_descriptors: int = 0  # Number of descriptors; 0 uses the stored message format.
    # Descriptors to poll, in output order. (count: num_descriptors)
    descriptors: _ty.List[_t.Gx5PollDescriptor] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x02
    NAME = "poll_gnss_data"
    ROLE = "command"
    _ATTRS = ("option", "num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("option", _c.enum(_t.Gx5PollOption, "u8")), _c.P("num_descriptors", _c.U8)),
        _c.Counted("descriptors", _t.Gx5PollDescriptor, count="num_descriptors", maximum=83),
    )


@_c.slotted
@_dc.dataclass
class PollFilterData(_c.Field):
    """Poll estimation filter data (set 0x0C, descriptor 0x03, command).

    Poll one estimation filter data packet (set 0x82) with the stored or the given format.

    Sources: 3dm-gx5-45-dcp.txt line 930. Field data: 2..251 bytes.
    """

    option: _ty.Union[_t.Gx5PollOption, int] = _t.Gx5PollOption.NORMAL  # Whether to send the ACK/NACK.
    num_descriptors: int = 0  # Number of descriptors; 0 uses the stored message format.
    # Descriptors to poll, in output order. (count: num_descriptors)
    descriptors: _ty.List[_t.Gx5PollDescriptor] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x03
    NAME = "poll_filter_data"
    ROLE = "command"
    _ATTRS = ("option", "num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("option", _c.enum(_t.Gx5PollOption, "u8")), _c.P("num_descriptors", _c.U8)),
        _c.Counted("descriptors", _t.Gx5PollDescriptor, count="num_descriptors", maximum=83),
    )


@_c.slotted
@_dc.dataclass
class PollNmeaData(_c.Field):
    """Poll NMEA data (set 0x0C, descriptor 0x04, command).

    Poll NMEA sentences once, with the given format or (if none is given) the stored NMEA message
    format. The sentences are sent separately as plain NMEA.

    Sources: 3dm-cv7-ins-docs.txt line 6793. Field data: 2..252 bytes.
    """

    suppress_ack: bool = False  # Do not send the ACK/NACK reply.
    count: int = 0  # Number of format entries.
    format_entries: _ty.List[_t.NmeaMessage] = _dc.field(default_factory=list)  # Sentences to produce. (count: count)

    SET = 0x0C
    DESCRIPTOR = 0x04
    NAME = "poll_nmea_data"
    ROLE = "command"
    _ATTRS = ("suppress_ack", "count", "format_entries")
    _OPS = (
        _c.Run(_c.P("suppress_ack", _c.BOOL), _c.P("count", _c.U8)),
        _c.Counted("format_entries", _t.NmeaMessage, count="count", maximum=50),
    )


@_c.slotted
@_dc.dataclass
class PollData(_c.Field):
    """Poll data (set 0x0C, descriptor 0x0D, command).

    Poll one data packet of the given descriptor set, with the listed descriptors (in that order)
    or, if none, the stored message format. The data comes as a separate data packet.

    Sources: 3dm-cv7-ins-docs.txt line 6826. Field data: 3..253 bytes.
    """

    desc_set: int = 0  # Data descriptor set to poll.
    suppress_ack: bool = False  # Do not send the ACK/NACK reply.
    num_descriptors: int = 0  # Number of descriptors.
    # Field descriptors, in output order. (count: num_descriptors)
    descriptors: _ty.List[int] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x0D
    NAME = "poll_data"
    ROLE = "command"
    _ATTRS = ("desc_set", "suppress_ack", "num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("desc_set", _c.U8), _c.P("suppress_ack", _c.BOOL), _c.P("num_descriptors", _c.U8)),
        _c.Counted("descriptors", _c.U8, count="num_descriptors", maximum=250),
    )


@_c.slotted
@_dc.dataclass
class GetImuBaseRate(_c.Field):
    """Get IMU data base rate (set 0x0C, descriptor 0x06, command).

    Get the IMU data base rate, from which message format decimations are computed.

    Responses: 0x83 imu_base_rate. Sources: 3dm-gx5-45-dcp.txt line 946. Field data: 0 bytes.
    """

    SET = 0x0C
    DESCRIPTOR = 0x06
    NAME = "get_imu_base_rate"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class ImuBaseRate(_c.Field):
    """IMU data base rate (set 0x0C, descriptor 0x83, response).

    IMU data base rate.

    Sources: 3dm-gx5-45-dcp.txt line 952. Field data: 2 bytes.
    """

    rate: int = 0  # Base rate used for rate decimation calculations. [Hz]

    SET = 0x0C
    DESCRIPTOR = 0x83
    NAME = "imu_base_rate"
    ROLE = "response"
    _ATTRS = ("rate",)
    _OPS = (_c.Run(_c.P("rate", _c.U16)),)


@_c.slotted
@_dc.dataclass
class GetGnssBaseRate(_c.Field):
    """Get GNSS data base rate (set 0x0C, descriptor 0x07, command).

    Get the GNSS data base rate, from which message format decimations are computed.

    Responses: 0x84 gnss_base_rate. Sources: 3dm-gx5-45-dcp.txt line 962. Field data: 0 bytes.
    """

    SET = 0x0C
    DESCRIPTOR = 0x07
    NAME = "get_gnss_base_rate"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class GnssBaseRate(_c.Field):
    """GNSS data base rate (set 0x0C, descriptor 0x84, response).

    GNSS data base rate (4 Hz on the 3DM-GX5).

    Sources: 3dm-gx5-45-dcp.txt line 968. Field data: 2 bytes.
    """

    rate: int = 0  # Base rate used for rate decimation calculations. [Hz]

    SET = 0x0C
    DESCRIPTOR = 0x84
    NAME = "gnss_base_rate"
    ROLE = "response"
    _ATTRS = ("rate",)
    _OPS = (_c.Run(_c.P("rate", _c.U16)),)


@_c.slotted
@_dc.dataclass
class GetFilterBaseRate(_c.Field):
    """Get estimation filter data base rate (set 0x0C, descriptor 0x0B, command).

    Get the estimation filter data base rate, from which message format decimations are computed.

    Responses: 0x8A filter_base_rate. Sources: 3dm-gx5-45-dcp.txt line 976. Field data: 0 bytes.
    """

    SET = 0x0C
    DESCRIPTOR = 0x0B
    NAME = "get_filter_base_rate"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class FilterBaseRate(_c.Field):
    """Estimation filter data base rate (set 0x0C, descriptor 0x8A, response).

    Estimation filter data base rate.

    Sources: 3dm-gx5-45-dcp.txt line 982. Field data: 2 bytes.
    """

    rate: int = 0  # Base rate used for rate decimation calculations. [Hz]

    SET = 0x0C
    DESCRIPTOR = 0x8A
    NAME = "filter_base_rate"
    ROLE = "response"
    _ATTRS = ("rate",)
    _OPS = (_c.Run(_c.P("rate", _c.U16)),)


@_c.slotted
@_dc.dataclass
class GetBaseRate(_c.Field):
    """Get data base rate (set 0x0C, descriptor 0x0E, command).

    Get the base rate of a data descriptor set.

    Responses: 0x8E base_rate. Sources: 3dm-cv7-ins-docs.txt line 6841; 3dm-cv7-ins-docs.txt line
    3919. Field data: 1 bytes.
    """

    desc_set: int = 0  # Data descriptor set (must be supported).

    SET = 0x0C
    DESCRIPTOR = 0x0E
    NAME = "get_base_rate"
    ROLE = "command"
    _ATTRS = ("desc_set",)
    _OPS = (_c.Run(_c.P("desc_set", _c.U8)),)


@_c.slotted
@_dc.dataclass
class BaseRate(_c.Field):
    """Data base rate (set 0x0C, descriptor 0x8E, response).

    Base rate of a data descriptor set.

    Sources: 3dm-cv7-ins-docs.txt line 6850. Field data: 3 bytes.
    """

    desc_set: int = 0  # Echo of the descriptor set in the command.
    rate: int = 0  # Base rate; 0 means variable or unknown (data sent as it arrives). [Hz]

    SET = 0x0C
    DESCRIPTOR = 0x8E
    NAME = "base_rate"
    ROLE = "response"
    _ATTRS = ("desc_set", "rate")
    _OPS = (_c.Run(_c.P("desc_set", _c.U8), _c.P("rate", _c.U16)),)


@_c.slotted
@_dc.dataclass
class ImuMessageFormat(_c.Field):
    """IMU message format (set 0x0C, descriptor 0x08, command).

    Set, read, save, load or reset the IMU data (0x80) message format.

    Functions: write, read, save, load, default. Responses: 0x80 imu_message_format_response.
    Sources: 3dm-gx5-45-dcp.txt line 990; 3dm-gx5-45-dcp.txt line 383. Field data: 1..251 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Number of descriptors (0 for every function except write, which may also leave it out). (sent for: write, read,
    # save, load, default)
    num_descriptors: _ty.Optional[int] = None
    # Descriptors and rate decimations (decimation = base rate / desired rate). (sent for: write, read, save, load,
    # default) (count: num_descriptors)
    descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None

    SET = 0x0C
    DESCRIPTOR = 0x08
    NAME = "imu_message_format"
    ROLE = "command"
    _ATTRS = ("function", "num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("num_descriptors", _c.U8))),
        _c.Opt(_c.Counted("descriptors", _t.DescriptorRate, count="num_descriptors", maximum=83)),
    )


@_c.slotted
@_dc.dataclass
class ImuMessageFormatResponse(_c.Field):
    """Current IMU message format (set 0x0C, descriptor 0x80, response).

    The IMU data message format.

    Sources: 3dm-gx5-45-dcp.txt line 997. Field data: 1..253 bytes.
    """

    num_descriptors: int = 0  # Number of descriptors.
    # Descriptors and rate decimations. (count: num_descriptors)
    descriptors: _ty.List[_t.DescriptorRate] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x80
    NAME = "imu_message_format_response"
    ROLE = "response"
    _ATTRS = ("num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("num_descriptors", _c.U8)),
        _c.Counted("descriptors", _t.DescriptorRate, count="num_descriptors", maximum=84),
    )


@_c.slotted
@_dc.dataclass
class GnssMessageFormat(_c.Field):
    """GNSS message format (set 0x0C, descriptor 0x09, command).

    Set, read, save, load or reset the GNSS data (0x81) message format.

    Functions: write, read, save, load, default. Responses: 0x81 gnss_message_format_response.
    Sources: 3dm-gx5-45-dcp.txt line 1009. Field data: 1..251 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Number of descriptors (0 for every function except write, which may also leave it out). (sent for: write, read,
    # save, load, default)
    num_descriptors: _ty.Optional[int] = None
    # Descriptors and rate decimations (decimation = base rate / desired rate). (sent for: write, read, save, load,
    # default) (count: num_descriptors)
    descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None

    SET = 0x0C
    DESCRIPTOR = 0x09
    NAME = "gnss_message_format"
    ROLE = "command"
    _ATTRS = ("function", "num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("num_descriptors", _c.U8))),
        _c.Opt(_c.Counted("descriptors", _t.DescriptorRate, count="num_descriptors", maximum=83)),
    )


@_c.slotted
@_dc.dataclass
class GnssMessageFormatResponse(_c.Field):
    """Current GNSS message format (set 0x0C, descriptor 0x81, response).

    The GNSS data message format.

    Sources: 3dm-gx5-45-dcp.txt line 1015. Field data: 1..253 bytes.
    """

    num_descriptors: int = 0  # Number of descriptors.
    # Descriptors and rate decimations. (count: num_descriptors)
    descriptors: _ty.List[_t.DescriptorRate] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x81
    NAME = "gnss_message_format_response"
    ROLE = "response"
    _ATTRS = ("num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("num_descriptors", _c.U8)),
        _c.Counted("descriptors", _t.DescriptorRate, count="num_descriptors", maximum=84),
    )


@_c.slotted
@_dc.dataclass
class FilterMessageFormat(_c.Field):
    """Estimation filter message format (set 0x0C, descriptor 0x0A, command).

    Set, read, save, load or reset the estimation filter data (0x82) message format.

    Functions: write, read, save, load, default. Responses: 0x82 filter_message_format_response.
    Sources: 3dm-gx5-45-dcp.txt line 1027; 3dm-gx5-45-dcp.txt line 395. Field data: 1..251 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Number of descriptors (0 for every function except write, which may also leave it out). (sent for: write, read,
    # save, load, default)
    num_descriptors: _ty.Optional[int] = None
    # Descriptors and rate decimations (decimation = base rate / desired rate). (sent for: write, read, save, load,
    # default) (count: num_descriptors)
    descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None

    SET = 0x0C
    DESCRIPTOR = 0x0A
    NAME = "filter_message_format"
    ROLE = "command"
    _ATTRS = ("function", "num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("num_descriptors", _c.U8))),
        _c.Opt(_c.Counted("descriptors", _t.DescriptorRate, count="num_descriptors", maximum=83)),
    )


@_c.slotted
@_dc.dataclass
class FilterMessageFormatResponse(_c.Field):
    """Current estimation filter message format (set 0x0C, descriptor 0x82, response).

    The estimation filter data message format.

    Sources: 3dm-gx5-45-dcp.txt line 1033. Field data: 1..253 bytes.
    """

    num_descriptors: int = 0  # Number of descriptors.
    # Descriptors and rate decimations. (count: num_descriptors)
    descriptors: _ty.List[_t.DescriptorRate] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x82
    NAME = "filter_message_format_response"
    ROLE = "response"
    _ATTRS = ("num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("num_descriptors", _c.U8)),
        _c.Counted("descriptors", _t.DescriptorRate, count="num_descriptors", maximum=84),
    )


@_c.slotted
@_dc.dataclass
class NmeaMessageFormat(_c.Field):
    """NMEA message format (set 0x0C, descriptor 0x0C, command).

    Set, read, save, load or reset the list of NMEA sentences the device outputs.

    Functions: write, read, save, load, default. Responses: 0x8C nmea_message_format_response.
    Sources: 3dm-cv7-ins-docs.txt line 6807; 3dm-cv7-ins-docs.txt line 1060. Field data: 1..252
    bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    count: _ty.Optional[int] = None  # Number of format entries. (sent for: write)
    # Sentences, talkers, sources and decimations. (sent for: write) (count: count)
    format_entries: _ty.Optional[_ty.List[_t.NmeaMessage]] = None

    SET = 0x0C
    DESCRIPTOR = 0x0C
    NAME = "nmea_message_format"
    ROLE = "command"
    _ATTRS = ("function", "count", "format_entries")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("count", _c.U8))),
        _c.Opt(_c.Counted("format_entries", _t.NmeaMessage, count="count", maximum=50)),
    )


@_c.slotted
@_dc.dataclass
class NmeaMessageFormatResponse(_c.Field):
    """Current NMEA message format (set 0x0C, descriptor 0x8C, response).

    The NMEA sentence list.

    Sources: 3dm-cv7-ins-docs.txt line 6818. Field data: 1..251 bytes.
    """

    count: int = 0  # Number of format entries.
    # Sentences, talkers, sources and decimations. (count: count)
    format_entries: _ty.List[_t.NmeaMessage] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x8C
    NAME = "nmea_message_format_response"
    ROLE = "response"
    _ATTRS = ("count", "format_entries")
    _OPS = (
        _c.Run(_c.P("count", _c.U8)),
        _c.Counted("format_entries", _t.NmeaMessage, count="count", maximum=50),
    )


@_c.slotted
@_dc.dataclass
class MessageFormat(_c.Field):
    """Message format (set 0x0C, descriptor 0x0F, command).

    Set, read, save, load or reset the message format of a data descriptor set. Output keeps the
    order of the list.

    Functions: write, read, save, load, default. Responses: 0x8F message_format_response. Sources:
    3dm-cv7-ins-docs.txt line 6858. Field data: 2..252 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    desc_set: int = 0  # Data descriptor set; 0 means all sets for save, load and default.
    num_descriptors: _ty.Optional[int] = None  # Number of descriptors. (sent for: write)
    # Descriptors and decimations. (sent for: write) (count: num_descriptors)
    descriptors: _ty.Optional[_ty.List[_t.DescriptorRate]] = None

    SET = 0x0C
    DESCRIPTOR = 0x0F
    NAME = "message_format"
    ROLE = "command"
    _ATTRS = ("function", "desc_set", "num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("desc_set", _c.U8)),
        _c.Opt(_c.Run(_c.P("num_descriptors", _c.U8))),
        _c.Opt(_c.Counted("descriptors", _t.DescriptorRate, count="num_descriptors", maximum=83)),
    )


@_c.slotted
@_dc.dataclass
class MessageFormatResponse(_c.Field):
    """Current message format (set 0x0C, descriptor 0x8F, response).

    The message format of a data descriptor set.

    Sources: 3dm-cv7-ins-docs.txt line 6870. Field data: 2..251 bytes.
    """

    desc_set: int = 0  # Echo of the descriptor set in the command.
    num_descriptors: int = 0  # Number of descriptors.
    # Descriptors and decimations. (count: num_descriptors)
    descriptors: _ty.List[_t.DescriptorRate] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x8F
    NAME = "message_format_response"
    ROLE = "response"
    _ATTRS = ("desc_set", "num_descriptors", "descriptors")
    _OPS = (
        _c.Run(_c.P("desc_set", _c.U8), _c.P("num_descriptors", _c.U8)),
        _c.Counted("descriptors", _t.DescriptorRate, count="num_descriptors", maximum=83),
    )


@_c.slotted
@_dc.dataclass
class FactoryStreaming(_c.Field):
    """Factory streaming (set 0x0C, descriptor 0x10, command).

    Configure every data stream with the predefined formats technical support asks for.

    Sources: 3dm-cv7-ins-docs.txt line 6879. Field data: 2 bytes.
    """

    # How to combine the support descriptors with the current formats.
    action: _ty.Union[_t.FactoryStreamingAction, int] = _t.FactoryStreamingAction.OVERWRITE
    reserved: int = 0  # Reserved; set to 0x00.

    SET = 0x0C
    DESCRIPTOR = 0x10
    NAME = "factory_streaming"
    ROLE = "command"
    _ATTRS = ("action", "reserved")
    _OPS = (_c.Run(_c.P("action", _c.enum(_t.FactoryStreamingAction, "u8")), _c.P("reserved", _c.U8)),)


@_c.slotted
@_dc.dataclass
class DataStreamControl_gx5_45(_c.Field):
    """Data stream control (set 0x0C, descriptor 0x11, command), device gx5_45.

    Enable or disable continuous output of a data stream. All streams are enabled by default. The
    enable value is used only by write.

    Functions: write, read, save, load, default. Responses: 0x85 data_stream_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1047; 3dm-gx5-45-dcp.txt line 419. Field data: 2..3 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    device_selector: _ty.Union[_t.Gx5StreamSelector, int] = _t.Gx5StreamSelector.IMU  # Stream to control.
    # 0x00 disable, 0x01 enable (default); ignored except for write, and may be left out by the other functions. (sent
    # for: write, read, save, load, default)
    enable: _ty.Optional[int] = None

    SET = 0x0C
    DESCRIPTOR = 0x11
    NAME = "data_stream_control"
    ROLE = "command"
    DEVICE = "gx5_45"
    _ATTRS = ("function", "device_selector", "enable")
    _OPS = (
        _c.Run(
            _c.P("function", _c.enum(_t.FunctionSelector, "u8")),
            _c.P("device_selector", _c.enum(_t.Gx5StreamSelector, "u8")),
        ),
        _c.Opt(_c.Run(_c.P("enable", _c.U8))),
    )


@_c.slotted
@_dc.dataclass
class DataStreamControl_cv7_ins(_c.Field):
    """Data stream control (set 0x0C, descriptor 0x11, command), device cv7_ins.

    Enable or disable continuous output of a data stream. All streams are enabled by default. The
    enable value is used only by write.

    Functions: write, read, save, load, default. Responses: 0x85 data_stream_control_response.
    Sources: 3dm-cv7-ins-docs.txt line 6898. Field data: 2..3 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    desc_set: int = 0  # Data descriptor set of the stream; 0 means all streams for save, load and default.
    enable: _ty.Optional[bool] = None  # Enable (true) or disable (false) the stream. (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x11
    NAME = "data_stream_control"
    ROLE = "command"
    DEVICE = "cv7_ins"
    _ATTRS = ("function", "desc_set", "enable")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("desc_set", _c.U8)),
        _c.Opt(_c.Run(_c.P("enable", _c.BOOL))),
    )


@_c.slotted
@_dc.dataclass
class DataStreamControlResponse_gx5_45(_c.Field):
    """Data stream control (response) (set 0x0C, descriptor 0x85, response), device gx5_45.

    Whether a data stream is enabled.

    Sources: 3dm-gx5-45-dcp.txt line 1053. Field data: 2 bytes.
    """

    device_selector: _ty.Union[_t.Gx5StreamSelector, int] = _t.Gx5StreamSelector.IMU  # Stream.
    enabled: int = 0  # Current enable flag: 0x00 disabled, 0x01 enabled.

    SET = 0x0C
    DESCRIPTOR = 0x85
    NAME = "data_stream_control_response"
    ROLE = "response"
    DEVICE = "gx5_45"
    _ATTRS = ("device_selector", "enabled")
    _OPS = (_c.Run(_c.P("device_selector", _c.enum(_t.Gx5StreamSelector, "u8")), _c.P("enabled", _c.U8)),)


@_c.slotted
@_dc.dataclass
class DataStreamControlResponse_cv7_ins(_c.Field):
    """Data stream control (response) (set 0x0C, descriptor 0x85, response), device cv7_ins.

    Whether a data stream is enabled.

    Sources: 3dm-cv7-ins-docs.txt line 6909. Field data: 2 bytes.
    """

    desc_set: int = 0  # Data descriptor set of the stream.
    enabled: bool = False  # Whether the stream is enabled.

    SET = 0x0C
    DESCRIPTOR = 0x85
    NAME = "data_stream_control_response"
    ROLE = "response"
    DEVICE = "cv7_ins"
    _ATTRS = ("desc_set", "enabled")
    _OPS = (_c.Run(_c.P("desc_set", _c.U8), _c.P("enabled", _c.BOOL)),)


@_c.slotted
@_dc.dataclass
class RawRtcmMessage(_c.Field):
    """Raw RTCM 2.3 message (set 0x0C, descriptor 0x20, command).

    Send raw RTCM 2.3 differential corrections to the GNSS receiver (message types 1, 2, 3 and 9; no
    RTK). A stream may be split into chunks of at most 253 bytes.

    Sources: 3dm-gx5-45-dcp.txt line 1392. Field data: 0..253 bytes.
    """

    # Raw RTCM 2.3 bytes, passed through unchanged. (to the end of the field)
    data: _ty.List[int] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0x20
    NAME = "raw_rtcm_message"
    ROLE = "command"
    _ATTRS = ("data",)
    _OPS = (_c.Remaining("data", _c.U8, maximum=253),)


@_c.slotted
@_dc.dataclass
class GnssConstellationSettings(_c.Field):
    """GNSS constellation settings (set 0x0C, descriptor 0x21, command).

    Choose which satellite constellations the receiver tracks and how many tracking channels each
    may reserve and use (32 channels in all; GLONASS and BeiDou not together).

    Functions: write, read, save, load, default. Responses: 0xA0
    gnss_constellation_settings_response. Sources: 3dm-gx5-45-dcp.txt line 1063. Field data: 1..250
    bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Maximum tracking channels to use in total (0 up to the available channels). (sent for: write, read, save, load,
    # default)
    max_channels: _ty.Optional[int] = None
    # Number of constellation entries. (sent for: write, read, save, load, default)
    config_count: _ty.Optional[int] = None
    # Per-constellation settings. (sent for: write, read, save, load, default) (count: config_count)
    settings: _ty.Optional[_ty.List[_t.ConstellationSettings]] = None

    SET = 0x0C
    DESCRIPTOR = 0x21
    NAME = "gnss_constellation_settings"
    ROLE = "command"
    _ATTRS = ("function", "max_channels", "config_count", "settings")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("max_channels", _c.U16))),
        _c.Opt(_c.Run(_c.P("config_count", _c.U8))),
        _c.Opt(_c.Counted("settings", _t.ConstellationSettings, count="config_count", maximum=41)),
    )


@_c.slotted
@_dc.dataclass
class GnssConstellationSettingsResponse(_c.Field):
    """GNSS constellation settings (response) (set 0x0C, descriptor 0xA0, response).

    Current constellation configuration.

    Sources: 3dm-gx5-45-dcp.txt line 1135. Field data: 5..251 bytes.
    """

    max_channels_available: int = 0  # Tracking channels the receiver has.
    max_channels: int = 0  # Maximum tracking channels to use in total.
    config_count: int = 0  # Number of constellation entries.
    # Per-constellation settings. (count: config_count)
    settings: _ty.List[_t.ConstellationSettings] = _dc.field(default_factory=list)

    SET = 0x0C
    DESCRIPTOR = 0xA0
    NAME = "gnss_constellation_settings_response"
    ROLE = "response"
    _ATTRS = ("max_channels_available", "max_channels", "config_count", "settings")
    _OPS = (
        _c.Run(_c.P("max_channels_available", _c.U16), _c.P("max_channels", _c.U16), _c.P("config_count", _c.U8)),
        _c.Counted("settings", _t.ConstellationSettings, count="config_count", maximum=41),
    )


@_c.slotted
@_dc.dataclass
class GnssSbasSettings(_c.Field):
    """GNSS SBAS settings (set 0x0C, descriptor 0x22, command).

    Configure how SBAS satellites augment the GNSS solution: enable, options, and the SBAS PRNs to
    search for (none listed = all).

    Functions: write, read, save, load, default. Responses: 0xA1 gnss_sbas_settings_response.
    Sources: 3dm-gx5-45-dcp.txt line 1143; 3dm-cv7-ins-docs.txt line 6919. Field data: 1..253 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    enable_sbas: _ty.Optional[int] = None  # 0 SBAS disabled, 1 SBAS enabled (default). (sent for: write)
    sbas_options: _ty.Optional[_t.SbasOptions] = None  # SBAS options. (sent for: write)
    num_included_prns: _ty.Optional[int] = None  # Number of SBAS PRNs listed; 0 includes all. (sent for: write)
    # SBAS PRNs to search for. (sent for: write) (count: num_included_prns)
    included_prns: _ty.Optional[_ty.List[int]] = None

    SET = 0x0C
    DESCRIPTOR = 0x22
    NAME = "gnss_sbas_settings"
    ROLE = "command"
    _ATTRS = ("function", "enable_sbas", "sbas_options", "num_included_prns", "included_prns")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("enable_sbas", _c.U8))),
        _c.Opt(_c.Run(_c.P("sbas_options", _c.flags(_t.SbasOptions)))),
        _c.Opt(_c.Run(_c.P("num_included_prns", _c.U8))),
        _c.Opt(_c.Counted("included_prns", _c.U16, count="num_included_prns", maximum=124)),
    )


@_c.slotted
@_dc.dataclass
class GnssSbasSettingsResponse(_c.Field):
    """GNSS SBAS settings (response) (set 0x0C, descriptor 0xA1, response).

    Current SBAS configuration.

    Sources: 3dm-gx5-45-dcp.txt line 1149; 3dm-cv7-ins-docs.txt line 6936. Field data: 4..252 bytes.
    """

    enable_sbas: int = 0  # 0 SBAS disabled, 1 SBAS enabled.
    sbas_options: _t.SbasOptions = _t.SbasOptions(0)  # SBAS options.
    num_included_prns: int = 0  # Number of SBAS PRNs listed; 0 means all.
    included_prns: _ty.List[int] = _dc.field(default_factory=list)  # SBAS PRNs searched for. (count: num_included_prns)

    SET = 0x0C
    DESCRIPTOR = 0xA1
    NAME = "gnss_sbas_settings_response"
    ROLE = "response"
    _ATTRS = ("enable_sbas", "sbas_options", "num_included_prns", "included_prns")
    _OPS = (
        _c.Run(
            _c.P("enable_sbas", _c.U8), _c.P("sbas_options", _c.flags(_t.SbasOptions)), _c.P("num_included_prns", _c.U8)
        ),
        _c.Counted("included_prns", _c.U16, count="num_included_prns", maximum=124),
    )


@_c.slotted
@_dc.dataclass
class GnssAssistedFixControl(_c.Field):
    """GNSS assisted fix control (set 0x0C, descriptor 0x23, command).

    Enable or disable assisted GNSS fix, which keeps the last fix in non-volatile memory to shorten
    the time to first fix. Disabling it erases that memory.

    Functions: write, read, save, load, default. Responses: 0xA2 gnss_assisted_fix_control_response.
    Sources: 3dm-gx5-45-dcp.txt line 1157. Field data: 1..3 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Assisted fix on or off. (sent for: write, read, save, load, default)
    option: _ty.Optional[_ty.Union[_t.AssistedFixOption, int]] = None
    flags: _ty.Optional[int] = None  # No flags defined; set to 0xFF. (sent for: write, read, save, load, default)

    SET = 0x0C
    DESCRIPTOR = 0x23
    NAME = "gnss_assisted_fix_control"
    ROLE = "command"
    _ATTRS = ("function", "option", "flags")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("option", _c.enum(_t.AssistedFixOption, "u8")))),
        _c.Opt(_c.Run(_c.P("flags", _c.U8))),
    )


@_c.slotted
@_dc.dataclass
class GnssAssistedFixControlResponse(_c.Field):
    """GNSS assisted fix control (response) (set 0x0C, descriptor 0xA2, response).

    Current assisted fix setting.

    Sources: 3dm-gx5-45-dcp.txt line 1165. Field data: 2 bytes.
    """

    option: _ty.Union[_t.AssistedFixOption, int] = _t.AssistedFixOption.NONE  # Assisted fix on or off.
    flags: int = 0  # Assisted fix flags.

    SET = 0x0C
    DESCRIPTOR = 0xA2
    NAME = "gnss_assisted_fix_control_response"
    ROLE = "response"
    _ATTRS = ("option", "flags")
    _OPS = (_c.Run(_c.P("option", _c.enum(_t.AssistedFixOption, "u8")), _c.P("flags", _c.U8)),)


@_c.slotted
@_dc.dataclass
class GnssAssistTimeUpdate(_c.Field):
    """GNSS assist time update (set 0x0C, descriptor 0x24, command).

    Give the receiver the current GPS time right after power-up when assisted fix is enabled, so it
    can judge whether its saved satellite information is still usable.

    Functions: write, read. Responses: 0xA3 gnss_assist_time_update_response. Sources:
    3dm-gx5-45-dcp.txt line 1176. Field data: 1..15 bytes.
    """

    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE  # Function selector (one of: write, read)
    tow: _ty.Optional[float] = None  # GPS time of week. [s] (sent for: write, read)
    week_number: _ty.Optional[int] = None  # GPS week number. (sent for: write, read)
    accuracy: _ty.Optional[float] = None  # Accuracy of the given time. [s] (sent for: write, read)

    SET = 0x0C
    DESCRIPTOR = 0x24
    NAME = "gnss_assist_time_update"
    ROLE = "command"
    _ATTRS = ("function", "tow", "week_number", "accuracy")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("tow", _c.F64))),
        _c.Opt(_c.Run(_c.P("week_number", _c.U16))),
        _c.Opt(_c.Run(_c.P("accuracy", _c.F32))),
    )


@_c.slotted
@_dc.dataclass
class GnssAssistTimeUpdateResponse(_c.Field):
    """GNSS assist time update (response) (set 0x0C, descriptor 0xA3, response).

    Current assist time values.

    Sources: 3dm-gx5-45-dcp.txt line 1182. Field data: 14 bytes.
    """

    tow: float = 0.0  # GPS time of week. [s]
    week_number: int = 0  # GPS week number.
    accuracy: float = 0.0  # Time accuracy. [s]

    SET = 0x0C
    DESCRIPTOR = 0xA3
    NAME = "gnss_assist_time_update_response"
    ROLE = "response"
    _ATTRS = ("tow", "week_number", "accuracy")
    _OPS = (_c.Run(_c.P("tow", _c.F64), _c.P("week_number", _c.U16), _c.P("accuracy", _c.F32)),)


@_c.slotted
@_dc.dataclass
class PpsSource(_c.Field):
    """PPS source control (set 0x0C, descriptor 0x28, command).

    Choose where the pulse-per-second signal comes from.

    Functions: write, read, save, load, default. Responses: 0xA8 pps_source_response. Sources:
    3dm-cv7-ins-docs.txt line 6950; 3dm-cv7-ins-docs.txt line 3927. Field data: 1..2 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    source: _ty.Optional[_ty.Union[_t.PpsSource, int]] = None  # PPS source. (sent for: write)

    SET = 0x0C
    DESCRIPTOR = 0x28
    NAME = "pps_source"
    ROLE = "command"
    _ATTRS = ("function", "source")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8"))),
        _c.Opt(_c.Run(_c.P("source", _c.enum(_t.PpsSource, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class PpsSourceResponse(_c.Field):
    """PPS source (response) (set 0x0C, descriptor 0xA8, response).

    Current PPS source.

    Sources: 3dm-cv7-ins-docs.txt line 6966. Field data: 1 bytes.
    """

    source: _ty.Union[_t.PpsSource, int] = _t.PpsSource.DISABLED  # PPS source.

    SET = 0x0C
    DESCRIPTOR = 0xA8
    NAME = "pps_source_response"
    ROLE = "response"
    _ATTRS = ("source",)
    _OPS = (_c.Run(_c.P("source", _c.enum(_t.PpsSource, "u8"))),)


@_c.slotted
@_dc.dataclass
class GetSupportedEvents(_c.Field):
    """Get supported events (set 0x0C, descriptor 0x2A, command).

    List the trigger or action types the device supports and how many slots it has.

    Responses: 0xB4 supported_events. Sources: 3dm-cv7-ins-docs.txt line 6980. Field data: 1 bytes.
    """

    # Trigger types or action types.
    query: _ty.Union[_t.SupportedEventsQuery, int] = _t.SupportedEventsQuery.TRIGGER_TYPES

    SET = 0x0C
    DESCRIPTOR = 0x2A
    NAME = "get_supported_events"
    ROLE = "command"
    _ATTRS = ("query",)
    _OPS = (_c.Run(_c.P("query", _c.enum(_t.SupportedEventsQuery, "u8"))),)


@_c.slotted
@_dc.dataclass
class SupportedEvents(_c.Field):
    """Supported events (set 0x0C, descriptor 0xB4, response).

    Number of slots and the supported trigger or action types with their maximum counts.

    Sources: 3dm-cv7-ins-docs.txt line 6992. Field data: 3..253 bytes.
    """

    query: _ty.Union[_t.SupportedEventsQuery, int] = _t.SupportedEventsQuery.TRIGGER_TYPES  # Echo of the query.
    info: _ty.Optional[_ty.Union[_t.SupportedTriggers, _t.SupportedActions]] = None  # Slots and supported types.

    SET = 0x0C
    DESCRIPTOR = 0xB4
    NAME = "supported_events"
    ROLE = "response"
    _ATTRS = ("query", "info")
    _OPS = (
        _c.Run(_c.P("query", _c.enum(_t.SupportedEventsQuery, "u8"))),
        _c.Choice("info", _t.SupportedEventsInfo, selector="query"),
    )


@_c.slotted
@_dc.dataclass
class DeviceStatus(_c.Field):
    """Device status (set 0x0C, descriptor 0x64, command).

    Get the model-specific status of the device, in the basic or the diagnostic structure. The reply
    layout is tied to the model number (6251 for the 3DM-GX5-45).

    Responses: 0x90 device_status_response. Sources: 3dm-gx5-45-dcp.txt line 1339. Field data: 3
    bytes.
    """

    model_number: int = 0  # Device model number; 6251 (0x186B) for the 3DM-GX5-45.
    # Which status structure to return.
    status_selector: _ty.Union[_t.DeviceStatusSelector, int] = _t.DeviceStatusSelector.BASIC

    SET = 0x0C
    DESCRIPTOR = 0x64
    NAME = "device_status"
    ROLE = "command"
    _ATTRS = ("model_number", "status_selector")
    _OPS = (_c.Run(_c.P("model_number", _c.U16), _c.P("status_selector", _c.enum(_t.DeviceStatusSelector, "u8"))),)


@_c.slotted
@_dc.dataclass
class DeviceStatusResponse(_c.Field):
    """Device status (response) (set 0x0C, descriptor 0x90, response).

    Echoes of the model number and selector, then the basic or diagnostic status structure chosen by
    the echoed selector.

    Sources: 3dm-gx5-45-dcp.txt line 1351; 3dm-gx5-45-dcp.txt line 1357. Field data: 13..73 bytes.
    """

    model_number: int = 0  # Echo of the model number.
    # Echo of the status selector.
    status_selector: _ty.Union[_t.DeviceStatusSelector, int] = _t.DeviceStatusSelector.BASIC
    status: _ty.Optional[_ty.Union[_t.Gx5BasicStatus, _t.Gx5DiagnosticStatus]] = None  # The selected status structure.

    SET = 0x0C
    DESCRIPTOR = 0x90
    NAME = "device_status_response"
    ROLE = "response"
    _ATTRS = ("model_number", "status_selector", "status")
    _OPS = (
        _c.Run(_c.P("model_number", _c.U16), _c.P("status_selector", _c.enum(_t.DeviceStatusSelector, "u8"))),
        _c.Choice("status", _t.Gx5DeviceStatus, selector="status_selector"),
    )


FIELDS: tuple[type[_c.Field], ...] = (
    EventControl,
    EventControlResponse,
    GetEventTriggerStatus,
    EventTriggerStatus,
    GetEventActionStatus,
    EventActionStatus,
    EventTriggerConfig,
    EventTriggerConfigResponse,
    EventActionConfig,
    EventActionConfigResponse,
    DeviceStartupSettings_gx5_45,
    DeviceStartupSettings_cv7_ins,
    SensorToVehicleEuler,
    SensorToVehicleEulerResponse,
    SensorToVehicleQuaternion,
    SensorToVehicleQuaternionResponse,
    SensorToVehicleDcm,
    SensorToVehicleDcmResponse,
    AccelBias_gx5_45,
    AccelBias_cv7_ins,
    AccelBiasResponse,
    GyroBias_gx5_45,
    GyroBias_cv7_ins,
    GyroBiasResponse,
    CaptureGyroBias,
    MagHardIronOffset_gx5_45,
    MagHardIronOffset_cv7_ins,
    MagHardIronOffsetResponse,
    MagSoftIronMatrix_gx5_45,
    MagSoftIronMatrix_cv7_ins,
    MagSoftIronMatrixResponse,
    ConingScullingEnable,
    ConingScullingEnableResponse,
    UartBaudrate,
    UartBaudrateResponse,
    GpioConfig,
    GpioConfigResponse,
    GpioState,
    GpioStateResponse,
    OdometerConfig,
    OdometerConfigResponse,
    AdvancedLowpassFilter,
    AdvancedLowpassFilterResponse,
    ComplementaryFilter,
    ComplementaryFilterResponse,
    SensorRange,
    SensorRangeResponse,
    GetCalibratedSensorRanges,
    CalibratedSensorRanges,
    LowpassFilter,
    LowpassFilterResponse,
    PollImuData,
    PollGnssData,
    PollFilterData,
    PollNmeaData,
    PollData,
    GetImuBaseRate,
    ImuBaseRate,
    GetGnssBaseRate,
    GnssBaseRate,
    GetFilterBaseRate,
    FilterBaseRate,
    GetBaseRate,
    BaseRate,
    ImuMessageFormat,
    ImuMessageFormatResponse,
    GnssMessageFormat,
    GnssMessageFormatResponse,
    FilterMessageFormat,
    FilterMessageFormatResponse,
    NmeaMessageFormat,
    NmeaMessageFormatResponse,
    MessageFormat,
    MessageFormatResponse,
    FactoryStreaming,
    DataStreamControl_gx5_45,
    DataStreamControl_cv7_ins,
    DataStreamControlResponse_gx5_45,
    DataStreamControlResponse_cv7_ins,
    RawRtcmMessage,
    GnssConstellationSettings,
    GnssConstellationSettingsResponse,
    GnssSbasSettings,
    GnssSbasSettingsResponse,
    GnssAssistedFixControl,
    GnssAssistedFixControlResponse,
    GnssAssistTimeUpdate,
    GnssAssistTimeUpdateResponse,
    PpsSource,
    PpsSourceResponse,
    GetSupportedEvents,
    SupportedEvents,
    DeviceStatus,
    DeviceStatusResponse,
)
