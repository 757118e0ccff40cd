"""Named types of the Memsense MS-CIP: enums, bitfields, structs and unions.

Enums are IntEnums; decoding keeps values that are not members as plain ints. Bitfields are ints
whose members are properties (bool for one bit, int for several) with UPPER_CASE mask constants.
Structs are dataclasses; a union value is the selected member's struct (None: member without data).
"""

from __future__ import annotations

import dataclasses as _dc

from .codec import layout as _c


class AccelRange(_c.Enum):
    """Accelerometer range code (u8).

    Dynamic range of all three accelerometer axes (Tables 37 and 60; device specific).
    """

    RANGE_2G = 0x00  # Accelerometer range +-2 g.
    RANGE_4G = 0x01  # Accelerometer range +-4 g.
    RANGE_8G = 0x02  # Accelerometer range +-8 g.
    RANGE_10G = 0x03  # Accelerometer range +-10 g.
    RANGE_15G = 0x04  # Accelerometer range +-15 g.
    RANGE_20G = 0x05  # Accelerometer range +-20 g.
    RANGE_40G = 0x06  # Accelerometer range +-40 g.


class BaudRate(_c.Enum):
    """UART baud rate (u32).

    Baud rates the UART accepts, sent as their value (Table 20).
    """

    BAUD_9600 = 0x2580  # 9600 baud (0x00002580).
    BAUD_19200 = 0x4B00  # 19200 baud (0x00004B00).
    BAUD_115200 = 0x1C200  # 115200 baud (0x0001C200).
    BAUD_230400 = 0x38400  # 230400 baud (0x00038400).
    BAUD_460800 = 0x70800  # 460800 baud (0x00070800).
    BAUD_921600 = 0xE1000  # 921600 baud (0x000E1000).


class ErrorCode(_c.Enum):
    """Error code (u8).

    Second data byte of the ack field (Table 2).
    """

    OK = 0x00  # The message was received without error.
    CHECKSUM_ERROR = 0x01  # The checksum sent with the previous message does not calculate to the correct value.
    INVALID_MESSAGE_TYPE = 0x02  # The previous message contained an invalid message type.
    INVALID_MESSAGE_CODE = 0x03  # The previous message had an invalid message code.
    INVALID_PARAMETER = 0x04  # A parameter in the previous message is not valid.


class FilterBandwidth(_c.Enum):
    """Filter bandwidth control code (u8).

    Digital filter setting: disabled, or an IIR low-pass with the given -3 dB cutoff. The cutoffs
    are device specific; these are the MS-IMU3020's (Table 24).
    """

    DISABLED = 0x00  # Disable filter.
    IIR_25HZ = 0x01  # IIR filter, -3 dB at 25 Hz.
    IIR_50HZ = 0x02  # IIR filter, -3 dB at 50 Hz.
    IIR_75HZ = 0x03  # IIR filter, -3 dB at 75 Hz.
    IIR_100HZ = 0x04  # IIR filter, -3 dB at 100 Hz.
    IIR_10HZ = 0x05  # IIR filter, -3 dB at 10 Hz.
    IIR_150HZ = 0x06  # IIR filter, -3 dB at 150 Hz.
    IIR_200HZ = 0x07  # IIR filter, -3 dB at 200 Hz.


class FunctionCode(_c.Enum):
    """Function code (u8).

    First data byte of the configuration messages (0x0201, 0x0203-0x0205, 0x0207-0x020D): chooses
    what the message does.
    """

    WRITE = 0x01  # Use new settings.
    READ = 0x02  # Request current settings.
    SAVE = 0x03  # Save current settings as startup settings.
    LOAD = 0x04  # Load saved startup settings.
    DEFAULT = 0x05  # Reset to default settings.


@_c.bitfield("u16")
class GpsTimeFlags(_c.Bitfield):
    """GPS correlated time flags (u16 bitfield).

    Status of the GPS time correlation (Table 71).
    """

    _MEMBERS = (
        ("pps_received", "pps_received", "PPS_RECEIVED", 0, 1),
        ("time_set", "time_set", "TIME_SET", 1, 1),
        ("time_not_set", "time_not_set", "TIME_NOT_SET", 2, 1),
        ("pps_lost", "pps_lost", "PPS_LOST", 3, 1),
        ("reserved", "reserved", "RESERVED", 4, 12),
    )
    PPS_RECEIVED = 0x0001  # bit 0: GPS 1 PPS received: set for one sample after the pulse (only once GPS time is set).
    TIME_SET = 0x0002  # bit 1: GPS time was set: set for one sample after the message that set it.
    TIME_NOT_SET = 0x0004  # bit 2: No GPS time set: the time counts from week 0, time 0 on the internal clock.
    # bit 3: 1 PPS lost: more than 1 s without a pulse since the time was set; the internal clock carries on.
    PPS_LOST = 0x0008
    RESERVED = 0xFFF0  # bits 4-15: Reserved. (reserved)

    pps_received = _c.bit(0)
    time_set = _c.bit(1)
    time_not_set = _c.bit(2)
    pps_lost = _c.bit(3)
    reserved = _c.bits(4, 12)


class GyroRange(_c.Enum):
    """Gyroscope range code (u8).

    Dynamic range of all three gyroscope axes (Table 41; device specific).
    """

    RANGE_120DPS = 0x01  # Gyroscope range +-120 deg/s.
    RANGE_240DPS = 0x02  # Gyroscope range +-240 deg/s.
    RANGE_480DPS = 0x03  # Gyroscope range +-480 deg/s.
    RANGE_960DPS = 0x04  # Gyroscope range +-960 deg/s.
    RANGE_1920DPS = 0x05  # Gyroscope range +-1920 deg/s.
    RANGE_75DPS = 0x06  # Gyroscope range +-75 deg/s.
    RANGE_200DPS = 0x07  # Gyroscope range +-200 deg/s.


class OnOff(_c.Enum):
    """On/off control code (u8).

    Control code of Data On/Off (Table 48) and XTRIG On/Off (Table 52).
    """

    OFF = 0x00  # Off.
    ON = 0x01  # On.


class SensorCode(_c.Enum):
    """Sensor select code (u8).

    A measurement to include in the IMU data message: the message code of its 0xA2 data field
    (Tables 31 and 56).
    """

    SCALED_ACCEL = 0x81  # Scaled acceleration vector in g.
    SCALED_GYRO = 0x82  # Scaled angular rate vector in deg/s.
    SCALED_MAG = 0x83  # Scaled magnetic field vector in gauss.
    DELTA_THETA = 0x84  # Delta theta vector in radians.
    DELTA_VELOCITY = 0x85  # Delta velocity vector in m/s.
    SCALED_PRESSURE = 0x86  # Scaled pressure in millibar.
    SCALED_TEMPERATURE = 0x87  # Scaled temperature in degrees Celsius.
    GPS_CORRELATED_TIME = 0x88  # GPS correlated time.
    SCALED_AUX_ACCEL = 0x89  # Scaled auxiliary acceleration vector in g (Select Sensors Rev B only).


@_dc.dataclass
class MessageId(_c.Struct):
    """Message identifier (struct, 2 bytes).

    One supported message: "2 bytes for each message supported indicating the Message Type in the
    MSB and the Message ID Code in the LSB" (line 200).
    """

    message_type: int = 0  # Message type (0x01, 0x02, 0xA2, ...).
    message_code: int = 0  # Message code within the type.

    _ATTRS = ("message_type", "message_code")
    _OPS = (_c.Run(_c.P("message_type", _c.U8), _c.P("message_code", _c.U8)),)
    _SIZE = 2
