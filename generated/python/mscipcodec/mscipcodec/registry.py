"""Dispatch tables of the Memsense MS-CIP: (set, descriptor) -> layout classes.

A field with per-device variants maps to several classes, tried in IR order (docs/conformance.md
section 2). Reserved fields apply to every set of a kind; shared data descriptors to every data set.
"""

from __future__ import annotations

from typing import Dict, Optional, Tuple, Type

from . import base, imu_config, imu_data, reserved
from .codec import Field

DEVICES: Tuple[str, ...] = ("ms_imu3020",)

SET_NAMES: Dict[int, str] = {
    0x01: "base",
    0x02: "imu_config",
    0xA2: "imu_data",
}

SET_KINDS: Tuple[Tuple[str, int, int], ...] = (
    ("command", 0x01, 0x7F),
    ("data", 0x80, 0xFF),
)

SHARED_SET: Optional[int] = None

FIELDS: Dict[Tuple[int, int], Tuple[Type[Field], ...]] = {
    (0x01, 0x02): (base.Ping,),
    (0x01, 0x03): (base.GetDeviceMessages,),
    (0x01, 0x83): (base.DeviceMessages,),
    (0x01, 0x04): (base.DeviceReset,),
    (0x01, 0x05): (base.GetDeviceModel,),
    (0x01, 0x85): (base.DeviceModel,),
    (0x01, 0x06): (base.GetDeviceSn,),
    (0x01, 0x86): (base.DeviceSn,),
    (0x01, 0x07): (base.GetDeviceFw,),
    (0x01, 0x87): (base.DeviceFw,),
    (0x01, 0x08): (base.GetDeviceCal,),
    (0x01, 0x88): (base.DeviceCal,),
    (0x01, 0x09): (base.CorrelateGpsTime,),
    (0x02, 0x01): (imu_config.UartBaudRate,),
    (0x02, 0x81): (imu_config.UartBaudRateResponse,),
    (0x02, 0x03): (imu_config.Filter,),
    (0x02, 0x83): (imu_config.FilterResponse,),
    (0x02, 0x04): (imu_config.SampleRate,),
    (0x02, 0x84): (imu_config.SampleRateResponse,),
    (0x02, 0x05): (imu_config.SelectSensors,),
    (0x02, 0x85): (imu_config.SelectSensorsResponse,),
    (0x02, 0x06): (imu_config.GetInternalSampleRate,),
    (0x02, 0x86): (imu_config.InternalSampleRate,),
    (0x02, 0x07): (imu_config.AccelRange,),
    (0x02, 0x87): (imu_config.AccelRangeResponse,),
    (0x02, 0x08): (imu_config.GyroRange,),
    (0x02, 0x88): (imu_config.GyroRangeResponse,),
    (0x02, 0x09): (imu_config.ConfigAll,),
    (0x02, 0x0A): (imu_config.DataOnOff,),
    (0x02, 0x8A): (imu_config.DataOnOffResponse,),
    (0x02, 0x0B): (imu_config.XtrigOnOff,),
    (0x02, 0x8B): (imu_config.XtrigOnOffResponse,),
    (0x02, 0x0C): (imu_config.SelectSensorsRevB,),
    (0x02, 0x8C): (imu_config.SelectSensorsRevBResponse,),
    (0x02, 0x0D): (imu_config.AuxAccelRange,),
    (0x02, 0x8D): (imu_config.AuxAccelRangeResponse,),
    (0xA2, 0x81): (imu_data.ScaledAccel,),
    (0xA2, 0x82): (imu_data.ScaledGyro,),
    (0xA2, 0x83): (imu_data.ScaledMag,),
    (0xA2, 0x84): (imu_data.DeltaTheta,),
    (0xA2, 0x85): (imu_data.DeltaVelocity,),
    (0xA2, 0x86): (imu_data.ScaledPressure,),
    (0xA2, 0x87): (imu_data.ScaledTemperature,),
    (0xA2, 0x88): (imu_data.GpsCorrelatedTime,),
    (0xA2, 0x89): (imu_data.ScaledAuxAccel,),
}

RESERVED: Dict[str, Dict[int, Tuple[Type[Field], ...]]] = {
    "command": {
        0x80: (reserved.Ack,),
    },
}


def set_kind(set_id: int) -> Optional[str]:
    """The kind of a descriptor set ("command", "data", ...) from the set_kinds ranges."""
    for kind, first, last in SET_KINDS:
        if first <= set_id <= last:
            return kind
    return None


def lookup(set_id: int, descriptor: int) -> Optional[Tuple[Type[Field], ...]]:
    """The layout classes for a field, or None: set's own field, reserved field, shared data field."""
    classes = FIELDS.get((set_id, descriptor))
    if classes is not None:
        return classes
    kind = set_kind(set_id)
    classes = RESERVED.get(kind or "", {}).get(descriptor)
    if classes is not None:
        return classes
    if kind == "data" and SHARED_SET is not None:
        return FIELDS.get((SHARED_SET, descriptor))
    return None
