"""IMU Configuration Messages (descriptor set 0x02, command).

Configure the serial baud rate, digital filter, output decimation, output contents, sensor ranges,
data output and external trigger; save, load or reset all settings.
"""

from __future__ import annotations

import dataclasses as _dc
import typing as _ty

from . import types as _t
from .codec import layout as _c


@_c.slotted
@_dc.dataclass
class UartBaudRate(_c.Field):
    """UART baud rate configure (set 0x02, descriptor 0x01, command).

    Set, read, save, load or reset the baud rate. Messages after the reply use the new rate; saving
    may delay the reply while the setting is written to flash.

    Functions: write, read, save, load, default. Responses: 0x81 uart_baud_rate_response. Sources:
    ms-cip-doc00419-revM.txt line 526; ms-cip-doc00419-revM.txt line 549. Field data: 1..5 bytes.
    """

    # Function code (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.WRITE
    baud_rate: _ty.Optional[_ty.Union[_t.BaudRate, int]] = None  # New baud rate. [baud] (sent for: write)

    SET = 0x02
    DESCRIPTOR = 0x01
    NAME = "uart_baud_rate"
    ROLE = "command"
    _ATTRS = ("function", "baud_rate")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),
        _c.Opt(_c.Run(_c.P("baud_rate", _c.enum(_t.BaudRate, "u32")))),
    )


@_c.slotted
@_dc.dataclass
class UartBaudRateResponse(_c.Field):
    """UART baud rate (read reply, inferred) (set 0x02, descriptor 0x81, response).

    Current baud rate, in reply to "Request current settings".

    Sources: ms-cip-doc00419-revM.txt line 526. Field data: 4 bytes.
    """

    baud_rate: _ty.Union[_t.BaudRate, int] = _t.BaudRate.BAUD_9600  # Current baud rate. [baud]

    SET = 0x02
    DESCRIPTOR = 0x81
    NAME = "uart_baud_rate_response"
    ROLE = "response"
    _ATTRS = ("baud_rate",)
    _OPS = (_c.Run(_c.P("baud_rate", _c.enum(_t.BaudRate, "u32"))),)


