"""Dispatch tables of the Memsense MS-CIP: (set, descriptor) -> layout classes.

A field with per-device variants maps to several classes, tried in IR order (docs/conformance.md
section 2). Reserved fields apply to every set of a kind; shared data descriptors to every data set.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any, Dict, Iterable, Optional, Tuple, Type

from .codec.layout import Field

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

# (set, descriptor) -> the layout classes as "module.Class": a set's module is imported when one of
# its fields is first looked up, so that decoding a log loads only the sets it holds.
_FIELD_CLASSES: Dict[Tuple[int, int], Tuple[str, ...]] = {
    (0x01, 0x02): ("base.Ping",),
    (0x01, 0x03): ("base.GetDeviceMessages",),
    (0x01, 0x83): ("base.DeviceMessages",),
    (0x01, 0x04): ("base.DeviceReset",),
    (0x01, 0x05): ("base.GetDeviceModel",),
    (0x01, 0x85): ("base.DeviceModel",),
    (0x01, 0x06): ("base.GetDeviceSn",),
    (0x01, 0x86): ("base.DeviceSn",),
    (0x01, 0x07): ("base.GetDeviceFw",),
    (0x01, 0x87): ("base.DeviceFw",),
    (0x01, 0x08): ("base.GetDeviceCal",),
    (0x01, 0x88): ("base.DeviceCal",),
    (0x01, 0x09): ("base.CorrelateGpsTime",),
    (0x02, 0x01): ("imu_config.UartBaudRate",),
    (0x02, 0x81): ("imu_config.UartBaudRateResponse",),
    (0x02, 0x03): ("imu_config.Filter",),
    (0x02, 0x83): ("imu_config.FilterResponse",),
    (0x02, 0x04): ("imu_config.SampleRate",),
    (0x02, 0x84): ("imu_config.SampleRateResponse",),
    (0x02, 0x05): ("imu_config.SelectSensors",),
    (0x02, 0x85): ("imu_config.SelectSensorsResponse",),
    (0x02, 0x06): ("imu_config.GetInternalSampleRate",),
    (0x02, 0x86): ("imu_config.InternalSampleRate",),
    (0x02, 0x07): ("imu_config.AccelRange",),
    (0x02, 0x87): ("imu_config.AccelRangeResponse",),
    (0x02, 0x08): ("imu_config.GyroRange",),
    (0x02, 0x88): ("imu_config.GyroRangeResponse",),
    (0x02, 0x09): ("imu_config.ConfigAll",),
    (0x02, 0x0A): ("imu_config.DataOnOff",),
    (0x02, 0x8A): ("imu_config.DataOnOffResponse",),
    (0x02, 0x0B): ("imu_config.XtrigOnOff",),
    (0x02, 0x8B): ("imu_config.XtrigOnOffResponse",),
    (0x02, 0x0C): ("imu_config.SelectSensorsRevB",),
    (0x02, 0x8C): ("imu_config.SelectSensorsRevBResponse",),
    (0x02, 0x0D): ("imu_config.AuxAccelRange",),
    (0x02, 0x8D): ("imu_config.AuxAccelRangeResponse",),
    (0xA2, 0x81): ("imu_data.ScaledAccel",),
    (0xA2, 0x82): ("imu_data.ScaledGyro",),
    (0xA2, 0x83): ("imu_data.ScaledMag",),
    (0xA2, 0x84): ("imu_data.DeltaTheta",),
    (0xA2, 0x85): ("imu_data.DeltaVelocity",),
    (0xA2, 0x86): ("imu_data.ScaledPressure",),
    (0xA2, 0x87): ("imu_data.ScaledTemperature",),
    (0xA2, 0x88): ("imu_data.GpsCorrelatedTime",),
    (0xA2, 0x89): ("imu_data.ScaledAuxAccel",),
}

_RESERVED_CLASSES: Dict[str, Dict[int, Tuple[str, ...]]] = {
    "command": {
        0x80: ("reserved.Ack",),
    },
}

if TYPE_CHECKING:
    # Built on first access (module __getattr__ below), every set's module imported.
    FIELDS: Dict[Tuple[int, int], Tuple[Type[Field], ...]]
    RESERVED: Dict[str, Dict[int, Tuple[Type[Field], ...]]]

_resolved: Dict[Any, Tuple[Type[Field], ...]] = {}


def _classes(names: Iterable[str]) -> Tuple[Type[Field], ...]:
    out = []
    for name in names:
        module, _, cls = name.partition(".")
        out.append(getattr(importlib.import_module(f"{__package__}.{module}"), cls))
    return tuple(out)


def _field(set_id: int, descriptor: int) -> Optional[Tuple[Type[Field], ...]]:
    key = (set_id, descriptor)
    classes = _resolved.get(key)
    if classes is None:
        names = _FIELD_CLASSES.get(key)
        if names is None:
            return None
        classes = _resolved[key] = _classes(names)
    return classes


def _reserved(kind: str, descriptor: int) -> Optional[Tuple[Type[Field], ...]]:
    key = (kind, descriptor)
    classes = _resolved.get(key)
    if classes is None:
        names = _RESERVED_CLASSES.get(kind, {}).get(descriptor)
        if names is None:
            return None
        classes = _resolved[key] = _classes(names)
    return classes


def __getattr__(name: str) -> Any:
    """FIELDS ((set, descriptor) -> layout classes) and RESERVED (kind -> descriptor -> layout
    classes), built on first access."""
    value: Any
    if name == "FIELDS":
        value = {key: _field(*key) for key in _FIELD_CLASSES}
    elif name == "RESERVED":
        value = {k: {d: _reserved(k, d) for d in entries} for k, entries in _RESERVED_CLASSES.items()}
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value


def set_kind(set_id: int) -> Optional[str]:
    """The kind of a descriptor set ("command", "data", ...) from the set_kinds ranges."""
    for kind, first, last in SET_KINDS:
        if first <= set_id <= last:
            return kind
    return None


def lookup(set_id: int, descriptor: int) -> Optional[Tuple[Type[Field], ...]]:
    """The layout classes for a field, or None: set's own field, reserved field, shared data field."""
    classes = _field(set_id, descriptor)
    if classes is not None:
        return classes
    kind = set_kind(set_id)
    classes = _reserved(kind or "", descriptor)
    if classes is not None:
        return classes
    if kind == "data" and SHARED_SET is not None:
        return _field(SHARED_SET, descriptor)
    return None
