"""Base Command Set (descriptor set 0x01, command).

Commands common to every MIP device: identify the device, list its descriptors, run built-in tests,
idle/resume/reset, and set the GPS time.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class Ping(_c.Field):
    """Ping (set 0x01, descriptor 0x01, command).

    Test communications with a device. The device responds with an ACK if present.

    Sources: 3dm-gx5-45-dcp.txt line 748; 3dm-cv7-ins-docs.txt line 8032. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x01
    NAME = "ping"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class SetToIdle(_c.Field):
    """Set to idle (set 0x01, descriptor 0x02, command).

    Turn off all device data streams; suspends streaming or wakes the device from sleep so it can
    answer status and setup commands. Resume restores the previous mode.

    Sources: 3dm-gx5-45-dcp.txt line 759; 3dm-cv7-ins-docs.txt line 8043. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x02
    NAME = "set_to_idle"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class GetDeviceInfo(_c.Field):
    """Get device information (set 0x01, descriptor 0x03, command).

    Get the device ID strings and firmware version.

    Responses: 0x81 device_info. Sources: 3dm-gx5-45-dcp.txt line 771; 3dm-cv7-ins-docs.txt line
    8054. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x03
    NAME = "get_device_info"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class DeviceInfo(_c.Field):
    """Device information (set 0x01, descriptor 0x81, response).

    Reply to Get device information.

    Sources: 3dm-gx5-45-dcp.txt line 779; 3dm-cv7-ins-docs.txt line 8064. Field data: 82 bytes.
    """

    info: _t.DeviceInfo = _dc.field(default_factory=_t.DeviceInfo)  # Device information.

    SET = 0x01
    DESCRIPTOR = 0x81
    NAME = "device_info"
    ROLE = "response"
    _ATTRS = ("info",)
    _OPS = (_c.Nested("info", _t.DeviceInfo),)


@_c.slotted
@_dc.dataclass
class GetDeviceDescriptors(_c.Field):
    """Get device descriptor sets (set 0x01, descriptor 0x04, command).

    Get the command and data descriptors supported by the device.

    Responses: 0x82 device_descriptors. Sources: 3dm-gx5-45-dcp.txt line 789; 3dm-cv7-ins-docs.txt
    line 8069. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x04
    NAME = "get_device_descriptors"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class DeviceDescriptors(_c.Field):
    """Device descriptors (set 0x01, descriptor 0x82, response).

    Array of 16-bit values: the MSB is the descriptor set and the LSB the descriptor. The array runs
    to the end of the field.

    Sources: 3dm-gx5-45-dcp.txt line 797; 3dm-cv7-ins-docs.txt line 8079. Field data: 0..252 bytes.
    """

    # Supported descriptors, (set << 8) | descriptor. (to the end of the field)
    descriptors: _ty.List[int] = _dc.field(default_factory=list)

    SET = 0x01
    DESCRIPTOR = 0x82
    NAME = "device_descriptors"
    ROLE = "response"
    _ATTRS = ("descriptors",)
    _OPS = (_c.Remaining("descriptors", _c.U16, maximum=126),)


@_c.slotted
@_dc.dataclass
class BuiltInTest(_c.Field):
    """Built-in test (set 0x01, descriptor 0x05, command).

    Run the device built-in test (BIT). The result is a 32-bit value; 0 means all tests passed.

    Responses: 0x83 built_in_test_result. Sources: 3dm-gx5-45-dcp.txt line 807; 3dm-cv7-ins-docs.txt
    line 8084. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x05
    NAME = "built_in_test"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class BuiltInTestResult_gx5_45(_c.Field):
    """Built-in test result (set 0x01, descriptor 0x83, response), device gx5_45.

    Result of the commanded built-in test. The flags are device specific.

    Sources: 3dm-gx5-45-dcp.txt line 820. Field data: 4 bytes.
    """

    flags: _t.Gx5BitFlags = _t.Gx5BitFlags(0)  # BIT error flags; 0 means all tests passed.

    SET = 0x01
    DESCRIPTOR = 0x83
    NAME = "built_in_test_result"
    ROLE = "response"
    DEVICE = "gx5_45"
    _ATTRS = ("flags",)
    _OPS = (_c.Run(_c.P("flags", _c.flags(_t.Gx5BitFlags))),)


@_c.slotted
@_dc.dataclass
class BuiltInTestResult_cv7_ins(_c.Field):
    """Built-in test result (set 0x01, descriptor 0x83, response), device cv7_ins.

    Result of the commanded built-in test. The flags are device specific.

    Sources: 3dm-cv7-ins-docs.txt line 8092. Field data: 4 bytes.
    """

    flags: _t.Cv7BitFlags = _t.Cv7BitFlags(0)  # BIT result bitfield; 0 means all tests passed.

    SET = 0x01
    DESCRIPTOR = 0x83
    NAME = "built_in_test_result"
    ROLE = "response"
    DEVICE = "cv7_ins"
    _ATTRS = ("flags",)
    _OPS = (_c.Run(_c.P("flags", _c.flags(_t.Cv7BitFlags))),)


