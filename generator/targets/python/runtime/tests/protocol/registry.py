"""Dispatch tables of the test protocol: (set, descriptor) -> layout classes (cf. registry.py.j2)."""

from __future__ import annotations

from typing import Dict, Optional, Tuple

from . import command, reserved, sensor, shared

DEVICES: Tuple[str, ...] = ("alpha", "beta")

SET_NAMES: Dict[int, str] = {
    0x01: "command",
    0x80: "sensor",
    0xFF: "shared",
}

SET_KINDS: Tuple[Tuple[str, int, int], ...] = (
    ("command", 0x01, 0x7F),
    ("data", 0x80, 0xFF),
)

SHARED_SET: Optional[int] = 0xFF

FIELDS: Dict[Tuple[int, int], Tuple[type, ...]] = {
    **{(cls.SET, cls.DESCRIPTOR): (cls,) for cls in command.FIELDS + sensor.FIELDS + shared.FIELDS},
    (0x80, 0x05): (sensor.Temperature_alpha, sensor.Temperature_beta),
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
