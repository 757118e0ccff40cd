"""Dispatch tables of the Demo protocol with every spec feature: (set, descriptor) -> layout classes.

A field with per-device variants maps to several classes, tried in IR order (docs/conformance.md
section 2). Reserved fields apply to every set of a kind; shared data descriptors to every data set.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any, Dict, Iterable, Optional, Tuple, Type

from .codec.layout import Field

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

# (set, descriptor) -> the layout classes as "module.Class": a set's module is imported when one of
# its fields is first looked up, so that decoding a log loads only the sets it holds.
_FIELD_CLASSES: Dict[Tuple[int, int], Tuple[str, ...]] = {
    (0x01, 0x01): ("commands.Ping",),
    (0x01, 0x02): ("commands.Configure",),
    (0x01, 0x82): ("commands.Configuration",),
    (0x01, 0x03): ("commands.PerDevice_dev_a", "commands.PerDevice_dev_b"),
    (0x90, 0x01): ("data.Sample",),
    (0x91, 0x03): ("receiver_1.LlhPosition",),
    (0x92, 0x03): ("receiver_2.LlhPosition",),
    (0xFF, 0xD3): ("shared.Timestamp",),
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