@_c.slotted
@_dc.dataclass
class Resume(_c.Field):
    """Resume (set 0x01, descriptor 0x06, command).

    Place the device back into the mode it was in before Set to idle (default mode if none).

    Sources: 3dm-gx5-45-dcp.txt line 832; 3dm-cv7-ins-docs.txt line 8099. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x06
    NAME = "resume"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class GetExtendedDescriptors(_c.Field):
    """Get extended device descriptor sets (set 0x01, descriptor 0x07, command).

    Get the descriptors supported in addition to those returned by Get device descriptor sets.

    Responses: 0x86 extended_descriptors. Sources: 3dm-gx5-45-dcp.txt line 844; 3dm-cv7-ins-docs.txt
    line 8110. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x07
    NAME = "get_extended_descriptors"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class ExtendedDescriptors(_c.Field):
    """Extended device descriptors (set 0x01, descriptor 0x86, response).

    Array of 16-bit descriptors (MSB set, LSB descriptor) running to the end of the field.

    Sources: 3dm-gx5-45-dcp.txt line 853; 3dm-cv7-ins-docs.txt line 8120. Field data: 0..252 bytes.
    """

    # Supported extended descriptors, (set << 8) | descriptor. (to the end of the field)
    descriptors: _ty.List[int] = _dc.field(default_factory=list)

    SET = 0x01
    DESCRIPTOR = 0x86
    NAME = "extended_descriptors"
    ROLE = "response"
    _ATTRS = ("descriptors",)
    _OPS = (_c.Remaining("descriptors", _c.U16, maximum=126),)