@_c.slotted
@_dc.dataclass
class Filter(_c.Field):
    """Configure filter (set 0x02, descriptor 0x03, command).

    Set, read, save, load or reset the internal digital filter.

    Functions: write, read, save, load, default. Responses: 0x83 filter_response. Sources:
    ms-cip-doc00419-revM.txt line 584; ms-cip-doc00419-revM.txt line 617. Field data: 1..2 bytes.
    """

    # Function code (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.WRITE
    # Filter bandwidth control code. (sent for: write)
    bandwidth: _ty.Optional[_ty.Union[_t.FilterBandwidth, int]] = None

    SET = 0x02
    DESCRIPTOR = 0x03
    NAME = "filter"
    ROLE = "command"
    _ATTRS = ("function", "bandwidth")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),
        _c.Opt(_c.Run(_c.P("bandwidth", _c.enum(_t.FilterBandwidth, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class FilterResponse(_c.Field):
    """Filter (read reply, inferred) (set 0x02, descriptor 0x83, response).

    Current filter bandwidth control code.

    Sources: ms-cip-doc00419-revM.txt line 584. Field data: 1 bytes.
    """

    bandwidth: _ty.Union[_t.FilterBandwidth, int] = _t.FilterBandwidth.DISABLED  # Filter bandwidth control code.

    SET = 0x02
    DESCRIPTOR = 0x83
    NAME = "filter_response"
    ROLE = "response"
    _ATTRS = ("bandwidth",)
    _OPS = (_c.Run(_c.P("bandwidth", _c.enum(_t.FilterBandwidth, "u8"))),)


@_c.slotted
@_dc.dataclass
class SampleRate(_c.Field):
    """IMU sample rate configure (set 0x02, descriptor 0x04, command).

    Set, read, save, load or reset the output decimation: the output rate is the internal sample
    rate (0x0206) divided by the decimation (800 Hz / 8 = 100 Hz).

    Functions: write, read, save, load, default. Responses: 0x84 sample_rate_response. Sources:
    ms-cip-doc00419-revM.txt line 649; ms-cip-doc00419-revM.txt line 666. Field data: 1..3 bytes.
    """

    # Function code (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.WRITE
    decimation: _ty.Optional[int] = None  # Divider of the internal sample rate. (sent for: write)

    SET = 0x02
    DESCRIPTOR = 0x04
    NAME = "sample_rate"
    ROLE = "command"
    _ATTRS = ("function", "decimation")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),
        _c.Opt(_c.Run(_c.P("decimation", _c.U16))),
    )


@_c.slotted
@_dc.dataclass
class SampleRateResponse(_c.Field):
    """IMU sample rate (read reply, inferred) (set 0x02, descriptor 0x84, response).

    Current output decimation.

    Sources: ms-cip-doc00419-revM.txt line 649. Field data: 2 bytes.
    """

    decimation: int = 0  # Divider of the internal sample rate.

    SET = 0x02
    DESCRIPTOR = 0x84
    NAME = "sample_rate_response"
    ROLE = "response"
    _ATTRS = ("decimation",)
    _OPS = (_c.Run(_c.P("decimation", _c.U16)),)


@_c.slotted
@_dc.dataclass
class SelectSensors(_c.Field):
    """Select sensors (Rev A) (set 0x02, descriptor 0x05, command).

    Choose the measurements the IMU data message (0xA2) carries, by their data codes. Its size byte
    is one less than its data on the wire, which the device expects (Select Sensors errata); Select
    Sensors Rev B (0x020C) is the corrected message.

    Functions: write, read, save, load, default. Responses: 0x85 select_sensors_response. Sources:
    ms-cip-doc00419-revM.txt line 699; ms-cip-doc00419-revM.txt line 732; ms-cip-doc00419-revM.txt
    line 738. Field data: 1..253 bytes.
    """

    # Function code (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.WRITE
    reserved: _ty.Optional[int] = None  # Reserved for future use (0x00). (sent for: write)
    # Measurements to output, in order. (sent for: write) (to the end of the field)
    sensors: _ty.Optional[_ty.List[_ty.Union[_t.SensorCode, int]]] = None

    SET = 0x02
    DESCRIPTOR = 0x05
    NAME = "select_sensors"
    ROLE = "command"
    _ATTRS = ("function", "reserved", "sensors")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),
        _c.Opt(_c.Run(_c.P("reserved", _c.U8))),
        _c.Opt(_c.Remaining("sensors", _c.enum(_t.SensorCode, "u8"), maximum=251)),
    )


@_c.slotted
@_dc.dataclass
class SelectSensorsResponse(_c.Field):
    """Select sensors (read reply, inferred) (set 0x02, descriptor 0x85, response).

    The selected measurements.

    Sources: ms-cip-doc00419-revM.txt line 699. Field data: 0..253 bytes.
    """

    # Selected measurements. (to the end of the field)
    sensors: _ty.List[_ty.Union[_t.SensorCode, int]] = _dc.field(default_factory=list)

    SET = 0x02
    DESCRIPTOR = 0x85
    NAME = "select_sensors_response"
    ROLE = "response"
    _ATTRS = ("sensors",)
    _OPS = (_c.Remaining("sensors", _c.enum(_t.SensorCode, "u8"), maximum=253),)


@_c.slotted
@_dc.dataclass
class GetInternalSampleRate(_c.Field):
    """Get IMU internal sample rate (set 0x02, descriptor 0x06, command).

    Ask for the internal sample rate that the decimation divides.

    Responses: 0x86 internal_sample_rate. Sources: ms-cip-doc00419-revM.txt line 772;
    ms-cip-doc00419-revM.txt line 778. Field data: 0 bytes.
    """

    SET = 0x02
    DESCRIPTOR = 0x06
    NAME = "get_internal_sample_rate"
    ROLE = "command"
    _ATTRS = ()
    _OPS = ()


