"""Shared data descriptors (set 0xFF) of the test protocol: an event source and a timestamp."""

from __future__ import annotations

import dataclasses as _dc

from . import codec as _c


@_dc.dataclass
class EventSource(_c.Field):
    """Event source (set 0xFF, descriptor 0xD0, data)."""

    trigger_id: int = 0

    SET = 0xFF
    DESCRIPTOR = 0xD0
    NAME = "event_source"
    ROLE = "data"
    _ATTRS = ("trigger_id",)
    _OPS = (_c.Run(_c.P("trigger_id", _c.U8)),)


@_dc.dataclass
class Timestamp(_c.Field):
    """Timestamp (set 0xFF, descriptor 0xD3, data): identifies a sample."""

    ticks: int = 0

    SET = 0xFF
    DESCRIPTOR = 0xD3
    NAME = "timestamp"
    ROLE = "data"
    _ATTRS = ("ticks",)
    _OPS = (_c.Run(_c.P("ticks", _c.U32)),)


FIELDS: tuple = (EventSource, Timestamp)