@_c.slotted
@_dc.dataclass
class ContinuousBit(_c.Field):
    """Continuous built-in test (set 0x01, descriptor 0x08, command).

    Report the result of the continuous built-in test (non-disruptive).

    Responses: 0x88 continuous_bit_result. Sources: 3dm-cv7-ins-docs.txt line 8125. Field data: 0
    bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x08
    NAME = "continuous_bit"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class ContinuousBitResult(_c.Field):
    """Continuous built-in test result (set 0x01, descriptor 0x88, response).

    Device-specific 128-bit bitfield, least-significant byte first: bit 0 is bit 0 of result[0], bit
    127 is bit 7 of result[15].

    Sources: 3dm-cv7-ins-docs.txt line 8133. Field data: 16 bytes.
    """

    # Continuous BIT bit map (16 bytes, least-significant byte first), as in system data 0xA0,0x01.
    result: _t.Cv7ContinuousBit = _dc.field(default_factory=_t.Cv7ContinuousBit)

    SET = 0x01
    DESCRIPTOR = 0x88
    NAME = "continuous_bit_result"
    ROLE = "response"
    _ATTRS = ("result",)
    _OPS = (_c.Nested("result", _t.Cv7ContinuousBit),)


@_c.slotted
@_dc.dataclass
class CommPortSpeed(_c.Field):
    """Comm port speed (set 0x01, descriptor 0x09, command).

    Controls the baud rate of a port. The device waits up to 250 ms for pending data before applying
    the change; send it alone, with the device idle.

    Functions: write, read, save, load, default. Responses: 0x89 comm_port_speed_response. Sources:
    3dm-cv7-ins-docs.txt line 8141; 3dm-cv7-ins-docs.txt line 2150. Field data: 2..6 bytes.
    """

    # Function selector (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    port: int = 0  # Port ID (0x01 main, 0x11-0x13 UART1-3, 0x21 USB); 0 means all ports for save, load and default.
    baud: _ty.Optional[int] = None  # Port baud rate; must be a supported rate. [bit/s] (sent for: write)

    SET = 0x01
    DESCRIPTOR = 0x09
    NAME = "comm_port_speed"
    ROLE = "command"
    _ATTRS = ("function", "port", "baud")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("port", _c.U8)),
        _c.Opt(_c.Run(_c.P("baud", _c.U32))),
    )


@_c.slotted
@_dc.dataclass
class CommPortSpeedResponse(_c.Field):
    """Comm port speed (response) (set 0x01, descriptor 0x89, response).

    Current baud rate of a port.

    Sources: 3dm-cv7-ins-docs.txt line 8153. Field data: 5 bytes.
    """

    port: int = 0  # Port ID (0x01 main, 0x11-0x13 UART1-3, 0x21 USB).
    baud: int = 0  # Port baud rate. [bit/s]

    SET = 0x01
    DESCRIPTOR = 0x89
    NAME = "comm_port_speed_response"
    ROLE = "response"
    _ATTRS = ("port", "baud")
    _OPS = (_c.Run(_c.P("port", _c.U8), _c.P("baud", _c.U32)),)


@_c.slotted
@_dc.dataclass
class GpsTimeUpdate_gx5_45(_c.Field):
    """GPS time update (set 0x01, descriptor 0x72, command), device gx5_45.

    Set the device's internal GPS time (week number or time of week). Combined with a PPS input this
    synchronises the device's timestamps with an external GPS clock.

    Functions: write, read, write_no_ack. Responses: 0x84 gps_week, 0x85 gps_seconds. Sources:
    3dm-gx5-45-dcp.txt line 865. Field data: 2..6 bytes.
    """

    # Function selector (one of: write, read, write_no_ack)
    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE
    # Which time value: 1 GPS week number, 2 GPS seconds.
    field_id: _ty.Union[_t.GpsTimeField, int] = _t.GpsTimeField.WEEK_NUMBER
    # New week number or seconds, depending on field_id. (sent for: write, write_no_ack)
    value: _ty.Optional[int] = None

    SET = 0x01
    DESCRIPTOR = 0x72
    NAME = "gps_time_update"
    ROLE = "command"
    DEVICE = "gx5_45"
    _ATTRS = ("function", "field_id", "value")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionSelector, "u8")), _c.P("field_id", _c.enum(_t.GpsTimeField, "u8"))),
        _c.Opt(_c.Run(_c.P("value", _c.U32))),
    )


@_c.slotted
@_dc.dataclass
class GpsTimeUpdate_cv7_ins(_c.Field):
    """GPS time update (set 0x01, descriptor 0x72, command), device cv7_ins.

    Set the device's internal GPS time (week number or time of week). Combined with a PPS input this
    synchronises the device's timestamps with an external GPS clock.

    Functions: write. Sources: 3dm-cv7-ins-docs.txt line 8160. Field data: 6 bytes.
    """

    function: _ty.Union[_t.FunctionSelector, int] = _t.FunctionSelector.WRITE  # Function selector (one of: write)
    field_id: _ty.Union[_t.GpsTimeField, int] = _t.GpsTimeField.WEEK_NUMBER  # Determines how to interpret value.
    value: int = 0  # Week number or time of week, depending on field_id.

    SET = 0x01
    DESCRIPTOR = 0x72
    NAME = "gps_time_update"
    ROLE = "command"
    DEVICE = "cv7_ins"
    _ATTRS = ("function", "field_id", "value")
    _OPS = (
        _c.Run(
            _c.P("function", _c.enum(_t.FunctionSelector, "u8")),
            _c.P("field_id", _c.enum(_t.GpsTimeField, "u8")),
            _c.P("value", _c.U32),
        ),
    )


@_c.slotted
@_dc.dataclass
class GpsWeek(_c.Field):
    """Current GPS week (set 0x01, descriptor 0x84, response).

    Reply to GPS time update read with field selector 1 (week).

    Sources: 3dm-gx5-45-dcp.txt line 876. Field data: 4 bytes.
    """

    week: int = 0  # Current GPS week value. [weeks]

    SET = 0x01
    DESCRIPTOR = 0x84
    NAME = "gps_week"
    ROLE = "response"
    _ATTRS = ("week",)
    _OPS = (_c.Run(_c.P("week", _c.U32)),)


@_c.slotted
@_dc.dataclass
class GpsSeconds(_c.Field):
    """Current GPS seconds (set 0x01, descriptor 0x85, response).

    Reply to GPS time update read with field selector 2 (seconds).

    Sources: 3dm-gx5-45-dcp.txt line 877. Field data: 4 bytes.
    """

    seconds: int = 0  # Current GPS seconds value. [s]

    SET = 0x01
    DESCRIPTOR = 0x85
    NAME = "gps_seconds"
    ROLE = "response"
    _ATTRS = ("seconds",)
    _OPS = (_c.Run(_c.P("seconds", _c.U32)),)


@_c.slotted
@_dc.dataclass
class DeviceReset(_c.Field):
    """Device reset (set 0x01, descriptor 0x7E, command).

    Resets the device. The device ACKs and then immediately resets.

    Sources: 3dm-gx5-45-dcp.txt line 884; 3dm-cv7-ins-docs.txt line 8181. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x7E
    NAME = "device_reset"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


FIELDS: tuple[type[_c.Field], ...] = (
    Ping,
    SetToIdle,
    GetDeviceInfo,
    DeviceInfo,
    GetDeviceDescriptors,
    DeviceDescriptors,
    BuiltInTest,
    BuiltInTestResult_gx5_45,
    BuiltInTestResult_cv7_ins,
    Resume,
    GetExtendedDescriptors,
    ExtendedDescriptors,
    ContinuousBit,
    ContinuousBitResult,
    CommPortSpeed,
    CommPortSpeedResponse,
    GpsTimeUpdate_gx5_45,
    GpsTimeUpdate_cv7_ins,
    GpsWeek,
    GpsSeconds,
    DeviceReset,
)
