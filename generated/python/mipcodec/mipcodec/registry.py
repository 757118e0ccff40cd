"""Dispatch tables of the MicroStrain MIP: (set, descriptor) -> layout classes.

A field with per-device variants maps to several classes, tried in IR order (docs/conformance.md
section 2). Reserved fields apply to every set of a kind; shared data descriptors to every data set.
"""

from __future__ import annotations

from typing import Dict, Optional, Tuple

from . import base, reserved, sensor, threedm

DEVICES: Tuple[str, ...] = ("gx5_45", "cv7_ins")

SET_NAMES: Dict[int, str] = {
    0x01: "base",
    0x0C: "threedm",
    0x80: "sensor",
}

SET_KINDS: Tuple[Tuple[str, int, int], ...] = (
    ("command", 0x01, 0x7F),
    ("data", 0x80, 0xFF),
)

SHARED_SET: Optional[int] = 0xFF

FIELDS: Dict[Tuple[int, int], Tuple[type, ...]] = {
    (0x01, 0x01): (base.Ping,),
    (0x01, 0x02): (base.SetToIdle,),
    (0x01, 0x03): (base.GetDeviceInfo,),
    (0x01, 0x81): (base.DeviceInfo,),
    (0x01, 0x04): (base.GetDeviceDescriptors,),
    (0x01, 0x82): (base.DeviceDescriptors,),
    (0x01, 0x05): (base.BuiltInTest,),
    (0x01, 0x83): (base.BuiltInTestResult_gx5_45, base.BuiltInTestResult_cv7_ins),
    (0x01, 0x06): (base.Resume,),
    (0x01, 0x07): (base.GetExtendedDescriptors,),
    (0x01, 0x86): (base.ExtendedDescriptors,),
    (0x01, 0x08): (base.ContinuousBit,),
    (0x01, 0x88): (base.ContinuousBitResult,),
    (0x01, 0x09): (base.CommPortSpeed,),
    (0x01, 0x89): (base.CommPortSpeedResponse,),
    (0x01, 0x72): (base.GpsTimeUpdate_gx5_45, base.GpsTimeUpdate_cv7_ins),
    (0x01, 0x84): (base.GpsWeek,),
    (0x01, 0x85): (base.GpsSeconds,),
    (0x01, 0x7E): (base.DeviceReset,),
    (0x0C, 0x2B): (threedm.EventControl,),
    (0x0C, 0xB5): (threedm.EventControlResponse,),
    (0x0C, 0x2C): (threedm.GetEventTriggerStatus,),
    (0x0C, 0xB6): (threedm.EventTriggerStatus,),
    (0x0C, 0x2D): (threedm.GetEventActionStatus,),
    (0x0C, 0xB7): (threedm.EventActionStatus,),
    (0x0C, 0x2E): (threedm.EventTriggerConfig,),
    (0x0C, 0xB8): (threedm.EventTriggerConfigResponse,),
    (0x0C, 0x2F): (threedm.EventActionConfig,),
    (0x0C, 0xB9): (threedm.EventActionConfigResponse,),
    (0x80, 0x04): (sensor.ScaledAccel,),
    (0x80, 0x05): (sensor.ScaledGyro,),
    (0x80, 0x06): (sensor.ScaledMag,),
}

RESERVED: Dict[str, Dict[int, Tuple[type, ...]]] = {
    "command": {
        0xF1: (reserved.AckNack,),
    },
}


def set_kind(set_id: int) -> Optional[str]:
    """The kind of a descriptor set ("command", "data", ...) from the set_kinds ranges."""
    for kind, first, last in SET_KINDS:
        if first <= set_id <= last:
            return kind
    return None


def lookup(set_id: int, descriptor: int) -> Optional[Tuple[type, ...]]:
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