@_c.slotted
@_dc.dataclass
class InternalSampleRate(_c.Field):
    """IMU internal sample rate (set 0x02, descriptor 0x86, response).

    The internal sample rate in hertz.

    Sources: ms-cip-doc00419-revM.txt line 792. Field data: 2 bytes.
    """

    rate: int = 0  # Internal sample rate (e.g. 800). [Hz]

    SET = 0x02
    DESCRIPTOR = 0x86
    NAME = "internal_sample_rate"
    ROLE = "response"
    _ATTRS = ("rate",)
    _OPS = (_c.Run(_c.P("rate", _c.U16)),)


@_c.slotted
@_dc.dataclass
class AccelRange(_c.Field):
    """Config accel range (set 0x02, descriptor 0x07, command).

    Set, read, save, load or reset the accelerometer dynamic range.

    Functions: write, read, save, load, default. Responses: 0x87 accel_range_response. Sources:
    ms-cip-doc00419-revM.txt line 812; ms-cip-doc00419-revM.txt line 844. Field data: 1..2 bytes.
    """

    # Function code (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.WRITE
    range: _ty.Optional[_ty.Union[_t.AccelRange, int]] = None  # Accelerometer range code. (sent for: write)

    SET = 0x02
    DESCRIPTOR = 0x07
    NAME = "accel_range"
    ROLE = "command"
    _ATTRS = ("function", "range")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),
        _c.Opt(_c.Run(_c.P("range", _c.enum(_t.AccelRange, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class AccelRangeResponse(_c.Field):
    """Accel range (read reply, inferred) (set 0x02, descriptor 0x87, response).

    Current accelerometer range code.

    Sources: ms-cip-doc00419-revM.txt line 812. Field data: 1 bytes.
    """

    range: _ty.Union[_t.AccelRange, int] = _t.AccelRange.RANGE_2G  # Accelerometer range code.

    SET = 0x02
    DESCRIPTOR = 0x87
    NAME = "accel_range_response"
    ROLE = "response"
    _ATTRS = ("range",)
    _OPS = (_c.Run(_c.P("range", _c.enum(_t.AccelRange, "u8"))),)


@_c.slotted
@_dc.dataclass
class GyroRange(_c.Field):
    """Configure gyro range (set 0x02, descriptor 0x08, command).

    Set, read, save, load or reset the gyroscope dynamic range.

    Functions: write, read, save, load, default. Responses: 0x88 gyro_range_response. Sources:
    ms-cip-doc00419-revM.txt line 876; ms-cip-doc00419-revM.txt line 908. Field data: 1..2 bytes.
    """

    # Function code (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.WRITE
    range: _ty.Optional[_ty.Union[_t.GyroRange, int]] = None  # Gyroscope range code. (sent for: write)

    SET = 0x02
    DESCRIPTOR = 0x08
    NAME = "gyro_range"
    ROLE = "command"
    _ATTRS = ("function", "range")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),
        _c.Opt(_c.Run(_c.P("range", _c.enum(_t.GyroRange, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class GyroRangeResponse(_c.Field):
    """Gyro range (read reply, inferred) (set 0x02, descriptor 0x88, response).

    Current gyroscope range code.

    Sources: ms-cip-doc00419-revM.txt line 876. Field data: 1 bytes.
    """

    range: _ty.Union[_t.GyroRange, int] = _t.GyroRange.RANGE_120DPS  # Gyroscope range code.

    SET = 0x02
    DESCRIPTOR = 0x88
    NAME = "gyro_range_response"
    ROLE = "response"
    _ATTRS = ("range",)
    _OPS = (_c.Run(_c.P("range", _c.enum(_t.GyroRange, "u8"))),)


@_c.slotted
@_dc.dataclass
class ConfigAll(_c.Field):
    """Configure all (set 0x02, descriptor 0x09, command).

    Save, load or reset to factory defaults every configurable setting.

    Functions: save, load, default. Sources: ms-cip-doc00419-revM.txt line 940;
    ms-cip-doc00419-revM.txt line 944; ms-cip-doc00419-revM.txt line 953. Field data: 1 bytes.
    """

    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.SAVE  # Function code (one of: save, load, default)

    SET = 0x02
    DESCRIPTOR = 0x09
    NAME = "config_all"
    ROLE = "command"
    _ATTRS = ("function",)
    _OPS = (_c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),)


@_c.slotted
@_dc.dataclass
class DataOnOff(_c.Field):
    """Data on/off (set 0x02, descriptor 0x0A, command).

    Enable or disable the data output.

    Functions: write, read, save, load, default. Responses: 0x8A data_on_off_response. Sources:
    ms-cip-doc00419-revM.txt line 984; ms-cip-doc00419-revM.txt line 1007. Field data: 1..2 bytes.
    """

    # Function code (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.WRITE
    control: _ty.Optional[_ty.Union[_t.OnOff, int]] = None  # Data on or off. (sent for: write)

    SET = 0x02
    DESCRIPTOR = 0x0A
    NAME = "data_on_off"
    ROLE = "command"
    _ATTRS = ("function", "control")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),
        _c.Opt(_c.Run(_c.P("control", _c.enum(_t.OnOff, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class DataOnOffResponse(_c.Field):
    """Data on/off (read reply, inferred) (set 0x02, descriptor 0x8A, response).

    Whether data output is on.

    Sources: ms-cip-doc00419-revM.txt line 984. Field data: 1 bytes.
    """

    control: _ty.Union[_t.OnOff, int] = _t.OnOff.OFF  # Data on or off.

    SET = 0x02
    DESCRIPTOR = 0x8A
    NAME = "data_on_off_response"
    ROLE = "response"
    _ATTRS = ("control",)
    _OPS = (_c.Run(_c.P("control", _c.enum(_t.OnOff, "u8"))),)


@_c.slotted
@_dc.dataclass
class XtrigOnOff(_c.Field):
    """XTRIG on/off (set 0x02, descriptor 0x0B, command).

    Enable or disable the external trigger input.

    Functions: write, read, save, load, default. Responses: 0x8B xtrig_on_off_response. Sources:
    ms-cip-doc00419-revM.txt line 1039; ms-cip-doc00419-revM.txt line 1062. Field data: 1..2 bytes.
    """

    # Function code (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.WRITE
    control: _ty.Optional[_ty.Union[_t.OnOff, int]] = None  # External trigger on or off. (sent for: write)

    SET = 0x02
    DESCRIPTOR = 0x0B
    NAME = "xtrig_on_off"
    ROLE = "command"
    _ATTRS = ("function", "control")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),
        _c.Opt(_c.Run(_c.P("control", _c.enum(_t.OnOff, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class XtrigOnOffResponse(_c.Field):
    """XTRIG on/off (read reply, inferred) (set 0x02, descriptor 0x8B, response).

    Whether the external trigger input is on.

    Sources: ms-cip-doc00419-revM.txt line 1039. Field data: 1 bytes.
    """

    control: _ty.Union[_t.OnOff, int] = _t.OnOff.OFF  # External trigger on or off.

    SET = 0x02
    DESCRIPTOR = 0x8B
    NAME = "xtrig_on_off_response"
    ROLE = "response"
    _ATTRS = ("control",)
    _OPS = (_c.Run(_c.P("control", _c.enum(_t.OnOff, "u8"))),)


@_c.slotted
@_dc.dataclass
class SelectSensorsRevB(_c.Field):
    """Select sensors (Rev B) (set 0x02, descriptor 0x0C, command).

    Choose the measurements the IMU data message (0xA2) carries, by their data codes; the corrected
    Select Sensors (size byte counts every data byte, no reserved byte).

    Functions: write, read, save, load, default. Responses: 0x8C select_sensors_rev_b_response.
    Sources: ms-cip-doc00419-revM.txt line 1094; ms-cip-doc00419-revM.txt line 1128. Field data:
    1..253 bytes.
    """

    # Function code (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.WRITE
    # Measurements to output, in order. (sent for: write) (to the end of the field)
    sensors: _ty.Optional[_ty.List[_ty.Union[_t.SensorCode, int]]] = None

    SET = 0x02
    DESCRIPTOR = 0x0C
    NAME = "select_sensors_rev_b"
    ROLE = "command"
    _ATTRS = ("function", "sensors")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),
        _c.Opt(_c.Remaining("sensors", _c.enum(_t.SensorCode, "u8"), maximum=252)),
    )


@_c.slotted
@_dc.dataclass
class SelectSensorsRevBResponse(_c.Field):
    """Select sensors Rev B (read reply, inferred) (set 0x02, descriptor 0x8C, response).

    The selected measurements.

    Sources: ms-cip-doc00419-revM.txt line 1094. Field data: 0..253 bytes.
    """

    # Selected measurements. (to the end of the field)
    sensors: _ty.List[_ty.Union[_t.SensorCode, int]] = _dc.field(default_factory=list)

    SET = 0x02
    DESCRIPTOR = 0x8C
    NAME = "select_sensors_rev_b_response"
    ROLE = "response"
    _ATTRS = ("sensors",)
    _OPS = (_c.Remaining("sensors", _c.enum(_t.SensorCode, "u8"), maximum=253),)


@_c.slotted
@_dc.dataclass
class AuxAccelRange(_c.Field):
    """Config aux accel range (set 0x02, descriptor 0x0D, command).

    Set, read, save, load or reset the auxiliary accelerometer dynamic range.

    Functions: write, read, save, load, default. Responses: 0x8D aux_accel_range_response. Sources:
    ms-cip-doc00419-revM.txt line 1161; ms-cip-doc00419-revM.txt line 1193. Field data: 1..2 bytes.
    """

    # Function code (one of: write, read, save, load, default)
    function: _ty.Union[_t.FunctionCode, int] = _t.FunctionCode.WRITE
    range: _ty.Optional[_ty.Union[_t.AccelRange, int]] = None  # Auxiliary accelerometer range code. (sent for: write)

    SET = 0x02
    DESCRIPTOR = 0x0D
    NAME = "aux_accel_range"
    ROLE = "command"
    _ATTRS = ("function", "range")
    _OPS = (
        _c.Run(_c.P("function", _c.enum(_t.FunctionCode, "u8"))),
        _c.Opt(_c.Run(_c.P("range", _c.enum(_t.AccelRange, "u8")))),
    )


@_c.slotted
@_dc.dataclass
class AuxAccelRangeResponse(_c.Field):
    """Aux accel range (read reply, inferred) (set 0x02, descriptor 0x8D, response).

    Current auxiliary accelerometer range code.

    Sources: ms-cip-doc00419-revM.txt line 1161. Field data: 1 bytes.
    """

    range: _ty.Union[_t.AccelRange, int] = _t.AccelRange.RANGE_2G  # Auxiliary accelerometer range code.

    SET = 0x02
    DESCRIPTOR = 0x8D
    NAME = "aux_accel_range_response"
    ROLE = "response"
    _ATTRS = ("range",)
    _OPS = (_c.Run(_c.P("range", _c.enum(_t.AccelRange, "u8"))),)


FIELDS: tuple[type[_c.Field], ...] = (
    UartBaudRate,
    UartBaudRateResponse,
    Filter,
    FilterResponse,
    SampleRate,
    SampleRateResponse,
    SelectSensors,
    SelectSensorsResponse,
    GetInternalSampleRate,
    InternalSampleRate,
    AccelRange,
    AccelRangeResponse,
    GyroRange,
    GyroRangeResponse,
    ConfigAll,
    DataOnOff,
    DataOnOffResponse,
    XtrigOnOff,
    XtrigOnOffResponse,
    SelectSensorsRevB,
    SelectSensorsRevBResponse,
    AuxAccelRange,
    AuxAccelRangeResponse,
)
