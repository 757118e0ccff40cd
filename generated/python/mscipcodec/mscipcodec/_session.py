"""What the Memsense MS-CIP spec says about every command, for the session layer (session/):
how a reply is matched, and per command layout (set, descriptor) -> rows of
(class, device, devices, functions, replies, ack suppression, timeout allowance).

functions: the function selector values the layout accepts (None: no selector). replies:
(descriptor, function or None, parameter or None, value or None) -- the reply field sent with
the ack when the function is that one and the parameter has that value (None: any non-zero).
ack suppression: ("function", value) or ("param", attribute, value or None: any non-zero).
timeout allowance: (ms, parameter whose value adds milliseconds or None, functions or None).
"""

from __future__ import annotations

from typing import Any, Dict, Tuple

from . import base, imu_config

ACK_DESCRIPTOR = 0x80
ACK_ECHO = "command_code"
ACK_CODE = "error_code"
ACK_OK = 0

FUNCTION_NAMES: Dict[int, str] = {
    1: "write",
    2: "read",
    3: "save",
    4: "load",
    5: "default",
}

# Function selector values that only some devices accept.
FUNCTION_DEVICES: Dict[int, Tuple[str, ...]] = {}

COMMANDS: Dict[Tuple[int, int], Tuple[Tuple[Any, ...], ...]] = {
    (0x01, 0x02): ((base.Ping, None, ("ms_imu3020",), None, (), None, None),),
    (0x01, 0x03): ((base.GetDeviceMessages, None, ("ms_imu3020",), None, ((0x83, None, None, None),), None, None),),
    (0x01, 0x04): ((base.DeviceReset, None, ("ms_imu3020",), None, (), None, None),),
    (0x01, 0x05): ((base.GetDeviceModel, None, ("ms_imu3020",), None, ((0x85, None, None, None),), None, None),),
    (0x01, 0x06): ((base.GetDeviceSn, None, ("ms_imu3020",), None, ((0x86, None, None, None),), None, None),),
    (0x01, 0x07): ((base.GetDeviceFw, None, ("ms_imu3020",), None, ((0x87, None, None, None),), None, None),),
    (0x01, 0x08): ((base.GetDeviceCal, None, ("ms_imu3020",), None, ((0x88, None, None, None),), None, None),),
    (0x01, 0x09): ((base.CorrelateGpsTime, None, ("ms_imu3020",), None, (), None, None),),
    (0x02, 0x01): (
        (imu_config.UartBaudRate, None, ("ms_imu3020",), (1, 2, 3, 4, 5), ((0x81, 2, None, None),), None, None),
    ),
    (0x02, 0x03): ((imu_config.Filter, None, ("ms_imu3020",), (1, 2, 3, 4, 5), ((0x83, 2, None, None),), None, None),),
    (0x02, 0x04): (
        (imu_config.SampleRate, None, ("ms_imu3020",), (1, 2, 3, 4, 5), ((0x84, 2, None, None),), None, None),
    ),
    (0x02, 0x05): (
        (imu_config.SelectSensors, None, ("ms_imu3020",), (1, 2, 3, 4, 5), ((0x85, 2, None, None),), None, None),
    ),
    (0x02, 0x06): (
        (imu_config.GetInternalSampleRate, None, ("ms_imu3020",), None, ((0x86, None, None, None),), None, None),
    ),
    (0x02, 0x07): (
        (imu_config.AccelRange, None, ("ms_imu3020",), (1, 2, 3, 4, 5), ((0x87, 2, None, None),), None, None),
    ),
    (0x02, 0x08): (
        (imu_config.GyroRange, None, ("ms_imu3020",), (1, 2, 3, 4, 5), ((0x88, 2, None, None),), None, None),
    ),
    (0x02, 0x09): ((imu_config.ConfigAll, None, ("ms_imu3020",), (3, 4, 5), (), None, None),),
    (0x02, 0x0A): (
        (imu_config.DataOnOff, None, ("ms_imu3020",), (1, 2, 3, 4, 5), ((0x8A, 2, None, None),), None, None),
    ),
    (0x02, 0x0B): (
        (imu_config.XtrigOnOff, None, ("ms_imu3020",), (1, 2, 3, 4, 5), ((0x8B, 2, None, None),), None, None),
    ),
    (0x02, 0x0C): (
        (imu_config.SelectSensorsRevB, None, ("ms_imu3020",), (1, 2, 3, 4, 5), ((0x8C, 2, None, None),), None, None),
    ),
    (0x02, 0x0D): (
        (imu_config.AuxAccelRange, None, ("ms_imu3020",), (1, 2, 3, 4, 5), ((0x8D, 2, None, None),), None, None),
    ),
}


def function_name(value: int) -> str:
    return FUNCTION_NAMES.get(value, str(value))
