"""Dispatch tables of the Demo protocol with every spec feature: (set, descriptor) -> layout classes.

A field with per-device variants maps to several classes, tried in IR order (docs/conformance.md
section 2). Reserved fields apply to every set of a kind; shared data descriptors to every data set.
"""

from __future__ import annotations

from typing import Dict, Optional, Tuple, Type

from . import commands, data, receiver_1, receiver_2, reserved, shared
from .codec import Field

DEVICES: Tuple[str, ...] = ("dev_a", "dev_b")

SET_NAMES: Dict[int, str] = {
    0x01: "commands",
    0x90: "data",
    0x91: "receiver_1",
    0x92: "receiver_2",
    0xFF: "shared",
}

SET_KINDS: Tuple[Tuple[str, int, int], ...] = (
    ("command", 0x01, 0x7F),
    ("data", 0x80, 0xFF),
)

SHARED_SET: Optional[int] = 0xFF

FIELDS: Dict[Tuple[int, int], Tuple[Type[Field], ...]] = {
    (0x01, 0x01): (commands.Ping,),
    (0x01, 0x02): (commands.Configure,),
    (0x01, 0x82): (commands.Configuration,),
    (0x01, 0x03): (commands.PerDevice_dev_a, commands.PerDevice_dev_b),
    (0x90, 0x01): (data.Sample,),
    (0x91, 0x03): (receiver_1.LlhPosition,),
    (0x92, 0x03): (receiver_2.LlhPosition,),
    (0xFF, 0xD3): (shared.Timestamp,),
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
