"""Base Messages (descriptor set 0x01, command).

Identify the device (supported messages, model, serial number, firmware, calibration date), ping and
reset it, and correlate its timestamps with GPS time.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class Ping(_c.Field):
    """Ping (set 0x01, descriptor 0x02, command).

    Check that the device is responsive; it answers with the ack.

    Sources: ms-cip-doc00419-revM.txt line 164; ms-cip-doc00419-revM.txt line 168;
    ms-cip-doc00419-revM.txt line 129. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x02
    NAME = "ping"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class GetDeviceMessages(_c.Field):
    """Get device messages (set 0x01, descriptor 0x03, command).

    Ask which messages the device supports.

    Responses: 0x83 device_messages. Sources: ms-cip-doc00419-revM.txt line 198;
    ms-cip-doc00419-revM.txt line 202. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x03
    NAME = "get_device_messages"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class DeviceMessages(_c.Field):
    """Device messages (set 0x01, descriptor 0x83, response).

    The supported messages, two bytes each (message type, then message code).

    Sources: ms-cip-doc00419-revM.txt line 216. Field data: 0..252 bytes.
    """

    # Supported messages ("2 * number of commands in bytes"). (to the end of the field)
    messages: _ty.List[_t.MessageId] = _dc.field(default_factory=list)

    SET = 0x01
    DESCRIPTOR = 0x83
    NAME = "device_messages"
    ROLE = "response"
    _ATTRS = ("messages",)
    _OPS = (_c.Remaining("messages", _t.MessageId, maximum=126),)


@_c.slotted
@_dc.dataclass
class DeviceReset(_c.Field):
    """Device reset (set 0x01, descriptor 0x04, command).

    Reset the device; the reset happens right after the ack is sent.

    Sources: ms-cip-doc00419-revM.txt line 242; ms-cip-doc00419-revM.txt line 246. Field data: 0
    bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x04
    NAME = "device_reset"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class GetDeviceModel(_c.Field):
    """Get device model (set 0x01, descriptor 0x05, command).

    Ask for the device model number.

    Responses: 0x85 device_model. Sources: ms-cip-doc00419-revM.txt line 276;
    ms-cip-doc00419-revM.txt line 280. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x05
    NAME = "get_device_model"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class DeviceModel(_c.Field):
    """Device model (set 0x01, descriptor 0x85, response).

    The model number, 16 characters, right-justified and padded with spaces.

    Sources: ms-cip-doc00419-revM.txt line 294. Field data: 16 bytes.
    """

    model: bytes = b" " * 16  # Device model, e.g. " MS_IMU3020".

    SET = 0x01
    DESCRIPTOR = 0x85
    NAME = "device_model"
    ROLE = "response"
    _ATTRS = ("model",)
    _OPS = (_c.Run(_c.P("model", _c.string(16))),)


@_c.slotted
@_dc.dataclass
class GetDeviceSn(_c.Field):
    """Get device serial number (set 0x01, descriptor 0x06, command).

    Ask for the device serial number.

    Responses: 0x86 device_sn. Sources: ms-cip-doc00419-revM.txt line 328; ms-cip-doc00419-revM.txt
    line 332. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x06
    NAME = "get_device_sn"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class DeviceSn(_c.Field):
    """Device serial number (set 0x01, descriptor 0x86, response).

    The serial number, 16 characters, right-justified and padded with spaces.

    Sources: ms-cip-doc00419-revM.txt line 346. Field data: 16 bytes.
    """

    serial_number: bytes = b" " * 16  # Serial number, e.g. " 20268".

    SET = 0x01
    DESCRIPTOR = 0x86
    NAME = "device_sn"
    ROLE = "response"
    _ATTRS = ("serial_number",)
    _OPS = (_c.Run(_c.P("serial_number", _c.string(16))),)


@_c.slotted
@_dc.dataclass
class GetDeviceFw(_c.Field):
    """Get device firmware (set 0x01, descriptor 0x07, command).

    Ask for the firmware revision.

    Responses: 0x87 device_fw. Sources: ms-cip-doc00419-revM.txt line 380; ms-cip-doc00419-revM.txt
    line 384. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x07
    NAME = "get_device_fw"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class DeviceFw(_c.Field):
    """Device firmware revision (set 0x01, descriptor 0x87, response).

    The firmware revision, 16 characters, right-justified and padded with spaces.

    Sources: ms-cip-doc00419-revM.txt line 398. Field data: 16 bytes.
    """

    firmware: bytes = b" " * 16  # Firmware revision, e.g. " R_1_2_3".

    SET = 0x01
    DESCRIPTOR = 0x87
    NAME = "device_fw"
    ROLE = "response"
    _ATTRS = ("firmware",)
    _OPS = (_c.Run(_c.P("firmware", _c.string(16))),)


@_c.slotted
@_dc.dataclass
class GetDeviceCal(_c.Field):
    """Get device calibration date (set 0x01, descriptor 0x08, command).

    Ask for the date the device was calibrated.

    Responses: 0x88 device_cal. Sources: ms-cip-doc00419-revM.txt line 432; ms-cip-doc00419-revM.txt
    line 436. Field data: 0 bytes.
    """

    SET = 0x01
    DESCRIPTOR = 0x08
    NAME = "get_device_cal"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class DeviceCal(_c.Field):
    """Device calibration date (set 0x01, descriptor 0x88, response).

    The calibration date as MM-DD-YYYY, 16 characters, right-justified and padded with spaces.

    Sources: ms-cip-doc00419-revM.txt line 450. Field data: 16 bytes.
    """

    date: bytes = b" " * 16  # Calibration date MM-DD-YYYY, e.g. " 05-08-2015".

    SET = 0x01
    DESCRIPTOR = 0x88
    NAME = "device_cal"
    ROLE = "response"
    _ATTRS = ("date",)
    _OPS = (_c.Run(_c.P("date", _c.string(16))),)


@_c.slotted
@_dc.dataclass
class CorrelateGpsTime(_c.Field):
    """Correlate GPS time (set 0x01, descriptor 0x09, command).

    Set the GPS week and time of week that the next 1-PPS pulse on the interface connector marks;
    send it right after the pulse. Any processor time in GPS format may stand in.

    Sources: ms-cip-doc00419-revM.txt line 484; ms-cip-doc00419-revM.txt line 488. Field data: 6
    bytes.
    """

    week: int = 0  # GPS week number. [weeks]
    seconds: int = 0  # GPS time of week in whole seconds. [s]

    SET = 0x01
    DESCRIPTOR = 0x09
    NAME = "correlate_gps_time"
    ROLE = "command"
    _ATTRS = ("week", "seconds")
    _OPS = (_c.Run(_c.P("week", _c.U16), _c.P("seconds", _c.U32)),)


FIELDS: tuple[type[_c.Field], ...] = (
    Ping,
    GetDeviceMessages,
    DeviceMessages,
    DeviceReset,
    GetDeviceModel,
    DeviceModel,
    GetDeviceSn,
    DeviceSn,
    GetDeviceFw,
    DeviceFw,
    GetDeviceCal,
    DeviceCal,
    CorrelateGpsTime,
)
